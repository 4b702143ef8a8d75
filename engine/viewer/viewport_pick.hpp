// Selecting by clicking in the view: a light whose marker (render/light_gizmo_pass.hpp) is near
// the click, else a ray from the eye through the clicked point, cast on the CPU
// (editor/picking.hpp) at the newest scene that compiled; the nearest object it meets is
// selected, empty space clears the selection. With Shift held the object is added to the
// selection instead (editor/multi_selection.hpp).
#pragma once

#include "editor_session.hpp"
#include "input_state.hpp"
#include "panel_layout.hpp"
#include "prepare/prepared_scene.hpp"
#include "render/light_gizmo_pass.hpp"

namespace rmsc::app {

// How near (pixels) a click must be to a light's marker to select the light.
constexpr float kLightPickRadius = 1.5f * kLightMarkerRadiusPixels;

// A left click (without Alt, outside the panels, while no gesture runs) in `viewport` selects
// what it hits in `prepared` (nothing happens while no scene has compiled).
void handleViewportClick(const InputState& input, const Rect& viewport, bool gestureActive,
                         const PreparedScene* prepared, EditorSession& session);

} // namespace rmsc::app
