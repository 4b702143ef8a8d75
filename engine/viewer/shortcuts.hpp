// The viewer's keyboard shortcuts: F12 screenshot; Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y undo and redo,
// Ctrl+S save, Ctrl+Shift+S save as, Ctrl+O open, Ctrl+D duplicate, Ctrl+C copy, Ctrl+V paste,
// Ctrl+G group (union); Delete, and F to frame the
// selection, when the panels leave the keyboard to the view and no gesture runs. (The camera's
// keys are camera_controls.hpp, the gestures' gesture_controls.hpp.)
#pragma once

#include "gesture_controls.hpp"
#include "input_state.hpp"
#include "viewer_commands.hpp"

namespace rmsc::app {

// Queues the commands of this frame's shortcuts; undo and redo end a running gesture.
void handleShortcuts(const InputState& input, ViewportGesture& gesture, ViewerCommands& commands);

} // namespace rmsc::app
