// Where input files come from: the disk, or files embedded in the binary (the built-in demo).
// Loaders read every file, the scene and what it references, through one FileSource, so the
// demo scene and its glTF assets load exactly like files on disk. The disk source also holds
// reads to folders: glTF URIs to the glTF file's folder, everything to the --sandbox folder.
#pragma once

#include "core/limits.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

// The folder every disk read of this process must resolve inside: `rmsc --sandbox DIR`, set
// once by the command before it reads anything, so that no reader can forget it. Empty (the
// default): reads may reach any file the process can read. setDiskReadSandbox stores the folder
// resolved (std::filesystem::canonical); it must exist.
void setDiskReadSandbox(const std::filesystem::path& folder);
const std::filesystem::path& diskReadSandbox();

struct FileSource {
    // Returns the file's bytes, or nullopt with `error` set to why it could not be read.
    std::function<std::optional<std::string>(const std::filesystem::path&, std::string& error)>
        read;
    // Reads `folder / relative`, which must also resolve inside `folder` after every symbolic
    // link is followed (glTF buffer and image URIs). Unset for sources without links (files in
    // memory, the embedded files): readInsideFolder then reads `folder / relative`, which is
    // inside as long as `relative` has no ".." (gltf::resolveInFolder checks that).
    std::function<std::optional<std::string>(const std::filesystem::path& folder,
                                             const std::filesystem::path& relative,
                                             std::string& error)>
        readInside = {};
    // readInside into a byte vector, for glTF buffers (tinygltf keeps them as vectors: a copy
    // from the string would briefly hold a 1 GiB buffer twice). Unset: readInside's bytes are
    // copied.
    std::function<bool(const std::filesystem::path& folder, const std::filesystem::path& relative,
                       std::vector<unsigned char>& out, std::string& error)>
        readInsideBytes = {};
};

// source.readInsideBytes, or readInsideFolder's bytes copied into `out`.
bool readInsideFolderBytes(const FileSource& source, const std::filesystem::path& folder,
                           const std::filesystem::path& relative, std::vector<unsigned char>& out,
                           std::string& error);

// source.readInside, or source.read(folder / relative) for a source without it.
std::optional<std::string> readInsideFolder(const FileSource& source,
                                            const std::filesystem::path& folder,
                                            const std::filesystem::path& relative,
                                            std::string& error);

// `path` with every symbolic link resolved (std::filesystem::weakly_canonical: a missing tail
// is kept as written), when it lies inside `folder` (resolved too) or is the folder itself.
// nullopt with `why` set otherwise: "resolves to /etc/passwd, outside /scenes/a", or why the
// path cannot be resolved (a link loop).
std::optional<std::filesystem::path> resolveInside(const std::filesystem::path& folder,
                                                   const std::filesystem::path& path,
                                                   std::string& why);

// Reads regular files from the local file system (through symbolic links); refuses files
// larger than maxBytes and anything that is not a regular file (devices, FIFOs, sockets,
// folders) before reading a byte. With a `sandbox` folder, every file read must resolve inside
// it (rmsc --sandbox DIR); readInside also holds files to their folder, checked before the file
// is opened and again, where /proc/self/fd tells, on the opened file.
FileSource diskFileSource(std::uintmax_t maxBytes = limits::kInputFileBytes,
                          const std::filesystem::path& sandbox = diskReadSandbox());

// Reads the files embedded at build time from samples/ (paths like "samples/scenes/demo.json").
FileSource embeddedFileSource();

} // namespace rmsc
