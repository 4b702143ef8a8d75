// Reading what posing needs beyond the meshes: skins, cameras and animations (see mesh_rig.hpp).
#pragma once

#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"
#include "scene/mesh_rig.hpp"

namespace rmsc::gltf {

// Fills rig.skins, rig.cameras and rig.animations from the model (rig.nodes already filled),
// checking them against the limits (kGltfJoints, kGltfAnimationKeys); returns false after
// reporting an error.
bool readRigExtras(const tinygltf::Model& model, Reporter& report, MeshRig& rig);

} // namespace rmsc::gltf
