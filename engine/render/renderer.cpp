// Frame orchestration.
#include "render/renderer.hpp"

#include "render/sdf_program_buffer.hpp"
#include "sdf/cpu_eval.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace rmsc {

FrameTargets createFrameTargets(int width, int height) {
    return {createGBuffer(width, height), createGBuffer(width, height),
            createConeTarget(width, height), createDisplayTarget(width, height)};
}

Renderer::Renderer(ShaderFiles files, PostPass post, ShadowPass shadow, GridPass grid,
                   HostPass host)
    : files_(std::move(files)), post_(std::move(post)), grid_(std::move(grid)),
      shadow_(std::move(shadow)), host_(std::move(host)) {
    frameBuffer_ = gl::createBufferWithData(sizeof(GpuFrame), nullptr);
    statistics_ = gl::createBufferWithData(4 * sizeof(std::uint32_t), nullptr);
    for (gl::Query& timer : timers_)
        timer = gl::createQuery(GL_TIME_ELAPSED);
}

std::optional<Renderer> Renderer::create(ShaderFiles files, std::string& error) {
    GLint uniformBlockBytes = 0;
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &uniformBlockBytes);
    if (uniformBlockBytes < kSdfUniformBlockBytes) {
        error = "the OpenGL driver's uniform blocks hold " + std::to_string(uniformBlockBytes) +
                " bytes; rmsc needs " + std::to_string(kSdfUniformBlockBytes);
        return std::nullopt;
    }
    GLint fragmentUnits = 0, texelBufferTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &fragmentUnits);
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texelBufferTexels);
    if (fragmentUnits <= GLint(kSdfCellTexelUnit)) {
        error = "the OpenGL driver's fragment shaders sample " + std::to_string(fragmentUnits) +
                " textures; rmsc needs " + std::to_string(kSdfCellTexelUnit + 1);
        return std::nullopt;
    }
    if (texelBufferTexels < kSdfMaxBufferTexels) {
        error = "the OpenGL driver's buffer textures hold " + std::to_string(texelBufferTexels) +
                " texels; rmsc needs " + std::to_string(kSdfMaxBufferTexels);
        return std::nullopt;
    }
    std::optional<PostPass> post = PostPass::create(files, error);
    if (!post) return std::nullopt;
    std::optional<ShadowPass> shadow = ShadowPass::create(files, error);
    if (!shadow) return std::nullopt;
    std::optional<GridPass> grid = GridPass::create(files, error);
    if (!grid) return std::nullopt;
    std::optional<HostPass> host = HostPass::create(files, error);
    if (!host) return std::nullopt;
    return Renderer(std::move(files), std::move(*post), std::move(*shadow), std::move(*grid),
                    std::move(*host));
}

namespace {

// The key of a shell's programs: they include the shading code, the scene's map and the
// shell's.
std::string shellKey(const ShadingCode& shading, const GpuScene& scene, const GpuShell& shell) {
    return sdfProgramsKey(shading, scene.sdfMap) + '\0' + shell.map;
}

} // namespace

std::string sdfProgramsKey(const ShadingCode& shading, const std::string& sdfMap) {
    return shadingDefines(shading) + '\0' + sdfMap;
}

ShadingCode Renderer::drawnShading(const GpuScene& scene, const ShadingCode& needed) const {
    if (sdfPasses_.contains(sdfProgramsKey(needed, scene.sdfMap))) return needed;
    for (const auto& [key, passes] : sdfPasses_)
        if (passes.shading.holds(needed) && key == sdfProgramsKey(passes.shading, scene.sdfMap))
            return passes.shading;
    return needed;
}

void Renderer::forgetScenePrograms() {
    sdfPasses_.clear();
    shellPasses_.clear();
}

bool Renderer::prepare(const GpuScene& scene, const ShadingCode& shading, std::string& error) {
    lastCompileMs_ = 0.0;
    const auto start = std::chrono::steady_clock::now();
    bool compiled = false;
    // A small cache, the least recently used map goes first: an editing session uses the
    // buffer map of its structure and baked maps of the last few selections.
    constexpr std::size_t kMaxCached = 16;
    ShaderFiles files = files_;
    files.files["generated/sdf_map.glsl"] = scene.sdfMap;
    files.files["generated/shading.glsl"] = shadingDefines(shading);
    const std::string key = sdfProgramsKey(shading, scene.sdfMap);
    if (!sdfPasses_.contains(key)) {
        std::optional<RasterPass> raster = RasterPass::create(files, error);
        if (!raster) return false;
        std::optional<ConePass> cone = ConePass::create(files, error);
        if (!cone) return false;
        std::optional<MarchPass> march = MarchPass::create(files, error);
        if (!march) return false;
        if (sdfPasses_.size() >= kMaxCached)
            sdfPasses_.erase(std::min_element(
                sdfPasses_.begin(), sdfPasses_.end(),
                [](const auto& a, const auto& b) { return a.second.lastUse < b.second.lastUse; }));
        sdfPasses_.emplace(key, SdfPasses{shading, std::move(*raster), std::move(*cone),
                                          std::move(*march), std::nullopt, std::nullopt});
        compiled = true;
    }
    SdfPasses& passes = sdfPasses_.find(key)->second;
    passes.lastUse = ++useClock_;
    if (countEvaluations_ && !passes.countingMarch) {
        passes.countingCone = ConePass::create(files, error, true);
        if (!passes.countingCone) return false;
        passes.countingMarch = MarchPass::create(files, error, true);
        if (!passes.countingMarch) return false;
        compiled = true;
    }
    for (const GpuShell& shell : scene.shells) {
        std::string shellProgramsKey = shellKey(shading, scene, shell);
        if (const auto found = shellPasses_.find(shellProgramsKey); found != shellPasses_.end()) {
            found->second.lastUse = useClock_;
            continue;
        }
        files.files["generated/shell_map.glsl"] = shell.map;
        std::optional<ShellPass> pass = ShellPass::create(files, error);
        if (!pass) return false;
        shellPasses_.emplace(std::move(shellProgramsKey),
                             CachedShellPass{std::move(*pass), useClock_});
        compiled = true;
    }
    // Past the cache's size, drop the least recently used shell programs, never one this scene
    // draws (a scene may have more shells than the cache holds: they all stay).
    while (shellPasses_.size() > kMaxCached * 4) {
        const auto oldest = std::min_element(
            shellPasses_.begin(), shellPasses_.end(),
            [](const auto& a, const auto& b) { return a.second.lastUse < b.second.lastUse; });
        if (oldest->second.lastUse == useClock_) break;
        shellPasses_.erase(oldest);
    }
    if (compiled) {
        glFinish(); // drivers may finish compiling lazily
        lastCompileMs_ =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
    }
    return true;
}

namespace {

// Limits what the following draws and clears touch to rows [begin, end) of a target of `width`
// pixels; everything when `rows` is null.
void limitRows(const RenderRows* rows, int begin, int end, int width) {
    if (!rows) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, begin, width, std::max(0, end - begin));
}

} // namespace

const SdfPasses& Renderer::beginFrame(const GpuScene& scene, const FrameCamera& frameCamera,
                                      bool zeroToOneDepth, const RenderSettings& settings,
                                      int width, int height, std::vector<const ShellPass*>& shells,
                                      bool drawShadowMaps) {
    std::string error;
    const ShadingCode shading =
        drawnShading(scene, shadingCode(settings, scene.shading.sdfTextures));
    if (!prepare(scene, shading, error))
        throw std::runtime_error("the SDF shaders do not build: " + error);
    const SdfPasses& sdf = sdfPasses_.find(sdfProgramsKey(shading, scene.sdfMap))->second;
    GpuFrame frame = packFrame(frameCamera, settings, width, height);
    packEnvironment(scene.environment, scene.skyLevels, frame);
    frame.shadowMap.x = settings.shadows.enabled ? float(scene.shadowMapSize) : 0.0f;
    frame.viewport.z = float(sdfNearestLeaf(scene.sdf, frameCamera.position)); // ~0u: 2^32
    frame.viewport.w = zeroToOneDepth ? 1.0f : 0.0f;
    glNamedBufferSubData(frameBuffer_.id(), 0, sizeof(GpuFrame), &frame);
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBinding, frameBuffer_.id());
    scene.bindBuffers();

    for (const GpuShell& shell : scene.shells) {
        const auto found = shellPasses_.find(shellKey(shading, scene, shell));
        if (found == shellPasses_.end()) throw std::logic_error("a shell's programs are missing");
        shells.push_back(&found->second.pass);
    }
    const std::uint32_t zeros[4] = {0, 0, 0, 0};
    glNamedBufferSubData(statistics_.id(), 0, sizeof zeros, zeros);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMarchStatisticsBinding, statistics_.id());

    glDisable(GL_SCISSOR_TEST);
    glBeginQuery(GL_TIME_ELAPSED, timers_[std::size_t(Pass::Shadow)].id());
    if (drawShadowMaps) shadow_.draw(scene, shells);
    glEndQuery(GL_TIME_ELAPSED);
    glBindTextureUnit(kShadowMapUnit, shadow_.maps().id());
    glBindTextureUnit(kSkyImageUnit, scene.skyImage.id());
    return sdf;
}

void Renderer::endFrame() const {
    glDisable(GL_SCISSOR_TEST);
    glBindTextureUnit(kShadowMapUnit, 0);
    glBindTextureUnit(kSkyImageUnit, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
}

void Renderer::render(const GpuScene& scene, const Camera& camera, const RenderSettings& settings,
                      FrameTargets& targets, const RenderRows* rows) {
    const int width = targets.display.width;
    const int height = targets.display.height;
    const FrameCamera frameCamera = makeFrameCamera(camera, width, height);
    std::vector<const ShellPass*> shells;
    const SdfPasses& sdf = beginFrame(scene, frameCamera, false, settings, width, height, shells,
                                      !(rows && rows->keepShadowMaps));

    auto timed = [this](Pass pass, auto&& draw) {
        glBeginQuery(GL_TIME_ELAPSED, timers_[std::size_t(pass)].id());
        draw();
        glEndQuery(GL_TIME_ELAPSED);
    };
    if (rows) limitRows(rows, rows->begin, rows->end, width);
    timed(Pass::Raster, [&] { sdf.raster.draw(scene, settings.background, targets.raster); });
    timed(Pass::Shell, [&] {
        for (std::size_t i = 0; i < shells.size(); ++i)
            shells[i]->draw(scene.shells[i], frameCamera.viewProjection, targets.raster);
    });
    const ConePass& cone = countEvaluations_ ? *sdf.countingCone : sdf.cone;
    if (rows)
        limitRows(rows, rows->begin / kConeTileSize,
                  (rows->end + kConeTileSize - 1) / kConeTileSize, targets.cone.width);
    timed(Pass::Cone, [&] {
        if (conePass_)
            cone.draw(targets.cone);
        else
            targets.cone.clear();
    });
    const MarchPass& march = countEvaluations_ ? *sdf.countingMarch : sdf.march;
    if (rows) limitRows(rows, rows->begin, rows->end, width);
    timed(Pass::March, [&] { march.draw(targets.raster, targets.cone, targets.combined); });
    timed(Pass::Grid, [&] {
        if (groundGrid_) grid_.draw(targets.combined);
    });
    // BLEND surfaces over everything the march finished (SDF objects behind glass show).
    timed(Pass::Blend, [&] { sdf.raster.drawBlended(scene, frameCamera, targets.combined); });
    if (rows) limitRows(rows, rows->postBegin, rows->postEnd, width);
    timed(Pass::Post, [&] { post_.draw(targets.combined, targets.display); });
    endFrame();
}

void Renderer::renderOverHost(const GpuScene& scene, const FrameCamera& camera, bool zeroToOneDepth,
                              const RenderSettings& settings, FrameTargets& targets,
                              const HostTarget& host) {
    const int width = targets.combined.width;
    const int height = targets.combined.height;
    // Nothing past the host's far plane: its depth could not hold it.
    RenderSettings bounded = settings;
    bounded.maxDistance = std::min(settings.maxDistance, camera.farPlane);
    std::vector<const ShellPass*> shells;
    const SdfPasses& sdf =
        beginFrame(scene, camera, zeroToOneDepth, bounded, width, height, shells);
    if (!shells.empty())
        throw std::logic_error("renderOverHost: shells must be prepared for the fullscreen pass");
    host_.importDepth(host, glm::inverse(camera.viewProjection), targets.raster);
    if (conePass_)
        sdf.cone.draw(targets.cone);
    else
        targets.cone.clear();
    sdf.march.draw(targets.raster, targets.cone, targets.combined);
    host_.composite(targets.combined, host);
    endFrame();
}

MarchStatistics Renderer::lastMarchStatistics() const {
    std::uint32_t counts[4] = {0, 0, 0, 0};
    glGetNamedBufferSubData(statistics_.id(), 0, sizeof counts, counts);
    return {counts[0], counts[1], counts[2] | (std::uint64_t(counts[3]) << 32)};
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
