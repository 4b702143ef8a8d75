// The modal dialogs: recover the edits a recovery file holds, unsaved changes (before closing or
// New), a file path (open, save as, add a mesh), the scene file changed on disk while there
// are unsaved edits, and, before a save, whether the scene camera should take the view when
// they differ. A dialog opens on the frame after it was asked for (the ask* flags) and,
// when answered, acts on the session, its files and the messages.
#pragma once

#include "editor_session.hpp"
#include "messages.hpp"
#include "scene_files.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace rmsc::app {

enum class PathPurpose { Open, SaveAs, AddMesh };
enum class AfterDiscard { Quit, New }; // what the unsaved-changes dialog goes on with

struct Dialogs {
    bool askRecover = false; // the recovery file found at start (offeredRecovery)
    bool askClose = false;   // unsaved changes; then afterDiscard
    bool askPath = false;    // a file for pathPurpose, starting from pathBuffer
    bool askReload = false;  // the scene file changed on disk, with unsaved edits
    bool askCamera = false;  // save (or save as, cameraThenSaveAs): the view differs from the
                             // scene camera; update it, keep it, or cancel
    bool cameraThenSaveAs = false;
    AfterDiscard afterDiscard = AfterDiscard::Quit;
    PathPurpose pathPurpose = PathPurpose::Open;
    std::string pathBuffer;
    std::optional<std::filesystem::path> offeredRecovery;
    bool quitNow = false; // closing is decided: the frame loop ends

    void askForPath(PathPurpose purpose, std::string initial);
};

// Closes now, or asks first when there are unsaved changes.
void requestClose(Dialogs& dialogs, const editor::Document& document);
// Saves to the scene's file, or asks for one when it has none yet.
void saveScene(EditorSession& session, SceneFiles& files, Messages& messages, Dialogs& dialogs);
// Save (Ctrl+S) or Save As (Ctrl+Shift+S) as the user asked for it: first, when the view shows
// something else than the scene camera, asks whether the scene camera should take the view.
void requestSave(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages,
                 bool saveAs);

// Opens the dialogs asked for and draws the open one.
void drawDialogs(Dialogs& dialogs, EditorSession& session, SceneFiles& files, Messages& messages);

} // namespace rmsc::app
