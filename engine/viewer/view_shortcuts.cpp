// The view's camera keys and what they do (see view_shortcuts.hpp).
#include "view_shortcuts.hpp"

#include "imgui_platform.hpp"

#include <imgui.h>

#include <string>

namespace rmsc::app {
namespace {

constexpr ViewShortcut kShortcuts[] = {
    {GLFW_KEY_KP_1, false, "Numpad 1", "look from the front (down -Z)", {ViewAction::FromFront}},
    {GLFW_KEY_KP_1, true, "Ctrl+Numpad 1", "look from the back (down +Z)", {ViewAction::FromBack}},
    {GLFW_KEY_KP_3, false, "Numpad 3", "look from the right (down -X)", {ViewAction::FromRight}},
    {GLFW_KEY_KP_3, true, "Ctrl+Numpad 3", "look from the left (down +X)", {ViewAction::FromLeft}},
    {GLFW_KEY_KP_7, false, "Numpad 7", "look from the top (down -Y)", {ViewAction::FromTop}},
    {GLFW_KEY_KP_7,
     true,
     "Ctrl+Numpad 7",
     "look from the bottom (up +Y)",
     {ViewAction::FromBottom}},
    {GLFW_KEY_KP_5,
     false,
     "Numpad 5",
     "switch between perspective and orthographic",
     {ViewAction::ToggleOrthographic}},
    {GLFW_KEY_1, true, "Ctrl+1", "keep the view as bookmark 1", {ViewAction::StoreBookmark, 1}},
    {GLFW_KEY_2, true, "Ctrl+2", "keep the view as bookmark 2", {ViewAction::StoreBookmark, 2}},
    {GLFW_KEY_3, true, "Ctrl+3", "keep the view as bookmark 3", {ViewAction::StoreBookmark, 3}},
    {GLFW_KEY_4, true, "Ctrl+4", "keep the view as bookmark 4", {ViewAction::StoreBookmark, 4}},
    {GLFW_KEY_5, true, "Ctrl+5", "keep the view as bookmark 5", {ViewAction::StoreBookmark, 5}},
    {GLFW_KEY_6, true, "Ctrl+6", "keep the view as bookmark 6", {ViewAction::StoreBookmark, 6}},
    {GLFW_KEY_7, true, "Ctrl+7", "keep the view as bookmark 7", {ViewAction::StoreBookmark, 7}},
    {GLFW_KEY_8, true, "Ctrl+8", "keep the view as bookmark 8", {ViewAction::StoreBookmark, 8}},
    {GLFW_KEY_9, true, "Ctrl+9", "keep the view as bookmark 9", {ViewAction::StoreBookmark, 9}},
    {GLFW_KEY_1, false, "1", "go to bookmark 1", {ViewAction::RecallBookmark, 1}},
    {GLFW_KEY_2, false, "2", "go to bookmark 2", {ViewAction::RecallBookmark, 2}},
    {GLFW_KEY_3, false, "3", "go to bookmark 3", {ViewAction::RecallBookmark, 3}},
    {GLFW_KEY_4, false, "4", "go to bookmark 4", {ViewAction::RecallBookmark, 4}},
    {GLFW_KEY_5, false, "5", "go to bookmark 5", {ViewAction::RecallBookmark, 5}},
    {GLFW_KEY_6, false, "6", "go to bookmark 6", {ViewAction::RecallBookmark, 6}},
    {GLFW_KEY_7, false, "7", "go to bookmark 7", {ViewAction::RecallBookmark, 7}},
    {GLFW_KEY_8, false, "8", "go to bookmark 8", {ViewAction::RecallBookmark, 8}},
    {GLFW_KEY_9, false, "9", "go to bookmark 9", {ViewAction::RecallBookmark, 9}},
};

editor::AxisView axisViewOf(ViewAction action) {
    switch (action) {
    case ViewAction::FromBack:
        return editor::AxisView::Back;
    case ViewAction::FromRight:
        return editor::AxisView::Right;
    case ViewAction::FromLeft:
        return editor::AxisView::Left;
    case ViewAction::FromTop:
        return editor::AxisView::Top;
    case ViewAction::FromBottom:
        return editor::AxisView::Bottom;
    default:
        return editor::AxisView::Front;
    }
}

} // namespace

std::span<const ViewShortcut> viewShortcuts() {
    return kShortcuts;
}

const char* viewShortcutKeys(const ViewRequest& request) {
    for (const ViewShortcut& s : kShortcuts)
        if (s.request.action == request.action && s.request.slot == request.slot) return s.keys;
    return nullptr;
}

void handleViewShortcuts(const InputState& input, bool busy, EditorSession& session,
                         Messages& messages) {
    const ImGuiIO& io = ImGui::GetIO();
    if (busy || io.WantCaptureKeyboard || io.WantTextInput) return;
    for (const ViewShortcut& s : kShortcuts)
        if (input.pressed(s.key) && input.ctrl() == s.ctrl && !input.alt())
            applyViewRequest(session, s.request, messages);
}

void applyViewRequest(EditorSession& session, const ViewRequest& request, Messages& messages) {
    editor::FlyCamera& camera = session.camera;
    switch (request.action) {
    case ViewAction::FromFront:
    case ViewAction::FromBack:
    case ViewAction::FromRight:
    case ViewAction::FromLeft:
    case ViewAction::FromTop:
    case ViewAction::FromBottom:
        camera.viewFrom(axisViewOf(request.action));
        break;
    case ViewAction::ToggleOrthographic:
        camera.setOrthographic(!camera.orthographic, session.sceneCamera.fovYDegrees);
        break;
    case ViewAction::StoreBookmark:
        if (session.bookmarks.store(request.slot, session.viewCamera()))
            messages.notice("view kept as bookmark " + std::to_string(request.slot) + " (press " +
                            std::to_string(request.slot) + " to go back to it)");
        break;
    case ViewAction::RecallBookmark:
        if (const std::optional<Camera> view = session.bookmarks.recall(request.slot))
            camera.setFromCamera(*view);
        else
            messages.notice("no bookmark " + std::to_string(request.slot) + " yet (Ctrl+" +
                            std::to_string(request.slot) + " keeps the view as one)");
        break;
    case ViewAction::ToggleRoll:
        camera.allowRoll = !camera.allowRoll;
        if (!camera.allowRoll) camera.level();
        break;
    }
}

} // namespace rmsc::app
