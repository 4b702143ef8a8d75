// Building GL programs (vertex + fragment, or compute) from shader files: assemble (includes),
// compile, link, and report any error with the original file and line.
#pragma once

#include "gl/handles.hpp"
#include "gl/shader_source.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace rmsc {

struct ProgramDesc {
    std::string_view vertexPath;   // relative to shaders/
    std::string_view fragmentPath; // relative to shaders/
    std::string_view defines;      // "#define NAME VALUE\n" lines, may be empty
};

// Returns the linked program, or nullopt with `error` naming file and line of the problem.
std::optional<gl::Program> buildProgram(const ShaderFiles& files, const ProgramDesc& desc,
                                        std::string& error);

// The same for a compute program of one shader at `computePath` (relative to shaders/).
std::optional<gl::Program> buildComputeProgram(const ShaderFiles& files,
                                               std::string_view computePath,
                                               std::string_view defines, std::string& error);

// Location of a uniform, looked up once when a pass is created; -1 if the shader lacks it.
GLint uniformLocation(const gl::Program& program, const char* name);

} // namespace rmsc
