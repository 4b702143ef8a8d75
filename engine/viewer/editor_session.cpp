// The document and the view's camera (see editor_session.hpp).
#include "editor_session.hpp"

namespace rmsc::app {

void EditorSession::resetCamera() {
    sceneCamera = document.scene().camera;
    camera.setFromCamera(sceneCamera);
}

void EditorSession::saveCameraToScene() {
    const Camera view = viewCamera();
    document.apply("Save camera", [&](Scene& scene, editor::Selection&) { scene.camera = view; });
    sceneCamera = view;
}

void EditorSession::lookThrough(const Camera& view) {
    sceneCamera.fovYDegrees = view.fovYDegrees;
    sceneCamera.nearPlane = view.nearPlane;
    sceneCamera.farPlane = view.farPlane;
    sceneCamera.projection = view.projection;
    sceneCamera.orthoHeight = view.orthoHeight;
    camera.setFromCamera(view);
}

} // namespace rmsc::app
