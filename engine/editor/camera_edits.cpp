// Editing the camera's frame with the reader's check first (see camera_edits.hpp).
#include "editor/camera_edits.hpp"

#include "scene/camera_spec.hpp"

namespace rmsc::editor {

bool setCameraFrame(Camera& camera, const Camera& wanted, std::string& error) {
    if (const std::optional<CameraProblem> problem = cameraFrameProblem(wanted)) {
        error = std::string(problem->key) + ": " + problem->message;
        return false;
    }
    camera.position = wanted.position;
    camera.target = wanted.target;
    camera.up = wanted.up;
    return true;
}

} // namespace rmsc::editor
