// Where input files come from: the disk, or files embedded in the binary (the built-in demo).
// Loaders read every file, the scene and what it references, through one FileSource, so the
// demo scene and its glTF assets load exactly like files on disk.
#pragma once

#include "core/limits.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace rmsc {

struct FileSource {
    // Returns the file's bytes, or nullopt with `error` set to why it could not be read.
    std::function<std::optional<std::string>(const std::filesystem::path&, std::string& error)>
        read;
};

// Reads regular files from the local file system (through symbolic links); refuses files
// larger than maxBytes and anything that is not a regular file (devices, FIFOs, sockets,
// folders) before reading a byte.
FileSource diskFileSource(std::uintmax_t maxBytes = limits::kInputFileBytes);

// Reads the files embedded at build time from samples/ (paths like "samples/scenes/demo.json").
FileSource embeddedFileSource();

} // namespace rmsc
