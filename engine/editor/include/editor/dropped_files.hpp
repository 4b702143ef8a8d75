// Files dropped on the viewer's window: what each kind does (a scene file opens, a glTF model is
// added as a mesh instance where a new shape goes, anything else is refused with the reason), and
// the mesh instance a dropped model becomes. GL- and window-free.
#pragma once

#include "editor/selection.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <glm/glm.hpp>
#include <string>

namespace rmsc::editor {

enum class DroppedKind {
    Scene,      // .json: opened (asking first when there are unsaved changes)
    Mesh,       // .gltf, .glb: added as a mesh instance
    Unsupported // refused
};

// By the extension, in any case.
DroppedKind droppedFileKind(const std::filesystem::path& file);
// Why a dropped file of another kind is refused: "FILE: cannot be dropped here: expected a
// scene (.json) or a glTF model (.gltf, .glb)".
std::string droppedFileRefusal(const std::filesystem::path& file);

// Appends a mesh instance of `file` (made absolute) with its origin at `position`, selects it
// and returns its index.
int addMeshAt(Scene& scene, Selection& selection, const std::filesystem::path& file,
              glm::vec3 position);

} // namespace rmsc::editor
