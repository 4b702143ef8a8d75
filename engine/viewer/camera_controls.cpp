// Flying, looking, orbiting and framing (see camera_controls.hpp).
#include "camera_controls.hpp"

#include "editor/scene_edits.hpp"
#include "imgui_platform.hpp"

#include <imgui.h>

namespace rmsc::app {

void handleCamera(const InputState& input, const Rect& viewport, bool gestureActive,
                  CameraDrags& drags, EditorSession& session, float seconds) {
    const ImGuiIO& io = ImGui::GetIO();
    editor::FlyInput fly;
    if (keyboardFree(input) && !gestureActive) { // the gesture keys do not fly
        const bool w = input.held(GLFW_KEY_W), s = input.held(GLFW_KEY_S);
        const bool a = input.held(GLFW_KEY_A), d = input.held(GLFW_KEY_D);
        const bool space = input.held(GLFW_KEY_SPACE);
        fly.moveForward = float(w) - float(s);
        fly.moveRight = float(d) - float(a);
        fly.moveUp = float(space);
        // Left Shift alone flies down while the right button looks around (without it, Shift
        // is for Shift+click, which must not move the view); with a movement key it is "fast".
        if (input.held(GLFW_KEY_LEFT_SHIFT) && input.buttons[1] && !(w || s || a || d || space))
            fly.moveUp = -1.0f;
        else
            fly.fast = input.shift();
        fly.roll = float(input.held(GLFW_KEY_E)) - float(input.held(GLFW_KEY_Q));
    }
    const bool inViewport = viewport.contains(input.mouse) && !io.WantCaptureMouse;
    if (input.clicked[1] && inViewport && !gestureActive) drags.looking = true;
    if (!input.buttons[1]) drags.looking = false;
    if (drags.looking) fly.look = input.mouseDelta;
    if (input.wheel != 0.0f && inViewport) { // orthographic: zoom, else the fly speed
        if (session.camera.orthographic)
            session.camera.zoom(input.wheel);
        else
            session.camera.changeSpeed(input.wheel);
    }

    if (input.clicked[0] && input.alt() && inViewport && !gestureActive) drags.orbiting = true;
    if (!input.buttons[0]) drags.orbiting = false;
    if (drags.orbiting && input.mouseDelta != glm::vec2(0.0f)) {
        const std::optional<editor::Bounds> bounds =
            editor::selectionBounds(session.document.scene(), session.document.selection);
        const glm::vec3 pivot = bounds ? bounds->center
                                       : session.camera.position + session.camera.forward() *
                                                                       session.camera.focusDistance;
        session.camera.orbit(pivot, input.mouseDelta);
    }
    session.camera.update(fly, seconds);
}

void frameSelection(EditorSession& session) {
    std::optional<editor::Bounds> bounds =
        editor::selectionBounds(session.document.scene(), session.document.selection);
    if (!bounds)
        bounds = editor::selectionBounds(session.document.scene(), editor::Selection::sdf({}));
    if (!bounds) return;
    session.camera.frame(bounds->center, bounds->radius, session.sceneCamera.fovYDegrees);
}

std::string viewLabel(const editor::FlyCamera& camera) {
    const std::optional<editor::AxisView> along = camera.axisView();
    return std::string(along ? editor::axisViewName(*along) : "User") +
           (camera.orthographic ? " Ortho" : " Persp") + (camera.allowRoll ? ", roll" : "");
}

} // namespace rmsc::app
