// The editor's document: the scene being edited, its file, the selection (the active object and
// any more that Shift-click added), and an unlimited undo/redo history. Edits change `scene()` in
// place and are then committed as one undo step (a slider drag commits once, when released). Each
// step stores the scene before and after, so undo and redo are exact whatever the edit was.
// GL-free.
#pragma once

#include "core/diagnostics.hpp"
#include "editor/selection.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rmsc::editor {

// A scene to start from: one light, no objects (what "New" and a failed load give).
Scene emptyScene();

// A save asked for (Document::saveOf): the scene as it was then, its paths relative to `path`'s
// folder, and where the document's history stood. Written by writeSceneSave, on any thread, and
// then given back to Document::saved.
struct SceneSave {
    Scene scene;
    std::filesystem::path path;
    std::uint64_t document = 0; // which scene of the Document (reset() starts another)
    std::size_t position = 0;   // its history's position
    std::uint64_t step = 0;     // the id of the step before that position (0: none)
};

// Writes `save.scene` to `save.path`: the text (sceneToJson) is checked first as `rmsc validate`
// would check it (editor/scene_check.hpp), so an invalid scene is not written and `error` names
// its first errors by JSON pointer; then it is written atomically, the previous file kept as
// FILE.bak. On failure returns false with `error` saying why; the old file is kept. GL-free and
// touches nothing else: it may run on any thread.
bool writeSceneSave(const SceneSave& save, std::string& error);

class Document {
  public:
    Document();
    explicit Document(Scene scene, std::filesystem::path file = {});

    const Scene& scene() const { return scene_; }
    // For in-place edits; call markChanged() after changing, and commit() when the gesture ends.
    Scene& editScene() { return scene_; }
    const std::filesystem::path& file() const { return file_; } // "" until saved
    bool dirty() const { return position_ != savedPosition_ || pending_; }

    // The active object: what the inspector and the gestures edit.
    Selection selection;
    // More selected objects (Shift-click, editor/multi_selection.hpp), in the order they were
    // added; never holding `selection` itself, none when `selection` is empty.
    std::vector<Selection> alsoSelected;

    // Records that the scene was changed by an edit named `label` (not yet an undo step).
    void markChanged(const std::string& label);
    bool hasPendingChange() const { return pending_; }
    // Makes the pending change one undo step. Does nothing without a pending change.
    void commit();
    // Abandons the pending change: the scene returns to the last committed state.
    void revertPending();
    // edit(scene, selection), then commit: one undo step. `alsoSelected` is cleared first (the
    // edit may move nodes, so their paths would name others): the edit selects what it leaves.
    void apply(const std::string& label, const std::function<void(Scene&, Selection&)>& edit);
    // The same for edits of several objects: edit(scene, selection, alsoSelected), which sees
    // the whole selection and leaves the one it wants.
    void
    applyToSelection(const std::string& label,
                     const std::function<void(Scene&, Selection&, std::vector<Selection>&)>& edit);

    bool canUndo() const { return position_ > 0; }
    bool canRedo() const { return position_ < history_.size(); }
    std::string undoLabel() const;
    std::string redoLabel() const;
    bool undo();
    bool redo();
    std::size_t historySize() const { return history_.size(); }

    // Increments whenever the scene changes (edit, undo, redo, load): renderers compare it.
    std::uint64_t revision() const { return revision_; }

    // Saves at once: saveOf, writeSceneSave, saved. On failure returns false with `error`
    // saying why; the scene, its edits and the old file are kept.
    bool save(std::string& error);
    bool saveAs(const std::filesystem::path& path, std::string& error);
    // A save of the scene as it is now to `path` (the pending change committed first), for
    // writeSceneSave to write, on another thread if need be, while the editing goes on.
    SceneSave saveOf(const std::filesystem::path& path);
    // `save` was written: the document's file is its path from now on (the scene's paths read
    // from its folder), and the document is clean where its history stood when the save was
    // asked for (dirty after edits made since, clean again after undoing them). Nothing
    // changes when the document holds another scene since (reset()).
    void saved(const SceneSave& save);

    // Replaces everything (New, Open, reload): history cleared, clean.
    void reset(Scene scene, std::filesystem::path file);
    // Replaces the scene after an external change of the file, as an undoable step that leaves
    // the document clean (the file on disk is what it now shows).
    void reloadFromDisk(Scene scene);

  private:
    struct Step {
        std::string label;
        Scene before, after;
        Selection selectionBefore, selectionAfter;
        std::vector<Selection> alsoBefore, alsoAfter;
        std::uint64_t id = 0; // names it for SceneSave::step (never 0)
    };
    // Drops what no longer exists and repeats from alsoSelected; an empty active selection
    // takes the last of them.
    void tidySelection();
    // A step from before a Save As into another folder holds the scene as it was written for
    // the old file: undo and redo rewrite its paths for the document's file, as saved() did the
    // scene's, so a path typed after them resolves from the folder the document is saved in.
    void placeInFile(Scene& scene) const;
    Scene scene_;
    Scene committed_;              // the scene after the last step (what undo returns from)
    Selection committedSelection_; // the selection when the pending change began (undo restores)
    std::vector<Selection> committedAlso_;
    std::filesystem::path file_;
    std::vector<Step> history_;
    std::size_t position_ = 0;      // steps [0, position_) are applied
    std::size_t savedPosition_ = 0; // position_ when last saved; SIZE_MAX when unreachable
    bool pending_ = false;
    std::string pendingLabel_;
    std::uint64_t revision_ = 1;
    std::uint64_t nextStepId_ = 1;
    std::uint64_t resets_ = 0; // reset()s so far: SceneSave::document
};

// Loads a scene file for editing (parse only: meshes are loaded by the renderer).
std::optional<Scene> loadSceneForEditing(const std::filesystem::path& path,
                                         Diagnostics& diagnostics);

} // namespace rmsc::editor
