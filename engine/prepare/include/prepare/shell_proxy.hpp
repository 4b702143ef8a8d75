// Proxy meshes of shells (SdfNode::shell): the closed triangle meshes rasterized so that only
// the pixels they cover march the shell's SDF. Generated in the shell's object space; GL-free.
#pragma once

#include "scene/mesh_asset.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace rmsc {

// Triangles counter-clockwise seen from outside (the shell pass draws the back faces only, so
// the camera may be inside).
struct ShellProxyMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

// The box [min, max]: 8 corners, 12 triangles.
ShellProxyMesh boxProxyMesh(glm::vec3 min, glm::vec3 max);

// A geodesic polyhedron (an icosahedron with each face split in four) scaled so every face lies
// outside the sphere through the corners of [min, max]: it contains the box.
ShellProxyMesh sphereProxyMesh(glm::vec3 min, glm::vec3 max);

// Every primitive of a glTF asset as one mesh (positions and indices only).
ShellProxyMesh assetProxyMesh(const MeshAsset& asset);

} // namespace rmsc
