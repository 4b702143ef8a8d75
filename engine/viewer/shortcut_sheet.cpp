// The shortcut sheet (see shortcut_sheet.hpp).
#include "shortcut_sheet.hpp"

#include "editor/shortcut_table.hpp"

#include <imgui.h>

#include <algorithm>
#include <vector>

namespace rmsc::app {

void drawShortcutSheet(bool& open, const Rect& viewport) {
    if (!open) return;
    // In the middle of the window, over the view and the panels, as wide as the window allows.
    const float em = ImGui::GetFontSize();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, viewport.y + viewport.height * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(
        ImVec2(std::min(display.x - 2 * em, 48 * em), std::min(viewport.height - em, 36 * em)),
        ImGuiCond_Appearing);
    ImGui::SetNextWindowBgAlpha(0.95f);
    if (!ImGui::Begin("Keyboard shortcuts (F1)", &open,
                      ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::End();
        return;
    }
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    const std::vector<editor::SheetLine> lines = editor::shortcutSheetLines();
    for (const editor::ShortcutSection section : editor::kShortcutSections) {
        const std::string_view name = editor::sectionName(section);
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.35f, 1.0f), "%.*s", int(name.size()), name.data());
        if (ImGui::BeginTable(name.data(), 2, flags)) {
            ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, 12 * em);
            ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
            for (const editor::SheetLine& line : lines) {
                if (line.section != section) continue;
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::PushTextWrapPos(0.0f);
                ImGui::TextUnformatted(line.keys.c_str());
                ImGui::PopTextWrapPos();
                ImGui::TableNextColumn();
                ImGui::PushTextWrapPos(0.0f);
                ImGui::TextUnformatted(line.description.data(),
                                       line.description.data() + line.description.size());
                ImGui::PopTextWrapPos();
            }
            ImGui::EndTable();
        }
        ImGui::Spacing();
    }
    if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) &&
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        open = false;
    ImGui::End();
}

} // namespace rmsc::app
