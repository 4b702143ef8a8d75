// The rule for a camera's position, target and up (see scene/camera_spec.hpp).
#include "scene/camera_spec.hpp"

#include <cmath>

namespace rmsc {

std::string_view cameraProjectionName(CameraProjection projection) {
    return projection == CameraProjection::Orthographic ? "orthographic" : "perspective";
}

std::optional<CameraProjection> findCameraProjection(std::string_view name) {
    for (const CameraProjection p : {CameraProjection::Perspective, CameraProjection::Orthographic})
        if (cameraProjectionName(p) == name) return p;
    return std::nullopt;
}

std::optional<CameraProblem> cameraFrameProblem(const Camera& camera) {
    const glm::vec3 view = camera.target - camera.position;
    if (view == glm::vec3(0.0f))
        return CameraProblem{"target",
                             "the camera's \"target\" equals its \"position\"; it must look "
                             "somewhere"};
    // Normalizing a float vector squares its components: from about 1.8e19 on they overflow.
    if (!std::isfinite(glm::length(view)))
        return CameraProblem{"target",
                             "target - position is too long for float arithmetic (its length "
                             "overflows to infinity); expected \"target\" and \"position\" less "
                             "than 1e19 apart"};
    const float upLength = glm::length(camera.up);
    if (!std::isfinite(upLength))
        return CameraProblem{"up", "the \"up\" vector is too long for float arithmetic (its "
                                   "length overflows to infinity); expected components below "
                                   "1e19, e.g. [0, 1, 0]"};
    const float sine = upLength > 0.0f
                           ? glm::length(glm::cross(camera.up / upLength, glm::normalize(view)))
                           : 0.0f;
    if (!(sine > 1e-4f))
        return CameraProblem{"up", "expected an \"up\" vector that is non-zero and not parallel "
                                   "to the view direction (target - position)"};
    return std::nullopt;
}

} // namespace rmsc
