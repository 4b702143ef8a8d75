// A scene ready to render, still without GL: the Scene, every glTF it references loaded once,
// its SDF tree compiled, and its materials resolved (the scene's, then the default material).
// This is what `rmsc render`, `rmsc validate`, `rmsc bench` and the viewer load.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/scene.hpp"
#include "sdf/program.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace rmsc {

struct PreparedScene {
    Scene scene;
    std::vector<MeshAsset> assets;   // distinct glTF files
    std::vector<int> instanceAsset;  // per scene.meshes: index into assets
    SdfProgram sdf;                  // empty when the scene has no SDF tree
    std::vector<Material> materials; // scene.materials + the default material
};

// The material used where none is named.
Material defaultMaterial();

// Loads every mesh and compiles the SDF of an already parsed scene. Mesh files are read through
// `files`; errors name the mesh instance's JSON pointer and the glTF element.
std::optional<PreparedScene> prepareScene(Scene scene, const FileSource& files,
                                          Diagnostics& diagnostics);

// Opens what the user named: a scene file (.json), a glTF model (.gltf / .glb, opened as a
// scene with a default light and a framing camera), or, for an empty path, the built-in demo.
std::optional<PreparedScene> openScene(const std::filesystem::path& path, Diagnostics& diagnostics);

// Path of the built-in demo scene among the embedded sample files.
inline constexpr const char* kDemoScenePath = "samples/scenes/demo.json";

} // namespace rmsc
