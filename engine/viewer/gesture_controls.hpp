// Moving (G), rotating (R) and scaling (S) the selected shape, group or mesh, and moving and
// turning the selected light, with the mouse, like Blender: X / Y / Z constrain to an axis (again:
// free), Ctrl held snaps (by default steps of 0.1 m, 15 degrees, tenths of the scale; the
// view's toolbar sets them), a click or Enter
// keeps the result as one undo step, Esc or the right button cancels. The math is
// editor/transform_gesture.hpp.
#pragma once

#include "editor/transform_gesture.hpp"
#include "editor_session.hpp"
#include "input_state.hpp"
#include "panel_layout.hpp"

namespace rmsc::app {

struct ViewportGesture {
    bool active = false;
    editor::TransformGesture math; // the start; its axis and space change while it runs
    glm::vec2 lastMouse{0.0f};     // viewport pixels last applied
    bool needsApply = false;       // apply even if the mouse did not move (axis changed)
};

// Starts a gesture when G, R or S is pressed with something movable selected; `worldAxes`
// makes X / Y / Z the world's axes (otherwise the object's own); Ctrl snaps to `steps`.
void startGesture(ViewportGesture& gesture, const InputState& input, EditorSession& session,
                  const Rect& viewport, bool worldAxes, const editor::SnapSteps& steps);
// Follows the mouse; keeps, cancels or changes the axis.
void updateGesture(ViewportGesture& gesture, const InputState& input, editor::Document& document,
                   const Rect& viewport);

} // namespace rmsc::app
