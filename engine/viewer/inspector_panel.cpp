// The Inspector panel's window and tabs; each kind of thing it shows has its own function
// (see inspector.hpp).
#include "inspector.hpp"

#include <imgui.h>

#include <utility>
#include <vector>

namespace rmsc::app {
namespace {

void drawObjectTab(EditorSession& session, InspectorState& state, ViewerCommands& commands) {
    const editor::Selection selection = session.document.selection;
    switch (selection.kind) {
    case editor::SelectionKind::Sdf:
        drawSdfNodeInspector(session.document, selection.sdfPath, state, commands);
        break;
    case editor::SelectionKind::Mesh:
        drawMeshInspector(session, selection.index, state, commands);
        break;
    case editor::SelectionKind::Light:
        drawLightInspector(session.document, selection.index, commands);
        break;
    case editor::SelectionKind::None:
        ImGui::TextWrapped("Nothing selected. Click an object in the view or in the Scene "
                           "panel, or add one with the + buttons.");
        break;
    }
}

void drawRenderTab(EditorSession& session, InspectorState& state, ViewSettings& view) {
    // Its labels are longer than the Object tab's 90 px ("surface epsilon" showed as "surface
    // epsil"): the column fits the longest, and its fields hold one number each.
    ImGui::PushItemWidth(
        -(ImGui::CalcTextSize("shadow normal offset").x + ImGui::GetStyle().ItemInnerSpacing.x));
    drawRenderSettingsInspector(session.document);
    ImGui::Separator();
    drawEnvironmentInspector(session.document, state.environment);
    ImGui::Separator();
    drawCameraInspector(session, state.cameraRefusal);
    ImGui::Separator();
    drawViewInspector(view);
    ImGui::PopItemWidth();
}

} // namespace

FileField* takeBrowseRequest(InspectorState& state) {
    std::vector<FileField*> fields = {&state.meshFile, &state.environment.skyFile};
    for (FileField& field : state.textureFiles)
        fields.push_back(&field);
    for (FileField* field : fields)
        if (std::exchange(field->browse, false)) return field;
    return nullptr;
}

void drawInspectorPanel(EditorSession& session, InspectorState& state, ViewSettings& view,
                        const PanelLayout& layout, ViewerCommands& commands) {
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - layout.rightPanelWidth, top));
    ImGui::SetNextWindowSize(ImVec2(layout.rightPanelWidth, io.DisplaySize.y - top));
    ImGui::Begin("Inspector", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-ImGui::GetFontSize() * (90.0f / 13.0f)); // labels: 90 px at scale 1
    if (ImGui::BeginTabBar("inspector tabs")) {
        if (ImGui::BeginTabItem("Object")) {
            drawObjectTab(session, state, commands);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Render")) {
            drawRenderTab(session, state, view);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

} // namespace rmsc::app
