// Move, rotate and scale gesture math (see transform_gesture.hpp).
#include "editor/transform_gesture.hpp"

#include "core/number_text.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {
namespace {

glm::vec3 startWorld(const TransformGesture& gesture) {
    return glm::vec3(gesture.parentWorld * glm::vec4(gesture.start.position, 1.0f));
}

// The world movement for a move gesture with the mouse at `mouse`.
glm::vec3 moveDelta(const TransformGesture& gesture, glm::vec2 mouse) {
    const glm::vec3 origin = startWorld(gesture);
    if (gesture.axis < 0)
        return screenToWorldAtDepth(gesture.view, mouse, origin) -
               screenToWorldAtDepth(gesture.view, gesture.startMouse, origin);
    // Along an axis: the mouse movement projected on the axis as drawn on screen, one unit of
    // the axis per its length in pixels.
    const glm::vec3 axis = constraintAxis(gesture);
    const glm::vec2 screenAxis =
        worldToScreen(gesture.view, origin + axis) - worldToScreen(gesture.view, origin);
    const float length2 = glm::dot(screenAxis, screenAxis);
    if (length2 < 1e-6f) return glm::vec3(0.0f); // the axis points at the camera
    const float along = glm::dot(mouse - gesture.startMouse, screenAxis) / length2;
    return axis * (gesture.snap ? snapToStep(along, gesture.steps.distance) : along);
}

// The world movement with snapping: a free move in steps along each world axis.
glm::vec3 snappedMoveDelta(const TransformGesture& gesture, glm::vec2 mouse) {
    glm::vec3 delta = moveDelta(gesture, mouse);
    if (gesture.snap && gesture.axis < 0)
        for (int i = 0; i < 3; ++i)
            delta[i] = snapToStep(delta[i], gesture.steps.distance);
    return delta;
}

} // namespace

glm::quat rotationOf(const glm::mat4& m) {
    glm::mat3 r(m);
    for (int c = 0; c < 3; ++c) {
        const float length = glm::length(r[c]);
        if (length > 0.0f) r[c] /= length;
    }
    return glm::normalize(glm::quat_cast(r));
}

// Normalized device coordinates back through the inverse view-projection matrix, at the depth
// `world` has: right for both projections (an orthographic one has w = 1 throughout).
glm::vec3 screenToWorldAtDepth(const GestureView& view, glm::vec2 screen, glm::vec3 world) {
    const glm::vec4 clip = view.viewProjection * glm::vec4(world, 1.0f);
    const float depth = clip.z / clip.w;
    const glm::vec2 ndc(screen.x / view.viewportSize.x * 2.0f - 1.0f,
                        1.0f - screen.y / view.viewportSize.y * 2.0f);
    const glm::vec4 back = glm::inverse(view.viewProjection) * glm::vec4(ndc, depth, 1.0f);
    return glm::vec3(back) / back.w;
}

float snapToStep(float value, float step) {
    if (!(step > 0.0f)) return value;
    return std::round(value / step) * step;
}

Transform movedTransform(const Transform& start, const glm::mat4& parentWorld,
                         glm::vec3 worldDelta) {
    Transform result = start;
    result.position = start.position + glm::inverse(glm::mat3(parentWorld)) * worldDelta;
    // A snapped step from a short decimal lands a float step off the short one (0.3 - 0.4 gives
    // -0.099999994): the short one, within 2 ulps, so panels and saved files show -0.1.
    for (int i = 0; i < 3; ++i)
        result.position[i] = nearestShortDecimal(result.position[i]);
    return result;
}

Transform turnedTransform(const Transform& start, const glm::mat4& parentWorld, glm::vec3 worldAxis,
                          float angle) {
    Transform result = start;
    const glm::quat worldTurn = glm::angleAxis(angle, worldAxis);
    // A world-space turn seen from the parent's frame, P^-1 * turn * P, applied after the
    // object's own rotation.
    const glm::quat parent = rotationOf(parentWorld);
    result.rotation = glm::normalize(glm::inverse(parent) * worldTurn * parent * start.rotation);
    return result;
}

Transform scaledTransform(const Transform& start, int axis, float factor) {
    Transform result = start;
    if (axis < 0)
        result.scale = start.scale * factor;
    else
        result.scale[axis] = start.scale[axis] * factor;
    for (int i = 0; i < 3; ++i) // as for a move
        result.scale[i] = nearestShortDecimal(result.scale[i]);
    return result;
}

glm::vec2 worldToScreen(const GestureView& view, glm::vec3 world) {
    const glm::vec4 clip = view.viewProjection * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / std::max(clip.w, 1e-4f);
    return glm::vec2((ndc.x * 0.5f + 0.5f) * view.viewportSize.x,
                     (0.5f - ndc.y * 0.5f) * view.viewportSize.y);
}

glm::vec2 gesturePivot(const TransformGesture& gesture) {
    return worldToScreen(gesture.view, startWorld(gesture));
}

float screenAngle(glm::vec2 pivot, glm::vec2 from, glm::vec2 to) {
    const glm::vec2 a = from - pivot, b = to - pivot;
    // atan2(cross, dot) is the signed angle from a to b; with y pointing down the cross product
    // is positive for a clockwise turn as seen, hence the minus sign.
    const float cross = a.x * b.y - a.y * b.x;
    return std::atan2(-cross, glm::dot(a, b));
}

float scaleFactor(glm::vec2 pivot, glm::vec2 from, glm::vec2 to) {
    const float startDistance = glm::length(from - pivot);
    const float distance = glm::length(to - pivot);
    return std::max(0.001f,
                    1.0f + (distance - startDistance) / std::max(startDistance, kMinScaleRadius));
}

glm::vec3 constraintAxis(const TransformGesture& gesture) {
    glm::vec3 axis(0.0f);
    axis[std::clamp(gesture.axis, 0, 2)] = 1.0f;
    if (gesture.space == AxisSpace::Local)
        axis = rotationOf(gesture.parentWorld) * gesture.start.rotation * axis;
    return glm::normalize(axis);
}

glm::vec3 rotationAxis(const TransformGesture& gesture) {
    // The view axis reversed points at the viewer: a counter-clockwise turn about it
    // (right-hand rule) is counter-clockwise on screen.
    const glm::vec3 towardViewer = -glm::normalize(gesture.view.forward);
    if (gesture.axis < 0) return towardViewer;
    const glm::vec3 axis = constraintAxis(gesture);
    // An axis pointing away from the viewer turns the other way on screen.
    return glm::dot(axis, towardViewer) < 0.0f ? -axis : axis;
}

Transform gestureTransform(const TransformGesture& gesture, glm::vec2 mouse) {
    switch (gesture.kind) {
    case GestureKind::Move:
        return movedTransform(gesture.start, gesture.parentWorld, snappedMoveDelta(gesture, mouse));
    case GestureKind::Rotate: {
        float angle = screenAngle(gesturePivot(gesture), gesture.startMouse, mouse);
        if (gesture.snap) angle = snapToStep(angle, gesture.steps.angle);
        return turnedTransform(gesture.start, gesture.parentWorld, rotationAxis(gesture), angle);
    }
    case GestureKind::Scale: {
        float factor = scaleFactor(gesturePivot(gesture), gesture.startMouse, mouse);
        if (gesture.snap)
            factor = std::max(gesture.steps.scale, snapToStep(factor, gesture.steps.scale));
        return scaledTransform(gesture.start, gesture.axis, factor);
    }
    }
    return gesture.start;
}

} // namespace rmsc::editor
