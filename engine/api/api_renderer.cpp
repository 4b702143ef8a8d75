// The public Renderer: the engine's Renderer on the caller's context, the scenes it has
// uploaded (the GPU side of each Scene, kept by its identity and revision), and the checks that
// turn misuse into errors before any GL call could fail.
#include "rmsc/renderer.hpp"

#include "scene_impl.hpp"

#include "core/limits.hpp"
#include "gl/current_context.hpp"
#include "gl/state_guard.hpp"
#include "render/host_camera.hpp"
#include "render/readback.hpp"
#include "render/renderer.hpp"
#include "render/shader_library.hpp"
#include "scene/scene_json.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstring>
#include <map>

namespace rmsc::api {
namespace {

constexpr std::size_t kUploadedScenes = 8;     // scenes kept on the GPU, least recently drawn goes
const std::string kHostLights = "host lights"; // the "file" of problems in a host's lights

template <class T> Image toImage(const Pixels<T>& pixels, int channels, Image::Type type) {
    Image image;
    image.width = pixels.width;
    image.height = pixels.height;
    image.channels = channels;
    image.type = type;
    const std::size_t count = std::size_t(pixels.width) * std::size_t(pixels.height);
    image.bytes.resize(count * std::size_t(channels) * sizeof(T));
    T* out = reinterpret_cast<T*>(image.bytes.data());
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < channels; ++c)
            out[i * std::size_t(channels) + std::size_t(c)] =
                pixels.data[i * std::size_t(pixels.channels) + std::size_t(c)];
    return image;
}

bool isDepthFormat(GLint format) {
    switch (format) {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH32F_STENCIL8:
        return true;
    default:
        return false;
    }
}

std::string hex(GLint value) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", unsigned(value));
    return text;
}

// The depth texture's name, checked: a 2D texture of a depth format at least as large as the
// viewport.
void checkDepthTexture(GLuint texture, const HostView& view) {
    if (texture == 0 || !glIsTexture(texture))
        throw Error(ErrorKind::Usage, "drawInto: depth texture " + std::to_string(texture) +
                                          " is not a texture of the current context");
    GLint target = 0;
    glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
    if (target != GL_TEXTURE_2D)
        throw Error(ErrorKind::Usage, "drawInto: the depth texture's target is " + hex(target) +
                                          "; expected GL_TEXTURE_2D (resolve a multisampled "
                                          "depth buffer into one first)");
    GLint format = 0, width = 0, height = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
    if (!isDepthFormat(format))
        throw Error(ErrorKind::Usage,
                    "drawInto: the depth texture's format is " + hex(format) +
                        "; expected GL_DEPTH_COMPONENT16, 24, 32 or 32F, GL_DEPTH24_STENCIL8 or "
                        "GL_DEPTH32F_STENCIL8");
    if (view.x < 0 || view.y < 0 || view.width <= 0 || view.height <= 0 ||
        view.x + view.width > width || view.y + view.height > height)
        throw Error(ErrorKind::Usage,
                    "drawInto: the viewport (" + std::to_string(view.x) + ", " +
                        std::to_string(view.y) + ", " + std::to_string(view.width) + "x" +
                        std::to_string(view.height) + ") is not inside the " +
                        std::to_string(width) + "x" + std::to_string(height) + " depth texture");
}

// The host's clip-space conventions, from the context, checked against what the host says.
bool zeroToOneClipDepth(DepthConvention convention) {
    GLint origin = 0, mode = 0;
    glGetIntegerv(GL_CLIP_ORIGIN, &origin);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &mode);
    GLfloat range[2] = {0, 1};
    glGetFloatv(GL_DEPTH_RANGE, range);
    if (origin != GL_LOWER_LEFT)
        throw Error(ErrorKind::Usage, "drawInto: the context's clip origin is GL_UPPER_LEFT; "
                                      "only GL_LOWER_LEFT is supported");
    if (range[0] != 0.0f || range[1] != 1.0f)
        throw Error(ErrorKind::Usage, "drawInto: the depth range is (" + std::to_string(range[0]) +
                                          ", " + std::to_string(range[1]) +
                                          "); only glDepthRange(0, 1) is supported");
    const bool zeroToOne = mode == GL_ZERO_TO_ONE;
    const bool wantsZeroToOne = convention != DepthConvention::Default;
    if (zeroToOne != wantsZeroToOne)
        throw Error(ErrorKind::Usage,
                    std::string("drawInto: the view's depth convention is ") +
                        (convention == DepthConvention::Default     ? "Default (-1 to 1)"
                         : convention == DepthConvention::ZeroToOne ? "ZeroToOne"
                                                                    : "ReversedZ") +
                        " but the context's clip depth mode is " +
                        (zeroToOne ? "GL_ZERO_TO_ONE" : "GL_NEGATIVE_ONE_TO_ONE") +
                        " (reversed-Z and ZeroToOne need glClipControl(GL_LOWER_LEFT, "
                        "GL_ZERO_TO_ONE))");
    return zeroToOne;
}

// Where the host's depth stencil texture is sampled as depth for the call, as it was after.
class DepthModeGuard {
  public:
    explicit DepthModeGuard(GLuint texture) : texture_(texture) {
        glGetTextureParameteriv(texture, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode_);
        if (mode_ != GL_DEPTH_COMPONENT)
            glTextureParameteri(texture, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    }
    ~DepthModeGuard() {
        if (mode_ != GL_DEPTH_COMPONENT)
            glTextureParameteri(texture_, GL_DEPTH_STENCIL_TEXTURE_MODE, mode_);
    }
    DepthModeGuard(const DepthModeGuard&) = delete;
    DepthModeGuard& operator=(const DepthModeGuard&) = delete;

  private:
    GLuint texture_;
    GLint mode_ = GL_DEPTH_COMPONENT;
};

// The engine's light of a host's, its values as given (checkLights checks them).
std::vector<::rmsc::Light> hostLights(std::span<const Light> lights) {
    std::vector<::rmsc::Light> out;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        ::rmsc::Light converted;
        switch (light.type) {
        case Light::Type::Directional:
            converted.type = LightType::Directional;
            break;
        case Light::Type::Point:
            converted.type = LightType::Point;
            break;
        case Light::Type::Spot:
            converted.type = LightType::Spot;
            break;
        default: {
            Diagnostics diagnostics;
            diagnostics.error(kHostLights, "/" + std::to_string(i) + "/type",
                              "unknown light type " + std::to_string(int(light.type)) +
                                  "; known types: Directional, Point, Spot");
            throw badInput(diagnostics);
        }
        }
        converted.name = light.name;
        converted.direction = glm::make_vec3(light.direction.data());
        converted.position = glm::make_vec3(light.position.data());
        converted.color = glm::make_vec3(light.color.data());
        converted.intensity = light.intensity;
        converted.range = light.range;
        converted.innerAngleDegrees = light.innerAngle;
        converted.outerAngleDegrees = light.outerAngle;
        converted.castShadows = light.castShadows;
        converted.shadowSoftness = light.shadowSoftness;
        out.push_back(std::move(converted));
    }
    return out;
}

bool sameLights(const std::vector<::rmsc::Light>& a, const std::vector<::rmsc::Light>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
        return x.type == y.type && x.direction == y.direction && x.position == y.position &&
               x.color == y.color && x.intensity == y.intensity && x.range == y.range &&
               x.innerAngleDegrees == y.innerAngleDegrees &&
               x.outerAngleDegrees == y.outerAngleDegrees && x.castShadows == y.castShadows &&
               x.shadowSoftness == y.shadowSoftness;
    });
}

} // namespace

struct Renderer::Impl {
    const void* context = nullptr;
    std::optional<::rmsc::Renderer> renderer;
    struct Uploaded {
        std::uint64_t revision = 0;
        GpuScene gpu;
        std::uint64_t lastUse = 0;
        bool hostLit = false; // gpu holds hostLights, not the scene's lights
        std::vector<::rmsc::Light> hostLights;
    };
    std::map<std::uint64_t, Uploaded> scenes; // by Scene::Impl::id
    std::uint64_t clock = 0;
    std::optional<FrameTargets> targets;
    RenderStats stats;

    void checkContext(const char* call) const {
        const void* current = currentGlContext();
        if (current == nullptr)
            throw Error(ErrorKind::Context,
                        std::string(call) + ": no OpenGL context is current on this thread");
        if (current != context)
            throw Error(ErrorKind::Context,
                        std::string(call) +
                            ": the current OpenGL context is not the one this Renderer was made "
                            "on; make that one current (or make a Renderer for this one)");
    }

    // The scene on the GPU with its programs built: uploaded again after an edit, through the
    // buffer map, whose text does not change with the numbers (so the programs are reused).
    // Lit by `lights` when given (checked), else by the scene's own.
    const GpuScene& upload(const Scene& scene, const std::vector<::rmsc::Light>* lights = nullptr) {
        const Scene::Impl& source = scene.impl();
        stats = {};
        auto found = scenes.find(source.id);
        if (found == scenes.end() || found->second.revision != source.revision) {
            const SdfStrategy strategy =
                found == scenes.end() ? SdfStrategy::Baked : SdfStrategy::Buffer;
            if (found == scenes.end() && scenes.size() >= kUploadedScenes)
                scenes.erase(std::min_element(scenes.begin(), scenes.end(),
                                              [](const auto& a, const auto& b) {
                                                  return a.second.lastUse < b.second.lastUse;
                                              }));
            Uploaded uploaded{
                source.revision, uploadScene(source.prepared, strategy), 0, false, {}};
            found = scenes.insert_or_assign(source.id, std::move(uploaded)).first;
        }
        Uploaded& uploaded = found->second;
        uploaded.lastUse = ++clock;
        if (lights && (!uploaded.hostLit || !sameLights(*lights, uploaded.hostLights))) {
            setSceneLights(uploaded.gpu, source.prepared, *lights);
            uploaded.hostLit = true;
            uploaded.hostLights = *lights;
        } else if (!lights && uploaded.hostLit) {
            const PreparedScene& prepared = source.prepared;
            setSceneLights(uploaded.gpu, prepared,
                           prepared.lights.empty() ? prepared.scene.lights : prepared.lights);
            uploaded.hostLit = false;
        }
        const bool ready =
            renderer->hasPrograms(found->second.gpu.shading, found->second.gpu.sdfMap);
        std::string error;
        if (!renderer->prepare(found->second.gpu, error))
            throw Error(ErrorKind::Context,
                        "the SDF shaders do not build on this driver: " + error);
        stats.compileMilliseconds = renderer->lastCompileMs();
        stats.compiledShaders = !ready || stats.compileMilliseconds > 0.0;
        return found->second.gpu;
    }

    // drawInto's work, after the context check: lit by `lights` (checked) or the scene's.
    void drawInto(const Scene& scene, const HostTarget& target, const HostView& view,
                  const std::vector<::rmsc::Light>* lights);

    FrameTargets& frameTargets(int width, int height) {
        if (!targets || targets->combined.width != width || targets->combined.height != height)
            targets = createFrameTargets(width, height);
        return *targets;
    }
};

Renderer::Renderer() {
    const void* context = currentGlContext();
    if (context == nullptr)
        throw Error(ErrorKind::Context,
                    "Renderer: no OpenGL context is current on this thread (make the host's "
                    "current first, or create a rmsc::api::HeadlessContext)");
    std::string error;
    if (!loadGlForCurrentContext(error)) throw Error(ErrorKind::Context, "Renderer: " + error);
    gl::StateGuard guard;
    auto impl = std::make_unique<Impl>();
    impl->context = context;
    impl->renderer = ::rmsc::Renderer::create(embeddedShaderFiles(), error);
    if (!impl->renderer) throw Error(ErrorKind::Context, "Renderer: " + error);
    impl_ = std::move(impl);
}

Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Renderer::~Renderer() {
    // Its GL objects belong to its context: with another one (or none) current, deleting their
    // names could delete someone else's objects, so they are left to the context.
    if (impl_ && currentGlContext() != impl_->context) (void)impl_.release();
}

void Renderer::compile(const Scene& scene) {
    impl_->checkContext("compile");
    gl::StateGuard guard;
    impl_->upload(scene);
}

Image Renderer::render(const Scene& scene, int width, int height, Aov aov) {
    impl_->checkContext("render");
    if (width < 1 || height < 1 || width > limits::kImageSize || height > limits::kImageSize ||
        std::int64_t(width) * height > limits::kImagePixels)
        throw Error(ErrorKind::Usage,
                    "render: the size " + std::to_string(width) + "x" + std::to_string(height) +
                        " is not 1.." + std::to_string(limits::kImageSize) +
                        " a side and at most " + std::to_string(limits::kImagePixels) + " pixels");
    gl::StateGuard guard;
    const GpuScene& gpu = impl_->upload(scene);
    FrameTargets& targets = impl_->frameTargets(width, height);
    const ::rmsc::Scene& source = scene.impl().prepared.scene;
    impl_->renderer->render(gpu, source.camera, source.render, targets);
    switch (aov) {
    case Aov::Color:
        return toImage(readDisplayColor(targets), 3, Image::Type::UInt8);
    case Aov::Depth: {
        Pixels<float> depth = readViewDepth(targets);
        for (float& value : depth.data)
            if (value >= kNoDepth) value = INFINITY;
        return toImage(depth, 1, Image::Type::Float32);
    }
    case Aov::Normal:
        return toImage(readNormals(targets), 3, Image::Type::Float32);
    case Aov::Id:
        return toImage(readObjectIds(targets), 1, Image::Type::UInt32);
    case Aov::Steps:
        return toImage(readMarchSteps(targets), 1, Image::Type::Float32);
    }
    throw Error(ErrorKind::Usage, "render: unknown aov");
}

void Renderer::Impl::drawInto(const Scene& scene, const HostTarget& target, const HostView& view,
                              const std::vector<::rmsc::Light>* lights) {
    // What to draw into: the host's framebuffer, or one made for its two textures.
    gl::Framebuffer own;
    GLuint framebuffer = target.framebuffer;
    GLuint depthTexture = target.depthTexture;
    if (framebuffer != 0) {
        if (!glIsFramebuffer(framebuffer))
            throw Error(ErrorKind::Usage, "drawInto: framebuffer " + std::to_string(framebuffer) +
                                              " is not a framebuffer object of the current "
                                              "context");
        GLint type = GL_NONE, name = 0;
        glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_DEPTH_ATTACHMENT,
                                                   GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type != GL_TEXTURE)
            throw Error(ErrorKind::Usage,
                        type == GL_RENDERBUFFER
                            ? "drawInto: the framebuffer's depth attachment is a renderbuffer, "
                              "which cannot be read; attach a depth texture instead"
                            : "drawInto: the framebuffer has no depth attachment");
        glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_DEPTH_ATTACHMENT,
                                                   GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
        depthTexture = GLuint(name);
        checkDepthTexture(depthTexture, view);
    } else {
        if (target.colorTexture == 0 || !glIsTexture(target.colorTexture))
            throw Error(ErrorKind::Usage,
                        "drawInto: give a framebuffer, or a colour texture and a depth texture "
                        "(colour texture " +
                            std::to_string(target.colorTexture) + " is not a texture)");
        checkDepthTexture(depthTexture, view);
    }
    const bool zeroToOne = zeroToOneClipDepth(view.depth);
    ::rmsc::HostView host;
    host.view = glm::make_mat4(view.view.data());
    host.projection = glm::make_mat4(view.projection.data());
    host.width = view.width;
    host.height = view.height;
    host.zeroToOne = zeroToOne;
    host.reversedZ = view.depth == DepthConvention::ReversedZ;
    std::string error;
    const std::optional<FrameCamera> camera = hostFrameCamera(host, error);
    if (!camera) throw Error(ErrorKind::Usage, "drawInto: " + error);

    gl::StateGuard guard;
    if (framebuffer == 0) {
        own = gl::createFramebuffer();
        glNamedFramebufferTexture(own.id(), GL_COLOR_ATTACHMENT0, target.colorTexture, 0);
        glNamedFramebufferTexture(own.id(), GL_DEPTH_ATTACHMENT, depthTexture, 0);
        if (glCheckNamedFramebufferStatus(own.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error(ErrorKind::Usage,
                        "drawInto: the colour and depth textures do not make a complete "
                        "framebuffer (is the colour texture colour-renderable, and of the depth "
                        "texture's size?)");
        framebuffer = own.id();
    } else if (glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER) !=
               GL_FRAMEBUFFER_COMPLETE) {
        throw Error(ErrorKind::Usage, "drawInto: the framebuffer is not complete");
    }
    DepthModeGuard depthMode(depthTexture);
    const GpuScene& gpu = upload(scene, lights);
    FrameTargets& frame = frameTargets(view.width, view.height);
    ::rmsc::HostTarget output;
    output.depthTexture = depthTexture;
    output.framebuffer = framebuffer;
    output.x = view.x;
    output.y = view.y;
    output.farDepth = hostFarDepth(host);
    output.displayEncoded = !target.linearColor;
    renderer->renderOverHost(gpu, *camera, zeroToOne, scene.impl().prepared.scene.render, frame,
                             output);
}

void Renderer::drawInto(const Scene& scene, const HostTarget& target, const HostView& view) {
    impl_->checkContext("drawInto");
    impl_->drawInto(scene, target, view, nullptr);
}

void Renderer::drawInto(const Scene& scene, const HostTarget& target, const HostView& view,
                        std::span<const Light> lights) {
    impl_->checkContext("drawInto");
    Diagnostics diagnostics;
    const std::optional<std::vector<::rmsc::Light>> checked =
        checkLights(hostLights(lights), kHostLights, diagnostics);
    if (!checked) throw badInput(diagnostics);
    impl_->drawInto(scene, target, view, &*checked);
}

RenderStats Renderer::lastStats() const {
    return impl_->stats;
}

} // namespace rmsc::api
