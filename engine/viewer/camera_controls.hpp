// The fly camera's controls: W / A / S / D, Space and Left Shift (while the right button is
// held) fly (Shift with a movement key is fast), Q / E roll (when roll is allowed), the right
// button held looks around, the wheel sets the speed (zooms an orthographic view), Alt + left
// drag orbits around the selection; and framing the selection (F). The numpad views and the
// bookmarks are view_shortcuts.hpp.
#pragma once

#include "editor_session.hpp"
#include "input_state.hpp"
#include "panel_layout.hpp"

#include <string>

namespace rmsc::app {

// The mouse drags that move the camera, from the frame they start in the view until the button
// is released.
struct CameraDrags {
    bool looking = false;  // right button
    bool orbiting = false; // Alt + left button
};

// One frame of camera movement; while `gestureActive` the keys belong to the gesture and no
// drag starts.
void handleCamera(const InputState& input, const Rect& viewport, bool gestureActive,
                  CameraDrags& drags, EditorSession& session, float seconds);
// Looks at the selection (or the whole SDF) so that it fills the view.
void frameSelection(EditorSession& session);
// The view's name, as Blender shows it: "Front Ortho", "User Persp" (a view along no axis), with
// ", roll" while roll is allowed.
std::string viewLabel(const editor::FlyCamera& camera);

} // namespace rmsc::app
