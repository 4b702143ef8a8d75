// The transform gizmo: input, drawing and its toolbar (see gizmo_controls.hpp).
#include "gizmo_controls.hpp"

#include "editor/gesture_target.hpp"
#include "panel_widgets.hpp"
#include "render/frame.hpp"

#include <glm/gtc/constants.hpp>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace rmsc::app {
namespace {

editor::GestureKind gestureKind(ViewportTool tool) {
    return tool == ViewportTool::Rotate  ? editor::GestureKind::Rotate
           : tool == ViewportTool::Scale ? editor::GestureKind::Scale
                                         : editor::GestureKind::Move;
}

editor::GizmoMode gizmoMode(ViewportTool tool) {
    return tool == ViewportTool::Rotate  ? editor::GizmoMode::Rotate
           : tool == ViewportTool::Scale ? editor::GizmoMode::Scale
                                         : editor::GizmoMode::Move;
}

// The gizmo of the selection for the tool, or nullopt when there is none (the select tool, no
// selection, or one the tool does not change, such as a point light to rotate).
struct ShownGizmo {
    editor::GestureTarget target;
    editor::GestureView view;
    editor::GizmoFrame frame;
};
std::optional<ShownGizmo> shownGizmo(ViewportTool tool, const editor::Document& document,
                                     const Camera& camera, const Rect& viewport, bool worldAxes) {
    if (tool == ViewportTool::Select) return std::nullopt;
    const std::optional<editor::GestureTarget> target =
        editor::gestureTarget(document.scene(), document.selection, gestureKind(tool));
    if (!target) return std::nullopt;
    ShownGizmo shown{*target, viewportView(camera, viewport), {}};
    const glm::vec3 centre = editor::gizmoCentre(target->start, target->parentWorld);
    // Not when the object is behind the camera (or nearer than the near plane).
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    if (glm::dot(centre - camera.position, forward) <= camera.nearPlane) return std::nullopt;
    // A scale is along the object's own axes (a world axis would need shear).
    const editor::AxisSpace space = worldAxes && tool != ViewportTool::Scale
                                        ? editor::AxisSpace::World
                                        : editor::AxisSpace::Local;
    shown.frame = editor::gizmoFrame(shown.view, centre,
                                     editor::gizmoAxes(target->start, target->parentWorld, space));
    return shown;
}

ImU32 axisColour(int axis, bool active) {
    if (active) return IM_COL32(255, 214, 40, 255);
    static const ImU32 colours[] = {IM_COL32(232, 64, 64, 255), IM_COL32(100, 205, 60, 255),
                                    IM_COL32(70, 125, 245, 255)};
    return axis >= 0 && axis < 3 ? colours[axis] : IM_COL32(235, 235, 235, 255);
}

ImU32 withAlpha(ImU32 colour, int alpha) {
    return (colour & ~IM_COL32_A_MASK) | (ImU32(alpha) << IM_COL32_A_SHIFT);
}

} // namespace

editor::GestureView viewportView(const Camera& camera, const Rect& viewport) {
    const int w = std::max(1, int(viewport.width)), h = std::max(1, int(viewport.height));
    const FrameCamera frame = makeFrameCamera(camera, w, h);
    editor::GestureView view;
    view.viewProjection = frame.viewProjection;
    view.viewportSize = glm::vec2(float(w), float(h));
    view.forward = frame.forward;
    return view;
}

bool handleGizmo(ViewportGizmo& gizmo, const InputState& input, editor::Document& document,
                 const Camera& camera, const Rect& viewport, bool worldAxes, bool blocked) {
    const glm::vec2 mouse = input.mouse - glm::vec2(viewport.x, viewport.y);
    if (gizmo.drag) {
        const std::optional<editor::GestureTarget> target =
            editor::gestureTarget(document.scene(), document.selection, gestureKind(gizmo.tool));
        if (!target) { // the selection went (undo, a reload)
            gizmo.drag.reset();
            return false;
        }
        if (input.pressed(GLFW_KEY_ESCAPE) || input.clicked[1]) {
            document.revertPending();
            gizmo.drag.reset();
            return false;
        }
        if (mouse != gizmo.lastMouse || input.ctrl() != gizmo.lastSnap) {
            gizmo.lastMouse = mouse;
            gizmo.lastSnap = input.ctrl();
            editor::setGestureTransform(
                document.editScene(), document.selection,
                editor::dragGizmo(*gizmo.drag, mouse, input.ctrl(), gizmo.steps));
            document.markChanged(editor::gizmoDragLabel(*gizmo.drag));
        }
        if (!input.buttons[0]) { // released: one undo step
            document.commit();
            gizmo.drag.reset();
        }
        return false;
    }
    gizmo.hovered = {};
    if (blocked) return false;
    const ImGuiIO& io = ImGui::GetIO();
    if (!viewport.contains(input.mouse) || io.WantCaptureMouse) return false;
    const std::optional<ShownGizmo> shown =
        shownGizmo(gizmo.tool, document, camera, viewport, worldAxes);
    if (!shown) return false;
    gizmo.hovered =
        editor::pickGizmoHandle(shown->frame, shown->view, gizmoMode(gizmo.tool), mouse);
    if (!input.clicked[0] || input.alt() || input.shift() ||
        gizmo.hovered.part == editor::GizmoPart::None)
        return false;
    gizmo.drag = editor::beginGizmoDrag(gizmo.hovered, shown->frame, shown->view,
                                        shown->target.start, shown->target.parentWorld, mouse);
    if (!gizmo.drag) return false;
    document.commit(); // whatever was pending is a step of its own
    gizmo.lastMouse = mouse;
    gizmo.lastSnap = input.ctrl();
    return true;
}

void drawGizmo(const ViewportGizmo& gizmo, const editor::Document& document, const Camera& camera,
               const Rect& viewport, bool worldAxes) {
    const std::optional<ShownGizmo> shown =
        shownGizmo(gizmo.tool, document, camera, viewport, worldAxes);
    if (!shown) return;
    const editor::GizmoFrame& f = shown->frame;
    const editor::GestureView& view = shown->view;
    const editor::GizmoHandle active = gizmo.drag ? gizmo.drag->handle : gizmo.hovered;
    auto screen = [&](glm::vec3 world) {
        const glm::vec2 p = editor::worldToScreen(view, world);
        return ImVec2(viewport.x + p.x, viewport.y + p.y);
    };
    auto along = [&](int axis, float arms) { return f.centre + f.axes[axis] * (arms * f.size); };
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    list->PushClipRect(ImVec2(viewport.x, viewport.y),
                       ImVec2(viewport.x + viewport.width, viewport.y + viewport.height));
    const ImVec2 centre = screen(f.centre);
    for (const editor::GizmoHandle handle : editor::gizmoHandles(gizmoMode(gizmo.tool))) {
        if (!editor::gizmoHandleVisible(f, handle)) continue;
        const bool lit = handle == active;
        const ImU32 colour = axisColour(handle.axis, lit);
        const float thickness = lit ? 3.5f : 2.5f;
        switch (handle.part) {
        case editor::GizmoPart::Axis: {
            const ImVec2 from = screen(along(handle.axis, editor::kGizmoAxisStart));
            const ImVec2 base = screen(along(handle.axis, 0.78f));
            const ImVec2 tip = screen(along(handle.axis, 1.0f));
            list->AddLine(from, base, colour, thickness);
            // The arrowhead: a triangle across the arm as drawn on screen.
            glm::vec2 d(tip.x - base.x, tip.y - base.y);
            const float length = glm::length(d);
            if (length > 1e-3f) {
                const glm::vec2 side = glm::vec2(-d.y, d.x) / length * 6.0f;
                list->AddTriangleFilled(tip, ImVec2(base.x + side.x, base.y + side.y),
                                        ImVec2(base.x - side.x, base.y - side.y), colour);
            }
            break;
        }
        case editor::GizmoPart::Plane: {
            const int a = (handle.axis + 1) % 3, b = (handle.axis + 2) % 3;
            auto corner = [&](float u, float v) {
                return screen(f.centre + (f.axes[a] * u + f.axes[b] * v) * f.size);
            };
            const float n = editor::kGizmoPlaneNear, x = editor::kGizmoPlaneFar;
            const ImVec2 quad[4] = {corner(n, n), corner(x, n), corner(x, x), corner(n, x)};
            list->AddQuadFilled(quad[0], quad[1], quad[2], quad[3],
                                withAlpha(colour, lit ? 170 : 90));
            list->AddQuad(quad[0], quad[1], quad[2], quad[3], colour, 1.5f);
            break;
        }
        case editor::GizmoPart::Screen:
            list->AddCircle(centre, editor::kGizmoCentreRadius * editor::kGizmoArmPixels,
                            axisColour(-1, lit), 32, thickness);
            break;
        case editor::GizmoPart::Ring: {
            const int a = (handle.axis + 1) % 3, b = (handle.axis + 2) % 3;
            constexpr int kSegments = 72;
            ImVec2 points[kSegments];
            for (int i = 0; i < kSegments; ++i) {
                const float angle = glm::two_pi<float>() * float(i) / float(kSegments);
                points[i] =
                    screen(f.centre + (f.axes[a] * std::cos(angle) + f.axes[b] * std::sin(angle)) *
                                          (editor::kGizmoRingRadius * f.size));
            }
            list->AddPolyline(points, kSegments, colour, ImDrawFlags_Closed, thickness);
            break;
        }
        case editor::GizmoPart::ScaleAxis: {
            const ImVec2 from = screen(along(handle.axis, editor::kGizmoAxisStart));
            const ImVec2 end = screen(along(handle.axis, 1.0f));
            list->AddLine(from, end, colour, thickness);
            const float h = editor::kGizmoBoxHalf * editor::kGizmoArmPixels;
            list->AddRectFilled(ImVec2(end.x - h, end.y - h), ImVec2(end.x + h, end.y + h), colour);
            break;
        }
        case editor::GizmoPart::ScaleUniform: {
            const float h = editor::kGizmoCentreRadius * editor::kGizmoArmPixels * 0.8f;
            list->AddRect(ImVec2(centre.x - h, centre.y - h), ImVec2(centre.x + h, centre.y + h),
                          axisColour(-1, lit), 0.0f, 0, thickness);
            break;
        }
        case editor::GizmoPart::None:
            break;
        }
    }
    if (gizmo.drag) {
        const std::string readout = editor::gizmoDragReadout(*gizmo.drag);
        list->AddText(ImVec2(centre.x + 14, centre.y + 14), IM_COL32(255, 230, 140, 255),
                      readout.c_str());
    }
    list->PopClipRect();
}

float drawViewportToolbar(ViewportGizmo& gizmo, bool& worldAxes, const std::string& viewName,
                          const Rect& viewport) {
    ImGui::SetNextWindowPos(
        ImVec2(viewport.x + viewport.width - 8, viewport.y + viewport.height - 8), ImGuiCond_Always,
        ImVec2(1, 1));
    ImGui::SetNextWindowBgAlpha(0.6f);
    constexpr ImGuiWindowFlags kFlags =
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
        ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
        ImGuiWindowFlags_NoNav;
    ImGui::Begin("tools", nullptr, kFlags);
    ImGui::TextDisabled("%s", viewName.c_str());
    helpTooltip("The view: along an axis (numpad 1 / 3 / 7, Ctrl for the opposite side) or "
                "not (User); perspective or orthographic (numpad 5)");
    struct ToolButton {
        ViewportTool tool;
        const char* label;
        const char* help;
    };
    static const ToolButton kTools[] = {
        {ViewportTool::Select, "Select", "No gizmo: click to select only"},
        {ViewportTool::Move, "Move",
         "Gizmo: drag an arrow (along an axis), a square (in a plane) or the centre circle (in "
         "the plane facing the camera)"},
        {ViewportTool::Rotate, "Rotate", "Gizmo: drag a ring to turn about its axis"},
        {ViewportTool::Scale, "Scale",
         "Gizmo: drag a box to scale along the object's own axis, the centre square to scale "
         "uniformly"},
    };
    for (const ToolButton& t : kTools) {
        if (ImGui::Selectable(t.label, gizmo.tool == t.tool, 0, ImVec2(54, 0))) {
            gizmo.tool = t.tool;
            gizmo.drag.reset();
        }
        helpTooltip(t.help);
    }
    ImGui::Checkbox("world", &worldAxes);
    helpTooltip("The gizmo's and G / R's axes: the world's (on) or the object's own (off); "
                "scaling is always along the object's own axes");
    if (ImGui::Button("snap", ImVec2(54, 0))) ImGui::OpenPopup("snap steps");
    helpTooltip("The steps Ctrl snaps to while dragging the gizmo or during G / R / S");
    // Over the toolbar, its right edge on the button's: the same place whatever its width.
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetItemRectMax().x, ImGui::GetItemRectMin().y),
                            ImGuiCond_Appearing, ImVec2(1, 1));
    if (ImGui::BeginPopup("snap steps")) {
        ImGui::TextUnformatted("Ctrl snaps to steps of");
        ImGui::SetNextItemWidth(80);
        ImGui::InputFloat("m", &gizmo.steps.distance, 0.0f, 0.0f, "%.3f");
        helpTooltip("Moving: 0.001 to 100 m");
        gizmo.steps.distance = std::clamp(gizmo.steps.distance, 0.001f, 100.0f);
        float degrees = glm::degrees(gizmo.steps.angle);
        ImGui::SetNextItemWidth(80);
        if (ImGui::InputFloat("degrees", &degrees, 0.0f, 0.0f, "%.1f"))
            gizmo.steps.angle = glm::radians(std::clamp(degrees, 0.1f, 180.0f));
        helpTooltip("Rotating: 0.1 to 180 degrees");
        ImGui::SetNextItemWidth(80);
        ImGui::InputFloat("scale", &gizmo.steps.scale, 0.0f, 0.0f, "%.2f");
        helpTooltip("Scaling: factors in steps of 0.01 to 10");
        gizmo.steps.scale = std::clamp(gizmo.steps.scale, 0.01f, 10.0f);
        // Esc closes it once no field is being typed in (there Esc gives the text up).
        if (!ImGui::IsAnyItemActive() &&
            ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    const float width = ImGui::GetWindowWidth();
    ImGui::End();
    return width + 8.0f;
}

} // namespace rmsc::app
