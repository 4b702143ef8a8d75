// Which SDF map the view is drawn with (editor/editing_map.hpp): the best one that is ready for
// the newest scene and the selection, uploaded when it differs from the one drawn, while the
// warmer builds the better ones (see view_renderer.hpp).
#include "view_renderer.hpp"

#include <chrono>
#include <cstdio>
#include <utility>

namespace rmsc::app {

void ViewRenderer::chooseSdfMap(const SdfLiveRange& live, bool waitForBuilds, int frameNumber,
                                std::optional<std::string>& sceneError) {
    if (!renderer_ || !prepared_) return;
    if (warmer_) {
        if (waitForBuilds) warmer_->waitUntilIdle();
        const std::string error = warmer_->takeError();
        if (!error.empty()) std::fprintf(stderr, "rmsc view: %s\n", error.c_str());
    }
    updateCells(frameNumber, waitForBuilds);
    const std::size_t built = warmer_ ? warmer_->finishedCount() : 0;
    if (choiceRevision_ == uploadedRevision_ && choiceLive_ == live && choiceBuilt_ == built &&
        choiceCells_ == cellGridRevision_)
        return;
    choiceRevision_ = uploadedRevision_;
    choiceLive_ = live;
    choiceBuilt_ = built;
    choiceCells_ = cellGridRevision_;
    // Without a warmer, or for the first picture, every map is built here (on the render thread)
    // when it is drawn.
    const bool first = !gpuScene_;
    if (first) choiceRevision_ = 0; // choose again next step: the other maps build meanwhile
    // A scene drawn with the cells map waits for its cells with the last picture (the
    // interpreter would take seconds a frame on such a scene).
    const bool cellsPending = cellsRequested_ == uploadedRevision_ &&
                              (cellGridRevision_ != uploadedRevision_ || !cellGrid_);
    const ShadingCode shading = sceneShading(*prepared_); // what its frames are shaded with
    auto isReady = [this, first, cellsPending, &shading](const std::string& map) {
        return !cellsPending && (!warmer_ || first || renderer_->hasPrograms(shading, map) ||
                                 warmer_->isWarm(shading, map));
    };
    const SdfCellFit cellFit = cellGrid_ ? sdfCellFit(*cellGrid_) : SdfCellFit{};
    editor::EditingMaps maps =
        editor::chooseEditingMaps(prepared_->sdf, *boundedSdf_, live, isReady, cellFit);
    if (warmer_) {
        warmer_->request(prepared_, maps.build);
        if (waitForBuilds && !maps.build.empty()) {
            warmer_->waitUntilIdle();
            maps = editor::chooseEditingMaps(prepared_->sdf, *boundedSdf_, live, isReady, cellFit);
            choiceBuilt_ = warmer_->finishedCount();
        }
    }
    if (maps.draw.empty() || (!sceneChanged_ && !gpuScene_))
        return; // nothing ready for the newest scene: the old picture stays
    const bool sameMap = gpuScene_ && gpuScene_->sdfMap == maps.draw;
    const bool cells = maps.kind == editor::EditingMapKind::Cells;
    const bool bounded = maps.kind == editor::EditingMapKind::Interpreter;
    if (sameMap && !sceneChanged_) return;
    // An edit of numbers drawn with the cells map: its buffers written in place, and of the
    // cells only what the re-prune changed (a large scene's upload is what such an edit costs).
    if (sameMap && cells && drawnCells_ && updateSdfScene(*gpuScene_, *prepared_, *cellGrid_)) {
        sceneChanged_ = false;
        drawnScene_ = prepared_;
        sceneError = sceneWarning_;
        lastRenderedRevision_ = 0;
        return;
    }
    std::optional<GpuScene> fresh; // a new upload: a newer scene, or the other program
    if (sceneChanged_ || bounded != drawnBounded_ || cells != drawnCells_) {
        if (cells)
            fresh = uploadScene(*prepared_, SdfStrategy::Cells, &*cellGrid_);
        else if (bounded)
            fresh = uploadScene(*prepared_, SdfStrategy::Interpreter, nullptr, &*boundedSdf_);
        else
            fresh = uploadScene(*prepared_, SdfStrategy::Buffer);
    }
    GpuScene& next = fresh ? *fresh : *gpuScene_;
    std::string previous = std::exchange(next.sdfMap, maps.draw);
    std::string error;
    if (!renderer_->prepare(next, error)) { // not expected: maps are generated
        next.sdfMap = std::move(previous);
        sceneChanged_ = false;
        sceneError =
            "The scene's shaders do not build (showing the last scene that did):\n" + error;
        std::fprintf(stderr, "rmsc view: %s\n", sceneError->c_str());
        return;
    }
    const double compileMs = renderer_->lastCompileMs();
    if (!sameMap) costMilliseconds_ = 0.0f; // the other map's cost says nothing of this one's
    if (fresh) {
        gpuScene_ = std::move(*fresh);
        drawnScene_ = prepared_;
        drawnBounded_ = bounded;
        drawnCells_ = cells;
        if (sceneChanged_) sceneError = sceneWarning_;
        sceneChanged_ = false;
        lastRenderedRevision_ = 0; // the picture may show an older scene: render again
    }
    if (sameMap) return;
    const std::string name(editor::editingMapName(maps.kind));
    const bool background = warmer_ && warmer_->isWarm(shading, maps.draw);
    if (!background && compileMs > 0.0)
        std::fprintf(stderr, "rmsc view: frame %d: built the %s map's shaders in %.0f ms\n",
                     frameNumber, name.c_str(), compileMs);
    std::fprintf(stderr, "rmsc view: frame %d: drawing with the %s map (%s)\n", frameNumber,
                 name.c_str(),
                 background ? ("built in the background in " +
                               std::to_string(int(warmer_->buildMs(shading, maps.draw))) + " ms, " +
                               std::to_string(int(compileMs)) + " ms to switch")
                                  .c_str()
                 : compileMs > 0 ? "built on the render thread"
                                 : "built before");
    drawnMap_ = maps.kind;
}

} // namespace rmsc::app

namespace rmsc::app {

// The cells of prepared_->sdf, the tree without the bounding hierarchy (whose order follows
// where things are: a move would change many instructions), pruned by cellPruning_ on its
// worker: again from the kept state after an edit of numbers, else anew.
void ViewRenderer::updateCells(int frameNumber, bool wait) {
    const bool wanted =
        effectiveSdfStrategy(prepared_->sdf, SdfStrategy::Baked) == SdfStrategy::Cells;
    if (wanted && cellsRequested_ != uploadedRevision_) {
        cellsRequested_ = uploadedRevision_;
        // Nothing draws the last cells again until the new ones come (they are pending), and the
        // worker prunes into the grid in place when nobody else holds it (instead of a copy).
        cellGrid_.reset();
        cellPruning_.request({uploadedRevision_, frameNumber, prepared_});
    }
    if (wait) cellPruning_.waitUntilIdle();
    std::optional<editor::CellPruningResult> result = cellPruning_.take();
    if (!result) return;
    std::fprintf(stderr, "rmsc view: frame %d: pruned %zu cells in %.0f ms (%s)\n", result->frame,
                 result->grid->stats.prunedCells, result->milliseconds,
                 result->again ? "again, after an edit of numbers" : "all");
    // (An older revision's: a newer one is pruned next.)
    if (result->revision != cellsRequested_) return;
    cellGrid_ = std::move(result->grid);
    cellGridRevision_ = result->revision;
}

} // namespace rmsc::app
