// What the glTF file of a mesh instance holds that the viewer lists: its animations (with their
// durations, for the timeline), its cameras (to look through one) and its scenes (to pick the
// one drawn), read from the asset the scene preparation loaded. GL-free.
#pragma once

#include "prepare/prepared_scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rmsc::editor {

struct GltfContents {
    std::vector<std::string> animations; // labels: "0 Walk", or "1" when unnamed
    std::vector<double> durations;       // per animation, seconds (its last key)
    std::vector<std::string> cameras;    // "0 Front", "1 (orthographic)"
    std::vector<std::string> scenes;     // "0 Scene", "1"
    int scene = -1;     // the scene drawn (the file's default when the mesh names none), -1 for
                        // a file without scenes (every root node)
    int animation = -1; // the animation the mesh shows, -1 for the rest pose
};

// The contents of mesh instance `mesh`'s file, or nullopt when it did not load.
std::optional<GltfContents> gltfContents(const PreparedScene& prepared, int mesh);

// The view through camera `camera` of mesh `mesh`'s file, at the mesh's pose (an animated
// camera node moves it), placed in the world by the mesh's transform (an orthographic camera's
// height and the planes scaled with it); nullopt with `why` when the mesh did not load or no node
// of the drawn scene places that camera.
std::optional<Camera> gltfCameraView(const PreparedScene& prepared, int mesh, int camera,
                                     std::string& why);

} // namespace rmsc::editor
