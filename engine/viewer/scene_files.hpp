// The edited scene's file: the scene named on the command line, Open, New, Save As (atomic,
// editor/document.hpp), the recovery file written while there are unsaved edits
// (editor/recovery.hpp), reloading when the file changes on disk, and the recent files (every
// scene file opened or saved goes first in the list, editor/recent_files.hpp).
#pragma once

#include "editor/file_watcher.hpp"
#include "editor/recovery_job.hpp"
#include "editor/save_job.hpp"
#include "editor_session.hpp"
#include "messages.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rmsc::app {

struct SceneFiles {
    editor::FileWatcher watcher;               // the scene file; none for a scene never saved
    std::uint64_t recoveryRevision = 0;        // document revision last given to the recovery file
    double lastRecoveryWrite = -1e9;           // seconds, on the clock `now` is given in
    editor::RecoveryJob recovery;              // writes it on a worker
    editor::SaveJob save;                      // writes the scene file on a worker
    std::filesystem::path savedFrom;           // the document's file when that save began
    std::filesystem::path recentFile;          // where the recent files are kept ("" = nowhere)
    std::vector<std::filesystem::path> recent; // newest first
};

// Reads the recent files from `recentFile` (editor/recent_files.hpp); a file that is not a list
// is said in `messages` and starts an empty one.
void loadRecentFiles(SceneFiles& files, Messages& messages);
// `path` first in the recent files, written at once; a write that fails is said in `messages`.
void rememberFile(SceneFiles& files, const std::filesystem::path& path, Messages& messages);
// The recent files without `path`s that no longer exist (forgetMissing) or none, written.
void forgetRecentFiles(SceneFiles& files, bool onlyMissing, Messages& messages);

// The scene `rmsc view` was started with: a scene file, a glTF model (as the one mesh of a new
// scene) or, for "", the built-in demo. One that does not open leaves an empty scene and says
// why in `messages.openError`; a scene file is watched even then, so fixing it loads it.
void openStartScene(const std::filesystem::path& path, EditorSession& session, SceneFiles& files,
                    Messages& messages);
// Open: replaces the document and puts the view at the scene's camera; a file that does not
// load changes nothing and says why in `messages.fileError`.
void openSceneFile(const std::filesystem::path& path, EditorSession& session, SceneFiles& files,
                   Messages& messages);
// New: an empty scene without a file.
void newScene(EditorSession& session, SceneFiles& files, Messages& messages);
// Starts saving to `path` on a worker (after the save under way, if any, is finished);
// finishSave ends it. The edits go on meanwhile.
void saveSceneAs(const std::filesystem::path& path, editor::Document& document, SceneFiles& files,
                 Messages& messages);
// Ends the save under way once it is written (waiting for it with `wait`): the document is clean
// where it was saved (editor::Document::saved) and, when nothing was edited since, the recovery
// files go; the file is watched and remembered. A failed save keeps the edits and says why.
// Returns true when a save ended here and succeeded.
bool finishSave(editor::Document& document, SceneFiles& files, Messages& messages, bool wait);
// Unsaved edits to the recovery file, at most every 5 seconds of `now`, on a worker; says in
// `messages` when an earlier write failed.
void writeRecoveryFile(const editor::Document& document, SceneFiles& files, Messages& messages,
                       double now);
// Removes the recovery file of `sceneFile`, after the write under way (none lands after it).
void removeRecoveryFile(SceneFiles& files, const std::filesystem::path& sceneFile);
// Reloads the scene file when it changed on disk (or opens it, when it did not open at start).
// Returns true when it changed but there are unsaved edits: the user is to be asked. Not while
// a save is under way: its own write is no change.
bool reloadChangedSceneFile(EditorSession& session, SceneFiles& files, Messages& messages);

} // namespace rmsc::app
