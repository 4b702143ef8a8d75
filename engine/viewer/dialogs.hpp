// The modal dialogs: recover the edits a recovery file holds, unsaved changes (before closing,
// New or opening another scene), the file browser (open, save as, add a mesh, a file field's
// file), the scene file changed on disk while there are unsaved edits, and, before a save,
// whether the scene camera should take the view when they differ. A dialog opens on the frame
// after it was asked for (the ask* flags) and, when answered, acts on the session, its files and
// the messages.
#pragma once

#include "editor_session.hpp"
#include "file_browser_dialog.hpp"
#include "file_field.hpp"
#include "messages.hpp"
#include "scene_files.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace rmsc::app {

// What the file browser's choice is for; Field: the file of `Dialogs::browseField`.
enum class PathPurpose { Open, SaveAs, AddMesh, Field };
// What the unsaved-changes dialog goes on with: quit, a new scene, or open `openAfterDiscard`.
enum class AfterDiscard { Quit, New, Open };

struct Dialogs {
    bool askRecover = false; // the recovery file found at start (offeredRecovery)
    bool askClose = false;   // unsaved changes; then afterDiscard
    bool askReload = false;  // the scene file changed on disk, with unsaved edits
    bool askCamera = false;  // save (or save as, cameraThenSaveAs): the view differs from the
                             // scene camera; update it, keep it, or cancel
    bool cameraThenSaveAs = false;
    AfterDiscard afterDiscard = AfterDiscard::Quit;
    std::filesystem::path openAfterDiscard;
    FileBrowser browser;
    PathPurpose pathPurpose = PathPurpose::Open;
    FileField* browseField = nullptr; // PathPurpose::Field: gets the chosen file, applied
    glm::vec3 newMeshAt{0.0f};        // PathPurpose::AddMesh: where the mesh goes (where a new
                                      // shape would, when the browser was opened)
    std::optional<std::filesystem::path> offeredRecovery;
    bool quitNow = false; // closing is decided: the frame loop ends

    // Opens the file browser for `purpose` at `start` (a file or a folder).
    void askForPath(PathPurpose purpose, const std::filesystem::path& start);
    // Opens it for a file field (its kind's filter), starting in `sceneFolder`.
    void askForFieldFile(FileField& field, const std::filesystem::path& sceneFolder);
};

// Closes now, or asks first when there are unsaved changes (after the save under way, if any,
// is written: it may leave none).
void requestClose(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages);
// A new scene now, or asks first when there are unsaved changes (the same).
void requestNew(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages);
// Opens the scene file `path` now, or asks first when there are unsaved changes (the same).
void requestOpen(Dialogs& dialogs, const std::filesystem::path& path, EditorSession& session,
                 SceneFiles& files, Messages& messages);
// Saves to the scene's file, or asks for one when it has none yet.
void saveScene(EditorSession& session, SceneFiles& files, Messages& messages, Dialogs& dialogs);
// Save (Ctrl+S) or Save As (Ctrl+Shift+S) as the user asked for it: first, when the view shows
// something else than the scene camera, asks whether the scene camera should take the view.
void requestSave(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages,
                 bool saveAs);

// Opens the dialogs asked for and draws the open one.
void drawDialogs(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages);

} // namespace rmsc::app
