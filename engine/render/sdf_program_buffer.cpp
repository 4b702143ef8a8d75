// Creating and binding the SDF program buffer (render/sdf_program_buffer.hpp).
#include "render/sdf_program_buffer.hpp"

#include "render/gpu_layout.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

namespace rmsc {

SdfProgramBuffer createSdfProgramBuffer(const GpuSdfHeader& header,
                                        std::span<const GpuSdfInstruction> code,
                                        std::span<const GpuSdfInstruction> more) {
    const std::size_t codeBytes = code.size_bytes(), moreBytes = more.size_bytes();
    const std::size_t bytes =
        std::max(sizeof header + codeBytes + moreBytes, std::size_t(kSdfUniformBlockBytes));
    SdfProgramBuffer program;
    program.buffer = gl::createBufferWithData(GLsizeiptr(bytes), nullptr);
    const GLuint id = program.buffer.id();
    glNamedBufferSubData(id, 0, sizeof header, &header);
    if (codeBytes) glNamedBufferSubData(id, sizeof header, GLsizeiptr(codeBytes), code.data());
    if (moreBytes)
        glNamedBufferSubData(id, GLintptr(sizeof header + codeBytes), GLsizeiptr(moreBytes),
                             more.data());
    const std::size_t written = sizeof header + codeBytes + moreBytes;
    if (written < bytes) { // the uniform window's rest: zeros, as a small program always had
        const std::vector<unsigned char> zeros(bytes - written, 0);
        glNamedBufferSubData(id, GLintptr(written), GLsizeiptr(zeros.size()), zeros.data());
    }
    program.texels = gl::createTexture(GL_TEXTURE_BUFFER);
    glTextureBuffer(program.texels.id(), GL_RGBA32F, program.buffer.id());
    return program;
}

void bindSdfProgramBuffer(const SdfProgramBuffer& program) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSdfProgramBinding, program.buffer.id());
    glBindBufferRange(GL_UNIFORM_BUFFER, kSdfProgramUniformBinding, program.buffer.id(), 0,
                      kSdfUniformBlockBytes);
    glBindTextureUnit(kSdfProgramTexelUnit, program.texels.id());
}

} // namespace rmsc
