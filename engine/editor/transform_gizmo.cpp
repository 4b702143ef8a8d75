// The transform gizmo's geometry, hit tests and drags (see transform_gizmo.hpp).
#include "editor/transform_gizmo.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rmsc::editor {
namespace {

constexpr int kCircleChords = 96;

glm::vec3 rayPoint(const ViewRay& ray, float t) {
    return ray.origin + ray.direction * t;
}

// The distance from a ray to a point.
float rayPointDistance(const ViewRay& ray, glm::vec3 point) {
    const float t = std::max(0.0f, glm::dot(point - ray.origin, ray.direction));
    return glm::length(rayPoint(ray, t) - point);
}

// The two axes of the plane at right angles to axis `axis` (the next two, in order).
int planeAxisA(int axis) {
    return (axis + 1) % 3;
}
int planeAxisB(int axis) {
    return (axis + 2) % 3;
}

// The ray's hit of plane handle `axis`: its coordinates along the plane's two axes, in arm
// lengths from the centre.
std::optional<glm::vec2> planeHandleHit(const GizmoFrame& frame, int axis, const ViewRay& ray) {
    const std::optional<float> t = rayPlane(ray, frame.centre, frame.axes[axis]);
    if (!t) return std::nullopt;
    const glm::vec3 offset = rayPoint(ray, *t) - frame.centre;
    return glm::vec2(glm::dot(offset, frame.axes[planeAxisA(axis)]),
                     glm::dot(offset, frame.axes[planeAxisB(axis)])) /
           frame.size;
}

// The world size of a pixel at the depth of world point `p` (the same everywhere in an
// orthographic view; in a perspective one it grows with the depth).
float pixelAt(const GestureView& view, glm::vec3 p) {
    const glm::vec2 screen = worldToScreen(view, p);
    return std::max(glm::length(screenToWorldAtDepth(view, screen + glm::vec2(1.0f, 0.0f), p) -
                                screenToWorldAtDepth(view, screen, p)),
                    1e-9f);
}

// How far (pixels) the mouse ray passes from a handle; infinity when it cannot grab it.
float handlePixels(const GizmoFrame& frame, const GestureView& view, GizmoHandle handle,
                   const ViewRay& ray) {
    const float inf = std::numeric_limits<float>::infinity();
    if (!gizmoHandleVisible(frame, handle)) return inf;
    const glm::vec3 axis = handle.axis >= 0 ? frame.axes[handle.axis] : glm::vec3(0.0f);
    glm::vec3 nearest(0.0f);
    switch (handle.part) {
    case GizmoPart::Screen:
    case GizmoPart::ScaleUniform: {
        const float d = rayPointDistance(ray, frame.centre) - kGizmoCentreRadius * frame.size;
        return std::max(d, 0.0f) / frame.pixel;
    }
    case GizmoPart::Axis:
    case GizmoPart::ScaleAxis: {
        const float d =
            raySegmentDistance(ray, frame.centre + axis * (kGizmoAxisStart * frame.size),
                               frame.centre + axis * frame.size, &nearest);
        return d / pixelAt(view, nearest);
    }
    case GizmoPart::Plane: {
        const std::optional<glm::vec2> hit = planeHandleHit(frame, handle.axis, ray);
        const bool inside = hit && hit->x >= kGizmoPlaneNear && hit->x <= kGizmoPlaneFar &&
                            hit->y >= kGizmoPlaneNear && hit->y <= kGizmoPlaneFar;
        return inside ? 0.0f : inf;
    }
    case GizmoPart::Ring: {
        const float d =
            rayCircleDistance(ray, frame.centre, axis, kGizmoRingRadius * frame.size, &nearest);
        return d / pixelAt(view, nearest);
    }
    case GizmoPart::None:
        break;
    }
    return inf;
}

// The parameter along the drag's axis under the mouse ray: where the ray meets the plane
// through the axis that faces the camera most, projected on the axis (the ray's nearest
// approach to the axis when it runs along that plane).
float alongAxis(const GizmoDrag& drag, const ViewRay& ray) {
    const glm::vec3 axis = drag.frame.axes[drag.handle.axis];
    const glm::vec3 facing = drag.frame.toViewer - axis * glm::dot(drag.frame.toViewer, axis);
    if (glm::length(facing) > 1e-6f)
        if (const std::optional<float> t = rayPlane(ray, drag.frame.centre, glm::normalize(facing)))
            return glm::dot(rayPoint(ray, *t) - drag.frame.centre, axis);
    return nearestRayLine(ray, drag.frame.centre, axis).lineS;
}

// The plane a move handle slides in: its normal.
glm::vec3 slidePlaneNormal(const GizmoDrag& drag) {
    return drag.handle.part == GizmoPart::Plane ? drag.frame.axes[drag.handle.axis]
                                                : drag.frame.toViewer;
}

// Whether a ring is dragged by where the ray meets its plane (it faces the viewer enough), or
// by the mouse's movement along its tangent on screen (seen nearly edge on).
bool ringFacesViewer(const GizmoFrame& frame, int axis) {
    return std::abs(glm::dot(frame.toViewer, frame.axes[axis])) >= 0.25f;
}

// The angle of the mouse on a ring: where the ray meets the ring's plane, about its axis from
// the press's point.
std::optional<float> ringAngle(const GizmoDrag& drag, const ViewRay& ray) {
    const glm::vec3 axis = drag.frame.axes[drag.handle.axis];
    const std::optional<float> t = rayPlane(ray, drag.frame.centre, axis);
    if (!t) return std::nullopt;
    return angleAbout(axis, drag.startPoint - drag.frame.centre,
                      rayPoint(ray, *t) - drag.frame.centre);
}

// The angle for a ring seen edge on: the mouse's movement along the ring's tangent at the
// grabbed point as drawn on screen, a radian per ring radius in pixels.
float ringTangentAngle(const GizmoDrag& drag, glm::vec2 mouse) {
    const glm::vec3 axis = drag.frame.axes[drag.handle.axis];
    const glm::vec3 radial = drag.startPoint - drag.frame.centre;
    const glm::vec3 tangent = glm::cross(axis, radial); // the way a positive turn moves it
    const glm::vec2 a = worldToScreen(drag.view, drag.startPoint);
    const glm::vec2 b = worldToScreen(drag.view, drag.startPoint + tangent);
    glm::vec2 screenTangent = b - a;
    if (glm::length(screenTangent) < 1e-3f) {
        // The grabbed point's tangent points at the camera: turn as the R gesture does, with
        // the mouse around the centre on screen.
        const float turn =
            screenAngle(worldToScreen(drag.view, drag.frame.centre), drag.startMouse, mouse);
        return glm::dot(axis, drag.frame.toViewer) < 0.0f ? -turn : turn;
    }
    screenTangent = glm::normalize(screenTangent);
    return glm::dot(mouse - drag.startMouse, screenTangent) / (kGizmoRingRadius * kGizmoArmPixels);
}

const char* axisName(int axis) {
    static const char* const names[] = {"X", "Y", "Z"};
    return names[std::clamp(axis, 0, 2)];
}

} // namespace

ViewRay viewRay(const GestureView& view, glm::vec2 screen) {
    const glm::vec2 ndc(screen.x / view.viewportSize.x * 2.0f - 1.0f,
                        1.0f - screen.y / view.viewportSize.y * 2.0f);
    const glm::mat4 inverse = glm::inverse(view.viewProjection);
    const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 midPoint = inverse * glm::vec4(ndc, 0.0f, 1.0f);
    ViewRay ray;
    ray.origin = glm::vec3(nearPoint) / nearPoint.w;
    ray.direction = glm::normalize(glm::vec3(midPoint) / midPoint.w - ray.origin);
    return ray;
}

glm::vec3 gizmoCentre(const Transform& start, const glm::mat4& parentWorld) {
    return glm::vec3(parentWorld * glm::vec4(start.position, 1.0f));
}

glm::mat3 gizmoAxes(const Transform& start, const glm::mat4& parentWorld, AxisSpace space) {
    if (space == AxisSpace::World) return glm::mat3(1.0f);
    return glm::mat3_cast(rotationOf(parentWorld) * start.rotation);
}

GizmoFrame gizmoFrame(const GestureView& view, glm::vec3 centre, const glm::mat3& axes) {
    GizmoFrame frame;
    frame.centre = centre;
    for (int i = 0; i < 3; ++i)
        frame.axes[i] = glm::normalize(axes[i]);
    const glm::vec2 screen = worldToScreen(view, centre);
    frame.pixel =
        std::max(glm::length(screenToWorldAtDepth(view, screen + glm::vec2(1.0f, 0.0f), centre) -
                             screenToWorldAtDepth(view, screen, centre)),
                 1e-7f);
    frame.size = kGizmoArmPixels * frame.pixel;
    frame.toViewer = -viewRay(view, screen).direction;
    return frame;
}

std::vector<GizmoHandle> gizmoHandles(GizmoMode mode) {
    std::vector<GizmoHandle> handles;
    switch (mode) {
    case GizmoMode::Move:
        for (int axis = 0; axis < 3; ++axis)
            handles.push_back({GizmoPart::Plane, axis});
        for (int axis = 0; axis < 3; ++axis)
            handles.push_back({GizmoPart::Axis, axis});
        handles.push_back({GizmoPart::Screen, -1});
        break;
    case GizmoMode::Rotate:
        for (int axis = 0; axis < 3; ++axis)
            handles.push_back({GizmoPart::Ring, axis});
        break;
    case GizmoMode::Scale:
        for (int axis = 0; axis < 3; ++axis)
            handles.push_back({GizmoPart::ScaleAxis, axis});
        handles.push_back({GizmoPart::ScaleUniform, -1});
        break;
    }
    return handles;
}

bool gizmoHandleVisible(const GizmoFrame& frame, GizmoHandle handle) {
    switch (handle.part) {
    case GizmoPart::Axis:
    case GizmoPart::ScaleAxis:
        return glm::length(glm::cross(frame.axes[handle.axis], frame.toViewer)) >=
               kGizmoMinAxisSine;
    case GizmoPart::Plane:
        return std::abs(glm::dot(frame.axes[handle.axis], frame.toViewer)) >= kGizmoMinPlaneCosine;
    case GizmoPart::Screen:
    case GizmoPart::Ring:
    case GizmoPart::ScaleUniform:
        return true;
    case GizmoPart::None:
        break;
    }
    return false;
}

GizmoHandle pickGizmoHandle(const GizmoFrame& frame, const GestureView& view, GizmoMode mode,
                            glm::vec2 screen) {
    const ViewRay ray = viewRay(view, screen);
    GizmoHandle best;
    float bestPixels = kGizmoPickPixels;
    for (const GizmoHandle handle : gizmoHandles(mode)) {
        const float pixels = handlePixels(frame, view, handle, ray);
        if (pixels <= bestPixels) {
            bestPixels = pixels;
            best = handle;
        }
    }
    return best;
}

RayLineNearest nearestRayLine(const ViewRay& ray, glm::vec3 point, glm::vec3 direction) {
    // The nearest points of two lines (David Eberly, "Distance Between Two Lines, Rays and
    // Segments", Geometric Tools): with
    // w = o - p, b = d.u, the parameters solve t - b s = -d.w and b t - s = -u.w.
    const glm::vec3 w = ray.origin - point;
    const float b = glm::dot(ray.direction, direction);
    const float d = glm::dot(ray.direction, w);
    const float e = glm::dot(direction, w);
    const float denominator = 1.0f - b * b;
    RayLineNearest out;
    if (denominator > 1e-8f) {
        out.rayT = (b * e - d) / denominator;
        out.lineS = (e - b * d) / denominator;
    } else { // parallel: any pair at the same distance
        out.rayT = 0.0f;
        out.lineS = e;
    }
    if (out.rayT < 0.0f) { // behind the ray's origin: the line's point nearest the origin
        out.rayT = 0.0f;
        out.lineS = e;
    }
    out.distance = glm::length(rayPoint(ray, out.rayT) - (point + direction * out.lineS));
    return out;
}

float raySegmentDistance(const ViewRay& ray, glm::vec3 a, glm::vec3 b, glm::vec3* nearest) {
    const float length = glm::length(b - a);
    const glm::vec3 direction = length > 1e-12f ? (b - a) / length : glm::vec3(0.0f);
    const RayLineNearest n =
        length > 1e-12f ? nearestRayLine(ray, a, direction) : RayLineNearest{0.0f, 0.0f, 0.0f};
    if (length > 1e-12f && n.lineS >= 0.0f && n.lineS <= length) {
        if (nearest) *nearest = a + direction * n.lineS;
        return n.distance;
    }
    // Past an end: that end is the segment's nearest point to the ray (the distance from the
    // ray to the line's points grows monotonically away from the nearest pair).
    const glm::vec3 end = n.lineS > length ? b : a;
    if (nearest) *nearest = end;
    return rayPointDistance(ray, end);
}

std::optional<float> rayPlane(const ViewRay& ray, glm::vec3 point, glm::vec3 normal) {
    const float facing = glm::dot(ray.direction, normal);
    if (std::abs(facing) < 1e-6f) return std::nullopt;
    const float t = glm::dot(point - ray.origin, normal) / facing;
    if (t < 0.0f) return std::nullopt;
    return t;
}

float rayCircleDistance(const ViewRay& ray, glm::vec3 centre, glm::vec3 normal, float radius,
                        glm::vec3* nearest) {
    // Two unit vectors spanning the circle's plane.
    const glm::vec3 helper =
        std::abs(normal.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(normal, helper));
    const glm::vec3 v = glm::cross(normal, u);
    float best = std::numeric_limits<float>::infinity();
    glm::vec3 previous = centre + u * radius;
    for (int i = 1; i <= kCircleChords; ++i) {
        const float a = glm::two_pi<float>() * float(i) / float(kCircleChords);
        const glm::vec3 point = centre + (u * std::cos(a) + v * std::sin(a)) * radius;
        glm::vec3 onChord;
        const float d = raySegmentDistance(ray, previous, point, &onChord);
        if (d < best) {
            best = d;
            if (nearest) *nearest = onChord;
        }
        previous = point;
    }
    return best;
}

float angleAbout(glm::vec3 axis, glm::vec3 from, glm::vec3 to) {
    const glm::vec3 a = from - axis * glm::dot(from, axis);
    const glm::vec3 b = to - axis * glm::dot(to, axis);
    return std::atan2(glm::dot(glm::cross(a, b), axis), glm::dot(a, b));
}

std::optional<GizmoDrag> beginGizmoDrag(GizmoHandle handle, const GizmoFrame& frame,
                                        const GestureView& view, const Transform& start,
                                        const glm::mat4& parentWorld, glm::vec2 mouse) {
    if (handle.part == GizmoPart::None) return std::nullopt;
    GizmoDrag drag;
    drag.handle = handle;
    drag.frame = frame;
    drag.view = view;
    drag.start = start;
    drag.last = start;
    drag.parentWorld = parentWorld;
    drag.startMouse = mouse;
    const ViewRay ray = viewRay(view, mouse);
    switch (handle.part) {
    case GizmoPart::Axis:
    case GizmoPart::ScaleAxis:
        drag.startAlong = alongAxis(drag, ray);
        // Scaling measures against the distance from the centre: never from (nearly) zero.
        if (handle.part == GizmoPart::ScaleAxis && std::abs(drag.startAlong) < 0.1f * frame.size)
            drag.startAlong = std::copysign(0.1f * frame.size, drag.startAlong);
        break;
    case GizmoPart::Plane:
    case GizmoPart::Screen:
    case GizmoPart::Ring: {
        const glm::vec3 normal =
            handle.part == GizmoPart::Ring ? frame.axes[handle.axis] : slidePlaneNormal(drag);
        std::optional<float> t = rayPlane(ray, frame.centre, normal);
        if (handle.part == GizmoPart::Ring) {
            if (!t) t = glm::dot(frame.centre - ray.origin, ray.direction); // edge on
            // The grabbed point, put on the ring itself.
            glm::vec3 radial = rayPoint(ray, *t) - frame.centre;
            radial -= normal * glm::dot(radial, normal);
            if (glm::length(radial) < 1e-6f * frame.size) return std::nullopt;
            drag.startPoint =
                frame.centre + glm::normalize(radial) * (kGizmoRingRadius * frame.size);
        } else {
            if (!t) return std::nullopt;
            drag.startPoint = rayPoint(ray, *t);
        }
        break;
    }
    case GizmoPart::ScaleUniform:
    case GizmoPart::None:
        break;
    }
    return drag;
}

Transform dragGizmo(GizmoDrag& drag, glm::vec2 mouse, bool snap, const SnapSteps& steps) {
    const ViewRay ray = viewRay(drag.view, mouse);
    const GizmoFrame& frame = drag.frame;
    auto snapped = [&](float value, float step) { return snap ? snapToStep(value, step) : value; };
    switch (drag.handle.part) {
    case GizmoPart::Axis: {
        const glm::vec3 axis = frame.axes[drag.handle.axis];
        const float along = snapped(alongAxis(drag, ray) - drag.startAlong, steps.distance);
        drag.moved = axis * along;
        drag.last = movedTransform(drag.start, drag.parentWorld, drag.moved);
        break;
    }
    case GizmoPart::Plane:
    case GizmoPart::Screen: {
        const std::optional<float> t = rayPlane(ray, frame.centre, slidePlaneNormal(drag));
        if (!t) break; // looking past the plane: keep the last result
        glm::vec3 delta = rayPoint(ray, *t) - drag.startPoint;
        if (drag.handle.part == GizmoPart::Plane) {
            // In steps along the plane's two axes (the object's own or the world's).
            const glm::vec3 a = frame.axes[planeAxisA(drag.handle.axis)];
            const glm::vec3 b = frame.axes[planeAxisB(drag.handle.axis)];
            delta = a * snapped(glm::dot(delta, a), steps.distance) +
                    b * snapped(glm::dot(delta, b), steps.distance);
        } else if (snap) { // the screen plane: in steps along each world axis, as G does
            for (int i = 0; i < 3; ++i)
                delta[i] = snapToStep(delta[i], steps.distance);
        }
        drag.moved = delta;
        drag.last = movedTransform(drag.start, drag.parentWorld, delta);
        break;
    }
    case GizmoPart::Ring: {
        const int axisIndex = drag.handle.axis;
        if (ringFacesViewer(frame, axisIndex)) {
            const std::optional<float> angle = ringAngle(drag, ray);
            if (!angle) break;
            // Unwrapped: the change since the last position, taken the short way round.
            float change = *angle - drag.lastAngle;
            if (change > glm::pi<float>()) change -= glm::two_pi<float>();
            if (change < -glm::pi<float>()) change += glm::two_pi<float>();
            drag.turned += change;
            drag.lastAngle = *angle;
        } else {
            drag.turned = ringTangentAngle(drag, mouse);
        }
        drag.angle = snapped(drag.turned, steps.angle);
        drag.last =
            turnedTransform(drag.start, drag.parentWorld, frame.axes[axisIndex], drag.angle);
        break;
    }
    case GizmoPart::ScaleAxis: {
        float factor = std::max(0.001f, alongAxis(drag, ray) / drag.startAlong);
        if (snap) factor = std::max(steps.scale, snapToStep(factor, steps.scale));
        drag.factor = factor;
        drag.last = scaledTransform(drag.start, drag.handle.axis, factor);
        break;
    }
    case GizmoPart::ScaleUniform: {
        // Right or up grows, left or down shrinks: an arm's length on screen doubles the size.
        const glm::vec2 d = mouse - drag.startMouse;
        float factor = std::max(0.001f, 1.0f + (d.x - d.y) / kGizmoArmPixels);
        if (snap) factor = std::max(steps.scale, snapToStep(factor, steps.scale));
        drag.factor = factor;
        drag.last = scaledTransform(drag.start, -1, factor);
        break;
    }
    case GizmoPart::None:
        break;
    }
    return drag.last;
}

std::string gizmoDragLabel(const GizmoDrag& drag) {
    const int axis = drag.handle.axis;
    switch (drag.handle.part) {
    case GizmoPart::Axis:
        return std::string("Move along ") + axisName(axis);
    case GizmoPart::Plane:
        return std::string("Move in the ") + axisName(planeAxisA(axis)) +
               axisName(planeAxisB(axis)) + " plane";
    case GizmoPart::Screen:
        return "Move";
    case GizmoPart::Ring:
        return std::string("Rotate about ") + axisName(axis);
    case GizmoPart::ScaleAxis:
        return std::string("Scale along ") + axisName(axis);
    case GizmoPart::ScaleUniform:
        return "Scale";
    case GizmoPart::None:
        break;
    }
    return "";
}

std::string gizmoDragReadout(const GizmoDrag& drag) {
    char text[96];
    switch (drag.handle.part) {
    case GizmoPart::Axis:
    case GizmoPart::Plane:
    case GizmoPart::Screen:
        std::snprintf(text, sizeof text, "%.3f, %.3f, %.3f", drag.moved.x, drag.moved.y,
                      drag.moved.z);
        break;
    case GizmoPart::Ring:
        std::snprintf(text, sizeof text, "%.1f deg", double(glm::degrees(drag.angle)));
        break;
    case GizmoPart::ScaleAxis:
    case GizmoPart::ScaleUniform:
        std::snprintf(text, sizeof text, "x %.2f", double(drag.factor));
        break;
    case GizmoPart::None:
        text[0] = '\0';
        break;
    }
    return text;
}

} // namespace rmsc::editor
