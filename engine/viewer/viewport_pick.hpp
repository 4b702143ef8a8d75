// Selecting by clicking in the view: a ray from the eye through the clicked point, cast on the
// CPU (editor/picking.hpp) at the newest scene that compiled; the nearest object it meets is
// selected, empty space clears the selection.
#pragma once

#include "editor_session.hpp"
#include "input_state.hpp"
#include "panel_layout.hpp"
#include "prepare/prepared_scene.hpp"

namespace rmsc::app {

// A left click (without Alt, outside the panels, while no gesture runs) in `viewport` selects
// what it hits in `prepared` (nothing happens while no scene has compiled).
void handleViewportClick(const InputState& input, const Rect& viewport, bool gestureActive,
                         const PreparedScene* prepared, EditorSession& session);

} // namespace rmsc::app
