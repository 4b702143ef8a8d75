// Files dropped on the viewer's window (see editor/dropped_files.hpp).
#include "editor/dropped_files.hpp"

#include "editor/file_browser.hpp"
#include "editor/scene_edits.hpp"

namespace rmsc::editor {

DroppedKind droppedFileKind(const std::filesystem::path& file) {
    if (matchesFileKind(file, FileKind::Scene)) return DroppedKind::Scene;
    if (matchesFileKind(file, FileKind::Mesh)) return DroppedKind::Mesh;
    return DroppedKind::Unsupported;
}

std::string droppedFileRefusal(const std::filesystem::path& file) {
    return file.string() +
           ": cannot be dropped here: expected a scene (.json) or a glTF model (.gltf, .glb)";
}

int addMeshAt(Scene& scene, Selection& selection, const std::filesystem::path& file,
              glm::vec3 position) {
    const int index = addMesh(scene, std::filesystem::absolute(file).lexically_normal());
    scene.meshes[std::size_t(index)].transform.position = position;
    selection = Selection::mesh(index);
    return index;
}

} // namespace rmsc::editor
