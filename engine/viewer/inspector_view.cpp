// The inspector's camera and view (Render tab): the scene camera's lens, saving the view into
// the scene or going back to it, the fly speed; what the view shows and its adaptive
// resolution (see inspector.hpp).
#include "inspector.hpp"

#include <imgui.h>

namespace rmsc::app {

void drawCameraInspector(EditorSession& session) {
    ImGui::TextDisabled("Camera");
    Camera& c = session.document.editScene().camera;
    bool cameraChanged = ImGui::DragFloat("fov", &c.fovYDegrees, 0.2f, 1.0f, 170.0f, "%.1f°",
                                          ImGuiSliderFlags_AlwaysClamp);
    cameraChanged |= ImGui::DragFloat("near", &c.nearPlane, 0.001f, 0.0001f, c.farPlane * 0.5f,
                                      "%.4f", ImGuiSliderFlags_AlwaysClamp);
    cameraChanged |= ImGui::DragFloat("far", &c.farPlane, 0.5f, c.nearPlane * 2.0f, 100000.0f,
                                      "%.1f", ImGuiSliderFlags_AlwaysClamp);
    if (cameraChanged) {
        session.sceneCamera.fovYDegrees = c.fovYDegrees;
        session.sceneCamera.nearPlane = c.nearPlane;
        session.sceneCamera.farPlane = c.farPlane;
        session.document.markChanged("Camera lens");
    }
    if (ImGui::Button("Save camera to scene")) session.saveCameraToScene();
    ImGui::SameLine();
    if (ImGui::Button("Reset to scene camera")) session.resetCamera();
    ImGui::DragFloat("fly speed", &session.camera.speed, 0.05f, 0.01f, 1000.0f, "%.2f m/s");
}

void drawViewInspector(ViewSettings& view) {
    ImGui::TextDisabled("View");
    const char* names[] = {"colour", "normals", "depth", "object id", "march steps"};
    int mode = int(view.mode);
    if (ImGui::Combo("show", &mode, names, 5)) view.mode = ViewMode(mode);
    ImGui::Checkbox("adaptive resolution", &view.adaptive.enabled);
    ImGui::DragFloat("target", &view.adaptive.targetMilliseconds, 0.5f, 5.0f, 500.0f,
                     "%.0f ms/frame");
}

} // namespace rmsc::app
