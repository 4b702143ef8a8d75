// The adaptive octree of manifold dual contouring (Schaefer, Ju and Warren, "Manifold Dual
// Contouring", IEEE TVCG 2007, sec. 4): the vertices dual contouring placed in the grid's cells
// are clustered bottom-up in the octree over the grid, and a cluster becomes one vertex where the
// surface it stands for is flat enough, so flat regions take few triangles. Internal to
// rmsc_export.
//
// Level L groups the cells into nodes of 2^L cells a side. In each node, the vertices that are
// joined by mesh edges inside the node form candidate clusters (the surface's pieces in the
// node: one node may hold several). A candidate is made of vertices that level L - 1 left
// standing (a leaf vertex, or a cluster collapsed there); it collapses into one vertex when
//   - the QEF of all its edge crossings (the sum of its vertices' QEFs), at the new vertex (its
//     minimizer in the node, moved onto the surface), has a root-mean-square plane distance
//     within the tolerance;
//   - the triangles around the cluster form a disk whose border is one simple loop (Euler
//     characteristic 1), every triangle with one cluster vertex has its opposite edge on that
//     loop, and a loop of three is not already a triangle elsewhere: then replacing the cluster
//     by one vertex joined to the loop keeps the mesh a closed 2-manifold of the same topology
//     (the link condition of Dey, Edelsbrunner, Guha and Nekhayev, "Topology preserving edge
//     contraction", 1999, for a contracted disk). MDC tests the same with the signs of the
//     node's cells; here it is tested on the mesh itself, which is what must stay manifold;
//   - each new triangle faces the way the SDF's gradient does (cos >= kMinFacing at its
//     centroid, so nothing folds over), its centroid and the midpoints of its new edges lie
//     within the tolerance of the surface, and it intersects no triangle near it that shares
//     none of its vertices (tested exactly, as countSelfIntersections does), so a mesh free of
//     self-intersections stays free of them.
// A candidate that fails stays as it is, and no larger cluster takes its vertices. Nodes whose
// candidates cannot touch (same parity of their coordinates: not neighbours) are tested on
// worker threads together; the collapses are then applied in order.
#pragma once

#include "export/dual_contouring.hpp"
#include "qef.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace rmsc::exporter {

inline constexpr float kMinFacing = 0.2f;

struct OctreeSettings {
    glm::vec3 origin{0.0f}; // the grid's
    float voxel = 1.0f;
    float tolerance = 0.1f; // in voxels
    int maxLevel = 6;       // nodes of up to 2^maxLevel cells a side
    int threads = 1;
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(double)> progress; // 0 to 1 over the levels
};

struct OctreeStats {
    std::int64_t collapsed = 0;           // clusters made one vertex
    std::int64_t refusedError = 0;        // candidates whose QEF or surface error was too large
    std::int64_t refusedTopology = 0;     // whose triangles around were not a disk
    std::int64_t refusedFolding = 0;      // whose new triangles would have faced the wrong way
    std::int64_t refusedIntersection = 0; // or would have intersected other triangles
    std::int64_t evaluations = 0;
};

// Collapses `mesh` (a closed mesh as dual contouring made it: cells[v] is the grid cell of
// vertex v, qefs[v] the planes of its edge crossings) in place: collapsed vertices are dropped,
// the others renumbered, triangles' materials taken again from their vertices. False when
// cancelled (the mesh is then left in pieces).
bool collapseOctree(const SdfField& field, ExportMesh& mesh, std::vector<glm::ivec3> cells,
                    std::vector<Qef> qefs, const OctreeSettings& settings, OctreeStats& stats);

} // namespace rmsc::exporter
