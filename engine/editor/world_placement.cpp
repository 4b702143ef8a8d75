// World placement of SDF nodes under a new parent (see world_placement.hpp).
#include "editor/world_placement.hpp"

#include "editor/scene_edits.hpp"

#include <glm/gtc/quaternion.hpp>

namespace rmsc::editor {

Transform transformFromMatrix(const glm::mat4& m) {
    Transform t;
    t.position = glm::vec3(m[3]);
    glm::vec3 x(m[0]), y(m[1]), z(m[2]);
    t.scale = glm::vec3(glm::length(x), glm::length(y), glm::length(z));
    if (t.scale.x <= 0.0f || t.scale.y <= 0.0f || t.scale.z <= 0.0f) return t;
    // Gram-Schmidt: the nearest rotation to the scaled columns' directions.
    x /= t.scale.x;
    y = glm::normalize(y - glm::dot(y, x) * x);
    glm::vec3 zz = glm::cross(x, y);
    if (glm::dot(zz, z) < 0.0f) { // a mirroring matrix: keep the rotation, flip the z scale
        t.scale.z = -t.scale.z;
    }
    t.rotation = glm::normalize(glm::quat_cast(glm::mat3(x, y, zz)));
    return t;
}

int effectiveMaterial(const Scene& scene, const std::vector<int>& path) {
    for (std::size_t length = path.size() + 1; length-- > 0;) {
        const SdfNode* node =
            findSdfNode(scene, std::vector<int>(path.begin(), path.begin() + long(length)));
        if (!node) return -1;
        if (node->material >= 0) return node->material;
    }
    return -1;
}

} // namespace rmsc::editor
