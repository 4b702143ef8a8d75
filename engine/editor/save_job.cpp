// Scene saves written on a worker thread (see save_job.hpp).
#include "editor/save_job.hpp"

#include <exception>
#include <utility>

namespace rmsc::editor {

SaveOutcome SaveJob::write(SceneSave& save) {
    SaveOutcome outcome;
    try {
        outcome.written = writeSceneSave(save, outcome.error);
    } catch (const std::exception& e) { // out of memory: said, the edits and the old file kept
        outcome.written = false;
        outcome.error = e.what();
    }
    outcome.save = std::move(save);
    return outcome;
}

bool SaveJob::start(SceneSave save) {
    if (underWay_) return false;
    underWay_ = true;
    worker_.request(std::move(save));
    return true;
}

std::optional<SaveOutcome> SaveJob::take(bool wait) {
    if (!underWay_) return std::nullopt;
    if (wait) worker_.waitUntilIdle();
    std::optional<SaveOutcome> outcome = worker_.take();
    if (outcome) underWay_ = false;
    return outcome;
}

} // namespace rmsc::editor
