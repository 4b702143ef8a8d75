// The edited scene compiled on a worker thread (prepare/prepared_scene.hpp): each revision the
// viewer draws is prepared here, together with its SDF compiled with the bounding hierarchy
// (what the interpreter and the cells' outside run). The viewer waits for a small scene's
// (a few milliseconds, and the next frame shows the edit) and draws on while a large scene's
// is compiled (tens of milliseconds on 10,000 shapes, every frame of a drag). Only the newest
// request waits: one that arrives while another is prepared replaces the one waiting. All the
// compiles run on the worker, so `files` (which may cache what it read) is used by one thread.
#pragma once

#include "core/file_source.hpp"
#include "editor/newest_request_worker.hpp"
#include "prepare/prepared_scene.hpp"
#include "scene/scene.hpp"
#include "sdf/program.hpp"

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rmsc::editor {

struct ScenePreparingResult {
    std::uint64_t revision = 0;
    std::optional<PreparedScene> prepared; // its SDF without the bounding hierarchy
    SdfProgram bounded;                    // the same SDF with it (or without, when it has none)
    std::string error;                     // why it did not compile (prepared empty)
    std::string warning; // what it is drawn without (prepared set): meshes that do not load
};

// What the job does for one revision (also callable on its own): prepareScene without the
// bounding hierarchy (the editor's: its order follows where parts are, so moving one must not
// change the program's structure), then the SDF with it. When only mesh instances fail (a file
// missing, moved or broken), the scene is prepared without them, so the rest still draws: their
// instances draw nothing (instanceAsset -1) and `warning` says why.
ScenePreparingResult prepareEditedScene(const Scene& scene, std::uint64_t revision,
                                        const FileSource& files);

class ScenePreparingJob {
  public:
    explicit ScenePreparingJob(FileSource files) : files_(std::move(files)) {}

    // The scene is copied over one the worker is done with or that a newer request replaced,
    // when there is one: assigning over its nodes reuses their memory, where a new copy of a
    // large scene takes fresh memory (20 to 35 ms for the 10,000-shape grid on a 2-core
    // machine, in a frame of every drag).
    void request(std::uint64_t revision, const Scene& scene);
    // The newest finished result, once (nullopt while none is new).
    std::optional<ScenePreparingResult> take() { return worker_.take(); }
    void waitUntilIdle() { worker_.waitUntilIdle(); }

  private:
    using Request = std::pair<std::uint64_t, Scene>;
    ScenePreparingResult prepare(Request& request); // on the worker
    Scene takeSpare();
    void keepSpare(Scene scene);

    FileSource files_;
    std::mutex spareMutex_;
    // Requests' scenes prepared or replaced, their memory used again by the next requests: two,
    // one for the request waiting and one for the next, while the worker prepares a third.
    std::vector<Scene> spares_;
    // Last: destroyed first, so the compile under way ends before what it uses.
    NewestRequestWorker<Request, ScenePreparingResult> worker_{
        [this](Request& request) { return prepare(request); }};
};

} // namespace rmsc::editor
