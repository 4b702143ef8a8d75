// Every file path a scene holds, visited from one place: the mesh files, the material textures,
// the sky image and the shells' proxy meshes (each a path key of the format: "relative to the
// scene file" in docs/scene.schema.json). Whatever rewrites paths, such as saving into another
// folder, goes through forEachScenePath, so a path key added to the format and listed there is
// rewritten everywhere.
#pragma once

#include "scene/scene.hpp"

#include <filesystem>
#include <functional>
#include <string>

namespace rmsc {

// One path of a scene: the text written in the file and what it resolves to.
struct ScenePath {
    std::string& file;           // as written in the scene file ("" for scenes built in code)
    std::filesystem::path& path; // resolved against the scene file's folder
    const std::string& pointer;  // JSON pointer of the key (or of its object), for messages
};

// Calls `visit` for every path the scene holds, in file order: meshes, material textures, the
// sky image, the shells' proxy meshes. Paths of absent textures and non-image skies are skipped.
void forEachScenePath(Scene& scene, const std::function<void(const ScenePath&)>& visit);

// The file that `file`, written in `scene`, names: relative to the scene file's folder (the
// working folder for a scene not saved yet), normalised; an absolute one as it is.
std::filesystem::path resolveScenePath(const Scene& scene, const std::string& file);

// Rewrites the written `file` of every path so that, read from a scene file in `folder`, it
// names the same file as before: relative files become relative to `folder`; absolute ones stay.
void rebaseScenePaths(Scene& scene, const std::filesystem::path& folder);

} // namespace rmsc
