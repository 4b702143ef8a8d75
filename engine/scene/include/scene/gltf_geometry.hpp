// Turns a validated glTF model's scene into MeshAsset triangles: checks the instanced counts
// against the load budget, reads each mesh primitive once, converts strips and fans to
// triangle lists, bakes node world transforms into positions and normals (flipping winding for
// mirroring transforms), computes missing normals and fills the bounds.
#pragma once

#include "scene/gltf_budget.hpp"
#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"
#include "scene/mesh_asset.hpp"

#include <cstdint>
#include <vector>

namespace rmsc::gltf {

// Fills asset.primitives, boundsMin, boundsMax and asset.lights. Takes the instanced vertices
// and triangle indices out of `vertices` and `indices`, from the accessors' counts, before
// reading any; returns false after reporting an error.
bool buildGeometry(const tinygltf::Model& model, Allowance& vertices, Allowance& indices,
                   Reporter& report, MeshAsset& asset);

// Area-weighted vertex normals of an indexed triangle list (flat where no vertex is shared);
// vertices in no triangle, or only in degenerate ones, get +y.
std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions,
                                     const std::vector<std::uint32_t>& triangles);

// Per-vertex tangents from UVs (Lengyel's method; see the .cpp), xyz orthogonal to the normal,
// w = +-1 so that cross(normal, tangent) * w points up the image (towards -v). Vertices
// without UV area get any perpendicular tangent.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs,
                                        const std::vector<std::uint32_t>& triangles);

// A unit vector perpendicular to the unit vector n.
glm::vec3 anyPerpendicular(const glm::vec3& n);

} // namespace rmsc::gltf
