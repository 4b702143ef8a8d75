// The triangle mesh an export makes, before it is written: positions in world units, unit
// normals from the SDF gradient, the blended base colour and the dominant material of each
// vertex, and each triangle's material (counter-clockwise seen from outside); and the checks
// made on it (topology, self-intersections).
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace rmsc {

struct ExportMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> colors;             // linear base colour blended by smooth operations
    std::vector<std::uint32_t> vertexMaterial; // index into the export's materials
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::uint32_t> triangleMaterial;
};

// How the triangles fit together. A closed, consistently oriented 2-manifold has every edge in
// exactly two triangles, once in each direction, and every vertex's triangles form one fan.
struct MeshTopology {
    std::int64_t edges = 0;
    std::int64_t boundaryEdges = 0;       // in one triangle only
    std::int64_t overSharedEdges = 0;     // in more than two triangles
    std::int64_t misorientedEdges = 0;    // in two triangles that run it the same way
    std::int64_t pinchedVertices = 0;     // whose triangles form more than one fan
    std::int64_t degenerateTriangles = 0; // with a vertex index twice
    bool closedManifold() const {
        return boundaryEdges == 0 && overSharedEdges == 0 && misorientedEdges == 0 &&
               pinchedVertices == 0 && degenerateTriangles == 0;
    }
};

MeshTopology meshTopology(const ExportMesh& mesh);

// Pairs of triangles that share no vertex and yet cross or overlap: a mesh free of them does not
// pass through itself. Tested exactly (Moller's triangle-triangle test, in double precision)
// for the pairs whose boxes meet in a uniform grid. Returns how many; `pairs`, when given, gets
// the first `keep` of them (triangle indices).
std::int64_t countSelfIntersections(const ExportMesh& mesh,
                                    std::vector<std::array<std::uint32_t, 2>>* pairs = nullptr,
                                    std::size_t keep = 16);

} // namespace rmsc
