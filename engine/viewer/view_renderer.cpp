// The viewer's GPU side: shaders, the scene upload, the warmer, rendering the view and
// capturing it (see view_renderer.hpp; the SDF map choice is sdf_map_choice.cpp).
#include "view_renderer.hpp"

#include "render/frame.hpp"
#include "render/readback.hpp"
#include "sdf/compiler.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace rmsc::app {

ViewRenderer::ViewRenderer(Window* warmerWindow) : warmerWindow_(warmerWindow) {
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
    shadowMapsDrawn_ = false;
    renderer_->setGroundGrid(true);
    display_ = std::move(newDisplay);
    gizmos_ = std::move(newGizmos);
    shaderFiles_ = std::move(files);
    startWarmer();
    lastRenderedRevision_ = 0; // render again
    return true;
}

void ViewRenderer::startWarmer() {
    warmer_.reset();            // waits for the build it is doing
    choiceRevision_ = 0;        // choose the map again
    if (!warmerWindow_) return; // (the render thread said why)
    Window* context = warmerWindow_;
    warmer_ = std::make_unique<ShaderWarmer>(
        [context](std::string&) -> std::function<void()> {
            context->makeCurrent();
            return [] { Window::releaseCurrent(); };
        },
        shaderFiles_);
}

void ViewRenderer::takeScene(const CompiledScene& compiled) {
    uploadedRevision_ = compiled.revision;
    if (!compiled.prepared) return; // the last one that compiled stays
    sceneWarning_ = compiled.warning;
    boundedSdf_ = compiled.bounded;
    // Drawn as soon as chooseSdfMap finds a map for it ready, which after a structural edit may
    // take a background build: the picture on screen stays until then.
    prepared_ = compiled.prepared;
    sceneChanged_ = true;
}

namespace {

float millisecondsSince(std::chrono::steady_clock::time_point t0) {
    return float(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
}

} // namespace

bool ViewRenderer::render(const ViewInput& view, GLuint framebuffer, int width, int height,
                          editor::AdaptiveScale& adaptive, float budgetMilliseconds,
                          bool refineAll) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!renderer_ || !display_ || !gpuScene_) return false;

    const int vw = width, vh = height;
    const bool changed = viewChanged(view, vw, vh);
    const bool rendered = wouldRender(view, vw, vh);
    if (changed) {
        if (!full_ || full_->display.width != vw || full_->display.height != vh)
            full_ = createFrameTargets(vw, vh);
        lastRenderedCamera_ = view.camera;
        lastRenderedRevision_ = view.revision;
        ++changes_;
        // A new map's cost is not known: its first quick render is the smallest.
        if (!(costMilliseconds_ > 0.0f)) adaptive.scale = adaptive.minScale;
        const float scale =
            refineAll ? 1.0f : adaptive.next(costMilliseconds_, costScale_, budgetMilliseconds);
        const auto t0 = std::chrono::steady_clock::now();
        if (scale >= 1.0f) { // the whole image fits the budget
            renderer_->render(*gpuScene_, view.camera, view.render, *full_);
            shadowMapsDrawn_ = true;
            glFinish();
            lastRenderMilliseconds_ = millisecondsSince(t0);
            refinement_.finish(vh, lastRenderMilliseconds_);
            ++refinements_;
            costMilliseconds_ = lastRenderMilliseconds_;
            costScale_ = 1.0f;
        } else {
            const int tw = std::max(1, int(std::lround(float(vw) * scale)));
            const int th = std::max(1, int(std::lround(float(vh) * scale)));
            if (!preview_ || preview_->display.width != tw || preview_->display.height != th)
                preview_ = createFrameTargets(tw, th);
            renderer_->render(*gpuScene_, view.camera, view.render, *preview_);
            shadowMapsDrawn_ = true;
            glFinish();
            lastRenderMilliseconds_ = millisecondsSince(t0);
            previewScale_ = scale;
            costMilliseconds_ = lastRenderMilliseconds_;
            costScale_ = scale;
            refinement_.restart(vh, lastRenderMilliseconds_ / (scale * scale));
        }
    } else if (!refinement_.done()) {
        const editor::RefineBand band = refinement_.nextBand(budgetMilliseconds, refineAll);
        // The render that started this refinement (or the band before) drew the shadow maps
        // for this scene; a new renderer has none yet.
        const RenderRows rows{band.begin, band.end, band.postBegin, band.postEnd, shadowMapsDrawn_};
        const auto t0 = std::chrono::steady_clock::now();
        renderer_->render(*gpuScene_, view.camera, view.render, *full_, &rows);
        shadowMapsDrawn_ = true;
        glFinish();
        lastRenderMilliseconds_ = millisecondsSince(t0);
        refinement_.rendered(band, lastRenderMilliseconds_);
        if (refinement_.done()) ++refinements_;
    }

    DisplayInput in;
    in.mode = view.mode;
    for (const editor::IdRange& range : view.selected)
        if (range.last > range.first) in.selected.emplace_back(range.first, range.last);
    in.nearPlane = view.camera.nearPlane;
    in.farPlane = std::min(view.camera.farPlane, view.render.maxDistance);
    in.maxSteps = view.render.maxSteps;
    in.framebuffer = framebuffer;
    in.width = vw;
    in.height = vh;
    if (!refinement_.done() && preview_) {
        in.frame = &*preview_;
        display_->draw(in);
        in.rows = refinement_.shownRows();
    }
    in.frame = &*full_;
    if (in.rows != 0) display_->draw(in);
    if (view.showLights && !view.lights.empty()) {
        const FrameCamera frame = makeFrameCamera(view.camera, vw, vh);
        gizmos_->draw({framebuffer, 0, 0, vw, vh}, frame.viewProjection, view.lights,
                      view.selectedLight);
    }
    return rendered;
}

std::optional<Pixels<std::uint8_t>> ViewRenderer::capture(const ViewInput& view, int width,
                                                          int height, std::string& error) {
    if (!renderer_ || !gpuScene_) {
        error = "nothing is rendered";
        return std::nullopt;
    }
    if (full_ && full_->display.width == width && full_->display.height == height &&
        refinement_.done() && view.camera == lastRenderedCamera_ &&
        lastRenderedRevision_ == view.revision)
        return readDisplayColor(*full_); // the view is already refined
    FrameTargets shot = createFrameTargets(width, height);
    renderer_->render(*gpuScene_, view.camera, view.render, shot);
    return readDisplayColor(shot);
}

bool ViewRenderer::viewChanged(const ViewInput& view, int width, int height) const {
    return !full_ || full_->display.width != width || full_->display.height != height ||
           view.camera != lastRenderedCamera_ || lastRenderedRevision_ != view.revision;
}

bool ViewRenderer::wouldRender(const ViewInput& view, int width, int height) const {
    return renderer_ && display_ && gpuScene_ &&
           (viewChanged(view, width, height) || !refinement_.done());
}

bool ViewRenderer::waitsForBackground() const {
    return sceneChanged_ || (warmer_ && !warmer_->idle());
}

ViewStatus ViewRenderer::status() const {
    ViewStatus status;
    status.renderMilliseconds = lastRenderMilliseconds_;
    status.refined = refined();
    const bool overPreview = !status.refined && preview_;
    status.renderScale = overPreview ? previewScale_ : 1.0f;
    const FrameTargets* shown = overPreview ? &*preview_ : full_ ? &*full_ : nullptr;
    status.width = shown ? shown->display.width : 0;
    status.height = shown ? shown->display.height : 0;
    status.refinedRows = refinement_.shownRows();
    status.changes = changes_;
    status.refinements = refinements_;
    status.map = drawnMap_;
    status.selectionLive = choiceLive_.first <= choiceLive_.last;
    status.newestScenePending = sceneChanged_;
    status.buildingMaps = warmer_ && !warmer_->idle();
    if (warmer_) {
        const ShaderWarmer::Progress p = warmer_->progress();
        status.build = {p.done, p.total, p.seconds,
                        sceneChanged_ ? "for the newest scene" : "better maps"};
    }
    return status;
}

} // namespace rmsc::app
