// The transform gizmo over the selected object, without a window: its handles in world space
// (three axis arrows, three plane squares and a screen-plane centre to move; three axis rings
// to rotate; three axis boxes and a centre to scale), sized to stay the same on screen, hit by
// the mouse ray, and a drag of one handle turned into the object's new transform (in the
// world's or the object's own axes, snapped to steps while Ctrl is held). The viewer draws the
// handles (viewer/gizmo_controls.cpp) from the same geometry and commits a drag as one undo
// step. GL-free.
#pragma once

#include "editor/transform_gesture.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rmsc::editor {

enum class GizmoMode { Move, Rotate, Scale };

enum class GizmoPart {
    None,
    Axis,         // move along axis `axis`
    Plane,        // move in the plane at right angles to axis `axis`
    Screen,       // move in the plane facing the camera (the centre)
    Ring,         // rotate about axis `axis`
    ScaleAxis,    // scale along axis `axis`
    ScaleUniform, // scale uniformly (the centre)
};

struct GizmoHandle {
    GizmoPart part = GizmoPart::None;
    int axis = -1; // 0, 1, 2 for the parts with an axis
    bool operator==(const GizmoHandle&) const = default;
};

// A ray in world space: origin + t * direction, direction of unit length.
struct ViewRay {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
};

// The ray under screen point `screen` (viewport pixels, y down): from the near plane away from
// the camera, for a perspective or an orthographic view.
ViewRay viewRay(const GestureView& view, glm::vec2 screen);

// Where the gizmo stands and how big it is.
struct GizmoFrame {
    glm::vec3 centre{0.0f}; // the object's origin, world space
    glm::mat3 axes{1.0f};   // columns: the unit world directions of its x, y and z
    float size = 1.0f;      // an arm's length in world units (kGizmoArmPixels on screen)
    float pixel = 0.01f;    // the world size of one pixel at the centre
    glm::vec3 toViewer{0.0f, 0.0f, 1.0f}; // unit, from the centre toward the camera
};

// The geometry, in pixels on screen or in arm lengths, shared by the hit tests and the drawing.
constexpr float kGizmoArmPixels = 90.0f; // an arm's length on screen
constexpr float kGizmoPickPixels = 7.0f; // how near the mouse ray must pass a handle
constexpr float kGizmoAxisStart = 0.22f; // the arms start outside the centre handle
constexpr float kGizmoPlaneNear = 0.3f;  // a plane square spans [near, far] on its two axes
constexpr float kGizmoPlaneFar = 0.55f;
constexpr float kGizmoCentreRadius = 0.12f; // the centre handle (move, uniform scale)
constexpr float kGizmoRingRadius = 0.9f;
constexpr float kGizmoBoxHalf = 0.07f; // the scale handles' boxes at the arms' ends
// Below these a handle faces the camera too squarely (an arm seen end on, a plane edge on) to
// be drawn or dragged: the sine of the angle between it and the view direction.
constexpr float kGizmoMinAxisSine = 0.15f;
constexpr float kGizmoMinPlaneCosine = 0.2f;

// Where the gizmo of an object whose transform in its parent is `start` stands: its origin in
// the world; and its axes: the world's, or its own (its rotation and its parents' applied).
// Scale handles always take its own axes (a scale is along them).
glm::vec3 gizmoCentre(const Transform& start, const glm::mat4& parentWorld);
glm::mat3 gizmoAxes(const Transform& start, const glm::mat4& parentWorld, AxisSpace space);

// The gizmo of an object at world position `centre` with the world directions `axes`, seen
// in `view`: its arms kGizmoArmPixels long on screen whatever the distance.
GizmoFrame gizmoFrame(const GestureView& view, glm::vec3 centre, const glm::mat3& axes);

// The handles of a mode, in the order they are drawn (later ones on top).
std::vector<GizmoHandle> gizmoHandles(GizmoMode mode);
// Whether a handle is drawn and can be grabbed in this view (an arm pointing at the camera or a
// plane seen edge on cannot).
bool gizmoHandleVisible(const GizmoFrame& frame, GizmoHandle handle);
// The handle the mouse ray under `screen` grabs: the nearest within kGizmoPickPixels (the
// centre and the plane squares when the ray passes through them), else None. A handle's
// distance from the ray counts in pixels at the depth of its point nearest the ray.
GizmoHandle pickGizmoHandle(const GizmoFrame& frame, const GestureView& view, GizmoMode mode,
                            glm::vec2 screen);

// Ray maths (world units):
// the points of a ray and of the line through `point` along unit `direction` that are nearest
// each other: their parameters (the ray's clamped to >= 0) and their distance.
struct RayLineNearest {
    float rayT = 0.0f;
    float lineS = 0.0f;
    float distance = 0.0f;
};
RayLineNearest nearestRayLine(const ViewRay& ray, glm::vec3 point, glm::vec3 direction);
// The distance between a ray and the segment from `a` to `b`; `nearest` (when given) gets the
// segment's point nearest the ray.
float raySegmentDistance(const ViewRay& ray, glm::vec3 a, glm::vec3 b,
                         glm::vec3* nearest = nullptr);
// The ray's parameter where it meets the plane through `point` at right angles to unit
// `normal`; nullopt when it runs along the plane or meets it behind its origin.
std::optional<float> rayPlane(const ViewRay& ray, glm::vec3 point, glm::vec3 normal);
// The distance between a ray and the circle of `radius` about `centre` in the plane at right
// angles to unit `normal` (the circle taken as 96 chords: within 0.06 % of its radius);
// `nearest` (when given) gets the circle's point nearest the ray.
float rayCircleDistance(const ViewRay& ray, glm::vec3 centre, glm::vec3 normal, float radius,
                        glm::vec3* nearest = nullptr);
// The signed angle (radians) from `from` to `to` about unit `axis`, both projected into the
// plane at right angles to it; positive counter-clockwise looking down the axis at the plane.
float angleAbout(glm::vec3 axis, glm::vec3 from, glm::vec3 to);

// A drag of one handle, from the press to the release.
struct GizmoDrag {
    GizmoHandle handle;
    GizmoFrame frame;            // at the press
    GestureView view;            // at the press
    Transform start;             // the object's transform in its parent at the press
    glm::mat4 parentWorld{1.0f}; // the parent's world matrix
    glm::vec2 startMouse{0.0f};  // viewport pixels
    glm::vec3 startPoint{0.0f};  // where the press's ray met the handle's line or plane
    float startAlong = 0.0f;     // its parameter along the handle's axis (Axis, ScaleAxis)
    float turned = 0.0f;         // the angle turned so far (Ring), unwrapped past half a turn
    float lastAngle = 0.0f;      // the ring angle of the last mouse position
    Transform last;              // the result for the last mouse position the handle could use
    // What the drag did so far, for the overlay: the movement (world units), the angle
    // (radians) or the scale factor, snapped as applied.
    glm::vec3 moved{0.0f};
    float angle = 0.0f;
    float factor = 1.0f;
};

// Starts dragging `handle` with the mouse at `mouse`; nullopt when the press's ray does not
// meet the handle's line or plane. An arm is followed where the mouse ray meets the plane
// through it that faces the camera most, so moving the mouse across the arm on screen does
// not move along it.
std::optional<GizmoDrag> beginGizmoDrag(GizmoHandle handle, const GizmoFrame& frame,
                                        const GestureView& view, const Transform& start,
                                        const glm::mat4& parentWorld, glm::vec2 mouse);
// The object's transform with the mouse at `mouse`; with `snap` the movement (along each of
// the handle's axes), the angle or the factor in `steps`. Where the mouse ray misses the
// handle's plane (it looks past it), the last result stays.
Transform dragGizmo(GizmoDrag& drag, glm::vec2 mouse, bool snap, const SnapSteps& steps);

// The undo step's name of a drag: "Move along X", "Move in the XY plane", "Move", "Rotate
// about Z", "Scale along Y", "Scale".
std::string gizmoDragLabel(const GizmoDrag& drag);
// What the drag did so far, for the overlay: "0.300, 0.000, 0.000", "45.0 deg", "x 1.20".
std::string gizmoDragReadout(const GizmoDrag& drag);

} // namespace rmsc::editor
