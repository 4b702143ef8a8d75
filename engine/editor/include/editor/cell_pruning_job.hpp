// The cells of the scene being edited, pruned on a worker thread (sdf/cell_pruning.hpp): the
// viewer asks for the newest revision's cells and keeps drawing the last ones until they are
// ready, so neither opening a scene of thousands of shapes nor an edit of it stops a frame.
// The worker keeps what it pruned from and prunes again from it after an edit of numbers (a
// shape moved, resized or retyped, an operation's or modifier's parameters changed) that keeps
// the content in the grid's cube; after any other edit it prunes anew. Only the newest request
// waits: one that arrives while another is pruned replaces the one waiting.
//
// The grid is shared with the result, not copied (a large scene's grid is tens of MB: on the
// 10,000-shape grid copying it took 67 to 82 ms of an edit's 83 to 95): the worker prunes again
// into the grid it last gave once nobody else holds it, and into a copy while someone does. So a
// taker drops its grid when it no longer needs it (the viewer: when it asks for the next revision's
// cells).
#pragma once

#include "editor/newest_request_worker.hpp"
#include "prepare/prepared_scene.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/program.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

namespace rmsc::editor {

// Shared, not copied: the viewer's frame never waits for a copy of a large scene.
struct CellPruningRequest {
    std::uint64_t revision = 0;                 // the document's
    int frame = 0;                              // the viewer's frame that asked (for its log)
    std::shared_ptr<const PreparedScene> scene; // its sdf: the tree pruned (no bounding hierarchy)
};

struct CellPruningResult {
    std::uint64_t revision = 0;
    int frame = 0;
    std::shared_ptr<const SdfCellGrid> grid; // never changed once given
    bool again = false; // pruned again from the kept state (an edit of numbers), not anew
    double milliseconds = 0.0;
};

class CellPruningJob {
  public:
    CellPruningJob() = default;

    void request(CellPruningRequest request) { worker_.request(std::move(request)); }
    // The newest finished result, once (nullopt while none is new).
    std::optional<CellPruningResult> take() { return worker_.take(); }
    // Nothing waits and nothing is pruned.
    bool idle() const { return worker_.idle(); }
    void waitUntilIdle() { worker_.waitUntilIdle(); }

  private:
    CellPruningResult prune(const CellPruningRequest& request); // on the worker

    // The worker's: what the last grid was pruned from, and that grid (the last result's,
    // pruned again after an edit; shared with the results that hold it).
    SdfCellStatePtr state_;
    std::shared_ptr<SdfCellGrid> grid_;
    // Last: destroyed first, so the pruning under way ends before what it uses.
    NewestRequestWorker<CellPruningRequest, CellPruningResult> worker_{
        [this](CellPruningRequest& request) { return prune(request); }};
};

} // namespace rmsc::editor
