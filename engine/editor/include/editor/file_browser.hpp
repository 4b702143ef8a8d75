// The file browser's model (the viewer's Open, Save As, + Mesh and file fields): the filter of
// each use (scene files, glTF meshes, textures, sky images), a folder's listing under a filter
// (folders first, then the files it lets through, each sorted by name without regard to case;
// hidden entries left out), and the path a typed name stands for. GL-free.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc::editor {

enum class FileKind {
    Scene,   // .json
    Mesh,    // .gltf, .glb
    Texture, // .png, .jpg, .jpeg (a material's textures)
    Sky,     // .hdr, .png, .jpg, .jpeg (an image sky)
};

// "Scene files (.json)", ...
std::string_view fileKindLabel(FileKind kind);
// The extensions, lower case with their dot.
std::span<const std::string_view> fileKindExtensions(FileKind kind);
// Whether `path` has one of the kind's extensions (in any case).
bool matchesFileKind(const std::filesystem::path& path, FileKind kind);

struct DirectoryEntry {
    std::string name;
    bool folder = false;
    std::uintmax_t bytes = 0; // files only
};

struct DirectoryListing {
    std::filesystem::path folder;
    std::vector<DirectoryEntry> entries;
    std::string error; // why the folder could not be read ("" when it could)
};

// The folders and the files of `kind` in `folder` (every file with `allFiles`).
DirectoryListing listDirectory(const std::filesystem::path& folder, FileKind kind,
                               bool allFiles = false);

// The path a name typed in the browser stands for: an absolute path as it is, "~/..." under
// `home` (when given), anything else relative to `folder`; lexically normal.
std::filesystem::path typedPath(const std::filesystem::path& folder, std::string_view typed,
                                const std::filesystem::path& home = {});

// How a file field names a chosen file: relative to `sceneFolder` when the scene has one and the
// file is inside it or a folder below, else absolute.
std::string fileFieldText(const std::filesystem::path& chosen,
                          const std::filesystem::path& sceneFolder);

} // namespace rmsc::editor
