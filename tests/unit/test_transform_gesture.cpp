// The move / rotate / scale gestures of the editor (editor/transform_gesture.hpp): the
// transform produced for a given mouse movement and axis constraint, in world and local axes
// and under a rotated parent, and a gesture applied over many frames being one undo step that
// undo (or cancelling) restores.
#include "editor/document.hpp"
#include "editor/transform_gesture.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

constexpr float kQuarterTurn = glm::radians(90.0f);

// A camera at (0, 0, 5) looking down -z at the origin, 90 degree vertical field of view, on a
// 200 x 200 viewport: the origin is at pixel (100, 100), and at depth 5 one pixel is
// 2 * 5 * tan(45 degrees) / 200 = 0.05 world units.
GestureView frontView() {
    GestureView view;
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    const glm::mat4 look = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    view.viewProjection = projection * look;
    view.viewportSize = glm::vec2(200.0f);
    view.forward = glm::vec3(0, 0, -1);
    return view;
}

TransformGesture gesture(GestureKind kind, int axis, glm::vec2 startMouse) {
    TransformGesture g;
    g.kind = kind;
    g.axis = axis;
    g.view = frontView();
    g.startMouse = startMouse;
    return g;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-4f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "actual y " << actual.y << " z " << actual.z;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "actual x " << actual.x << " z " << actual.z;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "actual x " << actual.x << " y " << actual.y;
}

} // namespace

TEST(TransformGesture, PivotAndScreenAngle) {
    const TransformGesture g = gesture(GestureKind::Rotate, -1, {150, 100});
    const glm::vec2 pivot = gesturePivot(g);
    EXPECT_NEAR(pivot.x, 100.0f, 1e-3f);
    EXPECT_NEAR(pivot.y, 100.0f, 1e-3f);
    // Right of the centre to above it is a counter-clockwise quarter turn as seen.
    EXPECT_NEAR(screenAngle(pivot, {150, 100}, {100, 50}), kQuarterTurn, 1e-5f);
    EXPECT_NEAR(screenAngle(pivot, {150, 100}, {100, 150}), -kQuarterTurn, 1e-5f);
}

TEST(TransformGesture, FreeMoveFollowsTheMouseInTheViewPlane) {
    const TransformGesture g = gesture(GestureKind::Move, -1, {100, 100});
    expectNear(gestureTransform(g, {150, 100}).position, {2.5f, 0, 0}); // 50 px * 0.05
    expectNear(gestureTransform(g, {100, 60}).position, {0, 2.0f, 0});  // up the screen is +y
}

TEST(TransformGesture, MoveAlongAnAxisUsesOnlyTheMovementAlongIt) {
    TransformGesture g = gesture(GestureKind::Move, 1, {100, 100});
    expectNear(gestureTransform(g, {150, 100}).position, glm::vec3(0)); // across the y axis
    const glm::vec3 up = gestureTransform(g, {130, 60}).position;
    expectNear(up, {0, 2.0f, 0}, 1e-3f);
    // The object's own x axis, turned to world y by its rotation.
    g.axis = 0;
    g.space = AxisSpace::Local;
    g.start.rotation = glm::angleAxis(kQuarterTurn, glm::vec3(0, 0, 1));
    expectNear(gestureTransform(g, {130, 60}).position, {0, 2.0f, 0}, 1e-3f);
    g.space = AxisSpace::World;
    expectNear(gestureTransform(g, {130, 60}).position, {1.5f, 0, 0}, 1e-3f);
}

TEST(TransformGesture, RotateAboutTheViewAxisFollowsTheMouse) {
    const TransformGesture g = gesture(GestureKind::Rotate, -1, {150, 100});
    const Transform turned = gestureTransform(g, {100, 50}); // a quarter turn counter-clockwise
    expectNear(turned.rotation * glm::vec3(1, 0, 0), {0, 1, 0});
    expectNear(turned.rotation * glm::vec3(0, 0, 1), {0, 0, 1});
    expectNear(turned.position, glm::vec3(0));
    expectNear(turned.scale, glm::vec3(1));
    // No movement, no turn.
    const Transform still = gestureTransform(g, {150, 100});
    expectNear(still.rotation * glm::vec3(1, 0, 0), {1, 0, 0});
}

TEST(TransformGesture, RotateAboutAWorldOrALocalAxis) {
    // The object is already turned a quarter about z: its own x axis is the world's y.
    TransformGesture g = gesture(GestureKind::Rotate, 0, {150, 100});
    g.start.rotation = glm::angleAxis(kQuarterTurn, glm::vec3(0, 0, 1));
    g.space = AxisSpace::Local;
    expectNear(rotationAxis(g), {0, 1, 0});
    const Transform local = gestureTransform(g, {100, 50});
    // Turning about its own x keeps its own x where it was.
    expectNear(local.rotation * glm::vec3(1, 0, 0), {0, 1, 0});
    expectNear(local.rotation * glm::vec3(0, 1, 0), {0, 0, 1}, 1e-4f);
    g.space = AxisSpace::World;
    expectNear(rotationAxis(g), {1, 0, 0});
    const Transform world = gestureTransform(g, {100, 50});
    // The turn (new rotation after the old one undone) is about world x.
    const glm::quat turn = world.rotation * glm::inverse(g.start.rotation);
    expectNear(turn * glm::vec3(1, 0, 0), {1, 0, 0});
    expectNear(turn * glm::vec3(0, 1, 0), {0, 0, 1});
}

TEST(TransformGesture, AxisPointingAwayTurnsTheOtherWaySoTheScreenTurnMatches) {
    // Camera behind the object looking down +z: a counter-clockwise turn on screen is a turn
    // about -z.
    TransformGesture g = gesture(GestureKind::Rotate, 2, {150, 100});
    g.view.viewProjection = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f) *
                            glm::lookAt(glm::vec3(0, 0, -5), glm::vec3(0), glm::vec3(0, 1, 0));
    g.view.forward = glm::vec3(0, 0, 1);
    expectNear(rotationAxis(g), {0, 0, -1});
}

TEST(TransformGesture, RotateUnderARotatedParentTurnsInWorldSpace) {
    // Parent turned a quarter about y; a world turn about the view axis (z) must appear as that
    // turn once the parent's rotation is applied.
    TransformGesture g = gesture(GestureKind::Rotate, -1, {150, 100});
    const glm::quat parent = glm::angleAxis(kQuarterTurn, glm::vec3(0, 1, 0));
    g.parentWorld = glm::mat4_cast(parent);
    const Transform turned = gestureTransform(g, {100, 50});
    const glm::quat worldRotation = parent * turned.rotation;
    const glm::quat expected = glm::angleAxis(kQuarterTurn, glm::vec3(0, 0, 1)) * parent;
    for (glm::vec3 v : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)})
        expectNear(worldRotation * v, expected * v);
}

TEST(TransformGesture, ScaleUniformlyOrAlongOneAxis) {
    TransformGesture g = gesture(GestureKind::Scale, -1, {150, 100}); // 50 px from the centre
    g.start.scale = glm::vec3(2.0f, 1.0f, 0.5f);
    expectNear(gestureTransform(g, {175, 100}).scale, {3.0f, 1.5f, 0.75f}); // 75 / 50
    expectNear(gestureTransform(g, {100, 75}).scale, {1.0f, 0.5f, 0.25f});  // 25 / 50
    g.axis = 1;
    expectNear(gestureTransform(g, {175, 100}).scale, {2.0f, 1.5f, 0.5f});
    // Back onto the centre: tiny, never zero or negative.
    EXPECT_GT(gestureTransform(g, {100, 100}).scale.y, 0.0f);
    EXPECT_LT(gestureTransform(g, {100, 100}).scale.y, 0.01f);
    expectNear(gestureTransform(g, {175, 100}).position, glm::vec3(0));
}

TEST(TransformGesture, CtrlSnapsMovesToGridStepsAnglesTo15DegreesAndScalesToTenths) {
    // Free move: 22.6 px right and 13.4 px up at 0.05 units a pixel is (1.13, 0.67), in steps
    // of 0.1 (the movements avoid half steps, which float rounding may put either way).
    TransformGesture move = gesture(GestureKind::Move, -1, {100, 100});
    move.snap = true;
    expectNear(gestureTransform(move, {122.6f, 86.6f}).position, {1.1f, 0.7f, 0}, 1e-3f);
    expectNear(gestureTransform(move, {100.8f, 100}).position, glm::vec3(0)); // 0.04: not yet
    move.snap = false;
    expectNear(gestureTransform(move, {122.6f, 86.6f}).position, {1.13f, 0.67f, 0}, 1e-3f);
    // Along an axis: the length along it, with the object off the grid staying off it.
    TransformGesture along = gesture(GestureKind::Move, 0, {100, 100});
    along.snap = true;
    along.start.position = glm::vec3(0.03f, 0, 0);
    expectNear(gestureTransform(along, {126.4f, 140}).position, {1.33f, 0, 0}, 1e-3f); // 1.32
    along.snap = false;
    expectNear(gestureTransform(along, {126.4f, 140}).position, {1.35f, 0, 0}, 2e-3f);
    // Rotation: a turn of 50 degrees on screen snaps to 45.
    TransformGesture turn = gesture(GestureKind::Rotate, -1, {150, 100});
    turn.snap = true;
    const float a = glm::radians(50.0f);
    const Transform turned =
        gestureTransform(turn, glm::vec2(100 + 50 * std::cos(a), 100 - 50 * std::sin(a)));
    expectNear(turned.rotation * glm::vec3(1, 0, 0),
               {std::cos(glm::radians(45.0f)), std::sin(glm::radians(45.0f)), 0});
    // Scale: 1.37 times snaps to 1.4, and never to 0.
    TransformGesture scale = gesture(GestureKind::Scale, -1, {150, 100});
    scale.snap = true;
    expectNear(gestureTransform(scale, {168.5f, 100}).scale, glm::vec3(1.4f));
    expectNear(gestureTransform(scale, {100, 100}).scale, glm::vec3(kSnapScale));
    EXPECT_FLOAT_EQ(snapToStep(0.26f, 0.1f), 0.3f);
    EXPECT_FLOAT_EQ(snapToStep(-0.26f, 0.1f), -0.3f);
}

// A snapped step from a short decimal is that short decimal, not the float beside it: 0.3 moved
// by -0.4 is -0.1 (float arithmetic gives -0.099999994), which panels and saved files show.
TEST(TransformGesture, SnappedStepsLandOnShortDecimals) {
    TransformGesture along = gesture(GestureKind::Move, 1, {100, 100});
    along.snap = true;
    along.start.position = glm::vec3(0, 0.3f, 0);
    ASSERT_EQ(0.3f + -0.4f, -0.099999994f);                           // what the sum alone gives
    EXPECT_EQ(gestureTransform(along, {100, 108}).position.y, -0.1f); // 8 px down: -0.4
    TransformGesture scale = gesture(GestureKind::Scale, 0, {150, 100});
    scale.snap = true;
    scale.start.scale = glm::vec3(0.7f);
    ASSERT_NE(0.7f * 1.4f, 0.98f);                                 // 0.97999996
    EXPECT_EQ(gestureTransform(scale, {170, 100}).scale.x, 0.98f); // 1.4 times
}

TEST(TransformGesture, ScaleStartedOnTheCentreDoesNotJump) {
    const TransformGesture g = gesture(GestureKind::Scale, -1, {101, 100}); // 1 px away
    expectNear(gestureTransform(g, {101, 100}).scale, glm::vec3(1.0f));
    // Measured against kMinScaleRadius: 20 px farther is 1 + 20 / 40.
    expectNear(gestureTransform(g, {121, 100}).scale, glm::vec3(1.5f));
}

TEST(TransformGesture, ManyFramesAreOneUndoStepAndUndoOrCancelRestores) {
    Scene scene = emptyScene();
    MeshInstance mesh;
    mesh.name = "pawn";
    mesh.transform.position = glm::vec3(1, 2, 3);
    scene.meshes.push_back(mesh);
    Document document(scene);
    TransformGesture g = gesture(GestureKind::Rotate, 1, {0, 0});
    g.start = document.scene().meshes[0].transform;
    const glm::vec2 pivot = gesturePivot(g); // where the mesh's origin is on screen
    g.startMouse = pivot + glm::vec2(50, 0);
    for (int frame = 1; frame <= 12; ++frame) { // the mouse circles a quarter turn in 12 frames
        const float angle = kQuarterTurn * float(frame) / 12.0f;
        const glm::vec2 mouse = pivot + 50.0f * glm::vec2(std::cos(angle), -std::sin(angle));
        document.editScene().meshes[0].transform = gestureTransform(g, mouse);
        document.markChanged("Rotate about Y");
    }
    document.commit();
    EXPECT_EQ(document.historySize(), 1u);
    EXPECT_EQ(document.undoLabel(), "Rotate about Y");
    const glm::quat done = document.scene().meshes[0].transform.rotation;
    EXPECT_LT(std::abs(done.w), 0.9f); // turned
    expectNear(document.scene().meshes[0].transform.position, {1, 2, 3});
    ASSERT_TRUE(document.undo());
    EXPECT_EQ(document.scene().meshes[0].transform.rotation, glm::quat(1, 0, 0, 0));
    ASSERT_TRUE(document.redo());
    EXPECT_EQ(document.scene().meshes[0].transform.rotation, done);

    // A cancelled gesture (Esc) leaves no step and the transform as it was.
    g.kind = GestureKind::Scale;
    g.start = document.scene().meshes[0].transform;
    document.editScene().meshes[0].transform = gestureTransform(g, pivot + glm::vec2(100, 0));
    document.markChanged("Scale");
    EXPECT_FLOAT_EQ(document.scene().meshes[0].transform.scale.y, 2.0f);
    document.revertPending();
    EXPECT_EQ(document.historySize(), 1u);
    EXPECT_FLOAT_EQ(document.scene().meshes[0].transform.scale.y, 1.0f);
}
