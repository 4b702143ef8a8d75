// Picking by CPU ray casts (see picking.hpp).
#include "editor/picking.hpp"

#include "editor/mesh_coverage.hpp"
#include "editor/ray_segment.hpp"
#include "editor/ray_triangle.hpp"
#include "editor/scene_edits.hpp"
#include "sdf/cpu_eval.hpp"

#include <algorithm>

namespace rmsc::editor {
namespace {

// The nearest drawn triangle point of one asset along a ray given in the asset's own space:
// back faces of single-sided materials and MASK cut-outs are skipped (editor/mesh_coverage),
// unless a scene material replaces the glTF's (drawn opaque from both sides).
std::optional<float> nearestTriangle(const MeshAsset& asset, glm::vec3 origin, glm::vec3 direction,
                                     float tMin, float tMax, bool materialOverride) {
    // A little room around the bounds so a flat mesh (zero thickness) is not culled by rounding.
    const glm::vec3 pad =
        glm::vec3(1e-4f) * (1.0f + glm::length(asset.boundsMax - asset.boundsMin));
    if (!rayHitsBox(origin, direction, asset.boundsMin - pad, asset.boundsMax + pad, tMin, tMax))
        return std::nullopt;
    std::optional<float> nearest;
    for (const MeshPrimitive& primitive : asset.primitives) {
        if (primitive.mode != PrimitiveMode::Triangles) continue; // nearestLine
        for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
            const std::uint32_t ia = primitive.indices[i], ib = primitive.indices[i + 1],
                                ic = primitive.indices[i + 2];
            if (std::max({ia, ib, ic}) >= primitive.vertices.size()) continue;
            const MeshVertex &a = primitive.vertices[ia], &b = primitive.vertices[ib],
                             &c = primitive.vertices[ic];
            const std::optional<TriangleHit> hit =
                rayTriangleHit(origin, direction, a.position, b.position, c.position, tMin,
                               nearest ? *nearest : tMax);
            if (hit && (materialOverride ||
                        meshPointDrawn(asset, primitive, a, b, c, hit->u, hit->v, hit->frontFace)))
                nearest = hit->t;
        }
    }
    return nearest;
}

// Whether a line or point is drawn where the ray comes nearest it: not where a MASK material
// cuts it out (its alpha interpolated along the segment).
bool lineDrawn(const MeshAsset& asset, const MeshPrimitive& primitive, const MeshVertex& a,
               const MeshVertex& b, float s) {
    if (primitive.material < 0 || std::size_t(primitive.material) >= asset.materials.size())
        return true;
    const MeshMaterial& m = asset.materials[std::size_t(primitive.material)];
    return m.alphaMode != AlphaMode::Mask ||
           meshAlphaAt(asset, m, a, b, b, s, 0.0f) >= m.alphaCutoff;
}

// The nearest line or point of one asset, placed by `model`, that the ray passes within
// kLinePickPixels pixels of. In world space, where the pixel's size is known.
std::optional<float> nearestLine(const MeshAsset& asset, const glm::mat4& model, const PickRay& ray,
                                 float tMax, bool materialOverride) {
    if (ray.pixelSize <= 0.0f && ray.pixelSpread <= 0.0f) return std::nullopt;
    std::optional<float> nearest;
    for (const MeshPrimitive& primitive : asset.primitives) {
        if (primitive.mode == PrimitiveMode::Triangles) continue;
        const std::size_t per = indicesPerElement(primitive.mode);
        for (std::size_t i = 0; i + per - 1 < primitive.indices.size(); i += per) {
            const std::uint32_t ia = primitive.indices[i], ib = primitive.indices[i + per - 1];
            if (std::max(ia, ib) >= primitive.vertices.size()) continue;
            const MeshVertex &a = primitive.vertices[ia], &b = primitive.vertices[ib];
            const glm::vec3 pa = glm::vec3(model * glm::vec4(a.position, 1.0f));
            const glm::vec3 pb = glm::vec3(model * glm::vec4(b.position, 1.0f));
            const std::optional<SegmentApproach> approach = raySegmentApproach(
                ray.origin, ray.direction, pa, pb, ray.tMin, nearest ? *nearest : tMax);
            if (!approach) continue;
            const float pixel = ray.pixelSize + ray.pixelSpread * approach->t;
            if (approach->distance > kLinePickPixels * pixel) continue;
            if (materialOverride || lineDrawn(asset, primitive, a, b, approach->s))
                nearest = approach->t;
        }
    }
    return nearest;
}

} // namespace

std::optional<PickHit> pickMesh(const PreparedScene& prepared, const PickRay& ray) {
    std::optional<PickHit> best;
    const std::vector<MeshInstance>& meshes = prepared.scene.meshes;
    for (std::size_t i = 0; i < meshes.size() && i < prepared.instanceAsset.size(); ++i) {
        const int assetIndex = prepared.instanceAsset[i];
        if (assetIndex < 0 || assetIndex >= int(prepared.assets.size())) continue;
        // Into the asset's space: an affine map keeps the ray parameter t, so hits there are at
        // the same t as in the world (the direction is mapped too, and not renormalized).
        const glm::mat4 toAsset = glm::inverse(meshes[i].transform.matrix());
        const glm::vec3 origin = glm::vec3(toAsset * glm::vec4(ray.origin, 1.0f));
        const glm::vec3 direction = glm::vec3(toAsset * glm::vec4(ray.direction, 0.0f));
        const float tMax = best ? best->t : ray.tMax;
        const MeshAsset& asset = prepared.assets[std::size_t(assetIndex)];
        const bool materialOverride = meshes[i].materialOverride >= 0;
        std::optional<float> t =
            nearestTriangle(asset, origin, direction, ray.tMin, tMax, materialOverride);
        if (const std::optional<float> line = nearestLine(asset, meshes[i].transform.matrix(), ray,
                                                          t ? *t : tMax, materialOverride))
            t = line;
        if (t) {
            const std::uint32_t id = kMeshIdBase + std::uint32_t(i);
            best = PickHit{id, *t, Selection::mesh(int(i))};
        }
    }
    return best;
}

std::optional<PickHit> pickSdf(const PreparedScene& prepared, const PickRay& ray) {
    const RenderSettings& settings = prepared.scene.render;
    float tMax = std::min(ray.tMax, settings.maxDistance);
    std::optional<PickHit> best;
    if (!prepared.sdf.instructions.empty()) {
        if (const std::optional<SdfHit> hit =
                sdfCastRay(prepared.sdf, settings, ray.origin, ray.direction, ray.tMin, tMax)) {
            // The shape that dominates the distance at the hit point is the one the id AOV
            // shows.
            const std::uint32_t id = sdfSurface(prepared.sdf, {}, hit->position).objectId;
            best = PickHit{id, hit->t, selectionForObjectId(prepared.scene, id)};
            tMax = hit->t;
        }
    }
    // Shells march on their own, in their own frames (prepare/prepared_scene.hpp).
    for (const PreparedShell& shell : prepared.shells) {
        const SdfProgram& program = shell.compiled.program;
        const std::optional<SdfHit> hit =
            sdfCastRayInFrame(program, shell.compiled.worldToObject, settings, ray.origin,
                              ray.direction, ray.tMin, tMax);
        if (!hit) continue;
        const glm::vec3 q =
            glm::vec3(shell.compiled.worldToObject * glm::vec4(hit->position, 1.0f));
        if (glm::any(glm::lessThan(q, shell.clipMin)) ||
            glm::any(glm::greaterThan(q, shell.clipMax)))
            continue; // beyond a shell's "bound": clipped away
        const std::uint32_t id = sdfSurface(program, {}, q).objectId;
        best = PickHit{id, hit->t, selectionForObjectId(prepared.scene, id)};
        tMax = hit->t;
    }
    return best;
}

std::optional<PickHit> pick(const PreparedScene& prepared, const PickRay& ray) {
    const std::optional<PickHit> mesh = pickMesh(prepared, ray);
    // The SDF only needs to be traced up to the mesh hit: anything farther is hidden.
    PickRay sdfRay = ray;
    if (mesh) sdfRay.tMax = mesh->t;
    const std::optional<PickHit> sdf = pickSdf(prepared, sdfRay);
    if (sdf && (!mesh || sdf->t < mesh->t)) return sdf;
    return mesh;
}

} // namespace rmsc::editor
