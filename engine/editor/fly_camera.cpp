// Free-flight and orbit camera (see fly_camera.hpp).
#include "editor/fly_camera.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

void FlyCamera::setFromCamera(const Camera& camera) {
    position = camera.position;
    glm::vec3 f = camera.target - camera.position;
    focusDistance = std::max(glm::length(f), 0.01f);
    f = glm::normalize(f);
    glm::vec3 u = camera.up;
    if (glm::length(glm::cross(f, u)) < 1e-4f)
        u = std::abs(f.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    // quatLookAt builds the rotation whose -Z is `f` and whose +Y is as close to `u` as possible.
    orientation = glm::normalize(glm::quatLookAt(f, glm::normalize(u)));
}

Camera FlyCamera::toCamera(const Camera& base) const {
    Camera camera = base;
    camera.position = position;
    camera.target = position + forward() * focusDistance;
    camera.up = up();
    return camera;
}

bool FlyCamera::update(const FlyInput& input, float seconds) {
    bool moved = false;
    if (input.look != glm::vec2(0.0f)) {
        // Yaw about the world up axis (no roll creeps in), pitch about the camera's right axis.
        const glm::quat yaw = glm::angleAxis(-input.look.x * radiansPerPixel, glm::vec3(0, 1, 0));
        const glm::quat pitch = glm::angleAxis(-input.look.y * radiansPerPixel, glm::vec3(1, 0, 0));
        orientation = glm::normalize(yaw * orientation * pitch);
        moved = true;
    }
    if (input.roll != 0.0f) {
        const glm::quat roll = glm::angleAxis(input.roll * 1.2f * seconds, glm::vec3(0, 0, -1));
        orientation = glm::normalize(orientation * roll);
        moved = true;
    }
    const glm::vec3 move =
        right() * input.moveRight + up() * input.moveUp + forward() * input.moveForward;
    if (move != glm::vec3(0.0f)) {
        position += glm::normalize(move) * speed * (input.fast ? 4.0f : 1.0f) * seconds;
        moved = true;
    }
    return moved;
}

void FlyCamera::changeSpeed(float notches) {
    speed = std::clamp(speed * std::pow(1.25f, notches), 0.01f, 1000.0f);
}

void FlyCamera::orbit(glm::vec3 pivot, glm::vec2 pixels) {
    const glm::quat yaw = glm::angleAxis(-pixels.x * radiansPerPixel, glm::vec3(0, 1, 0));
    const glm::quat pitch = glm::angleAxis(-pixels.y * radiansPerPixel, right());
    const glm::quat turn = glm::normalize(yaw * pitch);
    position = pivot + turn * (position - pivot);
    orientation = glm::normalize(turn * orientation);
    focusDistance = std::max(glm::length(pivot - position), 0.01f);
}

void FlyCamera::frame(glm::vec3 center, float radius, float fovYDegrees) {
    const float halfFov = glm::radians(std::max(fovYDegrees, 1.0f)) * 0.5f;
    const float distance = std::max(radius, 0.01f) / std::sin(halfFov) * 1.1f;
    position = center - forward() * distance;
    focusDistance = distance;
}

} // namespace rmsc::editor
