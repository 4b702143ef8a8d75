// Changing the glTF file a mesh instance places, from the editor: the file is set only after it
// has loaded as glTF, so a missing or broken file leaves the scene as it was and says why.
// GL-free: the file is read through a FileSource and loaded as the scene preparation loads it.
#pragma once

#include "core/file_source.hpp"
#include "scene/scene.hpp"

#include <string>

namespace rmsc::editor {

// Makes scene.meshes[mesh] place `file` (relative files are resolved against the scene file's
// folder, or for a scene without a file the current folder, and then stored absolute). The file
// is loaded first, within the limits a file of its own has; when anything fails (no such mesh,
// an empty name, a file that does not load) returns false with `error` saying why and `scene`
// unchanged. The instance's name, transform and material are kept.
bool setMeshFile(Scene& scene, int mesh, const std::string& file, const FileSource& files,
                 std::string& error);

} // namespace rmsc::editor
