// Position, rotation and scale of anything placed in a scene (meshes, SDF nodes).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace rmsc {

// Position, rotation and scale; the matrix applies scale, then rotation, then translation.
struct Transform {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // (w, x, y, z)
    glm::vec3 scale{1.0f};

    glm::mat4 matrix() const;
};

} // namespace rmsc
