// The worker that compiles the edited scene (see scene_preparing_job.hpp).
#include "editor/scene_preparing_job.hpp"

#include "core/diagnostics.hpp"
#include "sdf/compiler.hpp"

#include <algorithm>
#include <exception>
#include <optional>
#include <utility>

namespace rmsc::editor {

namespace {

// The mesh instances that every error of `diagnostics` is about (by their JSON pointers); empty
// when an error is about something else.
std::vector<std::size_t> failingMeshes(const Scene& scene, const Diagnostics& diagnostics) {
    std::vector<std::size_t> failing;
    if (diagnostics.omittedErrors() > 0) return {}; // (what they were about is not known)
    for (const Diagnostic& d : diagnostics.items) {
        if (d.severity != Severity::Error) continue;
        std::optional<std::size_t> mesh;
        for (std::size_t i = 0; i < scene.meshes.size() && !mesh; ++i) {
            const std::string& pointer = scene.meshes[i].pointer;
            if (!pointer.empty() &&
                (d.location == pointer || d.location.starts_with(pointer + "/")))
                mesh = i;
        }
        if (!mesh) return {};
        if (std::find(failing.begin(), failing.end(), *mesh) == failing.end())
            failing.push_back(*mesh);
    }
    std::sort(failing.begin(), failing.end());
    return failing;
}

// The scene prepared without the `failing` mesh instances, which then draw nothing: the
// prepared scene is `scene` itself, every instance at its own index (object ids and picking
// stay the document's).
std::optional<PreparedScene> prepareWithoutMeshes(const Scene& scene,
                                                  const std::vector<std::size_t>& failing,
                                                  const FileSource& files) {
    Scene reduced = scene;
    for (auto i = failing.rbegin(); i != failing.rend(); ++i)
        reduced.meshes.erase(reduced.meshes.begin() + std::ptrdiff_t(*i));
    Diagnostics diagnostics;
    std::optional<PreparedScene> prepared =
        prepareScene(std::move(reduced), files, diagnostics, ShellMode::AsScene, false);
    if (!prepared) return std::nullopt;
    std::vector<int> instanceAsset;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i)
        instanceAsset.push_back(std::binary_search(failing.begin(), failing.end(), i)
                                    ? -1
                                    : prepared->instanceAsset[kept++]);
    prepared->instanceAsset = std::move(instanceAsset);
    prepared->scene = scene;
    return prepared;
}

} // namespace

ScenePreparingResult prepareEditedScene(const Scene& scene, std::uint64_t revision,
                                        const FileSource& files) {
    ScenePreparingResult result;
    result.revision = revision;
    Diagnostics diagnostics;
    result.prepared = prepareScene(scene, files, diagnostics, ShellMode::AsScene, false);
    if (!result.prepared) {
        const std::vector<std::size_t> failing = failingMeshes(scene, diagnostics);
        if (!failing.empty()) result.prepared = prepareWithoutMeshes(scene, failing, files);
        if (!result.prepared) {
            result.error = diagnostics.format();
            return result;
        }
        result.warning = "Drawn without the meshes that do not load:\n" + diagnostics.format();
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
