// The export dialog and the export's progress window (see export_dialog.hpp).
#include "export_dialog.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <thread>

namespace rmsc::app {
namespace {

// The file the dialog proposes: beside the scene (or in the working folder for a scene never
// saved), named after the scene or the selected node, as binary glTF.
std::string proposedPath(const editor::Document& document, const std::string& name) {
    const std::filesystem::path folder = document.file().parent_path();
    std::string stem = name;
    if (stem.empty()) stem = document.file().empty() ? "scene" : document.file().stem().string();
    std::replace_if(
        stem.begin(), stem.end(),
        [](char c) { return c == '/' || c == '\\' || c == ' ' || c == ':'; }, '_');
    return (folder / (stem + ".glb")).string();
}

// The selected node's name, or "" (the node is then named after the scene).
std::string selectedName(const editor::Document& document) {
    const SdfNode* node = document.scene().sdf ? &*document.scene().sdf : nullptr;
    for (int index : document.selection.sdfPath) {
        if (!node || index < 0 || std::size_t(index) >= node->children.size()) return "";
        node = &node->children[std::size_t(index)];
    }
    return node ? node->name : "";
}

} // namespace

bool canExportSelection(const editor::Document& document) {
    return document.selection.kind == editor::SelectionKind::Sdf && document.scene().sdf;
}

void openExportDialog(ExportUi& ui, const editor::Document& document, bool selection,
                      glm::vec3 focus) {
    ui.selection = selection && canExportSelection(document);
    ui.form.node = ui.selection ? editor::sdfNodePointer(document.selection.sdfPath) : "/sdf";
    ui.form.path = proposedPath(document, ui.selection ? selectedName(document) : "");
    ui.content = editor::describeExportContent(document.scene(), ui.form.node);
    if (ui.content.found && ui.content.bounded) {
        ui.form.clip = false;
        ui.form.bounds = ui.content.box;
    } else {
        ui.form.clip = true;
        ui.form.bounds = Aabb{focus - glm::vec3(2.0f), focus + glm::vec3(2.0f)};
    }
    ui.error.clear();
    ui.ask = true;
}

void drawExportDialog(ExportUi& ui, const editor::Document& document) {
    const char* title = "Export mesh";
    if (ui.ask) {
        ImGui::OpenPopup(title);
        ui.ask = false;
    }
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    editor::ExportForm& form = ui.form;
    if (ui.selection)
        ImGui::Text("The selected node, %s, in its place in the scene", form.node.c_str());
    else
        ImGui::TextUnformatted("The scene's whole SDF tree");
    if (!ui.content.error.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", ui.content.error.c_str());
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(420);
    const bool entered = ImGui::InputText("File", &form.path, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::TextDisabled("the extension picks the format: .glb, .gltf, .obj (with .mtl), .stl");
    int sizing = form.byVoxel ? 1 : 0;
    ImGui::RadioButton("Resolution", &sizing, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Voxel size", &sizing, 1);
    form.byVoxel = sizing == 1;
    ImGui::SetNextItemWidth(160);
    if (form.byVoxel)
        ImGui::InputFloat("metres a cell", &form.voxel, 0.001f, 0.01f, "%.4f");
    else
        ImGui::InputInt("cells along the longest side", &form.resolution, 8, 64);
    ImGui::SetNextItemWidth(160);
    ImGui::InputFloat("tolerance (voxels)", &form.tolerance, 0.01f, 0.1f, "%.3f");
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("How far the adaptive octree may let the surface move where it joins\n"
                          "cells into one vertex, so flat regions take few triangles; 0 keeps\n"
                          "one vertex per cell");
    const bool unbounded = ui.content.found && !ui.content.bounded;
    if (unbounded) {
        form.clip = true; // the export refuses unbounded content without bounds
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f),
                           "%s reaches infinity: the mesh is cut to these bounds",
                           ui.content.unboundedBy.c_str());
    }
    ImGui::BeginDisabled(unbounded);
    ImGui::Checkbox("Cut to bounds (closed at the box's faces)", &form.clip);
    ImGui::EndDisabled();
    ImGui::BeginDisabled(!form.clip);
    ImGui::SetNextItemWidth(300);
    ImGui::DragFloat3("min", &form.bounds.min.x, 0.01f);
    ImGui::SetNextItemWidth(300);
    ImGui::DragFloat3("max", &form.bounds.max.x, 0.01f);
    ImGui::EndDisabled();
    if (!ui.error.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", ui.error.c_str());
    if (ImGui::Button("Export") || entered) {
        // Leave one core to the view and the panels.
        const int threads = int(std::max(1u, std::thread::hardware_concurrency() - 1));
        if (ui.job.start(document.scene(), form, threads, ui.error)) {
            ui.error.clear();
            ImGui::CloseCurrentPopup();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void drawExportProgress(ExportUi& ui, const Rect& viewport, Messages& messages) {
    if (ui.job.running()) {
        ImGui::SetNextWindowPos(
            ImVec2(viewport.x + viewport.width - 8, viewport.y + viewport.height - 8), 0,
            ImVec2(1, 1));
        ImGui::SetNextWindowBgAlpha(0.85f);
        ImGui::Begin("export progress", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                         ImGuiWindowFlags_NoNav);
        ImGui::Text("Exporting %s", ui.job.output().filename().string().c_str());
        ImGui::ProgressBar(float(ui.job.progress()), ImVec2(240, 0));
        if (ImGui::Button("Cancel export")) ui.job.cancel();
        ImGui::End();
    }
    if (std::optional<editor::ExportOutcome> outcome = ui.job.takeOutcome()) {
        if (outcome->written || outcome->cancelled)
            messages.notice(outcome->message);
        else {
            messages.fileError = "Export failed: " + outcome->message;
            std::fprintf(stderr, "rmsc view: export failed: %s\n", outcome->message.c_str());
        }
    }
}

} // namespace rmsc::app
