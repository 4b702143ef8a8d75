// Scene-to-shader strategies: how the compiled SDF program reaches the GPU as the GLSL of the
// virtual include "generated/sdf_map.glsl" (sdfSceneEmpty, sdfDistance and sdfSurface). The
// generated strategies turn the postfix program into straight-line GLSL, one statement per
// instruction, so the shader compiler sees only the primitives and operations the scene uses.
#pragma once

#include "sdf/program.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace rmsc {

enum class SdfStrategy {
    Interpreter, // the generic interpreter reading the program buffer (common/sdf_interpreter.glsl)
    Buffer,      // generated code, parameters read from the program buffer: edits need no compile
    Baked,       // generated code, parameters as literals: the fastest, recompiled on every edit
};

std::string_view sdfStrategyName(SdfStrategy strategy);
std::optional<SdfStrategy> parseSdfStrategy(std::string_view name);

// Generated code costs shader-compile time in proportion to the scene: the map is inlined at
// each place the shaders evaluate it (march, normal, surface, texture frame, soft shadow, AO),
// and on llvmpipe each leaf costs about 0.2 s of compiling and 15 MiB of compiler memory.
// Above this many leaves the renderer falls back to the interpreter, whose compile cost does
// not grow with the scene (about 40 s on llvmpipe).
constexpr int kMaxGeneratedLeaves = 160;

// The strategy used for `program` when `requested` is asked for (see kMaxGeneratedLeaves).
SdfStrategy effectiveSdfStrategy(const SdfProgram& program, SdfStrategy requested);

// GLSL of "generated/sdf_map.glsl" for `program` with effectiveSdfStrategy(program, strategy). The
// Interpreter strategy's text depends only on the set of primitive kinds used; the Buffer
// strategy's only on the program's structure (opcodes, kinds, operations), so parameter and
// transform edits keep the same text and the renderer's compiled program; the Baked strategy's on
// everything.
//
// `names` lets a second map live beside the scene's in one shader (a shell's, see
// sdf/compiler.hpp): its functions are named prefix + "SceneEmpty", "Distance" and "Surface", and
// the Buffer strategy reads its instructions from `instructionBase` on in the program buffer.
struct SdfMapNames {
    std::string prefix = "sdf";
    std::size_t instructionBase = 0;
};
std::string generateSdfMap(const SdfProgram& program, SdfStrategy strategy,
                           const SdfMapNames& names = {});

} // namespace rmsc
