// Where new shapes go (see new_object_place.hpp).
#include "editor/new_object_place.hpp"

#include "editor/scene_edits.hpp"

#include <algorithm>

namespace rmsc::editor {

glm::vec3 newObjectPoint(const PreparedScene* prepared, const PickRay& ray,
                         float fallbackDistance) {
    if (prepared)
        if (const std::optional<PickHit> hit = pick(*prepared, ray))
            return ray.origin + ray.direction * hit->t;
    const float t = std::clamp(fallbackDistance, ray.tMin, std::max(ray.tMin, ray.tMax));
    return ray.origin + ray.direction * t;
}

bool placeSdfNodeAt(Scene& scene, const std::vector<int>& path, glm::vec3 world) {
    SdfNode* node = findSdfNode(scene, path);
    if (!node) return false;
    const glm::mat4 parent = sdfParentWorldMatrix(scene, path);
    node->transform.position = glm::vec3(glm::inverse(parent) * glm::vec4(world, 1.0f));
    return true;
}

} // namespace rmsc::editor
