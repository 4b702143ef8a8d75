// Assembling GLSL from the files in shaders/: `#include "path"` is resolved (paths relative to
// shaders/, each file included once), `#line` directives keep line numbers, and compiler logs
// are mapped back from source-string numbers to file names.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc {

// Shader files by path relative to shaders/ ("common/lighting.glsl"); render/shader_library.hpp
// fills it with the files embedded at build time plus the generated ones. `overrideDirectory`
// (if set) is read first, so shaders can be edited on disk without a rebuild; paths under
// "generated/" always come from `files`.
struct ShaderFiles {
    std::map<std::string, std::string, std::less<>> files;
    std::string overrideDirectory;

    std::optional<std::string> find(std::string_view path) const;
};

struct AssembledShader {
    std::string text;               // one GLSL string, #version first
    std::vector<std::string> files; // source-string number -> file path
};

// Resolves includes starting at `path`. `defines` lines ("#define X 1") go right after
// #version. On failure returns nullopt and names the file and line in `error`.
std::optional<AssembledShader> assembleShader(const ShaderFiles& files, std::string_view path,
                                              std::string_view defines, std::string& error);

// Rewrites "N:LINE(COL): ..." and "N(LINE) : ..." in a GLSL info log to "FILE:LINE: ...".
std::string mapShaderLog(const AssembledShader& shader, std::string_view log);

// The same for a program's link log. Drivers that compile at link time (NVIDIA's) report each
// stage's errors under a heading ("Vertex info", "Fragment info", "Compute info") in that
// stage's numbering; a log of one stage needs no heading.
struct ShaderStageSource {
    std::string_view stage; // "Vertex", "Fragment", "Compute"
    const AssembledShader* source;
};
std::string mapLinkLog(std::span<const ShaderStageSource> stages, std::string_view log);

} // namespace rmsc
