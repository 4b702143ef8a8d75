// Move, rotate and scale gestures on the selection (see gesture_controls.hpp).
#include "gesture_controls.hpp"

#include "editor/gesture_target.hpp"
#include "imgui_platform.hpp"
#include "render/frame.hpp"

#include <string>

namespace rmsc::app {
namespace {

std::string gestureLabel(const editor::TransformGesture& g) {
    const char* verb = g.kind == editor::GestureKind::Move     ? "Move"
                       : g.kind == editor::GestureKind::Rotate ? "Rotate"
                                                               : "Scale";
    if (g.axis < 0) return verb;
    const char* preposition = g.kind == editor::GestureKind::Rotate ? " about " : " along ";
    return std::string(verb) + preposition + char('X' + g.axis);
}

} // namespace

void startGesture(ViewportGesture& gesture, const InputState& input, EditorSession& session,
                  const Rect& viewport, bool worldAxes, const editor::SnapSteps& steps) {
    if (gesture.active || !keyboardFree(input)) return;
    editor::GestureKind kind;
    if (input.pressed(GLFW_KEY_G))
        kind = editor::GestureKind::Move;
    else if (input.pressed(GLFW_KEY_R))
        kind = editor::GestureKind::Rotate;
    else if (input.pressed(GLFW_KEY_S) && !input.buttons[1]) // S with the right button: fly back
        kind = editor::GestureKind::Scale;
    else
        return;
    const std::optional<editor::GestureTarget> target =
        editor::gestureTarget(session.document.scene(), session.document.selection, kind);
    if (!target) return; // nothing this gesture changes is selected (S then flies back as usual)
    session.document.commit();
    editor::TransformGesture& g = gesture.math;
    g = {};
    g.kind = kind;
    g.space = worldAxes ? editor::AxisSpace::World : editor::AxisSpace::Local;
    g.start = target->start;
    g.parentWorld = target->parentWorld;
    g.steps = steps;
    const FrameCamera frame =
        makeFrameCamera(session.viewCamera(), int(viewport.width), int(viewport.height));
    g.view.viewProjection = frame.viewProjection;
    g.view.viewportSize = glm::vec2(viewport.width, viewport.height);
    g.view.forward = frame.forward;
    g.startMouse = input.mouse - glm::vec2(viewport.x, viewport.y);
    gesture.lastMouse = g.startMouse;
    gesture.needsApply = false;
    gesture.active = true;
}

void updateGesture(ViewportGesture& gesture, const InputState& input, editor::Document& document,
                   const Rect& viewport) {
    if (!gesture.active) return;
    const editor::Selection& selection = document.selection;
    if (!editor::gestureTarget(document.scene(), selection, gesture.math.kind)) {
        gesture.active = false;
        return;
    }
    editor::TransformGesture& g = gesture.math;
    for (int axis = 0; axis < 3; ++axis) {
        if (input.pressed(GLFW_KEY_X + axis) && !input.ctrl()) {
            g.axis = g.axis == axis ? -1 : axis;
            gesture.needsApply = true; // apply again with the new constraint
        }
    }
    if (input.pressed(GLFW_KEY_ESCAPE) || input.clicked[1]) {
        document.revertPending();
        gesture.active = false;
        return;
    }
    if (input.ctrl() != g.snap) { // Ctrl held: snap to steps
        g.snap = input.ctrl();
        gesture.needsApply = true;
    }
    const glm::vec2 mouse = input.mouse - glm::vec2(viewport.x, viewport.y);
    if (mouse != gesture.lastMouse || gesture.needsApply) {
        gesture.lastMouse = mouse;
        gesture.needsApply = false;
        editor::setGestureTransform(document.editScene(), selection,
                                    editor::gestureTransform(g, mouse));
        document.markChanged(gestureLabel(g));
    }
    if (input.pressed(GLFW_KEY_ENTER) || input.clicked[0]) {
        document.commit();
        gesture.active = false;
    }
}

} // namespace rmsc::app
