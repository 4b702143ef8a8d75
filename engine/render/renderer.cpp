// Frame orchestration.
#include "render/renderer.hpp"

namespace rmsc {

FrameTargets createFrameTargets(int width, int height) {
    return {createGBuffer(width, height), createGBuffer(width, height),
            createDisplayTarget(width, height)};
}

Renderer::Renderer(RasterPass raster, MarchPass march, PostPass post)
    : raster_(std::move(raster)), march_(std::move(march)), post_(std::move(post)) {
    frameBuffer_ = gl::createBufferWithData(sizeof(GpuFrame), nullptr);
    for (gl::Query& timer : timers_) timer = gl::createQuery(GL_TIME_ELAPSED);
}

std::optional<Renderer> Renderer::create(const ShaderFiles& files, std::string& error) {
    std::optional<RasterPass> raster = RasterPass::create(files, error);
    if (!raster) return std::nullopt;
    std::optional<MarchPass> march = MarchPass::create(files, error);
    if (!march) return std::nullopt;
    std::optional<PostPass> post = PostPass::create(files, error);
    if (!post) return std::nullopt;
    return Renderer(std::move(*raster), std::move(*march), std::move(*post));
}

void Renderer::render(const GpuScene& scene, const Camera& camera, const RenderSettings& settings,
                      FrameTargets& targets) {
    const int width = targets.display.width;
    const int height = targets.display.height;
    const FrameCamera frameCamera = makeFrameCamera(camera, width, height);
    const GpuFrame frame = packFrame(frameCamera, settings, width, height);
    glNamedBufferSubData(frameBuffer_.id(), 0, sizeof(GpuFrame), &frame);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, frameBuffer_.id());
    scene.bindBuffers();

    auto timed = [this](Pass pass, auto&& draw) {
        glBeginQuery(GL_TIME_ELAPSED, timers_[std::size_t(pass)].id());
        draw();
        glEndQuery(GL_TIME_ELAPSED);
    };
    timed(Pass::Raster, [&] { raster_.draw(scene, settings.background, targets.raster); });
    timed(Pass::March, [&] { march_.draw(targets.raster, targets.combined); });
    timed(Pass::Post, [&] { post_.draw(targets.combined, targets.display); });
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
}

PassTimes Renderer::lastPassTimes() const {
    PassTimes times{};
    for (std::size_t i = 0; i < times.size(); ++i) {
        GLuint64 nanoseconds = 0;
        glGetQueryObjectui64v(timers_[i].id(), GL_QUERY_RESULT, &nanoseconds);
        times[i] = double(nanoseconds) * 1e-6;
    }
    return times;
}

} // namespace rmsc
