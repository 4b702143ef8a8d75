// Finding the current context of a host program. EGL and OSMesa are linked (the headless back
// ends use them); GLX is looked up only in a libGL or libGLX the host has already loaded, so
// rmsc never loads it itself.
#include "gl/current_context.hpp"

#include "gl/gl.hpp"

#include <EGL/egl.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

namespace rmsc {
namespace {

using GetCurrentContext = void* (*)();
using GetProcAddress = void (*(*)(const unsigned char*))();

// A function of the GLX library the process has loaded (GLFW opens libGL.so.1 privately, so
// RTLD_DEFAULT does not see it), or nullptr.
void* glxFunction(const char* name) {
    for (const char* library : {"libGLX.so.0", "libGL.so.1"})
        if (void* handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD)) {
            void* function = dlsym(handle, name);
            dlclose(handle); // RTLD_NOLOAD took a reference; the library stays loaded
            if (function) return function;
        }
    return nullptr;
}

enum class ContextApi { None, Egl, OsMesa, Glx };

ContextApi currentApi(const void** context) {
    if (EGLContext egl = eglGetCurrentContext(); egl != EGL_NO_CONTEXT) {
        *context = egl;
        return ContextApi::Egl;
    }
    if (OSMesaContext osmesa = OSMesaGetCurrentContext()) {
        *context = osmesa;
        return ContextApi::OsMesa;
    }
    if (auto glx = reinterpret_cast<GetCurrentContext>(glxFunction("glXGetCurrentContext")))
        if (void* current = glx()) {
            *context = current;
            return ContextApi::Glx;
        }
    *context = nullptr;
    return ContextApi::None;
}

GLADapiproc glxProcAddress(const char* name) {
    static const auto get = reinterpret_cast<GetProcAddress>(glxFunction("glXGetProcAddressARB"));
    return get ? reinterpret_cast<GLADapiproc>(get(reinterpret_cast<const unsigned char*>(name)))
               : nullptr;
}

} // namespace

const void* currentGlContext() {
    const void* context = nullptr;
    currentApi(&context);
    return context;
}

bool loadGlForCurrentContext(std::string& error) {
    const void* context = nullptr;
    int version = 0;
    switch (currentApi(&context)) {
    case ContextApi::None:
        error = "no OpenGL context is current on this thread (EGL, OSMesa or GLX)";
        return false;
    case ContextApi::Egl:
        version = gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress));
        break;
    case ContextApi::OsMesa:
        version = gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress));
        break;
    case ContextApi::Glx:
        version = gladLoadGL(glxProcAddress);
        break;
    }
    if (version == 0) {
        error = "could not load the OpenGL functions of the current context";
        return false;
    }
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45) {
        error = "the current context is OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) +
                "." + std::to_string(GLAD_VERSION_MINOR(version)) + "; rmsc needs 4.5";
        return false;
    }
    // A compatibility-profile context works too; only the core functions are used.
    return true;
}

} // namespace rmsc
