// The editor document and its undo history (see document.hpp).
#include "editor/document.hpp"

#include "core/atomic_file.hpp"
#include "editor/scene_check.hpp"
#include "editor/scene_edits.hpp"
#include "scene/scene_json.hpp"
#include "scene/scene_paths.hpp"

#include <algorithm>
#include <limits>

namespace rmsc::editor {

Scene emptyScene() {
    Scene scene;
    Light light;
    light.name = "sun";
    light.direction = glm::normalize(light.direction);
    scene.lights.push_back(light);
    return scene;
}

Document::Document() : Document(emptyScene()) {}

Document::Document(Scene scene, std::filesystem::path file)
    : scene_(std::move(scene)), file_(std::move(file)) {
    committed_ = scene_;
}

void Document::markChanged(const std::string& label) {
    if (!pending_) {
        pendingLabel_ = label;
        committedSelection_ = selection; // what undo selects again: the selection of the edit
        committedAlso_ = alsoSelected;
    }
    pending_ = true;
    ++revision_;
}

void Document::commit() {
    if (!pending_) return;
    pending_ = false;
    tidySelection();
    history_.resize(position_); // a new edit drops the redo branch
    if (savedPosition_ > position_) savedPosition_ = std::numeric_limits<std::size_t>::max();
    history_.push_back({pendingLabel_, committed_, scene_, committedSelection_, selection,
                        committedAlso_, alsoSelected, nextStepId_++});
    position_ = history_.size();
    committed_ = scene_;
    committedSelection_ = selection;
    committedAlso_ = alsoSelected;
}

void Document::tidySelection() {
    if (!selectionValid(scene_, selection)) selection = Selection::none();
    std::vector<Selection> kept;
    for (const Selection& item : alsoSelected)
        if (!item.empty() && item != selection && selectionValid(scene_, item) &&
            std::find(kept.begin(), kept.end(), item) == kept.end())
            kept.push_back(item);
    alsoSelected = std::move(kept);
    if (selection.empty() && !alsoSelected.empty()) {
        selection = alsoSelected.back();
        alsoSelected.pop_back();
    }
}

void Document::revertPending() {
    if (!pending_) return;
    pending_ = false;
    scene_ = committed_;
    tidySelection();
    ++revision_;
}

void Document::apply(const std::string& label,
                     const std::function<void(Scene&, Selection&)>& edit) {
    applyToSelection(label, [&](Scene& scene, Selection& active, std::vector<Selection>& also) {
        also.clear();
        edit(scene, active);
    });
}

void Document::applyToSelection(
    const std::string& label,
    const std::function<void(Scene&, Selection&, std::vector<Selection>&)>& edit) {
    commit();
    const Selection before = selection;
    const std::vector<Selection> alsoBefore = alsoSelected;
    edit(scene_, selection, alsoSelected);
    markChanged(label);
    committedSelection_ = before; // undo selects what was selected before the edit changed it
    committedAlso_ = alsoBefore;
    commit();
}

std::string Document::undoLabel() const {
    return canUndo() ? history_[position_ - 1].label : "";
}
std::string Document::redoLabel() const {
    return canRedo() ? history_[position_].label : "";
}

bool Document::undo() {
    commit();
    if (!canUndo()) return false;
    const Step& step = history_[--position_];
    scene_ = step.before;
    placeInFile(scene_);
    selection = step.selectionBefore;
    alsoSelected = step.alsoBefore;
    committed_ = scene_;
    committedSelection_ = selection;
    committedAlso_ = alsoSelected;
    ++revision_;
    return true;
}

bool Document::redo() {
    commit();
    if (!canRedo()) return false;
    const Step& step = history_[position_++];
    scene_ = step.after;
    placeInFile(scene_);
    selection = step.selectionAfter;
    alsoSelected = step.alsoAfter;
    committed_ = scene_;
    committedSelection_ = selection;
    committedAlso_ = alsoSelected;
    ++revision_;
    return true;
}

void Document::placeInFile(Scene& scene) const {
    if (file_.empty() || scene.file == file_) return;
    rebaseScenePaths(scene, std::filesystem::absolute(file_).parent_path());
    scene.file = file_;
}

bool Document::save(std::string& error) {
    if (file_.empty()) {
        error = "the scene has no file yet: use Save As";
        return false;
    }
    return saveAs(file_, error);
}

bool Document::saveAs(const std::filesystem::path& path, std::string& error) {
    const SceneSave save = saveOf(path);
    if (!writeSceneSave(save, error)) return false;
    saved(save);
    return true;
}

SceneSave Document::saveOf(const std::filesystem::path& path) {
    commit();
    SceneSave save;
    save.scene = scene_;
    // Every path (meshes, textures, sky, proxies) is written relative to the file's folder.
    rebaseScenePaths(save.scene, std::filesystem::absolute(path).parent_path());
    save.scene.file = path;
    save.path = path;
    save.document = resets_;
    save.position = position_;
    save.step = position_ > 0 ? history_[position_ - 1].id : 0;
    return save;
}

void Document::saved(const SceneSave& save) {
    if (save.document != resets_) return; // another scene since
    const std::filesystem::path folder = std::filesystem::absolute(save.path).parent_path();
    for (Scene* scene : {&scene_, &committed_}) {
        rebaseScenePaths(*scene, folder);
        scene->file = save.path;
    }
    file_ = save.path;
    // Where the history stood, if it still holds that step there (an edit after an undo since
    // drops it).
    const bool stands =
        save.position <= history_.size() &&
        (save.position == 0 ? save.step == 0 : history_[save.position - 1].id == save.step);
    savedPosition_ = stands ? save.position : std::numeric_limits<std::size_t>::max();
}

bool writeSceneSave(const SceneSave& save, std::string& error) {
    const std::string text = sceneToJson(save.scene);
    Diagnostics problems;
    if (!checkSceneText(text, save.path, problems)) {
        error = "the scene is not valid, so nothing was written (" + save.path.string() +
                " is unchanged):\n" + firstErrors(problems);
        return false;
    }
    return saveTextFileAtomically(save.path, text, true, error);
}

void Document::reset(Scene scene, std::filesystem::path file) {
    ++resets_;
    scene_ = std::move(scene);
    committed_ = scene_;
    file_ = std::move(file);
    history_.clear();
    position_ = savedPosition_ = 0;
    pending_ = false;
    selection = committedSelection_ = Selection::none();
    alsoSelected.clear();
    committedAlso_.clear();
    ++revision_;
}

void Document::reloadFromDisk(Scene scene) {
    commit();
    scene_ = std::move(scene);
    alsoSelected.clear(); // the file may have moved nodes: keep only the active one, if valid
    tidySelection();
    markChanged("Reload from disk");
    commit();
    savedPosition_ = position_;
}

std::optional<Scene> loadSceneForEditing(const std::filesystem::path& path,
                                         Diagnostics& diagnostics) {
    return loadScene(path, diskFileSource(), diagnostics);
}

} // namespace rmsc::editor
