// Files embedded into the binary at build time (cmake/embed_files.cmake): the sample scenes and
// assets here, so the rmsc binary runs from any folder (the shaders: render/shader_library.hpp).
#pragma once

#include <span>
#include <string_view>

namespace rmsc {

struct EmbeddedFile {
    std::string_view path; // relative to the project root's shaders/ or samples/ parent
    std::string_view data;
};

std::span<const EmbeddedFile> embeddedSamples(); // paths like "samples/scenes/demo.json"

} // namespace rmsc
