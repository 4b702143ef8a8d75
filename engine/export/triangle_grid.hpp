// Triangles in a uniform grid, to find those near a place (the local intersection tests of the
// adaptive octree and of the untangling of quads), and the exact test of two triangles
// (mesh_intersections.cpp). Internal to rmsc_export.
#pragma once

#include "export/export_mesh.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace rmsc::exporter {

using TrianglePoints = std::array<glm::dvec3, 3>;

// Whether two triangles share a point; touching along a segment or at a point counts only where
// they overlap by more than `epsilon` (Moller's interval test; coplanar ones in their plane).
bool trianglesIntersect(const TrianglePoints& a, const TrianglePoints& b, double epsilon);

class TriangleGrid {
  public:
    TriangleGrid(glm::vec3 origin, float cellSize) : origin_(origin), cellSize_(cellSize) {}

    // Files triangle `t` under every cell its box [lo, hi] touches (once more when it moved:
    // callers check what they find).
    void insert(std::uint32_t t, glm::vec3 lo, glm::vec3 hi);
    // Calls visit(t) for every triangle filed under a cell the box touches (a triangle may come
    // more than once).
    template <class Visit> void visit(glm::vec3 lo, glm::vec3 hi, Visit visit) const {
        const glm::ivec3 a = cellOf(lo), b = cellOf(hi);
        for (int z = a.z; z <= b.z; ++z)
            for (int y = a.y; y <= b.y; ++y)
                for (int x = a.x; x <= b.x; ++x) {
                    auto it = cells_.find(key({x, y, z}));
                    if (it == cells_.end()) continue;
                    for (std::uint32_t t : it->second)
                        visit(t);
                }
    }

  private:
    glm::ivec3 cellOf(glm::vec3 p) const {
        return glm::ivec3(glm::floor((p - origin_) / cellSize_));
    }
    static std::uint64_t key(glm::ivec3 c) {
        return (std::uint64_t(std::uint32_t(c.x + (1 << 20)) & 0x1fffff) << 42) |
               (std::uint64_t(std::uint32_t(c.y + (1 << 20)) & 0x1fffff) << 21) |
               std::uint64_t(std::uint32_t(c.z + (1 << 20)) & 0x1fffff);
    }

    glm::vec3 origin_;
    float cellSize_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

// The points of triangle t of `mesh`.
inline TrianglePoints pointsOf(const ExportMesh& mesh, std::uint32_t t) {
    const auto& tri = mesh.triangles[t];
    return {glm::dvec3(mesh.positions[tri[0]]), glm::dvec3(mesh.positions[tri[1]]),
            glm::dvec3(mesh.positions[tri[2]])};
}

// Whether the triangle at `points`, whose vertices are `ids` (~0u: a vertex not in the mesh
// yet), intersects a triangle of `mesh` filed in `grid` near it that shares none of its
// vertices and that ignore(t) does not rule out (a triangle being replaced).
template <class Ignore>
bool intersectsNearby(const ExportMesh& mesh, const TriangleGrid& grid,
                      const TrianglePoints& points, const std::array<std::uint32_t, 3>& ids,
                      double epsilon, Ignore ignore) {
    const glm::dvec3 lo = glm::min(points[0], glm::min(points[1], points[2]));
    const glm::dvec3 hi = glm::max(points[0], glm::max(points[1], points[2]));
    bool found = false;
    grid.visit(glm::vec3(lo), glm::vec3(hi), [&](std::uint32_t t) {
        if (found || ignore(t)) return;
        const auto& tri = mesh.triangles[t];
        for (std::uint32_t v : tri)
            if (v == ids[0] || v == ids[1] || v == ids[2]) return;
        const TrianglePoints other = pointsOf(mesh, t);
        const glm::dvec3 olo = glm::min(other[0], glm::min(other[1], other[2]));
        const glm::dvec3 ohi = glm::max(other[0], glm::max(other[1], other[2]));
        if (glm::any(glm::lessThan(hi, olo)) || glm::any(glm::lessThan(ohi, lo))) return;
        if (trianglesIntersect(points, other, epsilon)) found = true;
    });
    return found;
}

// Files every triangle of `mesh` in a grid of `cellSize`.
TriangleGrid gridOfTriangles(const ExportMesh& mesh, glm::vec3 origin, float cellSize);

} // namespace rmsc::exporter
