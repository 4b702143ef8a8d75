// Click to select: a light's marker near the click, else a CPU ray cast through the clicked
// pixel (see viewport_pick.hpp).
#include "viewport_pick.hpp"

#include "editor/light_edits.hpp"
#include "editor/multi_selection.hpp"
#include "editor/picking.hpp"
#include "editor/scene_edits.hpp"
#include "gizmo_controls.hpp"
#include "render/frame.hpp"

#include <imgui.h>

#include <algorithm>

namespace rmsc::app {
namespace {

// The selection a click at window pixel `point` inside `viewport` makes, seen through `camera`.
editor::Selection pickAt(const PreparedScene& prepared, const Scene& scene, const Camera& camera,
                         const Rect& viewport, glm::vec2 point) {
    // A ray from the eye through the clicked point, built as the march pass builds its rays
    // (pixelRayDirection adds half a pixel, so the point itself is the pixel's centre).
    const int w = std::max(1, int(viewport.width)), h = std::max(1, int(viewport.height));
    const FrameCamera frame = makeFrameCamera(camera, w, h);
    const float x = point.x - viewport.x - 0.5f;
    const float y = viewport.height - (point.y - viewport.y) - 0.5f;  // rows from the bottom
    const glm::vec3 direction = pixelRayDirection(frame, x, y, w, h); // forward component 1
    const float length = glm::length(direction);
    editor::PickRay ray;
    ray.origin = pixelRayOrigin(frame, x, y, w, h); // the eye, or the pixel's (orthographic)
    ray.direction = direction / length;
    ray.tMin = camera.nearPlane * length; // the near and far planes are view depths
    ray.tMax = camera.farPlane * length;
    // A pixel's size along the ray, from the next pixel's ray, so that lines and points (a
    // pixel or a few wide) can be clicked.
    ray.pixelSize = glm::length(pixelRayOrigin(frame, x + 1.0f, y, w, h) - ray.origin);
    ray.pixelSpread = glm::length(pixelRayDirection(frame, x + 1.0f, y, w, h) - direction) / length;
    const std::optional<editor::PickHit> hit = editor::pick(prepared, ray);
    return hit ? editor::selectionForObjectId(scene, hit->objectId) : editor::Selection::none();
}

// The light whose marker is within a few pixels of window pixel `point`, or -1.
int lightAt(const Scene& scene, const Camera& camera, const Rect& viewport, glm::vec2 point) {
    return editor::pickLight(scene, viewportView(camera, viewport),
                             point - glm::vec2(viewport.x, viewport.y), kLightPickRadius);
}

} // namespace

void handleViewportClick(const InputState& input, const Rect& viewport, bool gestureActive,
                         const PreparedScene* prepared, EditorSession& session) {
    const ImGuiIO& io = ImGui::GetIO();
    if (gestureActive || !input.clicked[0] || input.alt()) return;
    if (!viewport.contains(input.mouse) || io.WantCaptureMouse) return;
    const Scene& scene = session.document.scene();
    // Shift adds to the selection (or takes out what is selected already).
    if (const int light = lightAt(scene, session.viewCamera(), viewport, input.mouse); light >= 0)
        editor::clickSelect(session.document, editor::Selection::light(light), input.shift());
    else if (prepared)
        editor::clickSelect(session.document,
                            pickAt(*prepared, scene, session.viewCamera(), viewport, input.mouse),
                            input.shift());
}

} // namespace rmsc::app
