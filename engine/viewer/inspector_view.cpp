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
    const NumberFieldStyle style{.format = "%.2f"};
    bool edited =
        numberField("position", &wanted.position.x, 3, 0.01f, unboundedRange(Unit::Metres),
                    "Where the scene's camera is. \"Save camera to scene\" sets "
                    "position, target and up from the view.",
                    style);
    edited |= numberField("target", &wanted.target.x, 3, 0.01f, unboundedRange(Unit::Metres),
                          "The point the scene's camera looks at (not its position).", style);
    edited |= numberField("up", &wanted.up.x, 3, 0.01f, unboundedRange(Unit::None),
                          "The direction shown upwards (not along the view).", style);
    ImGui::PopID();
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
    // (Typed values are clamped to the reader's ranges, with far kept above near.)
    bool cameraChanged =
        numberField("fov", &c.fovYDegrees, 1, 0.2f, kCameraFovRange, "The vertical field of view.",
                    {.format = "%.1f°", .drag = editor::FloatFieldRange{1, 170}});
    ParamRange nearRange = kCameraNearRange;
    nearRange.max = c.farPlane;
    nearRange.maxExclusive = true;
    cameraChanged |= numberField(
        "near", &c.nearPlane, 1, 0.001f, nearRange, "Nothing nearer than this is drawn.",
        {.format = "%.4f", .drag = editor::FloatFieldRange{0.0001f, c.farPlane * 0.5f}});
    ParamRange farRange = kCameraFarRange;
    farRange.min = c.nearPlane;
    cameraChanged |= numberField(
        "far", &c.farPlane, 1, 0.5f, farRange, "Nothing farther than this is drawn (beyond near).",
        {.format = "%.1f", .drag = editor::FloatFieldRange{c.nearPlane * 2.0f, 1e5f}});
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
        if (numberField("ortho height", &c.orthoHeight, 1, 0.02f, kCameraOrthoHeightRange,
                        "The height of the orthographic view.",
                        {.format = "%.3f m", .drag = editor::FloatFieldRange{1e-4f, 1e5f}}))
            session.document.markChanged("Camera ortho height");
    }
    if (ImGui::Button("Save camera to scene")) session.saveCameraToScene();
    ImGui::SameLine();
    if (ImGui::Button("Reset to scene camera")) session.resetCamera();
    numberField("fly speed", &session.camera.speed, 1, 0.05f,
                closedRange(0.01, 1000.0, Unit::MetresPerSecond),
                "How fast W / A / S / D fly (the wheel over the view sets it too).",
                {.format = "%.2f m/s"});
}

void drawViewInspector(ViewSettings& view) {
    ImGui::TextDisabled("View");
    const char* names[] = {"colour", "normals", "depth", "object id", "march steps"};
    int mode = int(view.mode);
    if (ImGui::Combo("show", &mode, names, 5)) view.mode = ViewMode(mode);
    ImGui::Checkbox("adaptive resolution", &view.adaptive.enabled);
    numberField("target", &view.adaptive.targetMilliseconds, 1, 0.5f,
                closedRange(5.0, 500.0, Unit::Milliseconds),
                "The frame time the adaptive resolution holds while the view changes.",
                {.format = "%.0f ms/frame"});
}

} // namespace rmsc::app
