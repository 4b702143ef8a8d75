// Picking by clicking in the view: a ray from the eye through the clicked point, cast on the CPU
// (editor/picking.hpp) at the newest scene that compiled.
#pragma once

#include "editor/selection.hpp"
#include "panel_layout.hpp"
#include "prepare/prepared_scene.hpp"

#include <glm/glm.hpp>

namespace rmsc::app {

// The selection a click at window pixel `point` inside `viewport` makes, seen through `camera`:
// the object the ray meets first, or none.
editor::Selection pickAt(const PreparedScene& prepared, const Scene& scene, const Camera& camera,
                         const Rect& viewport, glm::vec2 point);

} // namespace rmsc::app
