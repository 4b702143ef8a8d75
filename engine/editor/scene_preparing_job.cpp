// The worker that compiles the edited scene (see scene_preparing_job.hpp).
#include "editor/scene_preparing_job.hpp"

#include "core/diagnostics.hpp"
#include "sdf/compiler.hpp"

#include <exception>
#include <utility>

namespace rmsc::editor {

ScenePreparingResult prepareEditedScene(const Scene& scene, std::uint64_t revision,
                                        const FileSource& files) {
    ScenePreparingResult result;
    result.revision = revision;
    Diagnostics diagnostics;
    result.prepared = prepareScene(scene, files, diagnostics, ShellMode::AsScene, false);
    if (!result.prepared) {
        result.error = diagnostics.format();
        return result;
    }
    // The interpreter's program: with the hierarchy, the interpreter skips parts by their
    // boxes, and its text stays the same whatever the order.
    if (scene.sdf && !result.prepared->sdf.instructions.empty())
        if (std::optional<CompiledSdfScene> compiled =
                compileSdfScene(*scene.sdf, std::uint32_t(scene.materials.size()),
                                scene.file.string(), diagnostics, {.bounds = true}))
            result.bounded = std::move(compiled->main);
    if (result.bounded.instructions.empty()) result.bounded = result.prepared->sdf;
    return result;
}

ScenePreparingResult ScenePreparingJob::prepare(Request& request) {
    ScenePreparingResult result;
    try {
        result = prepareEditedScene(request.second, request.first, files_);
    } catch (const std::exception& e) { // out of memory: the scene is not drawn
        result = {};
        result.revision = request.first;
        result.error = std::string("the scene could not be compiled: ") + e.what();
    }
    keepSpare(std::move(request.second));
    return result;
}

Scene ScenePreparingJob::takeSpare() {
    std::lock_guard lock(spareMutex_);
    if (spares_.empty()) return Scene{};
    Scene scene = std::move(spares_.back());
    spares_.pop_back();
    return scene;
}

void ScenePreparingJob::keepSpare(Scene scene) {
    std::lock_guard lock(spareMutex_);
    if (spares_.size() < 2) spares_.push_back(std::move(scene));
}

void ScenePreparingJob::request(std::uint64_t revision, const Scene& scene) {
    Scene copy = takeSpare();
    copy = scene;
    if (std::optional<Request> replaced = worker_.request({revision, std::move(copy)}))
        keepSpare(std::move(replaced->second));
}

} // namespace rmsc::editor
