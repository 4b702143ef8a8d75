// The math of the viewer's move (G), rotate (R) and scale (S) gestures, without a window: given
// where the gesture started (the object's transform, the camera, the mouse) and where the mouse
// is now, the transform the object gets. Blender-like: moving follows the mouse in the plane
// through the object facing the camera (or along one axis as drawn on screen), rotating follows
// the angle the mouse turns around the object's centre on screen, scaling follows the mouse's
// distance from that centre. The viewer applies the result every frame and commits it as one
// undo step when the gesture is confirmed.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace rmsc::editor {

enum class GestureKind { Move, Rotate, Scale };

// Which axes X / Y / Z name: the world's, or the object's own (its world rotation applied).
enum class AxisSpace { World, Local };

// The camera as a gesture sees it: screen positions are viewport pixels, y down.
struct GestureView {
    glm::mat4 viewProjection{1.0f};
    glm::vec2 viewportSize{1.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}; // the viewing direction, world space
};

// Snapping steps (Ctrl held during a gesture or a gizmo drag), as in Blender's increment
// snapping: the movement in world units (each world axis of a free move, the length along a
// constraint axis), the angle turned, and the scale factor. The toolbar over the view sets them.
constexpr float kSnapDistance = 0.1f;      // a tenth of the ground grid's unit lines
constexpr float kSnapAngle = 0.261799388f; // 15 degrees, in radians
constexpr float kSnapScale = 0.1f;         // the factor in tenths: 1.1, 1.2, ...
struct SnapSteps {
    float distance = kSnapDistance; // world units, > 0
    float angle = kSnapAngle;       // radians, > 0
    float scale = kSnapScale;       // scale factor, > 0
};

struct TransformGesture {
    GestureKind kind = GestureKind::Move;
    int axis = -1; // -1: free move in the view plane / rotate about the view axis / uniform scale;
                   // 0, 1, 2: along / about x, y, z
    AxisSpace space = AxisSpace::World; // scaling always uses the object's own axes
    Transform start;                    // the object's transform (in its parent) at the start
    glm::mat4 parentWorld{1.0f};        // the parent's world matrix (identity for meshes)
    GestureView view;
    glm::vec2 startMouse{0.0f}; // viewport pixels, y down
    bool snap = false;          // held Ctrl: in steps of `steps`
    SnapSteps steps;
};

// `value` rounded to the nearest multiple of `step` (> 0).
float snapToStep(float value, float step);

// Below this distance from the pivot (pixels) the scale gesture measures movement against this
// distance instead, so starting with the mouse on the object does not make it jump.
constexpr float kMinScaleRadius = 40.0f;

// A world point on screen (viewport pixels, y down).
glm::vec2 worldToScreen(const GestureView& view, glm::vec3 world);
// The world point under screen point `screen` on the plane through `world` that faces the
// camera (the plane of constant view depth); for a perspective or an orthographic view.
glm::vec3 screenToWorldAtDepth(const GestureView& view, glm::vec2 screen, glm::vec3 world);
// The object's centre on screen at the start: what rotation and scaling turn around.
glm::vec2 gesturePivot(const TransformGesture& gesture);

// The angle (radians) the mouse turned around `pivot` going from `from` to `to`, positive when
// it turns counter-clockwise as seen on the screen (whose y axis points down); in (-pi, pi].
float screenAngle(glm::vec2 pivot, glm::vec2 from, glm::vec2 to);

// The scale factor for the mouse going from `from` to `to`: the ratio of their distances from
// `pivot` (1 + change / kMinScaleRadius near the pivot), never below 0.001.
float scaleFactor(glm::vec2 pivot, glm::vec2 from, glm::vec2 to);

// The world direction of axis `gesture.axis` (0, 1, 2) in the gesture's space, unit length.
glm::vec3 constraintAxis(const TransformGesture& gesture);

// The world-space axis a rotation turns about, pointing so that a positive angle turns the
// object the way the mouse turned on screen.
glm::vec3 rotationAxis(const TransformGesture& gesture);

// The rotation part of an affine matrix (its columns normalized; exact without shear).
glm::quat rotationOf(const glm::mat4& m);

// The three steps every gesture and gizmo drag ends in, on `start`, the transform of an object
// under a parent whose world matrix is `parentWorld`:
// moved by `worldDelta` (world units, seen from the parent's frame);
Transform movedTransform(const Transform& start, const glm::mat4& parentWorld,
                         glm::vec3 worldDelta);
// turned by `angle` radians about the unit world axis `worldAxis` through its own origin;
Transform turnedTransform(const Transform& start, const glm::mat4& parentWorld, glm::vec3 worldAxis,
                          float angle);
// scaled by `factor` uniformly (axis -1) or along its own axis 0, 1 or 2.
Transform scaledTransform(const Transform& start, int axis, float factor);

// The object's transform with the mouse at `mouse` (viewport pixels): start moved, rotated
// about its own origin, or scaled (uniformly, or along one of its own axes); with `snap`, the
// movement, angle or factor rounded to its step.
Transform gestureTransform(const TransformGesture& gesture, glm::vec2 mouse);

} // namespace rmsc::editor
