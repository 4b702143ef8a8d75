// The transform gizmo over the selected object (the model is editor/transform_gizmo.hpp): the
// tool chosen in the view's toolbar (select only, move, rotate, scale), the handle under the
// mouse, a drag of a handle with the left button (Ctrl held snaps to the toolbar's steps; Esc or
// the right button cancels; the release keeps the result as one undo step), and its drawing
// over the view with Dear ImGui's background draw list, the same size on screen at any
// distance. The G / R / S gestures (gesture_controls.hpp) work beside it.
#pragma once

#include "editor/transform_gizmo.hpp"
#include "editor_session.hpp"
#include "input_state.hpp"
#include "panel_layout.hpp"

#include <optional>
#include <string>

namespace rmsc::app {

enum class ViewportTool { Select, Move, Rotate, Scale };

struct ViewportGizmo {
    ViewportTool tool = ViewportTool::Move;
    editor::SnapSteps steps; // Ctrl while dragging (and during G / R / S)
    editor::GizmoHandle hovered;
    std::optional<editor::GizmoDrag> drag; // the drag running
    glm::vec2 lastMouse{0.0f};             // viewport pixels last applied to the drag
    bool lastSnap = false;                 // whether Ctrl was held then
    bool dragging() const { return drag.has_value(); }
};

// The camera of the view as the gestures and the gizmo see it.
editor::GestureView viewportView(const Camera& camera, const Rect& viewport);

// One frame of the gizmo: the handle under the mouse, a press on it starts a drag (and is not a
// click that selects), moving drags, releasing keeps. `worldAxes`: the world's axes, else the
// object's own; `blocked`: a G / R / S gesture runs, so the gizmo takes no input. Returns true
// when this frame's left click went to a handle (so it selects nothing).
bool handleGizmo(ViewportGizmo& gizmo, const InputState& input, editor::Document& document,
                 const Camera& camera, const Rect& viewport, bool worldAxes, bool blocked);
// Draws the gizmo of the selection (nothing with the select tool or when the selection has no
// transform the tool changes).
void drawGizmo(const ViewportGizmo& gizmo, const editor::Document& document, const Camera& camera,
               const Rect& viewport, bool worldAxes);
// The toolbar at the view's bottom-right corner: the view's name (`viewName`: which view, and
// its projection), the tool, world or own axes, the snap steps. Returns how much of the view's
// width it covers from the right edge.
float drawViewportToolbar(ViewportGizmo& gizmo, bool& worldAxes, const std::string& viewName,
                          const Rect& viewport);

} // namespace rmsc::app
