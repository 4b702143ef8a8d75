// Editing the camera's frame with the reader's check first (see camera_edits.hpp).
#include "editor/camera_edits.hpp"

#include "scene/camera_spec.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

bool setCameraFrame(Camera& camera, const Camera& wanted, std::string& error) {
    if (const std::optional<CameraProblem> problem = cameraFrameProblem(wanted)) {
        error = std::string(problem->key) + ": " + problem->message;
        return false;
    }
    camera.position = wanted.position;
    camera.target = wanted.target;
    camera.up = wanted.up;
    return true;
}

namespace {

// The unit up vector as seen on screen: `up` without its part along `forward`.
glm::vec3 screenUp(glm::vec3 up, glm::vec3 forward) {
    const glm::vec3 across = up - forward * glm::dot(up, forward);
    const float length = glm::length(across);
    return length > 0.0f ? across / length : glm::vec3(0.0f);
}

} // namespace

bool viewDiffersFromCamera(const Camera& view, const Camera& scene) {
    constexpr float kNoise = 1e-4f;
    if (view.projection != scene.projection) return true;
    if (view.projection == CameraProjection::Orthographic &&
        std::abs(view.orthoHeight - scene.orthoHeight) > kNoise * scene.orthoHeight)
        return true;
    const float size = std::max({1.0f, glm::length(scene.position), glm::length(view.position)});
    if (glm::length(view.position - scene.position) > kNoise * size) return true;
    const glm::vec3 viewForward = glm::normalize(view.target - view.position);
    const glm::vec3 sceneForward = glm::normalize(scene.target - scene.position);
    if (glm::length(viewForward - sceneForward) > kNoise) return true;
    return glm::length(screenUp(view.up, viewForward) - screenUp(scene.up, sceneForward)) > kNoise;
}

} // namespace rmsc::editor
