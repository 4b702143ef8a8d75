// Checks on the glTF JSON made before tinygltf sees it: things tinygltf would silently
// accept or misread (index values that do not fit an int, negative indices, required
// extensions), and every buffer and image URI (data URI sizes, folder confinement).
#pragma once

#include "scene/gltf_report.hpp"

#include <nlohmann/json.hpp>

namespace rmsc::gltf {

struct JsonCheckInput {
    bool isGlb = false;        // the JSON came from a GLB's JSON chunk
    bool hasBinChunk = false;  // the GLB has a BIN chunk
    std::uint64_t binSize = 0; // its length
};

// Reports every problem found; returns true when there were none.
bool checkGltfJson(const nlohmann::json& root, const JsonCheckInput& input, Reporter& report);

} // namespace rmsc::gltf
