// Crash recovery for the editor: while a scene has unsaved edits the viewer writes them, every
// few seconds, to a recovery file next to the scene ("SCENE.recovery", or one in the temporary
// folder for a scene never saved); a save or a deliberate close removes it, so a file that is
// still there on the next start means edits were lost, and the viewer offers them. GL-free.
#pragma once

#include "scene/scene.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace rmsc::editor {

// Where the edits of `sceneFile` ("" for a scene never saved) are kept.
std::filesystem::path recoveryPath(const std::filesystem::path& sceneFile);

// Writes `scene`, the edits of the scene file `sceneFile` ("" for a scene never saved), to
// recoveryPath(sceneFile) atomically, once it passes the check of a save
// (editor/scene_check.hpp). False with `error` saying why when it is not valid (nothing is
// written; an older recovery file stays) or cannot be written. The viewer writes it on a worker
// (editor/recovery_job.hpp).
bool writeRecovery(const Scene& scene, const std::filesystem::path& sceneFile, std::string& error);

// The recovery file of `sceneFile` if there is one worth offering: it exists and is newer than
// the scene file (or the scene file is gone, or was never saved).
std::optional<std::filesystem::path> findRecovery(const std::filesystem::path& sceneFile);

void removeRecovery(const std::filesystem::path& sceneFile);

} // namespace rmsc::editor
