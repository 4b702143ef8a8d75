// The viewer's camera controller: a free-flying camera (position + orientation quaternion, so
// roll works when allowed) with a speed the wheel changes, orbiting around a point, framing a
// sphere, the views along the axes, and a perspective or orthographic projection. The horizon
// stays level unless roll is allowed. Converts to and from the scene's Camera (position /
// target / up, projection). GL-free.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <optional>

namespace rmsc::editor {

// What the user holds this frame. Movement axes are -1, 0 or 1.
struct FlyInput {
    float moveRight = 0.0f, moveUp = 0.0f, moveForward = 0.0f;
    float roll = 0.0f;    // +1 rolls clockwise (E), -1 counter-clockwise (Q)
    glm::vec2 look{0.0f}; // mouse movement in pixels while looking (right button)
    bool fast = false;    // Shift: 4x speed
};

// The views along the world's axes (Blender's numpad views, the world's +Y up): from the front
// (looking down -Z), back, right (looking down -X), left, top (looking down, -Z up on screen)
// and bottom.
enum class AxisView { Front, Back, Right, Left, Top, Bottom };

class FlyCamera {
  public:
    glm::vec3 position{0.0f, 1.5f, 5.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f}; // camera space: -Z forward, +Y up
    float speed = 2.0f;                            // metres per second
    float focusDistance = 5.0f;                    // where `target` is put when converting back
    float radiansPerPixel = 0.004f;
    bool orthographic = false; // the projection (the scene camera's lens gives fov and planes)
    float orthoHeight = 4.0f;  // the height an orthographic view shows, world units
    bool allowRoll = false;    // Q / E roll; off, looking and orbiting keep the horizon level

    void setFromCamera(const Camera& camera);
    // `base` supplies fov and planes; position, target, up and the projection come from this
    // controller.
    Camera toCamera(const Camera& base) const;

    glm::vec3 forward() const { return orientation * glm::vec3(0, 0, -1); }
    glm::vec3 right() const { return orientation * glm::vec3(1, 0, 0); }
    glm::vec3 up() const { return orientation * glm::vec3(0, 1, 0); }

    // Applies one frame of input; returns true when the camera moved. Roll only when allowed;
    // without roll a look that would turn the camera over the top (its up below the horizon)
    // stops there.
    bool update(const FlyInput& input, float seconds);
    // Wheel notches: each multiplies the speed by 1.25 (up) or divides it.
    void changeSpeed(float notches);
    // Wheel notches in an orthographic view: each shows 1.25 times less (up) or more.
    void zoom(float notches);
    // Turns around `pivot` by a mouse movement in pixels (yaw about world up, pitch about the
    // camera's right axis), keeping the distance.
    void orbit(glm::vec3 pivot, glm::vec2 pixels);
    // Looks at a sphere from the current direction, at a distance that shows it whole (an
    // orthographic view also shows its height).
    void frame(glm::vec3 center, float radius, float fovYDegrees);
    // Looks along an axis at the point it looked at (focusDistance ahead), from as far.
    void viewFrom(AxisView view);
    // Switches the projection, keeping what the focus plane shows: the orthographic height is
    // the perspective view's at focusDistance, and back.
    void setOrthographic(bool on, float fovYDegrees);
    // Takes the roll out: the camera's right axis horizontal, looking where it looked (not when
    // it looks straight up or down).
    void level();
    // The view along an axis the camera looks along now (within 1e-4), if any.
    std::optional<AxisView> axisView() const;
};

// The direction a view along an axis looks and its up on screen.
void axisViewFrame(AxisView view, glm::vec3& forward, glm::vec3& up);
// "Front", "Back", "Right", "Left", "Top", "Bottom".
const char* axisViewName(AxisView view);

} // namespace rmsc::editor
