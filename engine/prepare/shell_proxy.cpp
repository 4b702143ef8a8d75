// Proxy meshes of shells: a box, a geodesic sphere, or a glTF asset's triangles.
#include "prepare/shell_proxy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace rmsc {

ShellProxyMesh boxProxyMesh(glm::vec3 min, glm::vec3 max) {
    ShellProxyMesh mesh;
    for (int c = 0; c < 8; ++c)
        mesh.positions.emplace_back(c & 1 ? max.x : min.x, c & 2 ? max.y : min.y,
                                    c & 4 ? max.z : min.z);
    // Two triangles per face, counter-clockwise seen from outside (corner bit 0 = x, 1 = y,
    // 2 = z).
    mesh.indices = {0, 4, 6, 0, 6, 2,  // -x
                    1, 3, 7, 1, 7, 5,  // +x
                    0, 1, 5, 0, 5, 4,  // -y
                    2, 6, 7, 2, 7, 3,  // +y
                    0, 2, 3, 0, 3, 1,  // -z
                    4, 5, 7, 4, 7, 6}; // +z
    return mesh;
}

ShellProxyMesh sphereProxyMesh(glm::vec3 min, glm::vec3 max) {
    // The regular icosahedron: the cyclic permutations of (0, +-1, +-phi).
    const float phi = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> vertices = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                                       {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                                       {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
    std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (glm::vec3& v : vertices)
        v = glm::normalize(v);
    // One subdivision: each edge's midpoint, pushed out to the unit sphere, shared by both faces.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax(a, b);
        auto found = midpoints.find(key);
        if (found != midpoints.end()) return found->second;
        vertices.push_back(glm::normalize(vertices[a] + vertices[b]));
        const auto index = std::uint32_t(vertices.size() - 1);
        midpoints.emplace(key, index);
        return index;
    };
    std::vector<std::array<std::uint32_t, 3>> split;
    for (const auto& f : faces) {
        const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                            ca = midpoint(f[2], f[0]);
        split.push_back({f[0], ab, ca});
        split.push_back({f[1], bc, ab});
        split.push_back({f[2], ca, bc});
        split.push_back({ab, bc, ca});
    }
    // The vertices lie on the unit sphere, the faces inside it: scale by 1 / (the least distance
    // from the centre to a face's plane) so the faces clear the sphere.
    float inradius = 1.0f;
    for (const auto& f : split) {
        const glm::vec3 n = glm::normalize(
            glm::cross(vertices[f[1]] - vertices[f[0]], vertices[f[2]] - vertices[f[0]]));
        inradius = std::min(inradius, std::abs(glm::dot(n, vertices[f[0]])));
    }
    const glm::vec3 center = 0.5f * (min + max);
    const float radius = 0.5f * glm::length(max - min) / inradius;
    ShellProxyMesh mesh;
    for (const glm::vec3& v : vertices)
        mesh.positions.push_back(center + v * radius);
    for (const auto& f : split) {
        // The icosahedron's faces above are listed counter-clockwise from outside; keep it so.
        const glm::vec3 n =
            glm::cross(vertices[f[1]] - vertices[f[0]], vertices[f[2]] - vertices[f[0]]);
        const bool outward = glm::dot(n, vertices[f[0]]) > 0.0f;
        mesh.indices.insert(mesh.indices.end(),
                            {f[0], outward ? f[1] : f[2], outward ? f[2] : f[1]});
    }
    return mesh;
}

ShellProxyMesh assetProxyMesh(const MeshAsset& asset) {
    ShellProxyMesh mesh;
    for (const MeshPrimitive& primitive : asset.primitives) {
        if (primitive.mode != PrimitiveMode::Triangles) continue; // lines enclose nothing
        const auto base = std::uint32_t(mesh.positions.size());
        for (const MeshVertex& v : primitive.vertices)
            mesh.positions.push_back(v.position);
        for (std::uint32_t index : primitive.indices)
            mesh.indices.push_back(base + index);
    }
    return mesh;
}

} // namespace rmsc
