// The viewer's keyboard shortcuts, from the one table of editor/shortcut_table.hpp: a row whose
// action is a command is carried out when its chord is pressed with exactly its modifiers, in
// its scope (function keys always; Ctrl chords unless a text field is being typed in; plain keys
// such as Delete, F and Shift+A only while the panels leave the keyboard to the view, no gesture
// runs and the right mouse button is up). The camera's keys are camera_controls.hpp's, the
// gestures' gesture_controls.hpp's, the view's keys (numpad, bookmarks: rows of the same table)
// view_shortcuts.hpp's.
#pragma once

#include "editor/shortcut_table.hpp"
#include "gesture_controls.hpp"
#include "input_state.hpp"
#include "viewer_commands.hpp"

#include <vector>

namespace rmsc::app {

// A row of the table that is a chord (any row but a Described one), its key resolved to GLFW's.
struct BoundShortcut {
    int key = -1;
    int mods = 0; // editor/input_queue.hpp's InputModifier bits
    const editor::Shortcut* row = nullptr;
};
const std::vector<BoundShortcut>& boundShortcuts();

// Whether `shortcut`'s chord is pressed this frame with exactly its modifiers, and its scope lets
// it count; `busy`: a gesture or a drag of the gizmo runs.
bool shortcutPressed(const BoundShortcut& shortcut, const InputState& input, bool busy);

// Queues the commands of this frame's shortcuts (the view's keys are view_shortcuts.hpp's);
// undo and redo end a running gesture. `gizmoDragging`: a drag of the gizmo runs.
void handleShortcuts(const InputState& input, ViewportGesture& gesture, bool gizmoDragging,
                     ViewerCommands& commands);

// The command a table row's action stands for (not for Described rows or the view's keys).
ViewerCommand shortcutCommand(editor::ShortcutAction action);

// A menu item's shortcut text for `action` (nullptr when it has none), from the table.
const char* menuShortcut(editor::ShortcutAction action);

} // namespace rmsc::app
