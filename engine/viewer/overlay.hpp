// What is drawn over the view: the status overlay (frame and render times, render scale, the SDF
// map drawn with a progress bar while shaders build in the background, view mode and fly speed,
// the gesture running, recent notices; the progress bar alone when the overlay is hidden) and
// the problems box
// (open, scene, shader and file errors, with a button that dismisses the open and file ones).
#pragma once

#include "editor/transform_gesture.hpp"
#include "messages.hpp"
#include "panel_layout.hpp"
#include "view_renderer.hpp"
#include "view_settings.hpp"

namespace rmsc::app {

// Drawn when view.showOverlay; `gesture` is the one running, or nullptr.
void drawStatusOverlay(const Rect& viewport, const ViewStatus& status, float frameMilliseconds,
                       const ViewSettings& view, float flySpeed,
                       const editor::TransformGesture* gesture, const Messages& messages);
// Drawn when there is a problem to show, at the view's bottom-left corner, left of the
// `rightMargin` pixels the view toolbar covers.
void drawProblems(const Rect& viewport, float rightMargin, Messages& messages);

} // namespace rmsc::app
