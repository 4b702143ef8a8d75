// The parts of glTF 2.0 core that rmsc cannot draw as the file means them (skin attributes
// without a skin): one warning each, saying what is drawn instead, so that nothing a file holds
// is dropped silently (docs/gltf.md).
#pragma once

#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"

namespace rmsc::gltf {

void warnUnsupportedFeatures(const tinygltf::Model& model, Reporter& report);

} // namespace rmsc::gltf
