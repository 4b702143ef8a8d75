// Keyboard shortcuts from the shortcut table (see shortcuts.hpp).
#include "shortcuts.hpp"

#include "imgui_platform.hpp"
#include "key_names.hpp"

#include <imgui.h>

#include <cassert>
#include <string>
#include <vector>

namespace rmsc::app {
namespace {

using editor::ShortcutAction;

// The modifiers a chord compares: Super is left to the window system.
constexpr int kChordMods = editor::kModCtrl | editor::kModShift | editor::kModAlt;

} // namespace

const std::vector<BoundShortcut>& boundShortcuts() {
    static const std::vector<BoundShortcut> bound = [] {
        std::vector<BoundShortcut> out;
        for (const editor::Shortcut& s : editor::shortcutTable()) {
            if (s.action == ShortcutAction::Described) continue;
            const std::optional<editor::Chord> chord = editor::parseChord(s.keys);
            assert(chord && "a command row's keys are one chord (unit-tested)");
            if (!chord) continue;
            const int key = glfwKeyNamed(chord->key);
            assert(key >= 0 && "a command row's key has a GLFW name");
            out.push_back({key, chord->mods, &s});
        }
        return out;
    }();
    return bound;
}

bool shortcutPressed(const BoundShortcut& shortcut, const InputState& input, bool busy) {
    if (!input.pressed(shortcut.key) || (input.mods & kChordMods) != shortcut.mods) return false;
    const ImGuiIO& io = ImGui::GetIO();
    switch (shortcut.row->scope) {
    case editor::ShortcutScope::Always:
        return true;
    case editor::ShortcutScope::NotTyping:
        return !io.WantTextInput;
    case editor::ShortcutScope::View:
        // Not keyboardFree(): that says no while Ctrl is held, and Ctrl+1 is a view key.
        return !io.WantCaptureKeyboard && !io.WantTextInput && !busy && !input.buttons[1];
    }
    return false;
}

ViewerCommand shortcutCommand(ShortcutAction action) {
    switch (action) {
    case ShortcutAction::Undo:
        return ViewerCommand::Undo;
    case ShortcutAction::Redo:
        return ViewerCommand::Redo;
    case ShortcutAction::Duplicate:
        return ViewerCommand::Duplicate;
    case ShortcutAction::Delete:
        return ViewerCommand::Delete;
    case ShortcutAction::Copy:
        return ViewerCommand::Copy;
    case ShortcutAction::Paste:
        return ViewerCommand::Paste;
    case ShortcutAction::GroupUnion:
        return ViewerCommand::Group;
    case ShortcutAction::AddSearch:
        return ViewerCommand::AddSearch;
    case ShortcutAction::Open:
        return ViewerCommand::Open;
    case ShortcutAction::Save:
        return ViewerCommand::Save;
    case ShortcutAction::SaveAs:
        return ViewerCommand::SaveAs;
    case ShortcutAction::Screenshot:
        return ViewerCommand::Screenshot;
    case ShortcutAction::FrameSelection:
        return ViewerCommand::FrameSelection;
    case ShortcutAction::ShortcutSheet:
        return ViewerCommand::ShortcutSheet;
    default: // Described rows, the view's keys
        break;
    }
    assert(false && "Described rows and the view's keys are no command");
    return ViewerCommand::Undo;
}

const char* menuShortcut(ShortcutAction action) {
    const std::string_view keys = editor::shortcutKeys(action);
    return keys.empty() ? nullptr : keys.data(); // the table's literals end in NUL
}

void handleShortcuts(const InputState& input, ViewportGesture& gesture, bool gizmoDragging,
                     ViewerCommands& commands) {
    for (const BoundShortcut& s : boundShortcuts()) {
        if (editor::isViewAction(s.row->action)) continue; // view_shortcuts.cpp's
        if (!shortcutPressed(s, input, gesture.active || gizmoDragging)) continue;
        const ViewerCommand command = shortcutCommand(s.row->action);
        if (command == ViewerCommand::Undo || command == ViewerCommand::Redo)
            gesture.active = false;
        commands.push_back(command);
    }
}

} // namespace rmsc::app
