// The scene being edited and the view's camera: the editor document (scene, file, selection,
// undo history) and the fly camera, whose lens is the scene camera's.
#pragma once

#include "editor/document.hpp"
#include "editor/fly_camera.hpp"

namespace rmsc::app {

struct EditorSession {
    editor::Document document;
    editor::FlyCamera camera;
    Camera sceneCamera; // fov and planes for the view (the Render tab edits them)

    Camera viewCamera() const { return camera.toCamera(sceneCamera); }
    // The view from the scene's camera (after opening a scene, or when asked).
    void resetCamera();
    // The view becomes the scene's camera, as one undo step.
    void saveCameraToScene();
};

} // namespace rmsc::app
