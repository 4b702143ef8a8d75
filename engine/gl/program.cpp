// Compile and link with logs mapped back to the shader files.
#include "gl/program.hpp"

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <vector>

namespace rmsc {
namespace {

struct CompiledShader {
    gl::Shader shader;
    AssembledShader source; // for the link log
    const char* stage;      // as NVIDIA's link log heads its part: "Vertex", "Fragment"...
};

std::optional<CompiledShader> compile(const ShaderFiles& files, GLenum stage, std::string_view path,
                                      std::string_view defines, std::string& error) {
    std::optional<AssembledShader> source = assembleShader(files, path, defines, error);
    if (!source) return std::nullopt;
    gl::Shader shader(glCreateShader(stage));
    const char* text = source->text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
        log.resize(std::strlen(log.c_str()));
        error = "shader compile error in " + std::string(path) + ":\n" + mapShaderLog(*source, log);
        return std::nullopt;
    }
    const char* name = stage == GL_VERTEX_SHADER     ? "Vertex"
                       : stage == GL_FRAGMENT_SHADER ? "Fragment"
                                                     : "Compute";
    return CompiledShader{std::move(shader), std::move(*source), name};
}

// Links the compiled `shaders` into a program; on failure names `what` in `error`.
std::optional<gl::Program> link(std::initializer_list<const CompiledShader*> shaders,
                                const std::string& what, std::string& error) {
    gl::Program program(glCreateProgram());
    for (const CompiledShader* shader : shaders)
        glAttachShader(program.id(), shader->shader.id());
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        log.resize(std::strlen(log.c_str()));
        std::vector<ShaderStageSource> stages;
        for (const CompiledShader* shader : shaders)
            stages.push_back({shader->stage, &shader->source});
        error = "shader link error (" + what + "): " + mapLinkLog(stages, log);
        return std::nullopt;
    }
    for (const CompiledShader* shader : shaders)
        glDetachShader(program.id(), shader->shader.id());
    return program;
}

} // namespace

std::optional<gl::Program> buildProgram(const ShaderFiles& files, const ProgramDesc& desc,
                                        std::string& error) {
    std::optional<CompiledShader> vertex =
        compile(files, GL_VERTEX_SHADER, desc.vertexPath, desc.defines, error);
    if (!vertex) return std::nullopt;
    std::optional<CompiledShader> fragment =
        compile(files, GL_FRAGMENT_SHADER, desc.fragmentPath, desc.defines, error);
    if (!fragment) return std::nullopt;
    return link({&*vertex, &*fragment},
                std::string(desc.vertexPath) + " + " + std::string(desc.fragmentPath), error);
}

std::optional<gl::Program> buildComputeProgram(const ShaderFiles& files,
                                               std::string_view computePath,
                                               std::string_view defines, std::string& error) {
    std::optional<CompiledShader> compute =
        compile(files, GL_COMPUTE_SHADER, computePath, defines, error);
    if (!compute) return std::nullopt;
    return link({&*compute}, std::string(computePath), error);
}

GLint uniformLocation(const gl::Program& program, const char* name) {
    return glGetUniformLocation(program.id(), name);
}

} // namespace rmsc
