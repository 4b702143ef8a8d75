// Scene saves written on a worker thread. Turning the 10,000-shape grid into text, checking it
// as `rmsc validate` would and writing it took 150 to 190 ms, a frozen frame for each Ctrl+S
// when the UI thread did it. The viewer hands the job a Document::saveOf (a copy of the scene)
// and takes the outcome in a later frame, giving it to Document::saved; the edits go on
// meanwhile. One save at a time: the caller takes the last outcome (waiting for it if need be)
// before it starts another. GL-free.
#pragma once

#include "editor/document.hpp"
#include "editor/newest_request_worker.hpp"

#include <optional>
#include <string>

namespace rmsc::editor {

struct SaveOutcome {
    SceneSave save;
    bool written = false;
    std::string error; // why not (as writeSceneSave says it)
};

class SaveJob {
  public:
    // Starts writing `save`. Refused (false) while the last save's outcome is not taken.
    bool start(SceneSave save);
    // From start() until its outcome is taken.
    bool underWay() const { return underWay_; }
    // The outcome once the write is done (waiting for it with `wait`), once; nullopt while it
    // is not done or when no save is under way.
    std::optional<SaveOutcome> take(bool wait);

  private:
    static SaveOutcome write(SceneSave& save); // on the worker
    bool underWay_ = false;
    // Last: destroyed first, so the write under way ends before what it uses.
    NewestRequestWorker<SceneSave, SaveOutcome> worker_{[](SceneSave& s) { return write(s); }};
};

} // namespace rmsc::editor
