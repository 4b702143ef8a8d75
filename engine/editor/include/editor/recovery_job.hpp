// The recovery file (editor/recovery.hpp) written on a worker thread. Turning a large scene into
// text, checking it as a save does and writing it took 128 to 221 ms on the 10,000-shape grid,
// a frozen frame every 5 seconds of editing when the UI thread did it. The viewer hands the job
// a copy of the scene, made over the last one written (its memory used again), and takes the
// outcome in a later frame. Before the recovery file is removed (a save, a discard, a clean
// close) the job is cancelled, so no write lands after the removal. GL-free.
#pragma once

#include "editor/newest_request_worker.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace rmsc::editor {

struct RecoveryOutcome {
    std::uint64_t revision = 0; // the document's revision it was asked for
    bool written = false;
    std::string error; // why not (as writeRecovery says it)
};

class RecoveryJob {
  public:
    // Asks for `scene`, revision `revision` of the document whose file is `sceneFile` ("" for a
    // scene never saved), to be written to recoveryPath(sceneFile). A request not yet begun is
    // replaced by the next one.
    void request(const Scene& scene, const std::filesystem::path& sceneFile,
                 std::uint64_t revision);
    // The newest finished outcome, once (nullopt while none is new).
    std::optional<RecoveryOutcome> take();
    // Drops the request waiting and waits for the write under way; its outcome is dropped too.
    void cancel();

  private:
    struct Request {
        std::uint64_t revision = 0;
        std::filesystem::path file;
        Scene scene;
    };
    struct Result {
        RecoveryOutcome outcome;
        Scene scene; // the request's, back for its memory
    };
    static Result write(Request& request); // on the worker
    void keepSpare(Scene scene);

    std::optional<Scene> spare_; // the UI thread's: the next request is copied over it
    // Last: destroyed first, so the write under way ends before what it uses.
    NewestRequestWorker<Request, Result> worker_{[](Request& r) { return write(r); }};
};

} // namespace rmsc::editor
