// The inspector's camera and view (Render tab): the scene camera's position, target, up (taken
// only when the reader would accept them, editor/camera_edits.hpp) and lens, saving the view
// into the scene or going back to it, the fly speed; what the view shows and its adaptive
// resolution (see inspector.hpp).
#include "inspector.hpp"

#include "editor/camera_edits.hpp"
#include "editor/param_fields.hpp"
#include "file_field.hpp"
#include "panel_widgets.hpp"
#include "scene/camera_spec.hpp"

#include <imgui.h>

#include <algorithm>

namespace rmsc::app {
namespace {

// Position, target and up: each drag edits a copy, taken when the camera it gives is valid.
bool editCameraFrame(Camera& camera, std::string& refusal) {
    Camera wanted = camera;
    ImGui::PushID("camera"); // the View section has a "target" of its own
    bool edited = ImGui::DragFloat3("position", &wanted.position.x, 0.01f, 0.0f, 0.0f, "%.2f");
    edited |= ImGui::DragFloat3("target", &wanted.target.x, 0.01f, 0.0f, 0.0f, "%.2f");
    edited |= ImGui::DragFloat3("up", &wanted.up.x, 0.01f, 0.0f, 0.0f, "%.2f");
    ImGui::PopID();
    helpTooltip("The scene's camera looks from its position at its target; up is the "
                "direction shown upwards. \"Save camera to scene\" sets all three from the view.");
    if (!edited) return false;
    std::string error;
    if (!editor::setCameraFrame(camera, wanted, error)) {
        refusal = "not taken: " + error;
        return false;
    }
    refusal.clear();
    return true;
}

} // namespace

void drawCameraInspector(EditorSession& session, std::string& refusal) {
    ImGui::TextDisabled("Camera");
    Camera& c = session.document.editScene().camera;
    if (editCameraFrame(c, refusal)) session.document.markChanged("Camera");
    drawRefusal(refusal);
    // The lens within the reader's ranges, narrowed to usable values: fov 1 to 170 degrees, near
    // from 0.0001, far up to 1e5 and kept at least twice near (the reader wants far > near).
    const editor::FloatFieldRange fov = editor::floatFieldRange(kCameraFovRange);
    bool cameraChanged =
        ImGui::DragFloat("fov", &c.fovYDegrees, 0.2f, std::max(fov.min, 1.0f),
                         std::min(fov.max, 170.0f), "%.1f°", ImGuiSliderFlags_AlwaysClamp);
    const editor::FloatFieldRange near = editor::floatFieldRange(kCameraNearRange);
    const editor::FloatFieldRange far = editor::floatFieldRange(kCameraFarRange);
    cameraChanged |= ImGui::DragFloat("near", &c.nearPlane, 0.001f, std::max(near.min, 0.0001f),
                                      c.farPlane * 0.5f, "%.4f", ImGuiSliderFlags_AlwaysClamp);
    cameraChanged |=
        ImGui::DragFloat("far", &c.farPlane, 0.5f, c.nearPlane * 2.0f, std::min(far.max, 1e5f),
                         "%.1f", ImGuiSliderFlags_AlwaysClamp);
    if (cameraChanged) {
        session.sceneCamera.fovYDegrees = c.fovYDegrees;
        session.sceneCamera.nearPlane = c.nearPlane;
        session.sceneCamera.farPlane = c.farPlane;
        session.document.markChanged("Camera lens");
    }
    // The scene camera's projection (the view's own is numpad 5 / View > Orthographic; "Reset
    // to scene camera" takes this one, "Save camera to scene" gives it the view's).
    const char* projections[] = {"perspective", "orthographic"};
    int projection = int(c.projection);
    if (ImGui::Combo("projection", &projection, projections, 2)) {
        c.projection = CameraProjection(projection);
        session.document.markChanged("Camera projection");
    }
    helpTooltip("How rmsc render projects the scene: perspective, or orthographic (parallel "
                "rays; sizes do not shrink with distance). The view's own projection is numpad "
                "5 or View > Orthographic.");
    if (c.projection == CameraProjection::Orthographic) {
        const editor::FloatFieldRange height = editor::floatFieldRange(kCameraOrthoHeightRange);
        if (ImGui::DragFloat("ortho height", &c.orthoHeight, 0.02f, std::max(height.min, 1e-4f),
                             std::min(height.max, 1e5f), "%.3f m", ImGuiSliderFlags_AlwaysClamp))
            session.document.markChanged("Camera ortho height");
        helpTooltip("The height of the orthographic view, world units (> 0)");
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
