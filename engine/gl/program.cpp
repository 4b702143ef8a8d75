// Compile and link with logs mapped back to the shader files.
#include "gl/program.hpp"

#include <algorithm>
#include <cstring>
#include <initializer_list>

namespace rmsc {
namespace {

std::optional<gl::Shader> compile(const ShaderFiles& files, GLenum stage, std::string_view path,
                                  std::string_view defines, std::string& error) {
    const std::optional<AssembledShader> source = assembleShader(files, path, defines, error);
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
    return shader;
}

// Links the compiled `shaders` into a program; on failure names `what` in `error`.
std::optional<gl::Program> link(std::initializer_list<const gl::Shader*> shaders,
                                const std::string& what, std::string& error) {
    gl::Program program(glCreateProgram());
    for (const gl::Shader* shader : shaders)
        glAttachShader(program.id(), shader->id());
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        error = "shader link error (" + what + "): " + log.c_str();
        return std::nullopt;
    }
    for (const gl::Shader* shader : shaders)
        glDetachShader(program.id(), shader->id());
    return program;
}

} // namespace

std::optional<gl::Program> buildProgram(const ShaderFiles& files, const ProgramDesc& desc,
                                        std::string& error) {
    std::optional<gl::Shader> vertex =
        compile(files, GL_VERTEX_SHADER, desc.vertexPath, desc.defines, error);
    if (!vertex) return std::nullopt;
    std::optional<gl::Shader> fragment =
        compile(files, GL_FRAGMENT_SHADER, desc.fragmentPath, desc.defines, error);
    if (!fragment) return std::nullopt;
    return link({&*vertex, &*fragment},
                std::string(desc.vertexPath) + " + " + std::string(desc.fragmentPath), error);
}

std::optional<gl::Program> buildComputeProgram(const ShaderFiles& files,
                                               std::string_view computePath,
                                               std::string_view defines, std::string& error) {
    std::optional<gl::Shader> compute =
        compile(files, GL_COMPUTE_SHADER, computePath, defines, error);
    if (!compute) return std::nullopt;
    return link({&*compute}, std::string(computePath), error);
}

GLint uniformLocation(const gl::Program& program, const char* name) {
    return glGetUniformLocation(program.id(), name);
}

} // namespace rmsc
