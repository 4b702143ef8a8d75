// Turns a validated glTF model's scene into MeshAsset triangles: checks the instanced counts
// against the load budget, reads each mesh primitive once, converts strips and fans to
// triangle lists, bakes node world transforms into positions and normals (flipping winding for
// mirroring transforms), computes missing normals and fills the bounds.
#pragma once

#include "scene/gltf_budget.hpp"
#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/mesh_rig.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rmsc::gltf {

// Fills asset.rig (of scene `scene`, -1 for the default one), asset.lights and, baked at the
// rest pose, asset.primitives, boundsMin and boundsMax. Takes the instanced vertices and
// triangle indices out of `vertices` and `indices`, from the accessors' counts, before reading
// any; returns false after reporting an error.
bool buildGeometry(const tinygltf::Model& model, int scene, Allowance& vertices, Allowance& indices,
                   Reporter& report, MeshAsset& asset);

// Appends `source` (positions, normals and tangents in its mesh's space) transformed by `world`
// to asset.primitives: normals by the inverse transpose, the winding flipped for a mirroring
// transform, missing normals and tangents computed. Reports at `nodePointer` and returns false
// when the transform makes positions infinite or NaN.
bool bakePrimitive(const RigPrimitive& source, const glm::dmat4& world,
                   const std::string& nodePointer, Reporter& report, MeshAsset& asset);

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
