// Creating and binding the SDF program buffer (render/sdf_program_buffer.hpp).
#include "render/sdf_program_buffer.hpp"

#include "render/gpu_layout.hpp"

#include <algorithm>
#include <cstring>

namespace rmsc {

SdfProgramBuffer createSdfProgramBuffer(const GpuSdfHeader& header,
                                        const std::vector<GpuSdfInstruction>& instructions) {
    std::vector<unsigned char> bytes(
        std::max(sizeof header + instructions.size() * sizeof(GpuSdfInstruction),
                 std::size_t(kSdfUniformBlockBytes)));
    std::memcpy(bytes.data(), &header, sizeof header);
    if (!instructions.empty())
        std::memcpy(bytes.data() + sizeof header, instructions.data(),
                    instructions.size() * sizeof(GpuSdfInstruction));
    SdfProgramBuffer program;
    program.buffer = gl::createBufferWithData(GLsizeiptr(bytes.size()), bytes.data());
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
