// The applied file name field (see file_field.hpp).
#include "file_field.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace rmsc::app {

bool drawFileField(const char* label, FileField& field, int owner, const std::string& file,
                   std::string_view help, editor::FileKind kind) {
    if (field.owner != owner || field.shownFile != file) {
        field.owner = owner;
        field.shownFile = file;
        field.text = file;
        field.error.clear();
        field.applyNow = false; // chosen for another owner
    }
    field.kind = kind;
    ImGui::PushID(label);
    const float buttons = ImGui::CalcTextSize("...apply").x +
                          ImGui::GetStyle().FramePadding.x * 4.0f +
                          ImGui::GetStyle().ItemSpacing.x * 2.0f;
    ImGui::SetNextItemWidth(
        std::max(4.0f * ImGui::GetFontSize(), ImGui::CalcItemWidth() - buttons));
    const bool entered = ImGui::InputText(label, &field.text, ImGuiInputTextFlags_EnterReturnsTrue);
    helpTooltip(help);
    ImGui::SameLine();
    if (ImGui::SmallButton("...")) field.browse = true;
    helpTooltip("Choose the file in the file browser.");
    ImGui::SameLine();
    const bool applied = ImGui::SmallButton("apply") || entered || field.applyNow;
    field.applyNow = false;
    ImGui::PopID();
    return applied;
}

void drawRefusal(const std::string& error) {
    if (error.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
}

} // namespace rmsc::app
