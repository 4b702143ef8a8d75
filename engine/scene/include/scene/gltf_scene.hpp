// Opening a .gltf/.glb directly as a scene: the asset as the only mesh, a default sun light,
// a neutral studio sky and a camera that frames the asset's bounds the way glTF viewers do.
#pragma once

#include "scene/mesh_asset.hpp"
#include "scene/scene.hpp"

#include <filesystem>

namespace rmsc {

// A scene showing `asset` (loaded from `gltfPath`): one MeshInstance, one directional light,
// a grey gradient sky (lighting every side), a camera looking at the bounds'
// centre from the +z/+y side, no SDF.
Scene sceneFromGltf(const std::filesystem::path& gltfPath, const MeshAsset& asset);

} // namespace rmsc
