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

} // namespace rmsc::app
