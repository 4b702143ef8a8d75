// Headless contexts: EGL (EGL_MESA_platform_surfaceless, or the first EGL device of
// EGL_EXT_platform_device where a driver lacks Mesa's platform, + EGL_KHR_surfaceless_context) and
// OSMesa (a core-profile context made current on a 1x1 buffer); glad loads GL through each.
#include "gl/context.hpp"

#include "gl/gl.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>

#include <mutex>
#include <utility>
#include <vector>

namespace rmsc {
namespace {

std::mutex debugMutex;
std::string debugErrors;

void GLAPIENTRY onGlDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                 const GLchar* message, const void*) {
    if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
    std::lock_guard lock(debugMutex);
    debugErrors += std::string("GL error: ") + message + "\n";
}

bool loadGl(GLADloadfunc load, bool debug, bool secondary, std::string& error) {
    if (!secondary && !gladLoadGL(load)) {
        error = "could not load the OpenGL functions";
        return false;
    }
    if (!GLAD_GL_VERSION_4_5) {
        error = "OpenGL 4.5 is not available";
        return false;
    }
    if (debug) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(onGlDebugMessage, nullptr);
    }
    return true;
}

class EglContext final : public HeadlessContext {
  public:
    ~EglContext() override {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        // One display per process: a secondary context leaves it to the first.
        if (!secondary_) eglTerminate(display_);
    }
    std::string_view backendName() const override { return "egl"; }
    bool makeCurrent() override {
        return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE;
    }

    bool create(bool debug, bool secondary, std::string& error) {
        secondary_ = secondary;
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) {
            error = "eglGetPlatformDisplayEXT is missing";
            return false;
        }
        display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
            // Drivers without Mesa's surfaceless platform (NVIDIA's, for one) offer their GPUs as
            // EGL devices (EGL_EXT_device_enumeration, EGL_EXT_platform_device).
            display_ = firstDeviceDisplay(getPlatformDisplay);
            if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
                display_ = EGL_NO_DISPLAY;
                error = "no surfaceless EGL display and no EGL device";
                return false;
            }
        }
        if (!eglBindAPI(EGL_OPENGL_API)) {
            error = "EGL cannot bind the desktop OpenGL API";
            return false;
        }
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG,
                                     debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
        context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT) {
            error = "EGL could not create an OpenGL 4.5 core context";
            return false;
        }
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            error = "EGL could not make the context current without a surface";
            return false;
        }
        return loadGl(reinterpret_cast<GLADloadfunc>(eglGetProcAddress), debug, secondary, error);
    }

  private:
    static EGLDisplay firstDeviceDisplay(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay) {
        auto queryDevices =
            reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        if (!queryDevices) return EGL_NO_DISPLAY;
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (!queryDevices(8, devices, &count) || count < 1) return EGL_NO_DISPLAY;
        return getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    bool secondary_ = false;
};

class OsMesaContext final : public HeadlessContext {
  public:
    ~OsMesaContext() override {
        if (context_) OSMesaDestroyContext(context_);
    }
    std::string_view backendName() const override { return "osmesa"; }
    bool makeCurrent() override {
        return OSMesaMakeCurrent(context_, pixel_, GL_UNSIGNED_BYTE, 1, 1) == GL_TRUE;
    }

    bool create(bool debug, bool secondary, std::string& error) {
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  0,
                                  OSMESA_PROFILE,
                                  OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  4,
                                  OSMESA_CONTEXT_MINOR_VERSION,
                                  5,
                                  0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!context_) {
            error = "OSMesa could not create an OpenGL 4.5 core context";
            return false;
        }
        // Everything renders into framebuffer objects; the default buffer is a placeholder.
        if (!OSMesaMakeCurrent(context_, pixel_, GL_UNSIGNED_BYTE, 1, 1)) {
            error = "OSMesa could not make the context current";
            return false;
        }
        return loadGl(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress), debug, secondary,
                      error);
    }

  private:
    OSMesaContext context_ = nullptr;
    unsigned char pixel_[4] = {};
};

template <class Context>
std::unique_ptr<HeadlessContext> tryCreate(bool debug, bool secondary, std::string& error) {
    auto context = std::make_unique<Context>();
    if (!context->create(debug, secondary, error)) return nullptr;
    return context;
}

} // namespace

bool parseGlBackend(std::string_view name, GlBackend& backend) {
    if (name == "auto")
        backend = GlBackend::Auto;
    else if (name == "egl")
        backend = GlBackend::Egl;
    else if (name == "osmesa")
        backend = GlBackend::OsMesa;
    else
        return false;
    return true;
}

std::string HeadlessContext::renderer() const {
    auto text = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

std::unique_ptr<HeadlessContext> createHeadlessContext(GlBackend backend, bool debug,
                                                       std::string& error, bool secondary) {
    std::string eglError, osMesaError;
    if (backend == GlBackend::Egl || backend == GlBackend::Auto) {
        if (auto context = tryCreate<EglContext>(debug, secondary, eglError)) return context;
        if (backend == GlBackend::Egl) {
            error = "no OpenGL context: EGL: " + eglError;
            return nullptr;
        }
    }
    if (auto context = tryCreate<OsMesaContext>(debug, secondary, osMesaError)) return context;
    error = backend == GlBackend::Auto
                ? "no OpenGL 4.5 context: EGL: " + eglError + "; OSMesa: " + osMesaError
                : "no OpenGL context: OSMesa: " + osMesaError;
    return nullptr;
}

std::string takeGlDebugErrors() {
    std::lock_guard lock(debugMutex);
    return std::exchange(debugErrors, {});
}

} // namespace rmsc
