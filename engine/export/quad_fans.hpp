// Keeping dual contouring's quads from passing through each other. Dual contouring splits the
// quad of the four cell vertices around a crossed edge into two triangles; near sharp features
// two such quads can cross. Ju and Udeshi ("Intersection-Free Contouring on an Octree Grid",
// Pacific Graphics 2006) triangulate a quad instead as the fan of four triangles around the
// point where the surface crosses its edge: each triangle then lies in the two cells whose
// vertices it joins, provided the vertices lie in their cells. Here the quads whose triangles
// intersect others (export_mesh.hpp, countSelfIntersections) are made fans, in rounds, so the
// other quads keep their two triangles; where fans still intersect, their vertices that the
// steps onto the surface took out of their cells are moved back towards them (onto the surface
// as near as the cell, less and less of a margin around it, allows) and, last, to the mean of
// their crossings, and the rounds go on. Each vertex so moved then goes back towards its place
// as far as its triangles intersect nothing. Internal to rmsc_export.
#pragma once

#include "export/dual_contouring.hpp"
#include "qef.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace rmsc::exporter {

struct DcQuad {
    std::array<std::uint32_t, 4> corners; // the cell vertices, counter-clockwise from outside
    glm::vec3 point{0.0f};                // where the surface crosses the quad's edge
    glm::vec3 normal{0.0f};               // and its normal there
    glm::ivec3 cell{0};                   // one of the four cells around the edge
};

struct UntangleStats {
    std::int64_t fannedQuads = 0;
    std::int64_t verticesMovedIn = 0; // moved back into their cells
    std::int64_t left = 0;            // intersecting pairs left after the last round
    std::int64_t evaluations = 0;
};

// `mesh`'s triangles 2q and 2q + 1 are quad q's; `cells[v]` is vertex v's cell of `grid`,
// massPoints[v] the mean of its crossings (where it goes last: the vertex of surface nets).
// Makes the quads whose triangles intersect others fans around their edge's crossing point (a
// vertex added there: its cell appended to `cells` and, when `qefs` is not null, the crossing's
// plane to `qefs`), and moves the vertices of fans that still intersect into their cells, for
// up to `rounds` rounds. Stops between rounds when `cancel` is set.
UntangleStats untangleQuads(const SdfField& field, const DcGrid& grid, ExportMesh& mesh,
                            const std::vector<DcQuad>& quads, std::vector<glm::ivec3>& cells,
                            const std::vector<glm::vec3>& massPoints, std::vector<Qef>* qefs,
                            int rounds, const std::atomic<bool>* cancel);

} // namespace rmsc::exporter
