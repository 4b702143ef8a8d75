// The transform gizmo's model (editor/transform_gizmo.hpp): the ray maths it hit-tests with
// (ray to axis, to segment, to plane, to ring), the handle the mouse grabs, and what dragging
// each kind of handle does to the object, in world and local axes, under a parent, snapped, in
// a perspective and an orthographic view; a drag over many frames is one undo step.
#include "editor/document.hpp"
#include "editor/transform_gizmo.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

constexpr float kQuarterTurn = glm::radians(90.0f);

// A camera at (0, 0, 5) looking down -z at the origin, 90 degree vertical field of view, on a
// 200 x 200 viewport: the origin is at pixel (100, 100), and at depth 5 one pixel is
// 2 * 5 * tan(45 degrees) / 200 = 0.05 world units, so an arm of the gizmo at the origin is
// 90 * 0.05 = 4.5 units long.
GestureView frontView() {
    GestureView view;
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    const glm::mat4 look = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    view.viewProjection = projection * look;
    view.viewportSize = glm::vec2(200.0f);
    view.forward = glm::vec3(0, 0, -1);
    return view;
}

// The same camera with an orthographic projection 8 units high: 0.04 units a pixel at any
// depth.
GestureView orthographicView() {
    GestureView view = frontView();
    view.viewProjection = glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, 0.1f, 100.0f) *
                          glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    return view;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-4f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "actual y " << actual.y << " z " << actual.z;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "actual x " << actual.x << " z " << actual.z;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "actual x " << actual.x << " y " << actual.y;
}

GizmoFrame frameAt(const GestureView& view, const Transform& start = {},
                   const glm::mat4& parent = glm::mat4(1.0f), AxisSpace space = AxisSpace::World) {
    return gizmoFrame(view, gizmoCentre(start, parent), gizmoAxes(start, parent, space));
}

// Presses on `handle` at `from`, drags to `to`; the transform the object gets.
Transform drag(GizmoHandle handle, glm::vec2 from, glm::vec2 to, const Transform& start = {},
               const glm::mat4& parent = glm::mat4(1.0f), AxisSpace space = AxisSpace::World,
               bool snap = false, SnapSteps steps = {}) {
    const GestureView view = frontView();
    std::optional<GizmoDrag> d =
        beginGizmoDrag(handle, frameAt(view, start, parent, space), view, start, parent, from);
    EXPECT_TRUE(d.has_value());
    if (!d) return start;
    return dragGizmo(*d, to, snap, steps);
}

} // namespace

TEST(TransformGizmo, TheMouseRayThroughAPixel) {
    const ViewRay centre = viewRay(frontView(), {100, 100});
    expectNear(centre.origin, {0, 0, 4.9f}, 1e-3f); // on the near plane
    expectNear(centre.direction, {0, 0, -1});
    // 50 pixels right meets the plane z = 0 at x = 2.5.
    const ViewRay right = viewRay(frontView(), {150, 100});
    const std::optional<float> t = rayPlane(right, glm::vec3(0), glm::vec3(0, 0, 1));
    ASSERT_TRUE(t.has_value());
    expectNear(right.origin + right.direction * *t, {2.5f, 0, 0}, 1e-3f);
    // Orthographic: parallel rays, each from its own point.
    const ViewRay a = viewRay(orthographicView(), {100, 100});
    const ViewRay b = viewRay(orthographicView(), {150, 100});
    expectNear(a.direction, {0, 0, -1});
    expectNear(b.direction, {0, 0, -1});
    expectNear(b.origin - a.origin, {2.0f, 0, 0}, 1e-4f); // 50 px of 0.04
}

TEST(TransformGizmo, RayToLineSegmentPlaneAndRing) {
    ViewRay ray;
    ray.origin = glm::vec3(0, 0, 5);
    ray.direction = glm::vec3(0, 0, -1);
    // A line along y through (1, 0, 0): nearest at the line's origin, 5 along the ray, 1 apart.
    RayLineNearest n = nearestRayLine(ray, {1, 0, 0}, {0, 1, 0});
    EXPECT_NEAR(n.distance, 1.0f, 1e-6f);
    EXPECT_NEAR(n.rayT, 5.0f, 1e-6f);
    EXPECT_NEAR(n.lineS, 0.0f, 1e-6f);
    // A skew line along x at y = 2, z = 1: the ray passes it at t = 4, x = 0, 2 away.
    n = nearestRayLine(ray, {3, 2, 1}, {1, 0, 0});
    EXPECT_NEAR(n.distance, 2.0f, 1e-6f);
    EXPECT_NEAR(n.rayT, 4.0f, 1e-6f);
    EXPECT_NEAR(n.lineS, -3.0f, 1e-6f);
    // A line behind the ray's origin is measured from the origin.
    n = nearestRayLine(ray, {0, 1, 7}, {1, 0, 0});
    EXPECT_NEAR(n.rayT, 0.0f, 1e-6f);
    EXPECT_NEAR(n.distance, std::sqrt(5.0f), 1e-5f);
    // A segment: its nearest point, or an end.
    EXPECT_NEAR(raySegmentDistance(ray, {1, -1, 0}, {1, 1, 0}), 1.0f, 1e-6f);
    EXPECT_NEAR(raySegmentDistance(ray, {1, 2, 0}, {1, 4, 0}), std::sqrt(5.0f), 1e-5f);
    // A plane: where, and not behind the origin or along it.
    EXPECT_NEAR(*rayPlane(ray, {0, 0, 1}, {0, 0, 1}), 4.0f, 1e-6f);
    EXPECT_FALSE(rayPlane(ray, {0, 0, 6}, {0, 0, 1}).has_value());
    EXPECT_FALSE(rayPlane(ray, {0, 0, 0}, {1, 0, 0}).has_value());
    // A ring of radius 2 about the z axis: the ray down its axis is 2 from it everywhere; a ray
    // through a point of it meets it; one through (3, 0, 0) is 1 from it.
    EXPECT_NEAR(rayCircleDistance(ray, {0, 0, 0}, {0, 0, 1}, 2.0f), 2.0f, 2e-3f);
    ray.origin = glm::vec3(0, 2, 5);
    EXPECT_NEAR(rayCircleDistance(ray, {0, 0, 0}, {0, 0, 1}, 2.0f), 0.0f, 2e-3f);
    ray.origin = glm::vec3(3, 0, 5);
    EXPECT_NEAR(rayCircleDistance(ray, {0, 0, 0}, {0, 0, 1}, 2.0f), 1.0f, 2e-3f);
    // Seen edge on (the ray in the ring's plane): the distance to its nearer side.
    ray.origin = glm::vec3(0, 3, 5);
    EXPECT_NEAR(rayCircleDistance(ray, {0, 0, 0}, {1, 0, 0}, 2.0f), 1.0f, 2e-3f);
    // Angles about an axis: right-handed, in (-pi, pi].
    EXPECT_NEAR(angleAbout({0, 0, 1}, {1, 0, 0}, {0, 1, 0}), kQuarterTurn, 1e-6f);
    EXPECT_NEAR(angleAbout({0, 0, 1}, {1, 0, 5}, {0, -1, -3}), -kQuarterTurn, 1e-6f);
}

TEST(TransformGizmo, StaysTheSameSizeOnScreen) {
    const GizmoFrame near = gizmoFrame(frontView(), glm::vec3(0), glm::mat3(1.0f));
    EXPECT_NEAR(near.pixel, 0.05f, 1e-5f);
    EXPECT_NEAR(near.size, 4.5f, 1e-3f);
    // Twice as far (depth 10): twice the world size.
    const GizmoFrame far = gizmoFrame(frontView(), glm::vec3(0, 0, -5), glm::mat3(1.0f));
    EXPECT_NEAR(far.size, 9.0f, 2e-3f);
    // Orthographic: the same at any depth.
    for (const float z : {0.0f, -20.0f}) {
        const GizmoFrame ortho = gizmoFrame(orthographicView(), glm::vec3(0, 0, z), glm::mat3(1));
        EXPECT_NEAR(ortho.pixel, 0.04f, 1e-5f);
        expectNear(ortho.toViewer, {0, 0, 1});
    }
}

TEST(TransformGizmo, TheHandleUnderTheMouse) {
    const GestureView view = frontView();
    const GizmoFrame frame = frameAt(view);
    auto pick = [&](GizmoMode mode, glm::vec2 mouse) {
        return pickGizmoHandle(frame, view, mode, mouse);
    };
    using P = GizmoPart;
    EXPECT_EQ(pick(GizmoMode::Move, {100, 100}), (GizmoHandle{P::Screen, -1}));
    EXPECT_EQ(pick(GizmoMode::Move, {154, 100}), (GizmoHandle{P::Axis, 0}));
    EXPECT_EQ(pick(GizmoMode::Move, {155, 105}), (GizmoHandle{P::Axis, 0})); // within 7 px
    EXPECT_EQ(pick(GizmoMode::Move, {155, 109}), GizmoHandle{});             // 9 px off
    EXPECT_EQ(pick(GizmoMode::Move, {100, 46}), (GizmoHandle{P::Axis, 1}));
    EXPECT_EQ(pick(GizmoMode::Move, {138, 62}), (GizmoHandle{P::Plane, 2})); // the XY square
    EXPECT_EQ(pick(GizmoMode::Move, {200, 0}), GizmoHandle{});
    // The z arm points at the camera and the YZ and XZ squares are edge on: not drawn, not
    // grabbed.
    EXPECT_FALSE(gizmoHandleVisible(frame, {P::Axis, 2}));
    EXPECT_FALSE(gizmoHandleVisible(frame, {P::Plane, 0}));
    EXPECT_FALSE(gizmoHandleVisible(frame, {P::Plane, 1}));
    EXPECT_TRUE(gizmoHandleVisible(frame, {P::Plane, 2}));
    // Rotate: the z ring is a circle of 0.9 * 90 = 81 px; the x ring (in the YZ plane) is seen
    // as a vertical line through the centre, the y ring as a horizontal one (the rings cross
    // where they share a point, as at (181, 100)).
    EXPECT_EQ(pick(GizmoMode::Rotate, {100 + 70.15f, 100 - 40.5f}), (GizmoHandle{P::Ring, 2}));
    EXPECT_EQ(pick(GizmoMode::Rotate, {100 + 57.3f, 100 - 57.3f}), (GizmoHandle{P::Ring, 2}));
    EXPECT_EQ(pick(GizmoMode::Rotate, {100, 60}), (GizmoHandle{P::Ring, 0}));
    EXPECT_EQ(pick(GizmoMode::Rotate, {60, 100}), (GizmoHandle{P::Ring, 1}));
    EXPECT_EQ(pick(GizmoMode::Rotate, {130, 130}), GizmoHandle{});
    // Scale: the arms and the centre.
    EXPECT_EQ(pick(GizmoMode::Scale, {188, 100}), (GizmoHandle{P::ScaleAxis, 0}));
    EXPECT_EQ(pick(GizmoMode::Scale, {102, 101}), (GizmoHandle{P::ScaleUniform, -1}));
}

TEST(TransformGizmo, MoveAlongAnAxisInAPlaneOrFacingTheCamera) {
    using P = GizmoPart;
    // 20 px along the x arm at depth 5: 1 unit.
    expectNear(drag({P::Axis, 0}, {154, 100}, {174, 100}).position, {1, 0, 0}, 1e-3f);
    // Across the arm: nothing.
    expectNear(drag({P::Axis, 0}, {154, 100}, {154, 60}).position, {0, 0, 0}, 1e-3f);
    // The XY square: both.
    expectNear(drag({P::Plane, 2}, {138, 62}, {158, 42}).position, {1, 1, 0}, 1e-3f);
    // The centre: in the plane facing the camera.
    expectNear(drag({P::Screen, -1}, {100, 100}, {80, 120}).position, {-1, -1, 0}, 1e-3f);
    // The object's own axes: turned a quarter about z, its x arm points up the screen.
    Transform turned;
    turned.rotation = glm::angleAxis(kQuarterTurn, glm::vec3(0, 0, 1));
    const glm::vec2 upArm(100, 46);
    expectNear(
        drag({P::Axis, 0}, upArm, upArm - glm::vec2(0, 20), turned, glm::mat4(1), AxisSpace::Local)
            .position,
        {0, 1, 0}, 1e-3f);
    // Under a parent moved to (1, 0, 0) and scaled 2: the world movement, seen from the parent.
    const glm::mat4 parent =
        glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0)), glm::vec3(2.0f));
    const glm::vec2 arm(154 + 20, 100); // the gizmo stands at the parent's origin, x = 1
    expectNear(drag({P::Axis, 0}, arm, arm + glm::vec2(20, 0), {}, parent).position, {0.5f, 0, 0},
               1e-3f);
}

TEST(TransformGizmo, RotateByARingFollowsTheMouseAroundPastHalfATurn) {
    const GestureView view = frontView();
    const GizmoFrame frame = frameAt(view);
    std::optional<GizmoDrag> d =
        beginGizmoDrag({GizmoPart::Ring, 2}, frame, view, {}, glm::mat4(1.0f), {181, 100});
    ASSERT_TRUE(d.has_value());
    // Right of the centre to above it: a quarter turn about +z (x turns into y).
    Transform t = dragGizmo(*d, {100, 19}, false, {});
    expectNear(t.rotation * glm::vec3(1, 0, 0), {0, 1, 0}, 1e-3f);
    // On round to the left, then below: three quarters, not a quarter back.
    dragGizmo(*d, {19, 100}, false, {});
    t = dragGizmo(*d, {100, 181}, false, {});
    EXPECT_NEAR(d->angle, 3 * kQuarterTurn, 1e-3f);
    expectNear(t.rotation * glm::vec3(1, 0, 0), {0, -1, 0}, 1e-3f);
    // Snapped to 15 degrees: 50 becomes 45.
    std::optional<GizmoDrag> s =
        beginGizmoDrag({GizmoPart::Ring, 2}, frame, view, {}, glm::mat4(1.0f), {181, 100});
    const float a = glm::radians(50.0f);
    dragGizmo(*s, glm::vec2(100 + 81 * std::cos(a), 100 - 81 * std::sin(a)), true, {});
    EXPECT_NEAR(glm::degrees(s->angle), 45.0f, 1e-3f);
    EXPECT_EQ(gizmoDragLabel(*s), "Rotate about Z");
    EXPECT_EQ(gizmoDragReadout(*s), "45.0 deg");
}

TEST(TransformGizmo, RotateByARingSeenEdgeOnFollowsItsTangent) {
    // The x ring seen edge on (a vertical line on screen); grabbed above the centre, where a
    // positive turn about x moves the ring toward the camera, which is up the screen.
    const GestureView view = frontView();
    const GizmoFrame frame = frameAt(view);
    std::optional<GizmoDrag> d =
        beginGizmoDrag({GizmoPart::Ring, 0}, frame, view, {}, glm::mat4(1.0f), {100, 60});
    ASSERT_TRUE(d.has_value());
    dragGizmo(*d, {100, 60 - 81}, false, {}); // a ring radius up: one radian
    EXPECT_NEAR(d->angle, 1.0f, 1e-3f);
    dragGizmo(*d, {100, 60 + 40.5f}, false, {}); // half a radius down from the press
    EXPECT_NEAR(d->angle, -0.5f, 1e-3f);
}

TEST(TransformGizmo, ScaleAlongAnAxisOrUniformly) {
    using P = GizmoPart;
    Transform start;
    start.scale = glm::vec3(2.0f, 1.0f, 0.5f);
    // Grabbed at the arm's end (4.5 from the centre), dragged 45 px (2.25) farther: x 1.5.
    expectNear(drag({P::ScaleAxis, 0}, {190, 100}, {235, 100}, start).scale, {3, 1, 0.5f}, 1e-3f);
    // The centre: right grows, an arm's length doubles; down shrinks.
    expectNear(drag({P::ScaleUniform, -1}, {100, 100}, {145, 100}, start).scale, {3, 1.5f, 0.75f},
               1e-3f);
    expectNear(drag({P::ScaleUniform, -1}, {100, 100}, {100, 145}, start).scale, {1, 0.5f, 0.25f},
               1e-3f);
    // Never to zero or below.
    EXPECT_GT(drag({P::ScaleUniform, -1}, {100, 100}, {0, 200}, start).scale.x, 0.0f);
    // Snapped to tenths: 1.37 is 1.4.
    SnapSteps steps;
    expectNear(drag({P::ScaleUniform, -1}, {100, 100}, {133.3f, 100}, {}, glm::mat4(1),
                    AxisSpace::World, true, steps)
                   .scale,
               glm::vec3(1.4f), 1e-4f);
    // Scaling along a turned object's own axis changes its own x only.
    Transform turned;
    turned.rotation = glm::angleAxis(kQuarterTurn, glm::vec3(0, 0, 1));
    expectNear(
        drag({P::ScaleAxis, 0}, {100, 10}, {100, -35}, turned, glm::mat4(1), AxisSpace::Local)
            .scale,
        {1.5f, 1, 1}, 1e-3f);
}

TEST(TransformGizmo, CtrlSnapsMovesToTheStepSetInTheToolbar) {
    using P = GizmoPart;
    SnapSteps steps;
    steps.distance = 0.25f;
    // 1.13 along x (22.6 px) in steps of 0.25: 1.25.
    expectNear(drag({P::Axis, 0}, {154, 100}, {176.6f, 100}, {}, glm::mat4(1), AxisSpace::World,
                    true, steps)
                   .position,
               {1.25f, 0, 0}, 1e-4f);
    // In a plane, each of its axes: (1.13, 0.67) -> (1.25, 0.75).
    expectNear(drag({P::Plane, 2}, {138, 62}, {160.6f, 48.6f}, {}, glm::mat4(1), AxisSpace::World,
                    true, steps)
                   .position,
               {1.25f, 0.75f, 0}, 1e-4f);
    // An object off the grid moves by whole steps and stays off it.
    Transform off;
    off.position = glm::vec3(0.03f, 0, 0);
    const glm::vec2 arm(154 + 0.6f, 100); // the gizmo stands 0.6 px right
    expectNear(drag({P::Axis, 0}, arm, arm + glm::vec2(22.6f, 0), off, glm::mat4(1),
                    AxisSpace::World, true, steps)
                   .position,
               {1.28f, 0, 0}, 1e-4f);
}

TEST(TransformGizmo, ADragOfManyFramesIsOneUndoStep) {
    Scene scene = emptyScene();
    MeshInstance mesh;
    mesh.name = "pawn";
    scene.meshes.push_back(mesh);
    Document document(scene);
    const GestureView view = frontView();
    const Transform start = document.scene().meshes[0].transform;
    std::optional<GizmoDrag> d = beginGizmoDrag({GizmoPart::Axis, 0}, frameAt(view), view, start,
                                                glm::mat4(1.0f), {154, 100});
    ASSERT_TRUE(d.has_value());
    for (int frame = 1; frame <= 10; ++frame) {
        document.editScene().meshes[0].transform =
            dragGizmo(*d, glm::vec2(154 + 2 * frame, 100), false, {});
        document.markChanged(gizmoDragLabel(*d));
    }
    document.commit();
    EXPECT_EQ(document.historySize(), 1u);
    EXPECT_EQ(document.undoLabel(), "Move along X");
    expectNear(document.scene().meshes[0].transform.position, {1, 0, 0}, 1e-3f);
    document.undo();
    expectNear(document.scene().meshes[0].transform.position, {0, 0, 0});
}
