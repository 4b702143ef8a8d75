// Transform matrices, and the scene format's Euler angles.
#include "core/transform.hpp"

#include "core/number_text.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace rmsc {

glm::mat4 Transform::matrix() const {
    return glm::translate(glm::mat4(1.0f), position) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

glm::quat eulerDegreesToQuaternion(glm::vec3 degrees) {
    const glm::vec3 r = glm::radians(degrees);
    const glm::quat x = glm::angleAxis(r.x, glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::quat y = glm::angleAxis(r.y, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::quat z = glm::angleAxis(r.z, glm::vec3(0.0f, 0.0f, 1.0f));
    return z * y * x;
}

// The angles come from the rotation matrix R = Rz Ry Rx of q (x first), by the usual Tait-Bryan
// extraction (e.g. Slabaugh, "Computing Euler angles from a rotation matrix"): row 2 is
// (-sin y, cos y sin x, cos y cos x), column 0 is cos y (cos z, sin z, .). At y = +-90 degrees
// only x -+ z is defined: z is taken as 0 and x read from column 1, (sin(x - z), cos(x - z), 0)
// at +90, (-sin(x + z), cos(x + z), 0) at -90. (glm is column-major: R[column][row].)
glm::vec3 eulerDegrees(const glm::quat& q) {
    const glm::mat3 r = glm::mat3_cast(q);
    const float cosY = std::hypot(r[0][0], r[0][1]);
    glm::vec3 radians(0.0f, std::atan2(-r[0][2], cosY), 0.0f);
    if (cosY > 1e-6f) {
        radians.x = std::atan2(r[1][2], r[2][2]);
        radians.z = std::atan2(r[0][1], r[0][0]);
    } else {
        radians.x = std::atan2(r[0][2] < 0.0f ? r[1][0] : -r[1][0], r[1][1]);
    }
    return glm::degrees(radians);
}

namespace {

// The extraction's rounding leaves a zero angle near 0, not at it (and may give -0).
glm::vec3 withoutNoise(glm::vec3 degrees) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(degrees[i]) < 1e-3f) degrees[i] = 0.0f;
    return degrees;
}

} // namespace

std::optional<glm::vec3> exactEulerDegrees(const glm::quat& q) {
    glm::vec3 degrees = withoutNoise(eulerDegrees(q));
    // It also leaves an angle some ulps off (the check below keeps what is not exact from being
    // written).
    for (int i = 0; i < 3; ++i)
        if (degrees[i] != 0.0f) degrees[i] = nearestShortDecimal(degrees[i], 64);
    if (eulerDegreesToQuaternion(degrees) != q) return std::nullopt;
    return degrees;
}

glm::vec3 shownEulerDegrees(const glm::quat& q) {
    return exactEulerDegrees(q).value_or(withoutNoise(eulerDegrees(q)));
}

} // namespace rmsc
