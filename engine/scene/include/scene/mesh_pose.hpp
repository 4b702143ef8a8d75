// Posing a loaded glTF file: one of its animations at a time, with its morph weights and skins,
// baked into the asset's primitives (what picking reads), and the joint matrices the raster and
// shadow passes skin the bind vertices of skinned primitives with.
#pragma once

#include "core/diagnostics.hpp"
#include "scene/gltf_report.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/mesh_rig.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rmsc {

// Which animation at which time; animation -1 is the rest pose (the file's own transforms and
// weights).
struct MeshPose {
    int animation = -1; // index into MeshRig::animations
    double time = 0.0;  // seconds; clamped to the animation's keys
};

// The world matrix of every node of the rig at the pose.
std::vector<glm::dmat4> poseNodeWorlds(const MeshRig& rig, const MeshPose& pose);

// Bakes the pose into asset.primitives, asset.jointMatrices and the bounds; the primitives keep
// their order, count and indices (only the vertices, and bind vertices of morphed skinned
// primitives, change), and the joint matrices their count. Returns false, with the problem in
// `diagnostics` and the asset unchanged, when the animation does not exist or the pose makes
// positions infinite.
bool poseMeshAsset(MeshAsset& asset, const MeshPose& pose, Diagnostics& diagnostics);

// The animation given by name or by index ("2"); nullopt with `why` saying which exist.
std::optional<int> findAnimation(const MeshRig& rig, const std::string& nameOrIndex,
                                 std::string& why);

namespace gltf {
// poseMeshAsset's work: replaces asset.primitives and the bounds, reporting to `report`.
bool bakePose(const MeshRig& rig, const MeshPose& pose, Reporter& report, MeshAsset& asset);
} // namespace gltf

} // namespace rmsc
