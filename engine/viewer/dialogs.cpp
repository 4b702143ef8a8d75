// The modal dialogs, each a function of its own (see dialogs.hpp).
#include "dialogs.hpp"

#include "editor/camera_edits.hpp"
#include "editor/dropped_files.hpp"
#include "editor/file_browser.hpp"
#include "editor/recovery.hpp"
#include "editor/scene_edits.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace rmsc::app {
namespace {

// Dialogs open in the middle of the window.
void centerNextWindow() {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
}

// Opens popup `name` when `ask` is set (and clears it); then begins it when it is open.
bool beginModal(const char* name, bool& ask) {
    if (ask) {
        ImGui::OpenPopup(name);
        ask = false;
    }
    centerNextWindow();
    return ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

bool cancelled(const char* label) {
    return ImGui::Button(label) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
}

void drawRecoverDialog(Dialogs& dialogs, editor::Document& document, Messages& messages) {
    if (!beginModal("Recover unsaved edits", dialogs.askRecover)) return;
    ImGui::Text("Edits that were never saved were found in\n%s",
                dialogs.offeredRecovery ? dialogs.offeredRecovery->string().c_str() : "");
    if (ImGui::Button("Recover")) {
        Diagnostics diagnostics;
        std::optional<Scene> recovered =
            dialogs.offeredRecovery
                ? editor::loadSceneForEditing(*dialogs.offeredRecovery, diagnostics)
                : std::nullopt;
        if (recovered) {
            recovered->file = document.scene().file;
            document.apply("Recover unsaved edits",
                           [&](Scene& scene, editor::Selection&) { scene = *recovered; });
            messages.notice("recovered the unsaved edits; save to keep them");
        } else {
            messages.fileError = "The recovery file does not load:\n" + diagnostics.format();
        }
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard them")) {
        editor::removeRecovery(document.file());
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

// After the changes were saved or discarded: quit, the new scene or the file the user asked for.
void goOnAfterDiscard(Dialogs& dialogs, EditorSession& session, SceneFiles& files,
                      Messages& messages) {
    switch (dialogs.afterDiscard) {
    case AfterDiscard::Quit:
        dialogs.quitNow = true;
        break;
    case AfterDiscard::New:
        newScene(session, files, messages);
        break;
    case AfterDiscard::Open:
        openSceneFile(dialogs.openAfterDiscard, session, files, messages);
        break;
    }
}

void drawUnsavedChangesDialog(Dialogs& dialogs, EditorSession& session, SceneFiles& files,
                              Messages& messages) {
    if (!beginModal("Unsaved changes", dialogs.askClose)) return;
    ImGui::Text("The scene has unsaved changes.");
    if (ImGui::Button("Save")) {
        // What follows (quitting, another scene) needs the file written: waited for here.
        saveScene(session, files, messages, dialogs);
        finishSave(session.document, files, messages, true);
        if (!session.document.dirty()) goOnAfterDiscard(dialogs, session, files, messages);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard changes")) {
        removeRecoveryFile(files, session.document.file());
        goOnAfterDiscard(dialogs, session, files, messages);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (cancelled("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

// What the file browser's choice is used for.
void usePath(const std::filesystem::path& path, Dialogs& dialogs, EditorSession& session,
             SceneFiles& files, Messages& messages) {
    const PathPurpose purpose = dialogs.pathPurpose;
    if (purpose == PathPurpose::Open) {
        requestOpen(dialogs, path, session, files, messages);
    } else if (purpose == PathPurpose::Field) {
        if (dialogs.browseField) {
            dialogs.browseField->text =
                editor::fileFieldText(path, session.document.file().parent_path());
            dialogs.browseField->applyNow = true;
        }
    } else if (purpose == PathPurpose::SaveAs) {
        saveSceneAs(path, session.document, files, messages);
    } else {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) {
            messages.fileError = path.string() + ": no such file";
        } else {
            session.document.apply("Add mesh", [&](Scene& scene, editor::Selection& selection) {
                editor::addMeshAt(scene, selection, path, dialogs.newMeshAt);
            });
        }
    }
}

void drawPathDialog(Dialogs& dialogs, EditorSession& session, SceneFiles& files,
                    Messages& messages) {
    if (const std::optional<std::filesystem::path> chosen = drawFileBrowser(dialogs.browser))
        usePath(*chosen, dialogs, session, files, messages);
}

void drawChangedOnDiskDialog(Dialogs& dialogs, editor::Document& document, Messages& messages) {
    if (!beginModal("Changed on disk", dialogs.askReload)) return;
    ImGui::Text("%s changed on disk, and you have unsaved edits.",
                document.file().string().c_str());
    if (ImGui::Button("Reload (lose my edits)")) {
        Diagnostics diagnostics;
        if (std::optional<Scene> scene = editor::loadSceneForEditing(document.file(), diagnostics))
            document.reloadFromDisk(*scene);
        else
            messages.sceneError = diagnostics.format();
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep my edits")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

// Saves, or asks for the file to save as.
void goOnSaving(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages,
                bool saveAs) {
    if (saveAs)
        dialogs.askForPath(PathPurpose::SaveAs, session.document.file().empty()
                                                    ? std::filesystem::current_path() / "scene.json"
                                                    : session.document.file());
    else
        saveScene(session, files, messages, dialogs);
}

void drawCameraOnSaveDialog(Dialogs& dialogs, EditorSession& session, SceneFiles& files,
                            Messages& messages) {
    if (!beginModal("Scene camera", dialogs.askCamera)) return;
    ImGui::TextUnformatted("The view is not the scene camera's. Should the saved scene's camera\n"
                           "look from the view (rmsc render draws what the scene camera sees)?");
    if (ImGui::Button("Update the scene camera")) {
        session.saveCameraToScene(); // an undo step of its own
        goOnSaving(dialogs, session, files, messages, dialogs.cameraThenSaveAs);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    // The default (Enter): the scene as edited, its camera as it was.
    if (ImGui::Button("Keep the scene camera") ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)) {
        goOnSaving(dialogs, session, files, messages, dialogs.cameraThenSaveAs);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (cancelled("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::TextDisabled("Enter keeps the scene camera; Esc cancels the save.");
    ImGui::EndPopup();
}

} // namespace

void requestSave(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages,
                 bool saveAs) {
    if (editor::viewDiffersFromCamera(session.viewCamera(), session.document.scene().camera)) {
        messages.notice("the view is not the scene camera's: update the scene camera, keep it, "
                        "or cancel the save?");
        dialogs.askCamera = true;
        dialogs.cameraThenSaveAs = saveAs;
        return;
    }
    goOnSaving(dialogs, session, files, messages, saveAs);
}

void Dialogs::askForPath(PathPurpose purpose, const std::filesystem::path& start) {
    pathPurpose = purpose;
    browseField = nullptr;
    switch (purpose) {
    case PathPurpose::Open:
        browser.open("Open scene", editor::FileKind::Scene, false, start);
        break;
    case PathPurpose::SaveAs:
        browser.open("Save scene as", editor::FileKind::Scene, true, start);
        break;
    case PathPurpose::AddMesh:
    case PathPurpose::Field:
        browser.open("Add a glTF mesh", editor::FileKind::Mesh, false, start);
        break;
    }
}

void Dialogs::askForFieldFile(FileField& field, const std::filesystem::path& sceneFolder) {
    pathPurpose = PathPurpose::Field;
    browseField = &field;
    const char* title = field.kind == editor::FileKind::Mesh    ? "Choose a glTF file"
                        : field.kind == editor::FileKind::Sky   ? "Choose a sky image"
                        : field.kind == editor::FileKind::Scene ? "Choose a scene file"
                                                                : "Choose a texture";
    // Start where the field's file is, else in the scene's folder.
    std::filesystem::path start = sceneFolder;
    if (!field.text.empty()) {
        const std::filesystem::path typed(field.text);
        start = typed.is_absolute() ? typed : sceneFolder / typed;
    }
    browser.open(title, field.kind, false, start);
}

void requestOpen(Dialogs& dialogs, const std::filesystem::path& path, EditorSession& session,
                 SceneFiles& files, Messages& messages) {
    finishSave(session.document, files, messages, true);
    if (session.document.dirty()) {
        dialogs.askClose = true;
        dialogs.afterDiscard = AfterDiscard::Open;
        dialogs.openAfterDiscard = path;
    } else {
        openSceneFile(path, session, files, messages);
    }
}

void requestClose(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages) {
    finishSave(session.document, files, messages, true);
    if (session.document.dirty())
        dialogs.askClose = true;
    else
        dialogs.quitNow = true;
}

void requestNew(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages) {
    finishSave(session.document, files, messages, true);
    if (session.document.dirty()) {
        dialogs.askClose = true;
        dialogs.afterDiscard = AfterDiscard::New;
    } else {
        newScene(session, files, messages);
    }
}

void saveScene(EditorSession& session, SceneFiles& files, Messages& messages, Dialogs& dialogs) {
    if (session.document.file().empty())
        dialogs.askForPath(PathPurpose::SaveAs, std::filesystem::current_path() / "scene.json");
    else
        saveSceneAs(session.document.file(), session.document, files, messages);
}

void drawDialogs(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages) {
    drawRecoverDialog(dialogs, session.document, messages);
    drawUnsavedChangesDialog(dialogs, session, files, messages);
    drawPathDialog(dialogs, session, files, messages);
    drawChangedOnDiskDialog(dialogs, session.document, messages);
    drawCameraOnSaveDialog(dialogs, session, files, messages);
}

} // namespace rmsc::app
