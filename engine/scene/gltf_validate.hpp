// Structural checks of a parsed glTF model before any of its data is used: buffer views
// inside their buffers, every accessor's range, node transforms, the node hierarchy (no
// cycles, one parent at most, depth cap) and material factors. References between arrays were
// checked on the JSON already (gltf_json_checks.hpp).
#pragma once

#include "core/limits.hpp"
#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"

namespace rmsc::gltf {

constexpr int kMaxNodeDepth = limits::kGltfNodeDepth;

// Reports every problem found; returns true when there were none.
bool validateModel(const tinygltf::Model& model, Reporter& report);

} // namespace rmsc::gltf
