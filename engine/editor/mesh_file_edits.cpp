// Changing a mesh instance's glTF file with a load check first (see mesh_file_edits.hpp).
#include "editor/mesh_file_edits.hpp"

#include "scene/mesh_asset.hpp"
#include "scene/scene_paths.hpp"

namespace rmsc::editor {

bool setMeshFile(Scene& scene, int mesh, const std::string& file, const FileSource& files,
                 std::string& error) {
    if (mesh < 0 || mesh >= int(scene.meshes.size())) {
        error = "no such mesh";
        return false;
    }
    if (file.empty()) {
        error = "expected the path of a .gltf or .glb file, got \"\"";
        return false;
    }
    const std::filesystem::path path = resolveScenePath(scene, file);
    Diagnostics diagnostics;
    if (!loadGltf(path, files, diagnostics)) {
        error = "\"" + file + "\" does not load: ";
        for (const Diagnostic& d : diagnostics.items)
            if (d.severity == Severity::Error) {
                error += d.format();
                break;
            }
        if (diagnostics.errorCount() == 0) error += "no glTF asset";
        return false;
    }
    MeshInstance& instance = scene.meshes[std::size_t(mesh)];
    instance.path = path;
    instance.file = scene.file.empty() ? path.generic_string() : file;
    return true;
}

} // namespace rmsc::editor
