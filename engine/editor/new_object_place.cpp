// Where new shapes go (see new_object_place.hpp).
#include "editor/new_object_place.hpp"

#include "editor/scene_edits.hpp"
#include "sdf/bounds.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {
namespace {

std::optional<glm::vec3> hitPoint(const PreparedScene& prepared, PickRay ray) {
    if (const std::optional<PickHit> hit = pick(prepared, ray))
        return ray.origin + ray.direction * hit->t;
    return std::nullopt;
}

// The surface's normal at `point`, where `ray` met it: the cross product of the steps to where
// two rays a milliradian beside it meet the surface (meshes and SDF objects alike), turned to
// face the ray's origin; -direction where a neighbour misses or the steps are degenerate.
glm::vec3 surfaceNormal(const PreparedScene& prepared, const PickRay& ray, glm::vec3 point) {
    const glm::vec3 d = ray.direction;
    const glm::vec3 helper = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(d, helper));
    const glm::vec3 v = glm::cross(d, u);
    PickRay beside = ray;
    beside.direction = glm::normalize(d + 1e-3f * u);
    const std::optional<glm::vec3> a = hitPoint(prepared, beside);
    beside.direction = glm::normalize(d + 1e-3f * v);
    const std::optional<glm::vec3> b = hitPoint(prepared, beside);
    if (!a || !b) return -d;
    const glm::vec3 n = glm::cross(*a - point, *b - point);
    const float length = glm::length(n);
    if (!(length > 0.0f)) return -d;
    return glm::dot(n, d) > 0.0f ? -n / length : n / length;
}

} // namespace

NewObjectSpot newObjectSpot(const PreparedScene* prepared, const PickRay& ray,
                            float fallbackDistance) {
    if (prepared)
        if (const std::optional<glm::vec3> point = hitPoint(*prepared, ray))
            return {*point, surfaceNormal(*prepared, ray, *point)};
    const float t = std::clamp(fallbackDistance, ray.tMin, std::max(ray.tMin, ray.tMax));
    return {ray.origin + ray.direction * t, glm::vec3(0.0f)};
}

bool placeSdfNodeAt(Scene& scene, const std::vector<int>& path, glm::vec3 world) {
    SdfNode* node = findSdfNode(scene, path);
    if (!node) return false;
    const glm::mat4 parent = sdfParentWorldMatrix(scene, path);
    node->transform.position = glm::vec3(glm::inverse(parent) * glm::vec4(world, 1.0f));
    return true;
}

bool placeSdfNodeOn(Scene& scene, const std::vector<int>& path, const NewObjectSpot& spot) {
    const SdfNode* node = findSdfNode(scene, path);
    if (!node) return false;
    // The node's box about its origin, in the parent's frame, then in the world's axes: its
    // corner farthest against the normal is how far the node reaches into the surface.
    SdfNode atOrigin = *node;
    atOrigin.transform.position = glm::vec3(0.0f);
    const SdfBounds bounds = sdfNodeBounds(atOrigin);
    float reach = 0.0f;
    if (bounds.bounded && !bounds.box.empty()) {
        const glm::mat3 parent(sdfParentWorldMatrix(scene, path));
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 c((corner & 1) ? bounds.box.max.x : bounds.box.min.x,
                              (corner & 2) ? bounds.box.max.y : bounds.box.min.y,
                              (corner & 4) ? bounds.box.max.z : bounds.box.min.z);
            reach = std::max(reach, glm::dot(parent * c, -spot.normal));
        }
    }
    return placeSdfNodeAt(scene, path, spot.point + spot.normal * reach);
}

} // namespace rmsc::editor
