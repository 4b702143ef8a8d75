// The status overlay and the problems box over the view (see overlay.hpp).
#include "overlay.hpp"

#include <imgui.h>

#include <algorithm>

#include <string>

namespace rmsc::app {
namespace {

// Windows that stay where they are put and take no focus.
constexpr ImGuiWindowFlags kFixed =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;

// "Move along X (own axis): ..." for the gesture running.
void drawGestureHint(const editor::TransformGesture& g) {
    const char* what = g.kind == editor::GestureKind::Move     ? "Move"
                       : g.kind == editor::GestureKind::Rotate ? "Rotate"
                                                               : "Scale";
    const char* free = g.kind == editor::GestureKind::Move     ? "in the view plane"
                       : g.kind == editor::GestureKind::Rotate ? "about the view axis"
                                                               : "uniformly";
    std::string axis = free;
    if (g.axis >= 0) {
        // Scaling always uses the object's own axes (a world axis would need shear).
        const bool world =
            g.space == editor::AxisSpace::World && g.kind != editor::GestureKind::Scale;
        axis = std::string(g.kind == editor::GestureKind::Rotate ? "about " : "along ") +
               char('X' + g.axis) + (world ? " (world)" : " (own axis)");
    }
    ImGui::TextColored(ImVec4(1, 0.7f, 0.2f, 1),
                       "%s %s: mouse drives it, X/Y/Z axis, click/Enter keeps, Esc cancels", what,
                       axis.c_str());
}

// The background shader build as a progress bar: "building shaders 2 of 3 (better maps), 4.1 s"
// (editor/build_progress.hpp); nothing while nothing builds.
void drawBuildProgress(const ViewStatus& status) {
    if (status.build.total <= 0) return;
    const std::string text = editor::buildProgressText(status.build);
    ImGui::ProgressBar(
        editor::buildProgressFraction(status.build),
        ImVec2(ImGui::CalcTextSize(text.c_str()).x + ImGui::GetStyle().FramePadding.x * 4.0f, 0.0f),
        text.c_str());
    if (status.newestScenePending)
        ImGui::TextColored(ImVec4(1, 0.7f, 0.2f, 1), "the newest scene shows once they are built");
}

} // namespace

void drawStatusOverlay(const Rect& viewport, const ViewStatus& status, float frameMilliseconds,
                       const ViewSettings& view, float flySpeed,
                       const editor::TransformGesture* gesture, const Messages& messages) {
    if (!view.showOverlay) {
        // The build's progress shows even without the overlay.
        if (status.build.total <= 0) return;
        ImGui::SetNextWindowPos(ImVec2(viewport.x + 8, viewport.y + 8));
        ImGui::SetNextWindowBgAlpha(0.55f);
        ImGui::Begin("overlay", nullptr, kFixed | ImGuiWindowFlags_NoInputs);
        drawBuildProgress(status);
        ImGui::End();
        return;
    }
    ImGui::SetNextWindowPos(ImVec2(viewport.x + 8, viewport.y + 8));
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("overlay", nullptr, kFixed | ImGuiWindowFlags_NoInputs);
    ImGui::Text("frame %.1f ms   render %.1f ms", frameMilliseconds, status.renderMilliseconds);
    if (status.refined)
        ImGui::Text("render scale 100%% (%dx%d)%s", status.width, status.height,
                    view.adaptive.enabled ? "" : "  adaptive off");
    else
        ImGui::Text("render scale %.0f%% (%dx%d), refining: %d rows", status.renderScale * 100.0f,
                    status.width, status.height, status.refinedRows);
    const std::string_view map = editor::editingMapName(status.map);
    ImGui::Text("SDF map: %.*s%s", int(map.size()), map.data(),
                status.map == editor::EditingMapKind::Baked && status.selectionLive
                    ? ", selection live"
                    : "");
    drawBuildProgress(status);
    const char* names[] = {"colour", "normals", "depth", "object id", "march steps"};
    ImGui::Text("view: %s   speed %.2f m/s", names[int(view.mode)], flySpeed);
    if (gesture) drawGestureHint(*gesture);
    const auto t = std::chrono::steady_clock::now();
    for (const auto& [text, when] : messages.notices)
        if (t - when < std::chrono::seconds(4))
            ImGui::TextColored(ImVec4(0.6f, 0.9f, 0.6f, 1), "%s", text.c_str());
    ImGui::End();
}

void drawProblems(const Rect& viewport, float rightMargin, Messages& messages) {
    std::string errors;
    for (const std::string* e :
         {&messages.openError, &messages.sceneError, &messages.shaderError, &messages.fileError})
        if (!e->empty()) errors += (errors.empty() ? "" : "\n") + *e;
    if (errors.empty()) return;
    ImGui::SetNextWindowPos(ImVec2(viewport.x + 8, viewport.y + viewport.height - 8), 0,
                            ImVec2(0, 1));
    const float width = std::max(160.0f, viewport.width - 16 - rightMargin);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(width, viewport.height * 0.5f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("problems", nullptr, kFixed & ~ImGuiWindowFlags_NoDecoration);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::PushTextWrapPos(width - 24);
    ImGui::TextUnformatted(errors.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
    if (ImGui::SmallButton("dismiss")) {
        messages.openError.clear();
        messages.fileError.clear();
    }
    ImGui::End();
}

} // namespace rmsc::app
