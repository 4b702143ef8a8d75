// The cameras of a glTF file as rmsc cameras: found by name or index, placed by their node at
// a pose (a camera's node may be animated).
#pragma once

#include "scene/mesh_pose.hpp"
#include "scene/mesh_rig.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>

namespace rmsc {

// The camera given by name or by index ("1"); nullopt with `why` saying which exist.
std::optional<int> findGltfCamera(const MeshRig& rig, const std::string& nameOrIndex,
                                  std::string& why);

// Camera `camera` of the rig seen from its node at `pose` (glTF 2.0 section 3.10: it looks
// down the node's -Z with +Y up), perspective or orthographic (2 * ymag high; the image's aspect
// gives the width); nullopt with `why` when no node of the drawn scene places it.
std::optional<Camera> gltfCameraAt(const MeshRig& rig, int camera, const MeshPose& pose,
                                   std::string& why);

// "0 \"Front\", 1 (orthographic)": the cameras, for messages and the viewer.
std::string describeGltfCameras(const MeshRig& rig);

} // namespace rmsc
