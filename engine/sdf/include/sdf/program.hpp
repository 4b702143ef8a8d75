// The compiled SDF scene as the shader reads it: a postfix program over a table of
// instructions, in an SSBO laid out std430. The same struct is read by the CPU evaluator
// (sdf/cpu_eval.hpp) and by the GLSL interpreter (shaders/common/sdf_scene.glsl).
#pragma once

#include "core/limits.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rmsc {

// Stack size of the GLSL interpreter (SDF_MAX_STACK; the shaders' copies of these numbers are
// generated, sdf/glsl_constants.hpp).
constexpr int kSdfMaxStack = limits::kSdfStack;
// The deepest value stack the Cells map holds in variables instead of an array, where every
// list of its grid is that shallow (SdfCellFit, sdf/glsl_codegen.hpp; SDF_REGISTER_STACK).
constexpr int kSdfRegisterStack = 5;
// The same for the point stack (SDF_REGISTER_POINT_STACK): how deep PushPoint may nest there.
constexpr int kSdfRegisterPointStack = 4;
// Most instructions one scene may compile to.
constexpr int kSdfMaxInstructions = limits::kSdfInstructions;
// Point stack of the GLSL interpreter (SDF_MAX_POINT_STACK): how deep PushPoint may nest.
constexpr int kSdfMaxPointStack = limits::kSdfPointStack;
// The program buffer's header and first instructions are also bound as a uniform block
// (SdfProgramUniforms in shaders/common/sdf_functions.glsl): 16 + 511 * 128 bytes, within the
// 64 KiB uniform blocks of desktop GL 4.5 drivers. Generated code reads the instructions it can
// from there: on llvmpipe a uniform read costs less than a storage read (the 100-shape grid's
// buffer map: 150 ms a frame instead of 332, and a cold first frame of 15 s instead of 47 s).
constexpr int kSdfUniformInstructions = 511;
constexpr int kSdfUniformBlockBytes = 16 + kSdfUniformInstructions * 128;
// The distance of an empty program (or before anything is united into it): nothing anywhere.
constexpr float kSdfFar = 1e10f;
// Most vec4 entries of the SDF data buffer (polygon points, one per entry).
constexpr int kSdfMaxData = limits::kSdfData;

// The interpreter keeps a current point p (world space at the start) and a stack of saved
// points. Shapes read p through their worldToLocal; nodes with point modifiers save p, move it
// into their local frame and modify it, and restore it after their subtree.
enum class SdfOpcode : std::uint32_t {
    Shape = 0,            // push the distance of primitive `kind` at worldToLocal * p
    Combine = 1,          // pop b, pop a, push op `kind` (an SdfOp) of a and b
    PushPoint = 2,        // save p on the point stack, then p = worldToLocal * p
    PointModifier = 3,    // p = point modifier `kind` of p (modifierKind, sdf/modifiers.hpp)
    PopPoint = 4,         // p = the saved point on top of the point stack (popped)
    DistanceModifier = 5, // top of the value stack changed by distance modifier `kind`
    Profile = 6,          // push the distance of a 2D profile solid (`kind`: SdfProfileType)
    // Bounds (the compiler's bounding-volume hierarchy over the plain unions at the top of the
    // tree): the program keeps the union of the finished parts in a running value `best`.
    BoundSkip = 7,  // skip the next `kind` instructions when the box params[0].xyz (centre),
                    // params[1].xyz (half extents), in the current point's frame, is at least
                    // `best` away (box distance times misc.x, world units per unit of the frame)
    Accumulate = 8, // pop a value and unite it into `best`; a program that accumulates returns
                    // `best` (its stack ends empty)
    // Distances only: best = min(best, the distance to the farthest point of either of two
    // boxes), each holding surface of the parts it bounds, so the result is at most that. Boxes
    // packed (centre a, half a, centre b, half b) in params[0..2], scale in misc.x. Emitted
    // before a hierarchy node's two children, so the nearer child tightens `best` before the
    // farther one is tested (a static stand-in for visiting the nearer child first).
    SeedBest = 9,
};

// PointModifier and DistanceModifier parameters: as the modifier's catalogue row packs them
// (ModifierSpec::pack in engine/sdf/modifiers.cpp), lengths of distance modifiers already in the
// units of the value on the stack. The instruction kinds, each stage's rows in catalogue order
// (modifierKind; checked in modifiers.cpp); the keys of the formulas in sdf/sdf_functions.hpp.
enum class SdfPointModifierKind : std::uint32_t {
    Repeat,
    Mirror,
    Polar,
    Elongate,
    Twist,
    Bend,
    Taper
};
enum class SdfDistanceModifierKind : std::uint32_t { Round, Onion, Displace };
// Profile parameters: params[0] = (radius, half width, half height, -), params[1] = (solid:
// 0 extrusion / 1 revolution, half depth or offset, -, -), params[2] = (first point in the data
// buffer, point count, -, -); worldToLocal and misc as for Shape.

// One instruction. std430: 128 bytes, 16-byte aligned; mirrored by struct SdfInstruction in GLSL.
struct GpuSdfInstruction {
    std::uint32_t opcode = 0;    // SdfOpcode
    std::uint32_t kind = 0;      // PrimitiveId for Shape, SdfOp for Combine
    std::uint32_t material = 0;  // Shape: index into the material buffer
    std::uint32_t objectId = 0;  // Shape: object id (kSdfIdBase + node pre-order index)
    glm::vec4 params[3]{};       // Shape: PrimitiveParams; Combine: params[0].x = smoothness k,
                                 // params[0].y = SmoothBlend
    glm::vec4 worldToLocal[3]{}; // Shape: rows of the affine world-to-local matrix (scale removed
                                 // only as far as `distanceScale` accounts for it)
    glm::vec4 misc{};            // Shape: x = distance scale (smallest scale factor of the
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
    std::uint32_t pointStackDepth = 0;
    std::uint32_t dataCount = 0; // vec4 entries of the data buffer (binding 3)
};
static_assert(sizeof(GpuSdfHeader) == 16);

struct SdfProgram {
    std::vector<GpuSdfInstruction> instructions; // postfix order
    int stackDepth = 0;                          // largest stack the program needs
    int pointStackDepth = 0;                     // largest point stack the program needs
    std::vector<glm::vec4> data;                 // the data buffer: polygon points (xy)
    // For each SDF node in pre-order (index = objectId - kSdfIdBase): its JSON pointer.
    std::vector<std::string> nodePointers;
};

// The forms of program the lean loops run (engine/sdf/program_form.cpp):
// - parts only: the bounding hierarchy's instructions over parts of one shape each, every shape
//   followed by its Accumulate (shaders/common/sdf_parts_loop.glsl);
// - a union of shapes: shapes and profiles united by plain unions only (a grid without bounds).
// Either one's value is the least of its shapes' (the first of equal ones for the surface).
bool sdfIsPartsOnly(const SdfProgram& program);
bool sdfIsUnionOfShapes(const SdfProgram& program);
inline bool sdfIsLeastOfShapes(const SdfProgram& program) {
    return sdfIsPartsOnly(program) || sdfIsUnionOfShapes(program);
}

// How a list of instruction indices (a cell's program, sdf/cell_pruning.hpp) is read:
// - Postfix: a postfix program, one instruction a word;
// - PostfixPairs: the same program in entries of two words, one step of the shader's loop each
//   (sdfPairList): an instruction, then the combine that follows it, held whole in the entry
//   (its operation, curve and smoothness: no read of its instruction). Every combine is in an
//   entry that way; one that follows another has an entry of its own, whose instruction is the
//   combine itself and runs nothing there;
// - LeastOfShapes: the least of its shapes and profiles, where unions and Accumulate do nothing
//   (the cells of a least-of-shapes program leave their unions out of their lists).
// BoundSkip and SeedBest do what they do in a program either way (a BoundSkip skips entries:
// a list that has one gives each combine an entry of its own).
enum class SdfListReading { Postfix, PostfixPairs, LeastOfShapes };

// An entry in pairs: word 0 the instruction's index (bits below kSdfEntryIndexBits; indices stay
// below 2^24, core/limits.hpp) and the combine after it in the bits above (sdfEntryCombine: 0
// none, else 1 + 2 SdfOp + SmoothBlend); word 1 the combine's smoothness (float bits; 0 for none).
constexpr std::uint32_t kSdfEntryIndexBits = 24;
inline std::uint32_t sdfEntryIndex(std::uint32_t word) {
    return word & ((1u << kSdfEntryIndexBits) - 1u);
}
inline std::uint32_t sdfEntryCombine(std::uint32_t word) {
    return word >> kSdfEntryIndexBits;
}
// The words of a list of `entries` entries read as `reading`, and the entries of `words` words.
inline std::size_t sdfListWords(std::size_t entries, SdfListReading reading) {
    return reading == SdfListReading::PostfixPairs ? 2 * entries : entries;
}
inline std::size_t sdfListEntries(std::size_t words, SdfListReading reading) {
    return reading == SdfListReading::PostfixPairs ? words / 2 : words;
}
// `list` (a postfix list of `code`'s instructions) in entries of two words, appended to `out`:
// each combine in the entry of the instruction before it unless that one has a combine already
// (which leaves the fewest entries).
void sdfPairList(std::span<const GpuSdfInstruction> code, std::span<const std::uint32_t> list,
                 std::vector<std::uint32_t>& out);
// The instructions `words` (a list of `code`'s read as `reading`) run, in order, appended to
// `out`: a combine in pairs as its entry holds it (its opcode, kind and params[0]; the rest of it
// zero).
void sdfListProgram(std::span<const GpuSdfInstruction> code, std::span<const std::uint32_t> words,
                    SdfListReading reading, std::vector<GpuSdfInstruction>& out);
// How many instructions that is (without making them).
std::size_t sdfListInstructionCount(std::span<const GpuSdfInstruction> code,
                                    std::span<const std::uint32_t> words, SdfListReading reading);
// The most entries the shader's value stack holds while it reads `words` (a list of `code`'s
// read as `reading`): a shape or profile pushes one, a combine and Accumulate pop one. 0 for
// LeastOfShapes, which the shader reads as a running minimum.
int sdfListStackDepth(std::span<const GpuSdfInstruction> code, std::span<const std::uint32_t> words,
                      SdfListReading reading);
// The same for the point stack: PushPoint pushes, PopPoint pops (in every reading).
int sdfListPointStackDepth(std::span<const GpuSdfInstruction> code,
                           std::span<const std::uint32_t> words, SdfListReading reading);

} // namespace rmsc
