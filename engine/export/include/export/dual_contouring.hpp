// Dual contouring of an SDF on a uniform grid (Ju, Losasso, Schaefer and Warren, "Dual
// Contouring of Hermite Data", SIGGRAPH 2002), with one vertex per surface component of a cell
// (Schaefer, Ju and Warren, "Manifold Dual Contouring", 2007), sampled sparsely: the grid is cut
// into blocks of kDcBlock^3 cells, and a block whose centre's |distance| exceeds its half
// diagonal times sqrt(2) (the steepest slope of the fields: the chamfer operations) holds no
// surface and is never sampled further. Quads that would pass through others become fans
// around their edge's crossing (Ju and Udeshi 2006; export/quad_fans.hpp), so the mesh has no
// self-intersections; then, with a tolerance, the adaptive octree collapses clusters of cells
// where the surface is flat enough (export/adaptive_octree.hpp).
#pragma once

#include "export/export_mesh.hpp"

#include <glm/glm.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace rmsc {

inline constexpr int kDcBlock = 8;

// Distances on lattices of points at once (a GPU's compute shader, render/gpu_field_sampler.hpp):
// for each start s, side^3 values at origin + spacing * (s + (x, y, z)), x fastest, then y, then
// z, go to out (start after start). False when it failed.
using SdfLattice = std::function<bool(glm::vec3 origin, float spacing, const glm::ivec3* starts,
                                      std::size_t count, int side, float* out)>;

// What is contoured: a distance (< 0 inside) and, at the vertices, the blended base colour and
// the dominant material.
struct SdfField {
    std::function<float(glm::vec3)> distance;
    std::function<void(glm::vec3, std::uint32_t& material, glm::vec3& color)> surface;
    // Optional: the passes that sample whole blocks (their centres, their corners) use it; where
    // it fails they call `distance`.
    SdfLattice lattice;
};

// Cell (i, j, k) spans origin + voxel * [(i, j, k), (i + 1, j + 1, k + 1)]. The field must be
// positive (outside) on the grid's outer corners, so the mesh is closed.
struct DcGrid {
    glm::vec3 origin{0.0f};
    float voxel = 1.0f;
    glm::ivec3 cells{0}; // rounded up to whole blocks by dualContour
};

struct DcOptions {
    int threads = 0; // 0: every core
    // Refused after the first pass (about one evaluation per block) when the estimate is over.
    std::uint64_t maxTriangles = ~std::uint64_t(0);
    std::function<void(double fraction)> progress; // called from the worker threads, serialized
    const std::atomic<bool>* cancel = nullptr;     // set: stop soon, return cancelled
    // The adaptive octree (Manifold Dual Contouring's vertex clustering,
    // export/adaptive_octree.hpp): clusters of cells whose surface is flat to within `tolerance`
    // voxels become one vertex, in nodes of up to 2^octreeLevels cells a side. 0: every cell keeps
    // its vertices.
    float tolerance = 0.0f;
    int octreeLevels = 6;
};

struct DcResult {
    ExportMesh mesh;
    bool cancelled = false;
    bool overLimit = false;               // estimate (or final count) over maxTriangles
    std::uint64_t estimatedTriangles = 0; // from the blocks near the surface
    std::int64_t activeBlocks = 0;
    std::int64_t evaluations = 0; // distance evaluations in all
    std::int64_t faceFlips = 0;   // checkerboard faces whose rule was flipped (manifold repair)
    std::uint64_t uniformTriangles = 0; // before the adaptive octree collapsed clusters
    std::int64_t collapsedClusters = 0;
    std::int64_t fannedQuads = 0;       // quads made fans so they do not intersect others
    std::int64_t verticesMovedIn = 0;   // of fans that did, moved back into their cells
    std::int64_t selfIntersections = 0; // pairs of the uniform mesh's left intersecting
    double samplingSeconds = 0.0; // the passes that sample the blocks (the centres, the corners)
    bool latticeSampled = false;  // SdfField::lattice sampled them
};

DcResult dualContour(const SdfField& field, DcGrid grid, const DcOptions& options = {});

// The triangles a surface through `activeBlocks` blocks near it may make, for the up-front
// refusal: two per cell of a block's face (kDcBlock^2 columns, as if a sheet crossed each).
// Measured at resolution 128: 1.6 times the pawn's triangles, 1.8 times the CSG sample's, 1.04
// times the chessboard's; 0.93 times a sphere's at 24 cells.
std::uint64_t estimateDcTriangles(std::int64_t activeBlocks);

} // namespace rmsc
