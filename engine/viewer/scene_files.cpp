// Opening, saving, recovering and reloading the scene file (see scene_files.hpp).
#include "scene_files.hpp"

#include "editor/recent_files.hpp"
#include "editor/recovery.hpp"
#include "prepare/prepared_scene.hpp"
#include "scene/scene_json.hpp"

#include <algorithm>
#include <cstdio>

namespace rmsc::app {

void openStartScene(const std::filesystem::path& path, EditorSession& session, SceneFiles& files,
                    Messages& messages) {
    editor::Document& document = session.document;
    Diagnostics diagnostics;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (path.empty()) {
        std::optional<Scene> demo = loadScene(kDemoScenePath, embeddedFileSource(), diagnostics);
        document.reset(demo ? *demo : editor::emptyScene(), {});
    } else if (extension == ".gltf" || extension == ".glb") {
        std::optional<PreparedScene> opened = openScene(path, diagnostics);
        if (opened) {
            // The model becomes a mesh instance of a new scene, saved wherever the user says.
            opened->scene.meshes[0].path = std::filesystem::absolute(path);
            document.reset(opened->scene, {});
            // Selected, so the inspector shows the file's animations, cameras and scenes.
            document.selection = editor::Selection::mesh(0);
        }
    } else {
        std::optional<Scene> scene = editor::loadSceneForEditing(path, diagnostics);
        if (scene) {
            document.reset(*scene, path);
            rememberFile(files, path, messages);
        }
        files.watcher = editor::FileWatcher(path); // a broken file that gets fixed loads then
    }
    if (diagnostics.hasErrors()) {
        messages.openError = "Could not open " + path.string() + "; showing an empty scene.\n" +
                             diagnostics.format();
        std::fputs(diagnostics.format().c_str(), stderr);
    }
    session.resetCamera();
}

void openSceneFile(const std::filesystem::path& path, EditorSession& session, SceneFiles& files,
                   Messages& messages) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = editor::loadSceneForEditing(path, diagnostics);
    if (!scene) {
        messages.fileError = "Could not open " + path.string() + " (the current scene stays):\n" +
                             diagnostics.format();
        return;
    }
    session.document.reset(*scene, path);
    files.watcher = editor::FileWatcher(path);
    session.resetCamera();
    rememberFile(files, path, messages);
    messages.fileError.clear();
    messages.sceneError.clear();
    messages.notice("opened " + path.string());
}

void newScene(EditorSession& session, SceneFiles& files, Messages& messages) {
    session.document.reset(editor::emptyScene(), {});
    files.watcher = editor::FileWatcher();
    session.resetCamera();
    messages.sceneError.clear();
}

void saveSceneAs(const std::filesystem::path& path, editor::Document& document, SceneFiles& files,
                 Messages& messages) {
    finishSave(document, files, messages, true); // one at a time
    files.savedFrom = document.file();
    files.save.start(document.saveOf(path));
}

bool finishSave(editor::Document& document, SceneFiles& files, Messages& messages, bool wait) {
    std::optional<editor::SaveOutcome> outcome = files.save.take(wait);
    if (!outcome) return false;
    const std::filesystem::path& path = outcome->save.path;
    if (!outcome->written) {
        messages.fileError = "Save failed; your edits are kept in memory.\n" + outcome->error;
        std::fprintf(stderr, "rmsc view: save failed: %s\n", outcome->error.c_str());
        return false;
    }
    document.saved(outcome->save);
    messages.notice("saved " + path.string());
    if (document.file() != path) return true; // another scene since: nothing of it was saved
    if (!document.dirty()) {                  // the edits are safe in the file now
        removeRecoveryFile(files, files.savedFrom);
        removeRecoveryFile(files, path);
    } else {
        files.recoveryRevision = 0; // the edits since: to the recovery file of the new path
    }
    messages.fileError.clear();
    files.watcher = editor::FileWatcher(path); // our own write is not an external change
    rememberFile(files, path, messages);
    return true;
}

void writeRecoveryFile(const editor::Document& document, SceneFiles& files, Messages& messages,
                       double now) {
    if (std::optional<editor::RecoveryOutcome> outcome = files.recovery.take();
        outcome && !outcome->written)
        messages.notice("cannot write the recovery file: " + outcome->error);
    if (!document.dirty() || document.revision() == files.recoveryRevision ||
        now - files.lastRecoveryWrite < 5.0)
        return;
    files.lastRecoveryWrite = now;
    // Asked once per revision: one that fails is said once, not every 5 s.
    files.recoveryRevision = document.revision();
    files.recovery.request(document.scene(), document.file(), document.revision());
}

void removeRecoveryFile(SceneFiles& files, const std::filesystem::path& sceneFile) {
    files.recovery.cancel();
    editor::removeRecovery(sceneFile);
}

bool reloadChangedSceneFile(EditorSession& session, SceneFiles& files, Messages& messages) {
    if (files.save.underWay() || files.watcher.path().empty() || !files.watcher.changed())
        return false;
    editor::Document& document = session.document;
    const std::filesystem::path& path = files.watcher.path();
    Diagnostics diagnostics;
    std::optional<Scene> scene = editor::loadSceneForEditing(path, diagnostics);
    if (!scene) {
        messages.sceneError = "Reloading " + path.string() +
                              " failed (the last good scene stays):\n" + diagnostics.format();
    } else if (document.file() != path) {
        document.reset(*scene, path); // the file failed to open at start
        messages.sceneError.clear();
        messages.openError.clear();
        session.resetCamera();
        messages.notice("opened " + path.string());
    } else if (document.dirty()) {
        return true; // ask: reload and lose edits, or keep them
    } else {
        document.reloadFromDisk(*scene);
        messages.sceneError.clear();
        messages.notice("reloaded " + path.string() + " (changed on disk)");
    }
    return false;
}

namespace {

void writeRecent(const SceneFiles& files, Messages& messages) {
    if (files.recentFile.empty()) return;
    std::string error;
    if (!editor::saveRecentFiles(files.recentFile, files.recent, error))
        messages.notice("cannot keep the recent files: " + error);
}

} // namespace

void loadRecentFiles(SceneFiles& files, Messages& messages) {
    std::string error;
    files.recent = editor::loadRecentFiles(files.recentFile, error);
    if (!error.empty()) messages.notice("the recent files start anew: " + error);
}

void rememberFile(SceneFiles& files, const std::filesystem::path& path, Messages& messages) {
    editor::addRecentFile(files.recent, path);
    writeRecent(files, messages);
}

void forgetRecentFiles(SceneFiles& files, bool onlyMissing, Messages& messages) {
    if (onlyMissing)
        editor::removeMissingFiles(files.recent);
    else
        files.recent.clear();
    writeRecent(files, messages);
}

} // namespace rmsc::app
