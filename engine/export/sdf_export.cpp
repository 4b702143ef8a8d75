// The node found and compiled in its place, its box, the limits, and the materials it uses.
#include "export/sdf_export.hpp"

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "prepare/prepared_scene.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <cmath>
#include <map>

namespace rmsc {
namespace {

// The path from `node` down to the node at `pointer` (inclusive); false when it is not there.
bool findPath(const SdfNode& node, const std::string& pointer, std::vector<const SdfNode*>& path) {
    path.push_back(&node);
    if (node.pointer == pointer) return true;
    for (const SdfNode& child : node.children)
        if (findPath(child, pointer, path)) return true;
    path.pop_back();
    return false;
}

// The node alone, inside one single-child union group per ancestor carrying the ancestor's
// transform, material and modifiers: what the node draws in the scene, without its siblings.
SdfNode inPlace(const std::vector<const SdfNode*>& path) {
    SdfNode node = *path.back();
    node.cut = false;
    for (auto it = path.rbegin() + 1; it != path.rend(); ++it) {
        SdfNode group;
        group.name = (*it)->name;
        group.pointer = (*it)->pointer;
        group.transform = (*it)->transform;
        group.material = (*it)->material;
        group.modifiers = (*it)->modifiers;
        group.isGroup = true;
        group.op = SdfOp::Union;
        group.children.push_back(std::move(node));
        node = std::move(group);
    }
    return node;
}

// The node's frame in the world: its ancestors' transforms and its own.
glm::mat4 nodeToWorld(const std::vector<const SdfNode*>& path) {
    glm::mat4 m(1.0f);
    for (const SdfNode* node : path)
        m = m * node->transform.matrix();
    return m;
}

float boxDistance(const Aabb& box, glm::vec3 p) {
    const glm::vec3 q = glm::abs(p - box.center()) - box.halfSize();
    return glm::length(glm::max(q, glm::vec3(0.0f))) +
           std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

std::string vecText(glm::vec3 v) {
    return "(" + shortestNumberText(v.x) + ", " + shortestNumberText(v.y) + ", " +
           shortestNumberText(v.z) + ")";
}

struct Compiled {
    SdfProgram program;
    std::vector<Material> materials;
};

} // namespace

namespace {

// The path to the node at `node` ("" : the root), or false with the problem in `diagnostics`.
bool nodePath(const Scene& scene, const std::string& node, std::vector<const SdfNode*>& path,
              Diagnostics& diagnostics) {
    const std::string file = scene.file.string();
    if (!scene.sdf) {
        diagnostics.error(file, "/sdf", "the scene has no SDF tree: nothing to export");
        return false;
    }
    const std::string pointer = node.empty() ? scene.sdf->pointer : node;
    if (!findPath(*scene.sdf, pointer, path)) {
        diagnostics.error(file, pointer,
                          "no SDF node at this JSON pointer (expected the pointer of a node "
                          "under /sdf, such as /sdf/children/0)");
        return false;
    }
    return true;
}

// The shell bound of the node at the end of `path`, as a world box.
std::optional<Aabb> shellBound(const std::vector<const SdfNode*>& path) {
    const SdfNode& target = *path.back();
    if (!target.shell || !target.shell->bound) return std::nullopt;
    return transformAabb(aabbAround(glm::vec3(0.0f), *target.shell->bound), nodeToWorld(path));
}

} // namespace

std::optional<SdfBounds> exportContentBounds(const Scene& scene, const std::string& node,
                                             Diagnostics& diagnostics) {
    std::vector<const SdfNode*> path;
    if (!nodePath(scene, node, path, diagnostics)) return std::nullopt;
    SdfBounds bounds = sdfNodeBounds(inPlace(path));
    if (const std::optional<Aabb> shell = shellBound(path)) {
        bounds.box = bounds.bounded ? intersectAabb(bounds.box, *shell) : *shell;
        bounds.bounded = true;
        bounds.unboundedBy.clear();
    }
    return bounds;
}

std::optional<ExportField> exportField(const Scene& scene, const std::string& node,
                                       const std::optional<Aabb>& clip, Diagnostics& diagnostics) {
    const std::string file = scene.file.string();
    std::vector<const SdfNode*> path;
    if (!nodePath(scene, node, path, diagnostics)) return std::nullopt;
    const std::string pointer = path.back()->pointer;
    const SdfNode& target = *path.back();
    const SdfNode root = inPlace(path);
    SdfBounds bounds = sdfNodeBounds(root);
    Aabb box = bounds.box;
    bool clipped = false;
    std::optional<Aabb> cut = clip;
    if (!cut) cut = shellBound(path);
    if (!bounds.bounded) {
        if (!cut) {
            diagnostics.error(
                file, bounds.unboundedBy.empty() ? pointer : bounds.unboundedBy,
                "the content reaches infinity (a plane or an infinite repetition): give "
                "bounds to cut it to (rmsc export --bounds; in the viewer's export dialog, "
                "\"Cut to bounds\"), or a shell \"bound\" on the exported node, to export it");
            return std::nullopt;
        }
        box = *cut;
        clipped = true;
    } else if (cut) {
        box = intersectAabb(box, *cut);
        clipped = true;
    }
    if (box.empty()) {
        diagnostics.error(file, pointer,
                          clipped ? "nothing of the node lies inside the bounds: nothing to export"
                                  : "the node is empty: nothing to export");
        return std::nullopt;
    }
    auto compiled = std::make_shared<Compiled>();
    compiled->materials = scene.materials;
    compiled->materials.push_back(defaultMaterial());
    Diagnostics compileDiagnostics;
    std::optional<SdfProgram> program =
        compileSdf(root, std::uint32_t(scene.materials.size()), file, compileDiagnostics);
    for (const Diagnostic& d : compileDiagnostics.items)
        diagnostics.add(d);
    if (!program) return std::nullopt;
    compiled->program = std::move(*program);
    ExportField out;
    out.box = box;
    out.clipped = clipped;
    out.name = target.name.empty() ? (path.size() == 1 ? "sdf" : "node") : target.name;
    out.pointer = pointer;
    out.materials = compiled->materials;
    const SdfProgram* p = &compiled->program;
    const std::vector<Material>* materials = &compiled->materials;
    if (clipped) {
        out.field.distance = [p, box](glm::vec3 x) {
            return std::max(sdfDistance(*p, x), boxDistance(box, x));
        };
    } else {
        out.field.distance = [p](glm::vec3 x) { return sdfDistance(*p, x); };
    }
    const std::uint32_t fallback = std::uint32_t(scene.materials.size());
    out.field.surface = [p, materials, fallback](glm::vec3 x, std::uint32_t& material,
                                                 glm::vec3& color) {
        const SdfSurface s = sdfSurface(*p, *materials, x);
        material = s.material < materials->size() ? s.material : fallback;
        color = s.baseColor;
    };
    out.program = p;
    out.keepAlive = compiled;
    return out;
}

std::optional<SdfExport> exportSdf(const Scene& scene, const ExportSettings& settings,
                                   Diagnostics& diagnostics) {
    const std::string file = scene.file.string();
    std::optional<ExportField> field =
        exportField(scene, settings.node, settings.bounds, diagnostics);
    if (!field) return std::nullopt;
    const glm::vec3 extent = field->box.max - field->box.min;
    const float longest = std::max(extent.x, std::max(extent.y, extent.z));
    float voxel = 0.0f;
    if (settings.voxel)
        voxel = *settings.voxel;
    else
        voxel = longest / float(settings.resolution.value_or(kExportDefaultResolution));
    if (!(voxel > 0.0f) || !std::isfinite(voxel)) {
        diagnostics.error(file, field->pointer,
                          "the voxel size must be a positive number, got " +
                              shortestNumberText(voxel));
        return std::nullopt;
    }
    if (!(settings.tolerance >= 0.0f) || !std::isfinite(settings.tolerance)) {
        diagnostics.error(file, field->pointer,
                          "the tolerance must be a number of voxels >= 0, got " +
                              shortestNumberText(settings.tolerance));
        return std::nullopt;
    }
    // Two cells of margin on every side: the grid's outer corners lie outside the content. The
    // grid is moved off round numbers by a few hundredths of a cell, so faces at round
    // coordinates (a box at the origin) do not lie exactly on its corners, where the distance
    // is 0 and the surface's crossings and corners fall on the cells' own corners.
    DcGrid grid;
    grid.voxel = voxel;
    grid.origin = field->box.min - 2.0f * voxel - voxel * glm::vec3(0.0131f, 0.0173f, 0.0191f);
    const glm::dvec3 cellsWanted = glm::ceil(glm::dvec3(extent) / double(voxel)) + 4.0;
    const glm::dvec3 cellsRounded = glm::ceil(cellsWanted / double(kDcBlock)) * double(kDcBlock);
    const double voxels = cellsRounded.x * cellsRounded.y * cellsRounded.z;
    if (voxels > double(limits::kExportVoxels)) {
        diagnostics.error(file, field->pointer,
                          "the export would sample " + std::to_string(std::int64_t(voxels)) +
                              " voxels (" + std::to_string(std::int64_t(cellsRounded.x)) + "x" +
                              std::to_string(std::int64_t(cellsRounded.y)) + "x" +
                              std::to_string(std::int64_t(cellsRounded.z)) + " at voxel size " +
                              shortestNumberText(voxel) + " over the box " +
                              vecText(field->box.min) + " to " + vecText(field->box.max) +
                              "), over the limit of " + std::to_string(limits::kExportVoxels) +
                              " (`rmsc limits`): use a larger --voxel or a smaller --resolution");
        return std::nullopt;
    }
    grid.cells = glm::ivec3(cellsWanted);

    if (settings.latticeSampler) {
        SdfLattice lattice = settings.latticeSampler(*field->program);
        if (lattice && field->clipped) {
            // The CPU's field is cut to the box (exportField): so is the sampler's.
            const Aabb box = field->box;
            field->field.lattice = [lattice, box](glm::vec3 origin, float spacing,
                                                  const glm::ivec3* starts, std::size_t count,
                                                  int side, float* out) {
                if (!lattice(origin, spacing, starts, count, side, out)) return false;
                for (std::size_t s = 0, i = 0; s < count; ++s)
                    for (int z = 0; z < side; ++z)
                        for (int y = 0; y < side; ++y)
                            for (int x = 0; x < side; ++x, ++i)
                                out[i] = std::max(
                                    out[i],
                                    boxDistance(box,
                                                origin + spacing * glm::vec3(starts[s] +
                                                                             glm::ivec3(x, y, z))));
                return true;
            };
        } else {
            field->field.lattice = std::move(lattice);
        }
    }
    DcOptions options;
    options.threads = settings.threads;
    options.maxTriangles = limits::kExportTriangles;
    options.progress = settings.progress;
    options.cancel = settings.cancel;
    options.tolerance = settings.tolerance;
    DcResult result = dualContour(field->field, grid, options);
    SdfExport out;
    if (result.cancelled) {
        out.cancelled = true;
        return out;
    }
    if (result.overLimit) {
        diagnostics.error(file, field->pointer,
                          "the export would make about " +
                              std::to_string(result.estimatedTriangles) +
                              " triangles at voxel size " + shortestNumberText(voxel) +
                              ", over the limit of " + std::to_string(limits::kExportTriangles) +
                              " (`rmsc limits`): use a larger --voxel or a smaller --resolution");
        return std::nullopt;
    }
    if (result.mesh.triangles.empty()) {
        diagnostics.error(file, field->pointer,
                          "the node has no surface at voxel size " + shortestNumberText(voxel) +
                              " (it is empty, or thinner than a voxel): nothing to export");
        return std::nullopt;
    }
    // Only the materials the triangles use, in first-use order.
    std::map<std::uint32_t, std::uint32_t> remap;
    for (std::uint32_t& m : result.mesh.triangleMaterial) {
        auto [it, added] = remap.try_emplace(m, std::uint32_t(out.materials.size()));
        if (added) out.materials.push_back(field->materials[m]);
        m = it->second;
    }
    for (std::uint32_t& m : result.mesh.vertexMaterial) {
        auto [it, added] = remap.try_emplace(m, std::uint32_t(out.materials.size()));
        if (added) out.materials.push_back(field->materials[m]);
        m = it->second;
    }
    out.mesh = std::move(result.mesh);
    out.name = field->name;
    out.pointer = field->pointer;
    grid.cells = ((grid.cells + glm::ivec3(kDcBlock - 1)) / kDcBlock) * kDcBlock;
    out.grid = grid;
    out.box = field->box;
    out.clipped = field->clipped;
    out.evaluations = result.evaluations;
    out.estimatedTriangles = result.estimatedTriangles;
    out.faceFlips = result.faceFlips;
    out.uniformTriangles = result.uniformTriangles;
    out.collapsedClusters = result.collapsedClusters;
    out.fannedQuads = result.fannedQuads;
    out.verticesMovedIn = result.verticesMovedIn;
    out.untangledLeft = result.selfIntersections;
    out.samplingSeconds = result.samplingSeconds;
    out.latticeSampled = result.latticeSampled;
    return out;
}

} // namespace rmsc
