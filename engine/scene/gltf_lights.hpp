// glTF KHR_lights_punctual: the lights a node refers to, turned into scene lights placed by the
// node's world transform (glTF lights shine down the node's -Z axis).
#pragma once

#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"
#include "scene/mesh_asset.hpp"

#include <glm/glm.hpp>

#include <string>

namespace rmsc::gltf {

// Adds the light of `node` (if it has one) to asset.lights; bad values are reported at the
// light's pointer ("/extensions/KHR_lights_punctual/lights/0/...") and skipped.
void addNodeLight(const tinygltf::Model& model, const tinygltf::Node& node, const glm::dmat4& world,
                  const std::string& nodePointer, Reporter& report, MeshAsset& asset);

} // namespace rmsc::gltf
