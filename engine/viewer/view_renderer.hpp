// The viewer's GPU side: the renderer and the display pass, the scene as uploaded, the choice of
// the SDF map it is drawn with (editor/editing_map.hpp: the best one that is ready, while the
// shader warmer builds better ones on a hidden window's context), and the view rendered at the
// resolution the adaptive scale asks for. It runs on the view's render thread, on a context of
// its own (view_render_thread.hpp, which the frame loop talks to): it takes the newest compiled
// scene, draws the picture into the framebuffer it is given, captures for screenshots, and
// reports the newest compiled scene (for picking) and what the overlay shows.
#pragma once

#include "core/image_io.hpp"
#include "display_pass.hpp"
#include "editor/adaptive_scale.hpp"
#include "editor/build_progress.hpp"
#include "editor/cell_pruning_job.hpp"
#include "editor/editing_map.hpp"
#include "editor/refinement.hpp"
#include "editor/scene_edits.hpp"
#include "editor/selection.hpp"
#include "panel_layout.hpp"
#include "render/light_gizmo_pass.hpp"
#include "render/renderer.hpp"
#include "render/shader_warmer.hpp"
#include "sdf/cell_pruning.hpp"
#include "window.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rmsc::app {

// What the view shows this frame (copies: the render thread reads it while the document
// changes).
struct ViewInput {
    Camera camera;
    RenderSettings render;                 // the document's
    std::vector<Light> lights;             // the document's, for their markers
    std::uint64_t revision = 0;            // the document's: a new one renders again
    std::vector<editor::IdRange> selected; // object ids to outline, a range per selected object
    int selectedLight = -1;                // the light drawn in the selection colour
    bool showLights = true;                // draw the lights' markers over the view
    ViewMode mode = ViewMode::Color;
};

// A revision of the document's scene, compiled (the render thread's UI side takes it from the
// compile job, editor/scene_preparing_job.hpp). Shared, never changed once made: picking, the
// warmer and the cell pruning read it on their threads.
struct CompiledScene {
    std::uint64_t revision = 0;
    std::shared_ptr<const PreparedScene> prepared; // null: it did not compile
    std::shared_ptr<const SdfProgram> bounded;     // its SDF with the bounding hierarchy
    std::string warning; // what it is drawn without (meshes that do not load)
};

// What the overlay says about the view.
struct ViewStatus {
    float renderMilliseconds = 0.0f; // of the last render (a quick one or a band)
    float renderScale = 1.0f;        // of the quick render shown under the refined rows, or 1
    int width = 0, height = 0;       // pixels of that render
    int refinedRows = 0;             // rows of the full-resolution image shown so far
    bool refined = false;            // the view shows the whole full-resolution image
    int changes = 0;                 // renders after a change so far (each restarts refining)
    int refinements = 0;             // refinements completed so far
    editor::EditingMapKind map = editor::EditingMapKind::Buffer; // drawn
    bool selectionLive = false;      // the map was chosen with a live range for the selection
    bool newestScenePending = false; // the newest scene shows once its shaders are built
    bool buildingMaps = false;       // better maps are being built in the background
    editor::BuildProgress build;     // of the background build, for the progress bar
};

class ViewRenderer {
  public:
    // `warmerWindow`: the hidden window whose context the shader warmer draws on (opened on the
    // UI thread, as windows must be), or null for none.
    explicit ViewRenderer(Window* warmerWindow);
    ~ViewRenderer();
    ViewRenderer(const ViewRenderer&) = delete;
    ViewRenderer& operator=(const ViewRenderer&) = delete;

    // Builds the renderer and the display pass from `files`, and the drawn scene's passes with
    // them so a broken shader shows here and not while drawing. On success they replace the
    // ones in use and the background builds start over; on failure `error` says why and
    // nothing changes.
    bool useShaders(ShaderFiles files, std::string& error);
    bool hasShaders() const { return renderer_.has_value(); }

    // Takes the newest compiled revision of the document's scene: drawn once chooseSdfMap finds
    // a map for it ready. One that did not compile leaves the last one that did.
    void takeScene(const CompiledScene& compiled);
    // Draws with the best SDF map that is ready for the uploaded scene and the selection's
    // `live` range (whose subtree stays live), asking the warmer for better ones;
    // `waitForBuilds` waits for them (replay scripts). Logs each switch with `frameNumber`. Sets
    // `sceneError` to the message about the scene when it changes: why the chosen map's shaders
    // do not build, or, when a newer scene is drawn, what it is drawn without (often nothing).
    void chooseSdfMap(const SdfLiveRange& live, bool waitForBuilds, int frameNumber,
                      std::optional<std::string>& sceneError);

    // Clears `framebuffer` (`width` x `height` pixels) and draws the view into it: when the
    // view changed, a quick render at the scale `adaptive` chooses for `budgetMilliseconds` (the
    // whole image when it fits); while it is not refined, the next band of the full-resolution
    // image that fits the budget, shown over the quick render; else the last image. With
    // `refineAll` (a replay script's window shot) the whole image is rendered now. The lights'
    // markers are drawn over it every time. True when it rendered the scene (a quick render or
    // a band), false when it only drew the last image again.
    bool render(const ViewInput& view, GLuint framebuffer, int width, int height,
                editor::AdaptiveScale& adaptive, float budgetMilliseconds, bool refineAll);
    // Milliseconds the last render() that rendered spent building programs: a frame whose
    // settings turn on a part of the shading code never built for the scene (render/
    // shading_code.hpp). 0 when it built none.
    double lastRenderCompileMs() const { return renderer_ ? renderer_->lastCompileMs() : 0.0; }
    // The view at `width` x `height` pixels and full resolution: the last render when it is
    // that, or a new render. nullopt with `error` when nothing is rendered yet.
    std::optional<Pixels<std::uint8_t>> capture(const ViewInput& view, int width, int height,
                                                std::string& error);

    // The scene the picture is drawn from (nullptr before the first): its object ids are the
    // id buffer's, which an edit's may not be until its map is ready.
    const std::shared_ptr<const PreparedScene>& drawnScene() const { return drawnScene_; }
    // The view shows the whole full-resolution image of what it was last asked to show:
    // nothing to do until something changes.
    bool refined() const { return full_ && refinement_.done(); }
    // A picture is being refined: the next render() with the same view renders its next band.
    bool refining() const { return gpuScene_ && full_ && !refinement_.done(); }
    // render() with `view` would render the scene (not only draw the last image again).
    bool wouldRender(const ViewInput& view, int width, int height) const;
    // Something the view waits for comes from a worker: the newest scene's map or cells, or
    // the maps being built. chooseSdfMap takes it once it is there.
    bool waitsForBackground() const;
    ViewStatus status() const;

  private:
    bool viewChanged(const ViewInput& view, int width, int height) const;
    void startWarmer();
    // Asks for the cells of the newest scene when it is drawn with the cells map, and takes
    // them once pruned (waiting for them with `wait`): cellGrid_ holds the newest.
    void updateCells(int frameNumber, bool wait);

    ShaderFiles shaderFiles_;
    std::optional<Renderer> renderer_;
    std::optional<DisplayPass> display_;
    std::optional<LightGizmoPass> gizmos_;
    std::optional<GpuScene> gpuScene_; // what is drawn
    bool shadowMapsDrawn_ = false;     // renderer_'s shadow maps hold gpuScene_'s (its content
                                       // changes only with a new revision, which renders whole)
    // The last scene that compiled (the newest), its SDF without the bounding hierarchy
    // (generated code's), and the same SDF with it, what the interpreter runs. Never changed
    // once made: the warmer and the cell pruning share them with their threads.
    std::shared_ptr<const PreparedScene> prepared_;
    std::shared_ptr<const SdfProgram> boundedSdf_;
    std::shared_ptr<const PreparedScene> drawnScene_; // what gpuScene_ holds
    bool sceneChanged_ = false; // `prepared_` is newer than what is drawn: it shows once a map
                                // for it is ready
    std::string sceneWarning_;  // what `prepared_` is drawn without (meshes that do not load)
    bool drawnBounded_ = false; // gpuScene_ holds boundedSdf_ (the interpreter draws)
    bool drawnCells_ = false;   // gpuScene_ holds the cells of prepared_->sdf (the cells map)
    // The cells map's grid, pruned on a worker (editor/cell_pruning_job.hpp): the newest one
    // taken and the revision it is of; the revision last asked for.
    editor::CellPruningJob cellPruning_;
    std::shared_ptr<const SdfCellGrid> cellGrid_; // dropped when the next cells are asked for
    std::uint64_t cellGridRevision_ = 0, cellsRequested_ = 0;
    std::uint64_t uploadedRevision_ = 0;
    // The SDF map drawn: the best one that is ready; the warmer builds better ones on its
    // hidden window's context meanwhile.
    Window* warmerWindow_ = nullptr;
    std::unique_ptr<ShaderWarmer> warmer_; // after warmerWindow_: goes first
    editor::EditingMapKind drawnMap_ = editor::EditingMapKind::Buffer;
    // What the map choice was made for: the revision, the selection, the warmer's finished maps.
    std::uint64_t choiceRevision_ = 0, choiceCells_ = 0;
    std::size_t choiceBuilt_ = 0;
    SdfLiveRange choiceLive_;
    // What is shown: the full-resolution image, refined up to refinement_.shownRows(), over
    // the quick render made right after the last change.
    std::optional<FrameTargets> full_;
    std::optional<FrameTargets> preview_;
    editor::Refinement refinement_;
    float previewScale_ = 1.0f;
    float lastRenderMilliseconds_ = 0.0f;
    // The last quick (or whole) render's cost: at costScale_ it took costMilliseconds_. Only
    // those size the next quick render: the bands' cost per row leaves out what a render costs
    // whatever its size (the shadow maps, the passes' set-up).
    float costMilliseconds_ = 0.0f, costScale_ = 1.0f;
    int changes_ = 0, refinements_ = 0;
    Camera lastRenderedCamera_;
    std::uint64_t lastRenderedRevision_ = 0;
};

} // namespace rmsc::app
