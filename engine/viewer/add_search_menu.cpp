// The searchable add menu's popup (see add_search_menu.hpp).
#include "add_search_menu.hpp"

#include "document_edits.hpp"
#include "editor/add_search.hpp"
#include "panel_widgets.hpp"
#include "sdf/operations.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <type_traits>
#include <vector>

namespace rmsc::app {
namespace {

constexpr const char* kPopup = "Add##search";

// Adds `item` as the Add menu does (a shape where `place` says).
void addItem(const editor::AddItem& item, editor::Document& document, const NewShapePlace& place,
             ViewerCommands& commands) {
    std::visit(
        [&](const auto& what) {
            using T = std::decay_t<decltype(what)>;
            if constexpr (std::is_same_v<T, PrimitiveId>)
                addShape(document, primitiveSpec(what), place);
            else if constexpr (std::is_same_v<T, SdfProfileSolid>)
                addProfileShape(document, what, place);
            else if constexpr (std::is_same_v<T, SdfOp>)
                addGroup(document, what);
            else if constexpr (std::is_same_v<T, LightType>)
                commands.push_back(addLightCommand(what));
            else
                commands.push_back(ViewerCommand::AddMesh);
        },
        item.what);
}

bool keyPressed(ImGuiKey key) {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key));
}

} // namespace

void drawAddSearchMenu(AddSearchMenu& menu, editor::Document& document, const NewShapePlace& place,
                       ViewerCommands& commands) {
    if (menu.askOpen) {
        ImGui::OpenPopup(kPopup);
        menu.askOpen = false;
        menu.query.clear();
        menu.highlighted = 0;
    }
    ImGui::SetNextWindowPos(ImVec2(menu.at.x, menu.at.y), ImGuiCond_Appearing);
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowSizeConstraints(ImVec2(22 * em, 0), ImVec2(32 * em, 30 * em));
    menu.open = ImGui::BeginPopup(kPopup);
    if (!menu.open) return;
    const std::vector<editor::AddItem>& items = editor::addItems();
    ImGui::TextDisabled("Add (type to search, Up / Down, Enter)");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1);
    const bool entered =
        ImGui::InputTextWithHint("##search", "shape, group, light, mesh...", &menu.query,
                                 ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemEdited()) menu.highlighted = 0;
    const std::vector<int> found = editor::searchAddItems(items, menu.query);
    const int count = int(found.size());
    bool moved = false;
    if (keyPressed(ImGuiKey_DownArrow)) {
        menu.highlighted = editor::moveHighlight(menu.highlighted, 1, count);
        moved = true;
    }
    if (keyPressed(ImGuiKey_UpArrow)) {
        menu.highlighted = editor::moveHighlight(menu.highlighted, -1, count);
        moved = true;
    }
    if (menu.highlighted >= count) menu.highlighted = count - 1;
    int chosen = entered && menu.highlighted >= 0 ? menu.highlighted : -1;

    ImGui::BeginChild(
        "matches", ImVec2(0, std::min(float(count), 16.0f) * ImGui::GetTextLineHeightWithSpacing() +
                                 ImGui::GetStyle().WindowPadding.y));
    if (count == 0) ImGui::TextDisabled("nothing matches");
    const editor::AddCategory* previous = nullptr;
    for (int row = 0; row < count; ++row) {
        const editor::AddItem& item = items[std::size_t(found[std::size_t(row)])];
        if (previous && *previous != item.category) ImGui::Separator();
        previous = &item.category;
        ImGui::PushID(row);
        const std::string label = item.name;
        if (ImGui::Selectable(label.c_str(), row == menu.highlighted)) chosen = row;
        helpTooltip(item.description);
        const std::string_view category = editor::addCategoryName(item.category);
        ImGui::SameLine(ImGui::GetContentRegionMax().x -
                        ImGui::CalcTextSize(category.data(), category.data() + category.size()).x);
        ImGui::TextDisabled("%.*s", int(category.size()), category.data());
        if (moved && row == menu.highlighted) ImGui::SetScrollHereY();
        ImGui::PopID();
    }
    ImGui::EndChild();

    if (chosen >= 0) {
        addItem(items[std::size_t(found[std::size_t(chosen)])], document, place, commands);
        ImGui::CloseCurrentPopup();
        menu.open = false;
    } else if (keyPressed(ImGuiKey_Escape)) {
        ImGui::CloseCurrentPopup();
        menu.open = false;
    }
    ImGui::EndPopup();
}

} // namespace rmsc::app
