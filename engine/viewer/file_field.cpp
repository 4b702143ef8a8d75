// The applied file name field (see file_field.hpp).
#include "file_field.hpp"

#include "panel_widgets.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace rmsc::app {

bool drawFileField(const char* label, FileField& field, int owner, const std::string& file,
                   std::string_view help) {
    if (field.owner != owner || field.shownFile != file) {
        field.owner = owner;
        field.shownFile = file;
        field.text = file;
        field.error.clear();
    }
    ImGui::PushID(label);
    const bool entered = ImGui::InputText(label, &field.text, ImGuiInputTextFlags_EnterReturnsTrue);
    helpTooltip(help);
    ImGui::SameLine();
    const bool applied = ImGui::SmallButton("apply") || entered;
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
