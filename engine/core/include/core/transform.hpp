// Position, rotation and scale of anything placed in a scene (meshes, SDF nodes).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <optional>

namespace rmsc {

// Position, rotation and scale; the matrix applies scale, then rotation, then translation.
struct Transform {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // (w, x, y, z)
    glm::vec3 scale{1.0f};

    glm::mat4 matrix() const;
};

// The scene format's Euler angles: degrees [x, y, z] applied X first, then Y, then Z about the
// fixed axes, R = Rz * Ry * Rx.
glm::quat eulerDegreesToQuaternion(glm::vec3 degrees);
// Its inverse: degrees whose eulerDegreesToQuaternion is q up to rounding (y in [-90, 90]).
glm::vec3 eulerDegrees(const glm::quat& q);
// Short Euler degrees that eulerDegreesToQuaternion turns into exactly q, if there are: what a
// person typed ([0, 30, 0]) is shown and written back so, not as a quaternion.
std::optional<glm::vec3> exactEulerDegrees(const glm::quat& q);
// The degrees a field shows for q: exactEulerDegrees where there are such, else eulerDegrees
// with the angles under a thousandth of a degree, float noise, shown as 0 (not as "-0.0").
glm::vec3 shownEulerDegrees(const glm::quat& q);

} // namespace rmsc
