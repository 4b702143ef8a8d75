// The main menu bar, one function per menu (see menu_bar.hpp).
#include "menu_bar.hpp"

#include "document_edits.hpp"
#include "editor/multi_selection.hpp"
#include "editor/selection_edits.hpp"
#include "export_dialog.hpp"
#include "panel_widgets.hpp"
#include "scene/light_spec.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"
#include "shortcuts.hpp"
#include "view_shortcuts.hpp"

#include <imgui.h>

#include <string>

namespace rmsc::app {
namespace {

using editor::ShortcutAction;

// File > Open Recent: the newest first; a file that no longer exists is greyed.
void drawRecentMenu(const std::vector<std::filesystem::path>& recent, ViewerCommands& commands) {
    if (!ImGui::BeginMenu("Open Recent", !recent.empty())) return;
    bool missing = false;
    for (std::size_t i = 0; i < recent.size(); ++i) {
        std::error_code ec;
        const bool exists = std::filesystem::exists(recent[i], ec);
        missing = missing || !exists;
        const std::string label = recent[i].filename().string() + (exists ? "" : " (missing)") +
                                  "##recent" + std::to_string(i);
        if (ImGui::MenuItem(label.c_str(), nullptr, false, exists))
            commands.push_back({ViewerCommand::OpenFile, recent[i]});
        helpTooltip(recent[i].string());
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Remove missing files", nullptr, false, missing))
        commands.push_back(ViewerCommand::ForgetMissingRecent);
    if (ImGui::MenuItem("Clear the list")) commands.push_back(ViewerCommand::ClearRecent);
    ImGui::EndMenu();
}

void drawFileMenu(const editor::Document& document, bool exporting,
                  const std::vector<std::filesystem::path>& recent, ViewerCommands& commands) {
    if (!ImGui::BeginMenu("File")) return;
    if (ImGui::MenuItem("New")) commands.push_back(ViewerCommand::NewScene);
    if (ImGui::MenuItem("Open...", menuShortcut(ShortcutAction::Open)))
        commands.push_back(ViewerCommand::Open);
    drawRecentMenu(recent, commands);
    if (ImGui::MenuItem("Save", menuShortcut(ShortcutAction::Save)))
        commands.push_back(ViewerCommand::Save);
    if (ImGui::MenuItem("Save As...", menuShortcut(ShortcutAction::SaveAs)))
        commands.push_back(ViewerCommand::SaveAs);
    ImGui::Separator();
    // One export at a time: the items wait while one runs.
    if (ImGui::MenuItem("Export scene...", nullptr, false, !exporting && document.scene().sdf))
        commands.push_back(ViewerCommand::ExportScene);
    if (ImGui::MenuItem("Export selection...", nullptr, false,
                        !exporting && canExportSelection(document)))
        commands.push_back(ViewerCommand::ExportSelection);
    ImGui::Separator();
    if (ImGui::MenuItem("Screenshot", menuShortcut(ShortcutAction::Screenshot)))
        commands.push_back(ViewerCommand::Screenshot);
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) commands.push_back(ViewerCommand::Quit);
    ImGui::EndMenu();
}

void drawEditMenu(editor::Document& document, ViewerCommands& commands) {
    if (!ImGui::BeginMenu("Edit")) return;
    const std::string undo = "Undo " + document.undoLabel();
    const std::string redo = "Redo " + document.redoLabel();
    if (ImGui::MenuItem(undo.c_str(), menuShortcut(ShortcutAction::Undo), false,
                        document.canUndo()))
        commands.push_back(ViewerCommand::Undo);
    if (ImGui::MenuItem(redo.c_str(), menuShortcut(ShortcutAction::Redo), false,
                        document.canRedo()))
        commands.push_back(ViewerCommand::Redo);
    ImGui::Separator();
    const bool selected = !document.selection.empty();
    if (ImGui::MenuItem("Copy", menuShortcut(ShortcutAction::Copy), false, selected))
        commands.push_back(ViewerCommand::Copy);
    if (ImGui::MenuItem("Paste", menuShortcut(ShortcutAction::Paste)))
        commands.push_back(ViewerCommand::Paste);
    if (ImGui::MenuItem("Duplicate", menuShortcut(ShortcutAction::Duplicate), false, selected))
        commands.push_back(ViewerCommand::Duplicate);
    if (ImGui::MenuItem("Delete", menuShortcut(ShortcutAction::Delete), false, selected))
        commands.push_back(ViewerCommand::Delete);
    // The selected SDF nodes into a new group of the chosen operation (Ctrl+G: union).
    const bool groupable =
        !editor::outermostSdfPaths(document.scene(), editor::selectedItems(document)).empty();
    if (ImGui::BeginMenu("Group selection", groupable)) {
        for (const OperationSpec& op : operationCatalogue()) {
            if (ImGui::MenuItem(operationLabel(op.op).c_str(),
                                op.op == SdfOp::Union ? menuShortcut(ShortcutAction::GroupUnion)
                                                      : nullptr))
                groupSelection(document, op.op);
            helpTooltip(op.description);
        }
        ImGui::EndMenu();
    }
    ImGui::MenuItem("Add to selection", "Shift+click", false, false);
    // The gestures, for their keys (they need the mouse over the view).
    ImGui::MenuItem("Move (grab)", "G, then X/Y/Z", false, false);
    ImGui::MenuItem("Rotate", "R, then X/Y/Z", false, false);
    ImGui::MenuItem("Scale", "S, then X/Y/Z", false, false);
    ImGui::EndMenu();
}

void drawAddMenu(editor::Document& document, const NewShapePlace& place, ViewerCommands& commands) {
    if (!ImGui::BeginMenu("Add")) return;
    if (ImGui::BeginMenu("Shape")) {
        for (const PrimitiveSpec& spec : primitiveCatalogue()) {
            if (ImGui::MenuItem(std::string(spec.name).c_str())) addShape(document, spec, place);
            helpTooltip(spec.description);
        }
        ImGui::Separator();
        for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
            if (ImGui::MenuItem(std::string(solid.name).c_str()))
                addProfileShape(document, solid.solid, place);
            helpTooltip(solid.description);
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Group")) {
        for (const OperationSpec& op : operationCatalogue())
            if (ImGui::MenuItem(operationLabel(op.op).c_str())) addGroup(document, op.op);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Light")) {
        for (const LightType type : kLightTypes)
            if (ImGui::MenuItem(std::string(lightTypeName(type)).c_str(), nullptr, false,
                                canAddLight(document)))
                commands.push_back(addLightCommand(type));
        ImGui::EndMenu();
    }
    if (ImGui::MenuItem("glTF mesh from a file...")) commands.push_back(ViewerCommand::AddMesh);
    ImGui::Separator();
    // At the mouse, which is over this menu now: Shift+A over the view puts it there. (The keys
    // in the label, not as a shortcut column, which would widen the menu.)
    const std::string search =
        "Search... (" + std::string(editor::shortcutKeys(ShortcutAction::AddSearch)) + ")";
    if (ImGui::MenuItem(search.c_str())) commands.push_back(ViewerCommand::AddSearch);
    ImGui::EndMenu();
}

// A menu item for a view request, with its shortcut's keys.
void viewItem(const char* label, ViewRequest request, EditorSession& session, Messages& messages,
              bool selected = false, bool enabled = true) {
    if (ImGui::MenuItem(label, viewShortcutKeys(request), selected, enabled))
        applyViewRequest(session, request, messages);
}

void drawViewMenu(EditorSession& session, ViewSettings& view, Messages& messages) {
    if (!ImGui::BeginMenu("View")) return;
    const char* names[] = {"Colour", "Normals", "Depth", "Object id", "March steps"};
    for (int i = 0; i < 5; ++i)
        if (ImGui::MenuItem(names[i], nullptr, int(view.mode) == i)) view.mode = ViewMode(i);
    ImGui::Separator();
    // The views along the axes, looking at the point the view looks at.
    const std::optional<editor::AxisView> along = session.camera.axisView();
    const struct {
        const char* label;
        ViewAction action;
        editor::AxisView view;
    } axisViews[] = {
        {"Front", ViewAction::FromFront, editor::AxisView::Front},
        {"Back", ViewAction::FromBack, editor::AxisView::Back},
        {"Right", ViewAction::FromRight, editor::AxisView::Right},
        {"Left", ViewAction::FromLeft, editor::AxisView::Left},
        {"Top", ViewAction::FromTop, editor::AxisView::Top},
        {"Bottom", ViewAction::FromBottom, editor::AxisView::Bottom},
    };
    for (const auto& v : axisViews)
        viewItem(v.label, {v.action}, session, messages, along == v.view);
    viewItem("Orthographic", {ViewAction::ToggleOrthographic}, session, messages,
             session.camera.orthographic);
    ImGui::Separator();
    ImGui::MenuItem("Overlay", nullptr, &view.showOverlay);
    ImGui::MenuItem("Light markers", nullptr, &view.showLights);
    ImGui::MenuItem("Adaptive resolution", nullptr, &view.adaptive.enabled);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * (120.0f / 13.0f));
    numberField("target ms", &view.adaptive.targetMilliseconds, 1, 0.5f,
                closedRange(5.0, 500.0, Unit::Milliseconds),
                "The frame time the adaptive resolution holds while the view changes.",
                {.format = "%.0f ms"});
    ImGui::EndMenu();
}

void drawCameraMenu(EditorSession& session, Messages& messages, ViewerCommands& commands) {
    if (!ImGui::BeginMenu("Camera")) return;
    if (ImGui::MenuItem("Frame selection", menuShortcut(ShortcutAction::FrameSelection)))
        commands.push_back(ViewerCommand::FrameSelection);
    if (ImGui::MenuItem("Save camera to scene")) commands.push_back(ViewerCommand::SaveCamera);
    if (ImGui::MenuItem("Reset to scene camera")) commands.push_back(ViewerCommand::ResetCamera);
    ImGui::Separator();
    // Bookmarks: keep the view in a slot, or go back to a kept one.
    if (ImGui::BeginMenu("Keep view as bookmark")) {
        for (int slot = 1; slot <= editor::kViewBookmarks; ++slot)
            viewItem(("Bookmark " + std::to_string(slot)).c_str(),
                     {ViewAction::StoreBookmark, slot}, session, messages,
                     session.bookmarks.recall(slot).has_value());
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Go to bookmark")) {
        for (int slot = 1; slot <= editor::kViewBookmarks; ++slot)
            viewItem(("Bookmark " + std::to_string(slot)).c_str(),
                     {ViewAction::RecallBookmark, slot}, session, messages, false,
                     session.bookmarks.recall(slot).has_value());
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Allow roll (Q / E)", nullptr, session.camera.allowRoll))
        applyViewRequest(session, {ViewAction::ToggleRoll}, messages);
    helpTooltip("Off (the default), the horizon stays level: Q / E do nothing and looking or "
                "orbiting stops at straight up or down; turning it off levels the view");
    ImGui::EndMenu();
}

void drawHelpMenu(ViewerCommands& commands) {
    if (!ImGui::BeginMenu("Help")) return;
    if (ImGui::MenuItem("Keyboard shortcuts", menuShortcut(ShortcutAction::ShortcutSheet)))
        commands.push_back(ViewerCommand::ShortcutSheet);
    ImGui::MenuItem("Hover a field for its unit and range", nullptr, false, false);
    ImGui::EndMenu();
}

} // namespace

void drawMenus(EditorSession& session, ViewSettings& view, const NewShapePlace& place,
               bool exporting, const std::vector<std::filesystem::path>& recent, Messages& messages,
               ViewerCommands& commands) {
    editor::Document& document = session.document;
    drawFileMenu(document, exporting, recent, commands);
    drawEditMenu(document, commands);
    drawAddMenu(document, place, commands);
    drawViewMenu(session, view, messages);
    drawCameraMenu(session, messages, commands);
    drawHelpMenu(commands);
}

void drawMenuBarTitle(const editor::Document& document) {
    const std::string title =
        (document.file().empty() ? std::string("(unsaved scene)") : document.file().string()) +
        (document.dirty() ? " *" : "");
    ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(title.c_str()).x - 16);
    ImGui::TextDisabled("%s", title.c_str());
}

} // namespace rmsc::app
