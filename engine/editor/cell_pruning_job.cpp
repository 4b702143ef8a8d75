// The worker that prunes the edited scene's cells (see cell_pruning_job.hpp).
#include "editor/cell_pruning_job.hpp"

#include "core/thread_priority.hpp"

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <utility>

namespace rmsc::editor {

CellPruningResult CellPruningJob::prune(const CellPruningRequest& request) {
    const auto start = std::chrono::steady_clock::now();
    CellPruningResult result;
    result.revision = request.revision;
    result.frame = request.frame;
    // Pruned again into the grid kept from the last result, so the result says which of its
    // words changed since (SdfCellGrid::changedWords, changedSince). A result still held has
    // its grid copied first: a grid once given never changes.
    const SdfProgram& program = request.scene->sdf;
    const Aabb content =
        request.scene->scene.sdf ? sdfContentBox(*request.scene->scene.sdf) : Aabb{};
    if (state_ && grid_ && grid_.use_count() > 1) grid_ = std::make_shared<SdfCellGrid>(*grid_);
    // (Read as 1: the holders' releases happened before; the fence orders their last reads of
    // the grid before the writes below.)
    std::atomic_thread_fence(std::memory_order_acquire);
    result.again = state_ && grid_ && repruneSdfCells(*state_, program, *grid_);
    if (result.again && !content.empty() &&
        (glm::any(glm::lessThan(content.min, grid_->origin)) ||
         glm::any(glm::greaterThan(content.max, grid_->origin + glm::vec3(grid_->size)))))
        result.again = false; // moved out of the cube: a new one
    if (!result.again) {
        // A full build takes seconds: it runs on a thread of its own at a lower priority (its
        // threads inherit it), so the frames come first; a re-prune after an edit, tens of
        // milliseconds, runs here at the UI's.
        grid_.reset(); // (a held one stays with its holder)
        std::thread build([&] {
            lowerThisThreadsPriority();
            grid_ = std::make_shared<SdfCellGrid>(buildSdfCells(program, content, {}, &state_));
        });
        build.join();
    }
    result.grid = grid_;
    result.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace rmsc::editor
