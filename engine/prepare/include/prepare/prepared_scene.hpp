// A scene ready to render, still without GL: the Scene, every glTF it references loaded once,
// its SDF tree compiled, and its materials resolved (the scene's, then the default material).
// This is what `rmsc render`, `rmsc validate`, `rmsc bench` and the viewer load.
#pragma once

#include "core/diagnostics.hpp"
#include "core/file_source.hpp"
#include "prepare/sdf_cost.hpp"
#include "prepare/shell_proxy.hpp"
#include "scene/material_textures.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/mesh_pose.hpp"
#include "scene/scene.hpp"
#include "scene/sky_image.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/compiler.hpp"
#include "sdf/program.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace rmsc {

// A shell ready to draw: its program (object space), the box its rays are clipped to and the
// proxy mesh, both in object space.
struct PreparedShell {
    SdfShellProgram compiled; // compiled.node is not kept (nullptr)
    SdfShell settings;
    glm::vec3 clipMin{0.0f}; // the content's bounds with a margin, or the user's "bound"
    glm::vec3 clipMax{0.0f};
    bool clipsContent = false; // the content may reach past the box (a "bound", or a mesh's
                               // bounds around unbounded content): it is clipped to it
    ShellProxyMesh proxy;
};

// How shells are drawn: as the scene says, or all in the fullscreen pass (for comparisons).
enum class ShellMode { AsScene, Fullscreen };

struct PreparedScene {
    Scene scene;
    std::vector<MeshAsset> assets;     // distinct glTF files (and poses of them)
    std::vector<MeshPose> assetPoses;  // per assets: the animation and time it is posed at
    std::vector<int> instanceAsset;    // per scene.meshes: index into assets
    SdfProgram sdf;                    // the fullscreen pass's: empty without an SDF tree
    std::vector<PreparedShell> shells; // the subtrees drawn through proxy meshes
    std::vector<Material> materials;   // scene.materials + the default material
    std::vector<TextureImage>
        textures;      // images of the materials' textures (MaterialTexture::image)
    SkyImage skyImage; // the image sky's pixels (empty unless it has one)
    // What lights the scene: scene.lights, then the glTF KHR_lights_punctual lights of each mesh
    // instance (placed by the instance's transform); at most limits::kLights in all.
    std::vector<Light> lights;
    // The worst-case cost of the SDF objects (prepare/sdf_cost.hpp), set by openScene.
    SdfSceneCost sdfCost;
    // The per-cell programs of `sdf` when the cost check had to prune it to know its cost; the
    // renderer uses them instead of pruning again (SdfCellGrid::code starts with sdf's
    // instructions: a grid that does not is not for this program).
    std::shared_ptr<const SdfCellGrid> sdfCells;
};

// The material used where none is named.
Material defaultMaterial();

// Loads every mesh and compiles the SDF of an already parsed scene. Mesh files are read through
// `files`; errors name the mesh instance's JSON pointer and the glTF element.
// `sdfBounds`: compile the bounding hierarchy (SdfCompileOptions::bounds). The editor turns it
// off: the hierarchy's order follows where parts are, so moving one could change the program's
// structure and cost a shader compile in the middle of a drag.
std::optional<PreparedScene> prepareScene(Scene scene, const FileSource& files,
                                          Diagnostics& diagnostics,
                                          ShellMode shellMode = ShellMode::AsScene,
                                          bool sdfBounds = true);

// scene.lights followed by the lights of the glTF assets placed by their instances; errors at
// the instance that goes over limits::kLights.
std::vector<Light> gatherLights(const Scene& scene, const std::vector<MeshAsset>& assets,
                                const std::vector<int>& instanceAsset, Diagnostics& diagnostics);

// Opens what the user named: a scene file (.json), a glTF model (.gltf / .glb, opened as a
// scene with a default light and a framing camera; `gltfScene` picks the glTF scene drawn, -1
// the file's default), or, for an empty path, the built-in demo.
std::optional<PreparedScene> openScene(const std::filesystem::path& path, Diagnostics& diagnostics,
                                       ShellMode shellMode = ShellMode::AsScene,
                                       int gltfScene = -1);

// Path of the built-in demo scene among the embedded sample files.
inline constexpr const char* kDemoScenePath = "samples/scenes/demo.json";

} // namespace rmsc
