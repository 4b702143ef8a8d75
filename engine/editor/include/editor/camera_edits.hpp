// Editing the scene camera's position, target and up from the editor: a change is taken only
// when the camera it gives is one the scene reader accepts (scene/camera_spec.hpp), so a target
// on the position or an up along the view is refused with the reader's reason; and whether the
// view shows something else than the scene camera (asked before a save). GL-free.
#pragma once

#include "scene/scene.hpp"

#include <string>

namespace rmsc::editor {

// Sets camera's position, target and up to those of `wanted` when they pass the reader's rule;
// otherwise returns false with `error` naming the key and why, and `camera` unchanged. The
// lens (fov, near, far) is not touched.
bool setCameraFrame(Camera& camera, const Camera& wanted, std::string& error);

// Whether the view `view` shows something else than the scene camera `scene`: another
// position, direction, roll (up seen across the view) or projection (and orthographic height).
// The lens (fov, near, far), which the view takes from the scene camera, and the target's
// distance along the view are not compared; differences within float noise (1e-4, relative to
// the sizes compared) are none.
bool viewDiffersFromCamera(const Camera& view, const Camera& scene);

} // namespace rmsc::editor
