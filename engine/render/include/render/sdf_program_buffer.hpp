// The SDF program buffer every SDF pass reads (shaders/common/sdf_functions.glsl): a
// GpuSdfHeader and the instructions, bound three ways: as a storage buffer, its first
// kSdfUniformBlockBytes as the uniform window generated code reads, and as RGBA32F texels (a
// buffer texture over the same storage) that the interpreters fetch.
#pragma once

#include "gl/handles.hpp"
#include "sdf/program.hpp"

#include <span>

namespace rmsc {

struct SdfProgramBuffer {
    gl::Buffer buffer;  // GpuSdfHeader + instructions, at least kSdfUniformBlockBytes
    gl::Texture texels; // the same storage, 16 bytes a texel
};

// The texels a driver must allow in a buffer texture for the largest program or cell table rmsc
// writes (checked by Renderer::create): 2^24, far above kSdfInstructions' 8 texels each with
// the cells' code and the shells' programs after it, and above the 8-byte texels of
// limits::kSdfCells' table and lists; desktop drivers and llvmpipe allow 2^27.
constexpr int kSdfMaxBufferTexels = 1 << 24;

// The buffer of `header`, then `code`, then `more` (the shells' programs after the scene's),
// written straight from them: a large scene's program is not copied on its way.
SdfProgramBuffer createSdfProgramBuffer(const GpuSdfHeader& header,
                                        std::span<const GpuSdfInstruction> code,
                                        std::span<const GpuSdfInstruction> more = {});

// Binds it at kSdfProgramBinding, kSdfProgramUniformBinding and kSdfProgramTexelUnit.
void bindSdfProgramBuffer(const SdfProgramBuffer& program);

} // namespace rmsc
