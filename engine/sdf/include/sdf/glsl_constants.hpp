// GLSL #defines of the numbers the shaders share with the C++ code, generated from the C++
// enums, catalogues and constants so that no shader repeats one by hand: the renderer serves
// them as the virtual include "generated/constants.glsl" (render/shader_library.hpp), the SDF
// layer's part from here (opcodes, modifier, profile and operation kinds, stack sizes), the
// renderer's own (buffer bindings, texture units) from render.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc {

// "#define name value".
struct GlslConstant {
    std::string name;
    std::string value;
};

// GLSL literals: 5u, 5, 1e10 as "10000000000.0".
std::string glslUint(std::uint32_t value);
std::string glslInt(int value);
std::string glslFloat(float value);
// A catalogue name as a GLSL name: "rounded_rectangle" -> "ROUNDED_RECTANGLE".
std::string glslName(std::string_view name);

// The SDF program's numbers: SDF_MAX_STACK, SDF_MAX_POINT_STACK, SDF_UNIFORM_INSTRUCTIONS,
// SDF_FAR, SDF_OPCODE_* (SdfOpcode), SDF_POINT_* and SDF_DISTANCE_* (modifier kinds),
// SDF_PROFILE_* (SdfProfileType) and SDF_OP_* (SdfOp).
std::vector<GlslConstant> sdfGlslConstants();

// One "#define name value" line per constant.
std::string glslDefines(std::span<const GlslConstant> constants);

} // namespace rmsc
