// Exporting an SDF tree, or one node of it, as a triangle mesh: the node is found by its JSON
// pointer and compiled in its place in the scene (its ancestors' transforms, materials and
// modifiers kept, its siblings left out), its bounds give the grid, the limits are checked up
// front, and dual contouring (export/dual_contouring.hpp) makes the triangles.
#pragma once

#include "core/diagnostics.hpp"
#include "core/material.hpp"
#include "export/dual_contouring.hpp"
#include "export/export_mesh.hpp"
#include "scene/scene.hpp"
#include "sdf/bounds.hpp"
#include "sdf/program.hpp"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

// Cells along the longest side of the content's box when neither size is given.
inline constexpr int kExportDefaultResolution = 128;
// How far, in voxels, the adaptive octree may let the surface of a collapsed cluster move from
// the SDF's (export/dual_contouring.hpp, DcOptions::tolerance); 0 keeps every cell's vertex.
inline constexpr float kExportDefaultTolerance = 0.1f;

struct ExportSettings {
    std::string node;              // JSON pointer of the node; "" or "/sdf": the whole tree
    std::optional<float> voxel;    // cell size in world units
    std::optional<int> resolution; // cells along the longest side (when voxel is not given)
    std::optional<Aabb> bounds;    // world box: clips the content (needed for unbounded content)
    float tolerance = kExportDefaultTolerance; // the adaptive octree's, in voxels (0: off)
    int threads = 0;                           // 0: every core
    // Optional: a lattice sampler for the compiled program (the GPU's, render/
    // gpu_field_sampler.hpp), which then samples the blocks; an empty one: the CPU does.
    std::function<SdfLattice(const SdfProgram&)> latticeSampler;
    std::function<void(double)> progress;
    const std::atomic<bool>* cancel = nullptr;
};

struct SdfExport {
    ExportMesh mesh;                 // vertexMaterial / triangleMaterial index `materials`
    std::vector<Material> materials; // the rmsc materials the mesh uses, in first-use order
    std::string name;                // the node's name (or "sdf")
    std::string pointer;             // the node's JSON pointer
    DcGrid grid;                     // as sampled (cells rounded up to whole blocks)
    Aabb box;                        // the content's box the grid covers
    bool clipped = false;            // the content was cut at `box` (bounds or shell bound)
    std::int64_t evaluations = 0;
    std::uint64_t estimatedTriangles = 0; // what the up-front limit check estimated
    std::int64_t faceFlips = 0;           // checkerboard faces flipped to keep it manifold
    std::uint64_t uniformTriangles = 0;   // before the adaptive octree collapsed clusters
    std::int64_t collapsedClusters = 0;   // by the adaptive octree
    std::int64_t fannedQuads = 0;         // made fans so they do not intersect others
    std::int64_t verticesMovedIn = 0;     // of fans, moved towards their cells for the same
    std::int64_t untangledLeft = 0;       // intersecting pairs the untangling left
    double samplingSeconds = 0.0;         // the block passes (DcResult::samplingSeconds)
    bool latticeSampled = false;          // by settings.latticeSampler's sampler
    bool cancelled = false;               // stopped by settings.cancel: nothing else is set
};

// nullopt with the problem in `diagnostics` (file: the scene file; location: the pointer of the
// node, or of what makes it unbounded) when the node is missing, empty, unbounded without
// bounds, over limits::kExportVoxels or limits::kExportTriangles, or has no surface.
std::optional<SdfExport> exportSdf(const Scene& scene, const ExportSettings& settings,
                                   Diagnostics& diagnostics);

// The node's content in the world as exportSdf bounds it: its box, or what makes it unbounded;
// a shell "bound" on the node bounds it. nullopt, with the problem in `diagnostics`, when the
// scene has no SDF tree or no node at the pointer.
std::optional<SdfBounds> exportContentBounds(const Scene& scene, const std::string& node,
                                             Diagnostics& diagnostics);

// The distance and surface of the node as exportSdf samples them (compiled in its place,
// clipped to `clip` when given), for measuring a mesh against the SDF. nullopt as above.
struct ExportField {
    SdfField field;
    Aabb box; // the content's box (clipped)
    bool clipped = false;
    std::string name, pointer;
    std::vector<Material> materials;       // every material the field may name (scene's + default)
    const SdfProgram* program = nullptr;   // the compiled node the functions evaluate
    std::shared_ptr<const void> keepAlive; // which keeps it
};
std::optional<ExportField> exportField(const Scene& scene, const std::string& node,
                                       const std::optional<Aabb>& clip, Diagnostics& diagnostics);

} // namespace rmsc
