// Filing triangles in the grid (see triangle_grid.hpp).
#include "triangle_grid.hpp"

namespace rmsc::exporter {

void TriangleGrid::insert(std::uint32_t t, glm::vec3 lo, glm::vec3 hi) {
    const glm::ivec3 a = cellOf(lo), b = cellOf(hi);
    for (int z = a.z; z <= b.z; ++z)
        for (int y = a.y; y <= b.y; ++y)
            for (int x = a.x; x <= b.x; ++x)
                cells_[key({x, y, z})].push_back(t);
}

TriangleGrid gridOfTriangles(const ExportMesh& mesh, glm::vec3 origin, float cellSize) {
    TriangleGrid grid(origin, cellSize);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const TrianglePoints p = pointsOf(mesh, t);
        grid.insert(t, glm::vec3(glm::min(p[0], glm::min(p[1], p[2]))),
                    glm::vec3(glm::max(p[0], glm::max(p[1], p[2]))));
    }
    return grid;
}

} // namespace rmsc::exporter
