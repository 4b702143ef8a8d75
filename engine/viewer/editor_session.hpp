// The scene being edited and the view's camera: the editor document (scene, file, selection,
// undo history), the fly camera, whose lens is the scene camera's, and the view's bookmarks.
#pragma once

#include "editor/document.hpp"
#include "editor/fly_camera.hpp"
#include "editor/view_bookmarks.hpp"

namespace rmsc::app {

struct EditorSession {
    editor::Document document;
    editor::FlyCamera camera;
    Camera sceneCamera;              // fov and planes for the view (the Render tab edits them)
    editor::ViewBookmarks bookmarks; // for the session (Ctrl+1..9, 1..9)

    Camera viewCamera() const { return camera.toCamera(sceneCamera); }
    // The view from the scene's camera (after opening a scene, or when asked).
    void resetCamera();
    // The view becomes the scene's camera, as one undo step.
    void saveCameraToScene();
    // The view looks through `view` (a glTF file's camera): its place and its lens; the scene's
    // camera is unchanged until saved to it.
    void lookThrough(const Camera& view);
};

} // namespace rmsc::app
