// Viewer gestures: keyboard shortcuts, the fly / orbit camera, picking by clicking in the
// viewport, and grab (G, then X / Y / Z to constrain to a world axis, like Blender) to move the
// selected object with the mouse (see viewer.hpp).
#include "app/viewer.hpp"

#include "editor/scene_edits.hpp"
#include "render/frame.hpp"

#include <imgui.h>

#include <cmath>

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
    if (input.ctrl() && !io.WantTextInput && !askPath) {
        if (input.pressed(GLFW_KEY_Z)) {
            grab.active = false;
            if (input.shift())
                document.redo();
            else
                document.undo();
        }
        if (input.pressed(GLFW_KEY_Y)) document.redo();
        if (input.pressed(GLFW_KEY_S)) {
            if (input.shift() || document.file().empty()) {
                askPath = true;
                pathPurpose = PathPurpose::SaveAs;
                pathBuffer = document.file().empty() ? "scene.json" : document.file().string();
            } else {
                save();
            }
        }
        if (input.pressed(GLFW_KEY_O)) {
            askPath = true;
            pathPurpose = PathPurpose::Open;
            pathBuffer = document.file().string();
        }
        if (input.pressed(GLFW_KEY_D))
            document.apply("Duplicate", [](Scene& scene, editor::Selection& selection) {
                selection = editor::duplicateSelected(scene, selection);
            });
    }
    if (!keyboardFree(input) || grab.active) return;
    if (input.pressed(GLFW_KEY_DELETE) && !document.selection.empty())
        document.apply("Delete", [](Scene& scene, editor::Selection& selection) {
            selection = editor::deleteSelected(scene, selection);
        });
    if (input.pressed(GLFW_KEY_F)) frameSelection();
}

void Viewer::handleCamera(float seconds) {
    const ImGuiIO& io = ImGui::GetIO();
    editor::FlyInput fly;
    if (keyboardFree(input)) {
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
        if (!grab.active) fly.roll = float(input.held(GLFW_KEY_E)) - float(input.held(GLFW_KEY_Q));
    }
    const bool inViewport = viewport.contains(input.mouse) && !io.WantCaptureMouse;
    if (input.clicked[1] && inViewport && !grab.active) looking = true;
    if (!input.buttons[1]) looking = false;
    if (looking) fly.look = input.mouseDelta;
    if (input.wheel != 0.0f && inViewport) camera.changeSpeed(input.wheel);

    if (input.clicked[0] && input.alt() && inViewport && !grab.active) orbiting = true;
    if (!input.buttons[0]) orbiting = false;
    if (orbiting && input.mouseDelta != glm::vec2(0.0f)) {
        const std::optional<editor::Bounds> bounds =
            editor::selectionBounds(document.scene(), document.selection);
        const glm::vec3 pivot =
            bounds ? bounds->center : camera.position + camera.forward() * camera.focusDistance;
        camera.orbit(pivot, input.mouseDelta);
    }
    camera.update(fly, seconds);
}

void Viewer::handleViewportMouse() {
    const ImGuiIO& io = ImGui::GetIO();
    if (grab.active || !input.clicked[0] || input.alt()) return;
    if (!viewport.contains(input.mouse) || io.WantCaptureMouse) return;
    pick(input.mouse);
}

void Viewer::frameSelection() {
    std::optional<editor::Bounds> bounds =
        editor::selectionBounds(document.scene(), document.selection);
    if (!bounds) bounds = editor::selectionBounds(document.scene(), editor::Selection::sdf({}));
    if (!bounds) return;
    camera.frame(bounds->center, bounds->radius, sceneCameraBase.fovYDegrees);
}

void Viewer::updateGrab() {
    const editor::Selection& selection = document.selection;
    const bool movable = selection.kind == editor::SelectionKind::Sdf ||
                         selection.kind == editor::SelectionKind::Mesh;
    if (!grab.active) {
        if (!input.pressed(GLFW_KEY_G) || !keyboardFree(input) || !movable ||
            !editor::selectionValid(document.scene(), selection))
            return;
        document.commit();
        grab.active = true;
        grab.axis = -1;
        grab.startMouse = input.mouse;
        grab.lastMoved = glm::vec2(0.0f);
        if (selection.kind == editor::SelectionKind::Sdf) {
            grab.startPosition =
                editor::findSdfNode(document.scene(), selection.sdfPath)->transform.position;
            grab.startWorld =
                glm::vec3(editor::sdfWorldMatrix(document.scene(), selection.sdfPath)[3]);
        } else {
            grab.startPosition =
                document.scene().meshes[std::size_t(selection.index)].transform.position;
            grab.startWorld = grab.startPosition;
        }
        return;
    }
    if (!editor::selectionValid(document.scene(), selection)) {
        grab.active = false;
        return;
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (input.pressed(GLFW_KEY_X + axis) && !input.ctrl()) {
            grab.axis = grab.axis == axis ? -1 : axis;
            grab.lastMoved = glm::vec2(-1e9f); // apply again with the new constraint
        }
    }
    if (input.pressed(GLFW_KEY_ESCAPE) || input.clicked[1]) {
        document.revertPending();
        grab.active = false;
        return;
    }

    const Camera view = viewCamera();
    const FrameCamera frame = makeFrameCamera(view, int(viewport.width), int(viewport.height));
    const glm::vec2 moved = input.mouse - grab.startMouse;
    glm::vec3 worldDelta(0.0f);
    if (grab.axis < 0) {
        // Free move in the view plane: one pixel is the world size of a pixel at the object.
        const float depth =
            std::max(glm::dot(grab.startWorld - view.position, frame.forward), 0.01f);
        const float worldPerPixel =
            2.0f * depth * std::tan(glm::radians(view.fovYDegrees) * 0.5f) / viewport.height;
        worldDelta =
            camera.right() * moved.x * worldPerPixel - camera.up() * moved.y * worldPerPixel;
    } else {
        // Along a world axis: the mouse movement projected on the axis as drawn on screen.
        glm::vec3 axis(0.0f);
        axis[grab.axis] = 1.0f;
        auto toScreen = [&](glm::vec3 p) {
            const glm::vec4 clip = frame.viewProjection * glm::vec4(p, 1.0f);
            const glm::vec2 ndc = glm::vec2(clip) / std::max(clip.w, 1e-4f);
            return glm::vec2((ndc.x * 0.5f + 0.5f) * viewport.width,
                             (0.5f - ndc.y * 0.5f) * viewport.height);
        };
        const glm::vec2 screenAxis = toScreen(grab.startWorld + axis) - toScreen(grab.startWorld);
        const float length2 = glm::dot(screenAxis, screenAxis);
        if (length2 > 1e-6f) worldDelta = axis * (glm::dot(moved, screenAxis) / length2);
    }
    if (moved != grab.lastMoved) {
        grab.lastMoved = moved;
        Scene& scene = document.editScene();
        if (selection.kind == editor::SelectionKind::Sdf) {
            const glm::mat3 parent(editor::sdfParentWorldMatrix(scene, selection.sdfPath));
            editor::findSdfNode(scene, selection.sdfPath)->transform.position =
                grab.startPosition + glm::inverse(parent) * worldDelta;
        } else {
            scene.meshes[std::size_t(selection.index)].transform.position =
                grab.startPosition + worldDelta;
        }
        document.markChanged(grab.axis < 0 ? "Move"
                                           : std::string("Move along ") + char('X' + grab.axis));
    }
    if (input.pressed(GLFW_KEY_ENTER) || input.clicked[0]) {
        document.commit();
        grab.active = false;
    }
}

} // namespace rmsc::app
