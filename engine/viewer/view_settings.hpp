// How the view is shown: what it shows (colour, normals, depth, object ids, march steps), the
// overlay, the lights' markers, and the adaptive resolution (its settings and its state,
// editor/adaptive_scale.hpp). The View menu and the inspector's Render tab edit them.
#pragma once

#include "display_pass.hpp"
#include "editor/adaptive_scale.hpp"

namespace rmsc::app {

struct ViewSettings {
    ViewMode mode = ViewMode::Color;
    bool showOverlay = true;
    bool showLights = true; // the light gizmos (render/light_gizmo_pass.hpp)
    editor::AdaptiveScale adaptive;
};

} // namespace rmsc::app
