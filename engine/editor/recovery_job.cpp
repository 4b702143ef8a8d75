// The recovery file written on a worker thread (see recovery_job.hpp).
#include "editor/recovery_job.hpp"

#include "editor/recovery.hpp"

#include <exception>
#include <utility>

namespace rmsc::editor {

RecoveryJob::Result RecoveryJob::write(Request& request) {
    Result result;
    result.outcome.revision = request.revision;
    try {
        result.outcome.written = writeRecovery(request.scene, request.file, result.outcome.error);
    } catch (const std::exception& e) { // out of memory: said, and the next edit tries again
        result.outcome.written = false;
        result.outcome.error = e.what();
    }
    result.scene = std::move(request.scene);
    return result;
}

void RecoveryJob::keepSpare(Scene scene) {
    if (!spare_) spare_ = std::move(scene);
}

void RecoveryJob::request(const Scene& scene, const std::filesystem::path& sceneFile,
                          std::uint64_t revision) {
    Scene copy = spare_ ? std::move(*spare_) : Scene{};
    spare_.reset();
    copy = scene; // over the spare's nodes: their memory is used again
    if (std::optional<Request> replaced = worker_.request({revision, sceneFile, std::move(copy)}))
        keepSpare(std::move(replaced->scene));
}

std::optional<RecoveryOutcome> RecoveryJob::take() {
    std::optional<Result> result = worker_.take();
    if (!result) return std::nullopt;
    keepSpare(std::move(result->scene));
    return std::move(result->outcome);
}

void RecoveryJob::cancel() {
    if (std::optional<Request> dropped = worker_.cancel()) keepSpare(std::move(dropped->scene));
    take();
}

} // namespace rmsc::editor
