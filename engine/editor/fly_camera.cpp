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
    orthographic = camera.projection == CameraProjection::Orthographic;
    orthoHeight = camera.orthoHeight;
}

Camera FlyCamera::toCamera(const Camera& base) const {
    Camera camera = base;
    camera.position = position;
    camera.target = position + forward() * focusDistance;
    camera.up = up();
    camera.projection =
        orthographic ? CameraProjection::Orthographic : CameraProjection::Perspective;
    camera.orthoHeight = orthoHeight;
    return camera;
}

bool FlyCamera::update(const FlyInput& input, float seconds) {
    bool moved = false;
    if (input.look != glm::vec2(0.0f)) {
        // Yaw about the world up axis (no roll creeps in), pitch about the camera's right axis.
        const glm::quat yaw = glm::angleAxis(-input.look.x * radiansPerPixel, glm::vec3(0, 1, 0));
        const glm::quat pitch = glm::angleAxis(-input.look.y * radiansPerPixel, glm::vec3(1, 0, 0));
        const bool upright = up().y >= 0.0f;
        orientation = glm::normalize(yaw * orientation);
        const glm::quat pitched = glm::normalize(orientation * pitch);
        // Without roll, never over the top: the pitch that would turn the camera upside down
        // is not taken (the yaw is).
        if (allowRoll || !upright || (pitched * glm::vec3(0, 1, 0)).y >= 0.0f)
            orientation = pitched;
        moved = true;
    }
    if (input.roll != 0.0f && allowRoll) {
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

void FlyCamera::zoom(float notches) {
    orthoHeight = std::clamp(orthoHeight / std::pow(1.25f, notches), 1e-4f, 1e6f);
}

void FlyCamera::orbit(glm::vec3 pivot, glm::vec2 pixels) {
    const glm::quat yaw = glm::angleAxis(-pixels.x * radiansPerPixel, glm::vec3(0, 1, 0));
    glm::quat pitch = glm::angleAxis(-pixels.y * radiansPerPixel, right());
    // Without roll, not over the top (as update's look).
    if (!allowRoll && up().y >= 0.0f && (pitch * orientation * glm::vec3(0, 1, 0)).y < 0.0f)
        pitch = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
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
    if (orthographic) orthoHeight = 2.0f * std::max(radius, 0.01f) * 1.1f;
}

void axisViewFrame(AxisView view, glm::vec3& forward, glm::vec3& up) {
    up = glm::vec3(0, 1, 0);
    switch (view) {
    case AxisView::Front:
        forward = glm::vec3(0, 0, -1);
        break;
    case AxisView::Back:
        forward = glm::vec3(0, 0, 1);
        break;
    case AxisView::Right:
        forward = glm::vec3(-1, 0, 0);
        break;
    case AxisView::Left:
        forward = glm::vec3(1, 0, 0);
        break;
    case AxisView::Top: // -Z up on screen, as Blender's top view shows its +Y
        forward = glm::vec3(0, -1, 0);
        up = glm::vec3(0, 0, -1);
        break;
    case AxisView::Bottom:
        forward = glm::vec3(0, 1, 0);
        up = glm::vec3(0, 0, 1);
        break;
    }
}

void FlyCamera::viewFrom(AxisView view) {
    const glm::vec3 pivot = position + forward() * focusDistance;
    glm::vec3 f, u;
    axisViewFrame(view, f, u);
    orientation = glm::normalize(glm::quatLookAt(f, u));
    position = pivot - f * focusDistance;
}

void FlyCamera::setOrthographic(bool on, float fovYDegrees) {
    if (on == orthographic) return;
    const float tanHalf = std::tan(glm::radians(std::clamp(fovYDegrees, 1.0f, 179.0f)) * 0.5f);
    if (on) {
        orthoHeight = 2.0f * focusDistance * tanHalf;
    } else {
        // The distance at which the perspective view shows the orthographic height.
        const glm::vec3 pivot = position + forward() * focusDistance;
        focusDistance = std::max(orthoHeight / (2.0f * tanHalf), 0.01f);
        position = pivot - forward() * focusDistance;
    }
    orthographic = on;
}

std::optional<AxisView> FlyCamera::axisView() const {
    for (const AxisView view : {AxisView::Front, AxisView::Back, AxisView::Right, AxisView::Left,
                                AxisView::Top, AxisView::Bottom}) {
        glm::vec3 f, u;
        axisViewFrame(view, f, u);
        if (glm::length(forward() - f) < 1e-4f && glm::length(up() - u) < 1e-4f) return view;
    }
    return std::nullopt;
}

const char* axisViewName(AxisView view) {
    switch (view) {
    case AxisView::Front:
        return "Front";
    case AxisView::Back:
        return "Back";
    case AxisView::Right:
        return "Right";
    case AxisView::Left:
        return "Left";
    case AxisView::Top:
        return "Top";
    case AxisView::Bottom:
        break;
    }
    return "Bottom";
}

void FlyCamera::level() {
    const glm::vec3 f = forward();
    if (std::abs(f.y) > 0.9999f) return; // straight up or down: no horizon to level
    orientation = glm::normalize(glm::quatLookAt(f, glm::vec3(0, 1, 0)));
}

} // namespace rmsc::editor
