// Headless contexts of the public API: the engine's EGL and OSMesa contexts.
#include "rmsc/context.hpp"
#include "rmsc/error.hpp"

#include "gl/context.hpp"
#include "gl/gl.hpp"

#include <atomic>

namespace rmsc::api {
namespace {

// Contexts alive: the first loads the GL functions and owns the EGL display, the others are
// secondary (gl/context.hpp).
std::atomic<int> liveContexts{0};

} // namespace

Backend parseBackend(const std::string& name) {
    GlBackend backend = GlBackend::Auto;
    if (!parseGlBackend(name, backend))
        throw Error(ErrorKind::Usage, "backend: expected auto, egl or osmesa, got '" + name + "'");
    return backend == GlBackend::Egl      ? Backend::Egl
           : backend == GlBackend::OsMesa ? Backend::OsMesa
                                          : Backend::Auto;
}

struct HeadlessContext::Impl {
    std::unique_ptr<::rmsc::HeadlessContext> context;
    ~Impl() {
        context.reset();
        --liveContexts;
    }
};

HeadlessContext::HeadlessContext(Backend backend) {
    const GlBackend engine = backend == Backend::Egl      ? GlBackend::Egl
                             : backend == Backend::OsMesa ? GlBackend::OsMesa
                                                          : GlBackend::Auto;
    std::string error;
    const bool secondary = liveContexts.load() > 0;
    std::unique_ptr<::rmsc::HeadlessContext> context =
        createHeadlessContext(engine, false, error, secondary);
    if (!context) throw Error(ErrorKind::Context, "no headless OpenGL context: " + error);
    ++liveContexts;
    impl_ = std::make_unique<Impl>();
    impl_->context = std::move(context);
}

HeadlessContext::HeadlessContext(HeadlessContext&&) noexcept = default;
HeadlessContext& HeadlessContext::operator=(HeadlessContext&&) noexcept = default;
HeadlessContext::~HeadlessContext() = default;

void HeadlessContext::makeCurrent() {
    if (!impl_->context->makeCurrent())
        throw Error(ErrorKind::Context, "the headless context cannot be made current again");
}

std::string HeadlessContext::backend() const {
    return std::string(impl_->context->backendName());
}

std::string HeadlessContext::renderer() const {
    return impl_->context->renderer();
}

} // namespace rmsc::api
