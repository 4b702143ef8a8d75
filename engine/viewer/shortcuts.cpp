// Keyboard shortcuts (see shortcuts.hpp).
#include "shortcuts.hpp"

#include "imgui_platform.hpp"

#include <imgui.h>

namespace rmsc::app {

void handleShortcuts(const InputState& input, ViewportGesture& gesture, ViewerCommands& commands) {
    const ImGuiIO& io = ImGui::GetIO();
    if (input.pressed(GLFW_KEY_F12)) commands.push_back(ViewerCommand::Screenshot);
    if (input.ctrl() && !io.WantTextInput) {
        if (input.pressed(GLFW_KEY_Z)) {
            gesture.active = false;
            commands.push_back(input.shift() ? ViewerCommand::Redo : ViewerCommand::Undo);
        }
        if (input.pressed(GLFW_KEY_Y)) commands.push_back(ViewerCommand::Redo);
        if (input.pressed(GLFW_KEY_S))
            commands.push_back(input.shift() ? ViewerCommand::SaveAs : ViewerCommand::Save);
        if (input.pressed(GLFW_KEY_O)) commands.push_back(ViewerCommand::Open);
        if (input.pressed(GLFW_KEY_D)) commands.push_back(ViewerCommand::Duplicate);
        if (input.pressed(GLFW_KEY_C)) commands.push_back(ViewerCommand::Copy);
        if (input.pressed(GLFW_KEY_V)) commands.push_back(ViewerCommand::Paste);
        if (input.pressed(GLFW_KEY_G)) commands.push_back(ViewerCommand::Group);
    }
    if (!keyboardFree(input) || gesture.active) return;
    if (input.pressed(GLFW_KEY_DELETE)) commands.push_back(ViewerCommand::Delete);
    if (input.pressed(GLFW_KEY_F)) commands.push_back(ViewerCommand::FrameSelection);
}

} // namespace rmsc::app
