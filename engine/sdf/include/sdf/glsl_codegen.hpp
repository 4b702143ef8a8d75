// Scene-to-shader strategies: how the compiled SDF program reaches the GPU as the GLSL of the
// virtual include "generated/sdf_map.glsl" (sdfSceneEmpty, sdfDistance and sdfSurface). The
// generated strategies turn the postfix program into straight-line GLSL, one statement per
// instruction, so the shader compiler sees only the primitives and operations the scene uses.
#pragma once

#include "core/limits.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/program.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rmsc {

enum class SdfStrategy {
    Interpreter, // the generic interpreter reading the program buffer (common/sdf_interpreter.glsl)
    Buffer,      // generated code, parameters read from the program buffer: edits need no compile
    Baked,       // generated code, parameters as literals: the fastest, recompiled on every edit
    Cells,       // the interpreter on the program pruned to the cell of each point (cells.glsl,
                 // sdf/cell_pruning.hpp): its text depends on the primitive kinds used only
};

std::string_view sdfStrategyName(SdfStrategy strategy);
std::optional<SdfStrategy> parseSdfStrategy(std::string_view name);

// Generated code costs shader-compile time in proportion to the scene: the map is inlined at
// each place the shaders evaluate it (march, normal, surface, texture frame, soft shadow, AO),
// and on llvmpipe each leaf costs about 0.2 s of compiling and 15 MiB of compiler memory.
// Above this many leaves, or limits::kGeneratedCodeStatements statements (a 150-shape union of
// twisted shapes is 600 statements: 3.5 GB and 24 s to compile cold), the renderer falls back
// to the Cells strategy, whose compile cost does not grow with the scene, nor its cost per step
// with the shapes away from the point.
constexpr int kMaxGeneratedLeaves = limits::kGeneratedCodeShapes;

// The strategy used for `program` when `requested` is asked for (see kMaxGeneratedLeaves).
SdfStrategy effectiveSdfStrategy(const SdfProgram& program, SdfStrategy requested);

// The objects whose numbers stay in the buffer when the rest of the map is baked: ids `first` to
// `last` (GpuSdfInstruction::objectId), which is one node and its subtree in pre-order, what the
// editor has selected. Empty when last < first.
struct SdfLiveRange {
    std::uint32_t first = 1;
    std::uint32_t last = 0;
    bool contains(std::uint32_t id) const { return id >= first && id <= last; }
    bool operator==(const SdfLiveRange&) const = default;
};

// GLSL of "generated/sdf_map.glsl" for `program` with effectiveSdfStrategy(program, strategy). The
// Interpreter strategy's text depends only on the set of primitive kinds used and on whether the
// program is box tests and one-shape parts only (then the lean common/sdf_parts_loop.glsl runs
// it, else the generic common/sdf_interpreter.glsl); the Buffer
// strategy's only on the program's structure (opcodes, kinds, operations), so parameter and
// transform edits keep the same text and the renderer's compiled program; the Baked strategy's on
// everything but the numbers of the `live` objects' instructions, which it reads from the buffer
// like the Buffer strategy: while the user edits those objects the text, and so the compiled
// program, stays the same, and the rest of the scene runs at the baked speed. (Generated code
// evaluates every part of a program compiled with bounds and skips none, but in the
// hierarchy's order, which follows where the parts are: the editor compiles without bounds.)
//
// `names` lets a second map live beside the scene's in one shader (a shell's, see
// sdf/compiler.hpp): its functions are named prefix + "SceneEmpty", "Distance" and "Surface", and
// the Buffer strategy reads its instructions from `instructionBase` on in the program buffer.
struct SdfMapNames {
    std::string prefix = "sdf";
    std::size_t instructionBase = 0;
};

// What the Cells map's text may assume of every postfix list of the grid it draws (common/
// sdf_interpreter.glsl; the lean loop of a union of shapes needs neither). The default assumes
// nothing and draws any grid; a grid that fits more gets faster text:
// - shortLists: one instruction per loop iteration, the fastest: llvmpipe runs every instruction
//   of a loop's body for all pixels, masked where a pixel's list has ended, and most lists are
//   one or two instructions. But llvmpipe also ends an invocation's loops after a budget of
//   iterations shared by all of them, which a long list would spend within a few march steps:
//   a grid with any list longer than kSdfShortCellList reads two instructions per iteration.
// - shallowStacks: the value and point stacks in variables, where every list's are at most
//   kSdfRegisterStack and kSdfRegisterPointStack deep (sdf/program.hpp). llvmpipe keeps an array
//   indexed by a value that differs between pixels in memory, one pixel at a time; the variables
//   cost a few selects. Deeper lists would overrun them: such a grid must not be drawn with that
//   text.
struct SdfCellFit {
    bool shortLists = false;
    bool shallowStacks = false;
    bool operator==(const SdfCellFit&) const = default;
};
constexpr int kSdfShortCellList = 64;
// What a grid fits: its longest list, deepest value stack and deepest point stack, the outside
// list's included (sdfLongestCellList, sdfDeepestCellStack, sdfDeepestCellPointStack).
inline SdfCellFit sdfCellFit(const SdfCellGrid& grid) {
    return {sdfLongestCellList(grid) <= kSdfShortCellList,
            sdfDeepestCellStack(grid) <= kSdfRegisterStack &&
                sdfDeepestCellPointStack(grid) <= kSdfRegisterPointStack};
}

// `cellFit` applies to the Cells strategy's postfix lists only: the text is one of four for
// every program of the same primitive kinds.
std::string generateSdfMap(const SdfProgram& program, SdfStrategy strategy,
                           const SdfMapNames& names = {}, const SdfLiveRange& live = {},
                           SdfCellFit cellFit = {});
// What a map's text (generateSdfMap's) assumes of the lists of the grid it draws: nothing for
// any other strategy, nor for the lean loop.
SdfCellFit sdfMapCellFit(std::string_view map);

} // namespace rmsc
