// The viewer's GPU side: shaders, the scene upload, the warmer, rendering the view and
// capturing it (see view_renderer.hpp; the SDF map choice is sdf_map_choice.cpp).
#include "view_renderer.hpp"

#include "editor_file_source.hpp"
#include "render/frame.hpp"
#include "render/readback.hpp"
#include "sdf/compiler.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace rmsc::app {
namespace {

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.target == b.target && a.up == b.up &&
           a.fovYDegrees == b.fovYDegrees && a.nearPlane == b.nearPlane && a.farPlane == b.farPlane;
}

} // namespace

ViewRenderer::ViewRenderer() {
    lastRenderedCamera_.fovYDegrees = -1.0f; // no camera is the same: the first frame renders
}

ViewRenderer::~ViewRenderer() = default;

bool ViewRenderer::useShaders(ShaderFiles files, std::string& error) {
    std::optional<Renderer> newRenderer = Renderer::create(files, error);
    // The scene's SDF passes too, so a broken shader is found here and not while drawing.
    if (newRenderer && gpuScene_ && !newRenderer->prepare(*gpuScene_, error)) newRenderer.reset();
    std::optional<DisplayPass> newDisplay;
    if (newRenderer) newDisplay = DisplayPass::create(files, error);
    std::optional<LightGizmoPass> newGizmos;
    if (newDisplay) newGizmos = LightGizmoPass::create(files, error);
    if (!newRenderer || !newDisplay || !newGizmos) return false;
    renderer_ = std::move(newRenderer);
    renderer_->setGroundGrid(true);
    display_ = std::move(newDisplay);
    gizmos_ = std::move(newGizmos);
    shaderFiles_ = std::move(files);
    startWarmer();
    lastRenderedRevision_ = 0; // render again
    return true;
}

void ViewRenderer::startWarmer() {
    warmer_.reset();     // waits for the build it is doing
    choiceRevision_ = 0; // choose the map again
    std::string error;
    if (!warmerWindow_) warmerWindow_ = Window::openHidden(error);
    if (!warmerWindow_) {
        std::fprintf(stderr, "rmsc view: shaders are not built in the background (%s)\n",
                     error.c_str());
        return;
    }
    Window* context = warmerWindow_.get();
    warmer_ = std::make_unique<ShaderWarmer>(
        [context](std::string&) -> std::function<void()> {
            context->makeCurrent();
            return [] { Window::releaseCurrent(); };
        },
        shaderFiles_);
}

void ViewRenderer::updateScene(const Scene& scene, std::uint64_t revision,
                               std::string& sceneError) {
    if (revision == uploadedRevision_) return;
    uploadedRevision_ = revision;
    static const FileSource files = editorFileSource();
    Diagnostics diagnostics;
    // Without the bounding hierarchy: its order follows where things are, and a drag must
    // never change the program's structure (the maps for editing would need another build).
    std::optional<PreparedScene> next =
        prepareScene(scene, files, diagnostics, ShellMode::AsScene, false);
    if (!next) {
        sceneError =
            "The scene does not compile (showing the last one that did):\n" + diagnostics.format();
        return;
    }
    // The interpreter's program: with the hierarchy, the interpreter skips parts by their boxes,
    // and its text stays the same whatever the order.
    boundedSdf_ = {};
    if (scene.sdf && !next->sdf.instructions.empty())
        if (std::optional<CompiledSdfScene> compiled =
                compileSdfScene(*scene.sdf, std::uint32_t(scene.materials.size()),
                                scene.file.string(), diagnostics, {.bounds = true}))
            boundedSdf_ = std::move(compiled->main);
    if (boundedSdf_.instructions.empty()) boundedSdf_ = next->sdf;
    // Drawn as soon as chooseSdfMap finds a map for it ready, which after a structural edit may
    // take a background build: the picture on screen stays until then.
    prepared_ = std::move(next);
    sceneChanged_ = true;
}

void ViewRenderer::render(const ViewInput& view, const ViewportPixels& viewport,
                          editor::AdaptiveScale& adaptive) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, viewport.framebufferWidth, viewport.framebufferHeight);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!renderer_ || !display_ || !gpuScene_) return;

    const int vw = viewport.width, vh = viewport.height;
    const bool sizeChanged =
        !targets_ || (lastRenderScale_ >= 1.0f &&
                      (targets_->display.width != vw || targets_->display.height != vh));
    viewChanged_ = !sameCamera(view.camera, lastRenderedCamera_) ||
                   lastRenderedRevision_ != view.revision || sizeChanged;
    const float scale = adaptive.next(viewChanged_, lastRenderMilliseconds_, lastRenderScale_);
    const int tw = std::max(1, int(std::lround(float(vw) * scale)));
    const int th = std::max(1, int(std::lround(float(vh) * scale)));
    const bool needRender = viewChanged_ || scale != lastRenderScale_ || !targets_ ||
                            targets_->display.width != tw || targets_->display.height != th;
    if (needRender) {
        if (!targets_ || targets_->display.width != tw || targets_->display.height != th)
            targets_ = createFrameTargets(tw, th);
        const auto t0 = std::chrono::steady_clock::now();
        renderer_->render(*gpuScene_, view.camera, view.scene->render, *targets_);
        glFinish();
        lastRenderMilliseconds_ =
            float(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                      .count());
        lastRenderScale_ = scale;
        lastRenderedCamera_ = view.camera;
        lastRenderedRevision_ = view.revision;
    }
    DisplayInput in;
    in.frame = &*targets_;
    in.mode = view.mode;
    for (const editor::IdRange& range : view.selected)
        if (range.last > range.first) in.selected.emplace_back(range.first, range.last);
    in.nearPlane = view.camera.nearPlane;
    in.farPlane = std::min(view.camera.farPlane, view.scene->render.maxDistance);
    in.maxSteps = view.scene->render.maxSteps;
    in.x = viewport.x;
    in.y = viewport.y;
    in.width = vw;
    in.height = vh;
    display_->draw(in);
    if (view.showLights && !view.scene->lights.empty()) {
        const FrameCamera frame = makeFrameCamera(view.camera, vw, vh);
        gizmos_->draw({0, viewport.x, viewport.y, vw, vh}, frame.viewProjection, view.scene->lights,
                      view.selectedLight);
    }
}

std::optional<Pixels<std::uint8_t>> ViewRenderer::capture(const ViewInput& view, int width,
                                                          int height, std::string& error) {
    if (!renderer_ || !gpuScene_) {
        error = "nothing is rendered";
        return std::nullopt;
    }
    if (targets_ && targets_->display.width == width && targets_->display.height == height &&
        lastRenderScale_ >= 1.0f && sameCamera(view.camera, lastRenderedCamera_) &&
        lastRenderedRevision_ == view.revision)
        return readDisplayColor(*targets_); // the view is already refined
    FrameTargets shot = createFrameTargets(width, height);
    renderer_->render(*gpuScene_, view.camera, view.scene->render, shot);
    return readDisplayColor(shot);
}

ViewStatus ViewRenderer::status() const {
    ViewStatus status;
    status.renderMilliseconds = lastRenderMilliseconds_;
    status.renderScale = lastRenderScale_;
    status.width = targets_ ? targets_->display.width : 0;
    status.height = targets_ ? targets_->display.height : 0;
    status.map = drawnMap_;
    status.selectionLive = choiceLive_.first <= choiceLive_.last;
    status.newestScenePending = sceneChanged_;
    status.buildingMaps = warmer_ && !warmer_->idle();
    return status;
}

} // namespace rmsc::app
