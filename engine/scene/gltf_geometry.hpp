// Turns a validated glTF model's scene into MeshAsset triangles: reads each mesh primitive
// once, converts strips and fans to triangle lists, bakes node world transforms into positions
// and normals (flipping winding for mirroring transforms), computes missing normals and fills
// the bounds.
#pragma once

#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"
#include "scene/mesh_asset.hpp"

#include <cstdint>
#include <vector>

namespace rmsc::gltf {

// Fills asset.primitives, boundsMin and boundsMax. Returns false after reporting an error.
bool buildGeometry(const tinygltf::Model& model, Reporter& report, MeshAsset& asset);

// Area-weighted vertex normals of an indexed triangle list (flat where no vertex is shared);
// vertices in no triangle, or only in degenerate ones, get +y.
std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions,
                                     const std::vector<std::uint32_t>& triangles);

} // namespace rmsc::gltf
