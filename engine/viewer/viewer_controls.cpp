// Viewer gestures: keyboard shortcuts, the fly / orbit camera, picking by clicking in the
// viewport, and move / rotate / scale of the selected object with the mouse (G / R / S, then
// X / Y / Z to constrain to an axis, like Blender; the math is editor/transform_gesture.hpp).
// See viewer_app.hpp.
#include "viewer_app.hpp"
#include "viewport_pick.hpp"

#include "editor/scene_edits.hpp"
#include "render/frame.hpp"

#include <imgui.h>

#include <string>

namespace rmsc::app {
namespace {

bool keyboardFree(const InputState& input) {
    const ImGuiIO& io = ImGui::GetIO();
    return !io.WantCaptureKeyboard && !io.WantTextInput && !input.ctrl();
}

} // namespace

void Viewer::handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (input.pressed(GLFW_KEY_F12)) screenshotToDefaultFile();
    if (input.ctrl() && !io.WantTextInput && !dialogs.askPath) {
        if (input.pressed(GLFW_KEY_Z)) {
            gesture.active = false;
            if (input.shift())
                session.document.redo();
            else
                session.document.undo();
        }
        if (input.pressed(GLFW_KEY_Y)) session.document.redo();
        if (input.pressed(GLFW_KEY_S)) {
            if (input.shift() || session.document.file().empty()) {
                dialogs.askForPath(PathPurpose::SaveAs, session.document.file().empty()
                                                            ? "scene.json"
                                                            : session.document.file().string());
            } else {
                saveScene(session, files, messages, dialogs);
            }
        }
        if (input.pressed(GLFW_KEY_O)) {
            dialogs.askForPath(PathPurpose::Open, session.document.file().string());
        }
        if (input.pressed(GLFW_KEY_D))
            session.document.apply("Duplicate", [](Scene& scene, editor::Selection& selection) {
                selection = editor::duplicateSelected(scene, selection);
            });
    }
    if (!keyboardFree(input) || gesture.active) return;
    if (input.pressed(GLFW_KEY_DELETE) && !session.document.selection.empty())
        session.document.apply("Delete", [](Scene& scene, editor::Selection& selection) {
            selection = editor::deleteSelected(scene, selection);
        });
    if (input.pressed(GLFW_KEY_F)) frameSelection();
}

void Viewer::handleCamera(float seconds) {
    const ImGuiIO& io = ImGui::GetIO();
    editor::FlyInput fly;
    if (keyboardFree(input) && !gesture.active) { // the gesture keys do not fly
        const bool w = input.held(GLFW_KEY_W), s = input.held(GLFW_KEY_S);
        const bool a = input.held(GLFW_KEY_A), d = input.held(GLFW_KEY_D);
        const bool space = input.held(GLFW_KEY_SPACE);
        fly.moveForward = float(w) - float(s);
        fly.moveRight = float(d) - float(a);
        fly.moveUp = float(space);
        // Left Shift alone flies down; held with another movement key it means "fast".
        if (input.held(GLFW_KEY_LEFT_SHIFT) && !(w || s || a || d || space))
            fly.moveUp = -1.0f;
        else
            fly.fast = input.shift();
        fly.roll = float(input.held(GLFW_KEY_E)) - float(input.held(GLFW_KEY_Q));
    }
    const bool inViewport = layout.viewport.contains(input.mouse) && !io.WantCaptureMouse;
    if (input.clicked[1] && inViewport && !gesture.active) looking = true;
    if (!input.buttons[1]) looking = false;
    if (looking) fly.look = input.mouseDelta;
    if (input.wheel != 0.0f && inViewport) session.camera.changeSpeed(input.wheel);

    if (input.clicked[0] && input.alt() && inViewport && !gesture.active) orbiting = true;
    if (!input.buttons[0]) orbiting = false;
    if (orbiting && input.mouseDelta != glm::vec2(0.0f)) {
        const std::optional<editor::Bounds> bounds =
            editor::selectionBounds(session.document.scene(), session.document.selection);
        const glm::vec3 pivot = bounds ? bounds->center
                                       : session.camera.position + session.camera.forward() *
                                                                       session.camera.focusDistance;
        session.camera.orbit(pivot, input.mouseDelta);
    }
    session.camera.update(fly, seconds);
}

void Viewer::handleViewportMouse() {
    const ImGuiIO& io = ImGui::GetIO();
    if (gesture.active || !input.clicked[0] || input.alt()) return;
    if (!layout.viewport.contains(input.mouse) || io.WantCaptureMouse) return;
    if (const PreparedScene* prepared = gpu.newestScene())
        session.document.selection = pickAt(*prepared, session.document.scene(),
                                            session.viewCamera(), layout.viewport, input.mouse);
}

void Viewer::frameSelection() {
    std::optional<editor::Bounds> bounds =
        editor::selectionBounds(session.document.scene(), session.document.selection);
    if (!bounds)
        bounds = editor::selectionBounds(session.document.scene(), editor::Selection::sdf({}));
    if (!bounds) return;
    session.camera.frame(bounds->center, bounds->radius, session.sceneCamera.fovYDegrees);
}

namespace {

// The selected object's transform (an SDF node's is relative to its parent group), or nullptr.
Transform* selectedTransform(Scene& scene, const editor::Selection& selection) {
    if (selection.kind == editor::SelectionKind::Sdf) {
        SdfNode* node = editor::findSdfNode(scene, selection.sdfPath);
        return node ? &node->transform : nullptr;
    }
    if (selection.kind == editor::SelectionKind::Mesh && editor::selectionValid(scene, selection))
        return &scene.meshes[std::size_t(selection.index)].transform;
    return nullptr;
}

std::string gestureLabel(const editor::TransformGesture& g) {
    const char* verb = g.kind == editor::GestureKind::Move     ? "Move"
                       : g.kind == editor::GestureKind::Rotate ? "Rotate"
                                                               : "Scale";
    if (g.axis < 0) return verb;
    const char* preposition = g.kind == editor::GestureKind::Rotate ? " about " : " along ";
    return std::string(verb) + preposition + char('X' + g.axis);
}

} // namespace

void Viewer::startGesture() {
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
    const editor::Selection& selection = session.document.selection;
    const Transform* transform = selectedTransform(session.document.editScene(), selection);
    if (!transform) return; // nothing movable selected (S then flies back as usual)
    session.document.commit();
    editor::TransformGesture& g = gesture.math;
    g = {};
    g.kind = kind;
    g.space = inspector.worldCoordinates ? editor::AxisSpace::World : editor::AxisSpace::Local;
    g.start = *transform;
    if (selection.kind == editor::SelectionKind::Sdf)
        g.parentWorld = editor::sdfParentWorldMatrix(session.document.scene(), selection.sdfPath);
    const FrameCamera frame = makeFrameCamera(session.viewCamera(), int(layout.viewport.width),
                                              int(layout.viewport.height));
    g.view.viewProjection = frame.viewProjection;
    g.view.viewportSize = glm::vec2(layout.viewport.width, layout.viewport.height);
    g.view.forward = frame.forward;
    g.startMouse = input.mouse - glm::vec2(layout.viewport.x, layout.viewport.y);
    gesture.lastMouse = g.startMouse;
    gesture.needsApply = false;
    gesture.active = true;
}

void Viewer::updateGesture() {
    if (!gesture.active) return;
    const editor::Selection& selection = session.document.selection;
    if (!selectedTransform(session.document.editScene(), selection)) {
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
        session.document.revertPending();
        gesture.active = false;
        return;
    }
    const glm::vec2 mouse = input.mouse - glm::vec2(layout.viewport.x, layout.viewport.y);
    if (mouse != gesture.lastMouse || gesture.needsApply) {
        gesture.lastMouse = mouse;
        gesture.needsApply = false;
        *selectedTransform(session.document.editScene(), selection) =
            editor::gestureTransform(g, mouse);
        session.document.markChanged(gestureLabel(g));
    }
    if (input.pressed(GLFW_KEY_ENTER) || input.clicked[0]) {
        session.document.commit();
        gesture.active = false;
    }
}

} // namespace rmsc::app
