// The compiled SDF scene as the shader reads it: a postfix program over a table of
// instructions, in an SSBO laid out std430. The same struct is read by the CPU evaluator
// (sdf/cpu_eval.hpp) and by the GLSL interpreter (shaders/common/sdf_scene.glsl).
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rmsc {

// Stack size of the GLSL interpreter (SDF_MAX_STACK in shaders/common/sdf_scene.glsl).
constexpr int kSdfMaxStack = 24;
// Most instructions one scene may compile to.
constexpr int kSdfMaxInstructions = 1 << 16;

enum class SdfOpcode : std::uint32_t {
    Shape = 0,   // push the distance of primitive `kind` at worldToLocal * p
    Combine = 1, // pop b, pop a, push op `kind` (an SdfOp) of a and b
};

// One instruction. std430: 128 bytes, 16-byte aligned; mirrored by struct SdfInstruction in GLSL.
struct GpuSdfInstruction {
    std::uint32_t opcode = 0;   // SdfOpcode
    std::uint32_t kind = 0;     // PrimitiveId for Shape, SdfOp for Combine
    std::uint32_t material = 0; // Shape: index into the material buffer
    std::uint32_t objectId = 0; // Shape: object id (kSdfIdBase + node pre-order index)
    glm::vec4 params[3]{};      // Shape: PrimitiveParams; Combine: params[0].x = smoothness k
    glm::vec4 worldToLocal[3]{};// Shape: rows of the affine world-to-local matrix (scale removed
                                // only as far as `distanceScale` accounts for it)
    glm::vec4 misc{};           // Shape: x = distance scale (smallest scale factor of the
                                // node's world transform, exact for uniform scale, a bound
                                // otherwise, times the primitive's step scale)
};
static_assert(sizeof(GpuSdfInstruction) == 128);
static_assert(offsetof(GpuSdfInstruction, params) == 16);
static_assert(offsetof(GpuSdfInstruction, worldToLocal) == 64);
static_assert(offsetof(GpuSdfInstruction, misc) == 112);

// Header at the start of the SDF SSBO, before the instruction array.
struct GpuSdfHeader {
    std::uint32_t instructionCount = 0;
    std::uint32_t stackDepth = 0;
    std::uint32_t pad[2]{};
};
static_assert(sizeof(GpuSdfHeader) == 16);

struct SdfProgram {
    std::vector<GpuSdfInstruction> instructions; // postfix order
    int stackDepth = 0;                          // largest stack the program needs
    // For each SDF node in pre-order (index = objectId - kSdfIdBase): its JSON pointer.
    std::vector<std::string> nodePointers;
};

} // namespace rmsc
