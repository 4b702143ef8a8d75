// The viewer's camera controller: a free-flying camera (position + orientation quaternion, so
// roll works) with a speed the wheel changes, orbiting around a point and framing a sphere.
// Converts to and from the scene's Camera (position / target / up). GL-free.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace rmsc::editor {

// What the user holds this frame. Movement axes are -1, 0 or 1.
struct FlyInput {
    float moveRight = 0.0f, moveUp = 0.0f, moveForward = 0.0f;
    float roll = 0.0f;    // +1 rolls clockwise (E), -1 counter-clockwise (Q)
    glm::vec2 look{0.0f}; // mouse movement in pixels while looking (right button)
    bool fast = false;    // Shift: 4x speed
};

class FlyCamera {
  public:
    glm::vec3 position{0.0f, 1.5f, 5.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f}; // camera space: -Z forward, +Y up
    float speed = 2.0f;                            // metres per second
    float focusDistance = 5.0f;                    // where `target` is put when converting back
    float radiansPerPixel = 0.004f;

    void setFromCamera(const Camera& camera);
    // `base` supplies fov and planes; position, target and up come from this controller.
    Camera toCamera(const Camera& base) const;

    glm::vec3 forward() const { return orientation * glm::vec3(0, 0, -1); }
    glm::vec3 right() const { return orientation * glm::vec3(1, 0, 0); }
    glm::vec3 up() const { return orientation * glm::vec3(0, 1, 0); }

    // Applies one frame of input; returns true when the camera moved.
    bool update(const FlyInput& input, float seconds);
    // Wheel notches: each multiplies the speed by 1.25 (up) or divides it.
    void changeSpeed(float notches);
    // Turns around `pivot` by a mouse movement in pixels (yaw about world up, pitch about the
    // camera's right axis), keeping the distance.
    void orbit(glm::vec3 pivot, glm::vec2 pixels);
    // Looks at a sphere from the current direction, at a distance that shows it whole.
    void frame(glm::vec3 center, float radius, float fovYDegrees);
};

} // namespace rmsc::editor
