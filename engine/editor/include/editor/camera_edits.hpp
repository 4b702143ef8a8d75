// Editing the scene camera's position, target and up from the editor: a change is taken only
// when the camera it gives is one the scene reader accepts (scene/camera_spec.hpp), so a target
// on the position or an up along the view is refused with the reader's reason. GL-free.
#pragma once

#include "scene/scene.hpp"

#include <string>

namespace rmsc::editor {

// Sets camera's position, target and up to those of `wanted` when they pass the reader's rule;
// otherwise returns false with `error` naming the key and why, and `camera` unchanged. The
// lens (fov, near, far) is not touched.
bool setCameraFrame(Camera& camera, const Camera& wanted, std::string& error);

} // namespace rmsc::editor
