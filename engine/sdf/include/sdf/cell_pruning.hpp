// Per-cell pruning of a compiled SDF program: a hierarchy of cells (4x4x4 per level, coarse to
// fine) over the scene's content, and for each cell the program specialised to it, holding
// only the nodes that can change the distance inside the cell. The march, normals, shadows
// and AO evaluate the program of the cell the point is in (shaders/common/sdf_cells.glsl, the
// Cells strategy of sdf/glsl_codegen.hpp), so a step costs what the few shapes near the point
// cost, not what the scene costs. After "Lipschitz Pruning" (Barbier, Sanchez, Paris, Galin,
// Tricard and Guérin, Eurographics 2025) and the per-tile specialisation of Keeter, "Massively
// Parallel Rendering of Complex Closed-Form Implicit Surfaces" (SIGGRAPH 2020).
//
// The rule: every leaf's field (a shape, a profile, or a node with its own point frame taken
// whole) is 1-Lipschitz as the compiler emits it (its distance scale and step corrections make
// it so), so over a cell of half-diagonal r its value lies in [v - r, v + r], v its value at the
// centre. The operations are monotone, so intervals go up the tree; an operation whose result
// provably equals one operand over the whole cell (each operation's own rule,
// sdfOperationPrune) is replaced by that operand. Inside a cell the pruned program's value,
// material blend and object id are those of the whole program, except in far cells when
// SdfCellOptions::farConstants asks for them: where the whole program is at least the cell's
// edge everywhere in the cell and its program is long, a constant lower bound of that (never
// above the true distance). Outside the grid run the whole program's unbounded operands (a
// floor plane) and the distance to the box of the rest (SdfCellGrid::outsideFloor).
//
// The planes among the operands of the root's chain of unions (a floor, walls: most scenes have
// one) are taken out of every list (SdfCellGrid::planes): the shader evaluates each at every
// point as one dot product and unites it with the list's value, where a list would read the
// plane's instruction and a union's. The 4,096-sphere tree's lists, mostly a sphere beside the
// floor, shrink from three instructions to one.
//
// What it costs: a node whose floor (its exact distance to a box, less how far its operations
// may dip below it) already decides its operation over a cell is dropped without being
// evaluated, and when the tree's root is a chain of unions of small operands (a scene of many
// objects), each cell is pruned straight from the whole chain, the operands that can matter
// found nearest first in a bounding-volume hierarchy of their floors: a cell costs what it
// keeps, not what its parent kept. An edit of numbers prunes again only the cells where a
// changed object is not dropped by its floor, before or after the edit (repruneSdfCells).
#pragma once

#include "core/limits.hpp"
#include "sdf/bounds.hpp"
#include "sdf/cpu_eval.hpp"
#include "sdf/program.hpp"
#include "sdf/sdf_tree.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace rmsc {

// An interval of field values over a region.
struct SdfInterval {
    float lo = 0.0f;
    float hi = 0.0f;
};

// Which operand an operation equals over a region where its operands lie in `a` and `b`.
enum class SdfPruneSide { Both, A, B };
SdfPruneSide sdfOperationPrune(SdfOp op, SdfInterval a, SdfInterval b, float smoothness);
// The interval of op(a, b) over the region (op is monotone in each operand).
SdfInterval sdfOperationInterval(SdfOp op, SdfInterval a, SdfInterval b, const glm::vec4& opParams);

struct SdfCellOptions {
    int levels = 6; // subdivision levels: 4^levels cells per axis at the finest (at most 6)
    // The grid is the content's cube grown 4^outerLevels times: what lies around the content
    // (a floor plane to the horizon) is pruned too, and the finest cells are the content's cube
    // divided 4^(levels - outerLevels) times.
    int outerLevels = 2;
    int refineLeaves = 4; // a cell whose program has more leaves than this is refined
    int threads = 0;      // 0: one per hardware thread
    // Far cells with long programs run a constant lower bound (see above). Without it the air
    // around dense content keeps long programs (the 400-sphere grid: 55 shapes per cell instead
    // of 2, 7 GB to prune); with it, soft shadows that read those distances are darker in the
    // penumbra than the whole program gives (depth and ids stay exact).
    bool farConstants = true;
    // The most cells in all (memory: 8 bytes each plus their programs); refinement stops there,
    // cells near the surface refined first.
    std::size_t maxCells = std::size_t(limits::kSdfCells);
};

struct SdfCellStats {
    std::vector<int> cellsPerLevel; // cells made at each level (64 per refined cell)
    int leafCells = 0;              // cells with a program of their own (not refined)
    double meanLength = 0.0;        // entries per leaf cell's list, mean (steps of the shader's
    int maxLength = 0;              // loop: SdfCellGrid::reading), and largest
    int maxStack = 0;               // the deepest value stack of a leaf cell's list
                                    // (sdfListStackDepth)
    int maxPointStack = 0;          // and point stack (sdfListPointStackDepth)
    double meanInstructions = 0.0;  // instructions per leaf cell's program, mean
    double meanLeaves = 0.0;        // shape evaluations per leaf cell's program, mean
    std::size_t uniquePrograms = 0; // distinct programs after sharing equal ones
    std::size_t prunedCells = 0;    // cells pruned by the build (or the re-prune)
    int affineCells = 0;            // leaf cells whose program is one plane (kSdfCellAffine)
    double buildMs = 0.0;           // wall time of buildSdfCells (or repruneSdfCells)
    std::size_t bytes = 0;          // bytes of the cell table and index lists (on the GPU: their
                                    // buffer, render/gpu_scene.hpp)
};

// The cells and their programs, laid out as the GPU reads them (sdf_cells.glsl): `words` holds
// blocks of 64 cells of 2 words each (block 0: the cells of the first level, x + 4 y + 16 z),
// then the programs' index lists. A cell is (offset in words of its list, its entries: one word
// or two each, as SdfCellGrid::reading says) or, when refined, (kSdfCellRefined | the index of
// its block of 64, 0). Indices refer to `code`: the program's instructions followed by the
// instructions the pruning adds.
constexpr std::uint32_t kSdfCellRefined = 0x80000000u;
// Set in a leaf cell's length word (the length is the bits below it) when its program is one
// plane instruction: a floor's plane, or a far cell's constant. Its field is affine along any
// ray, and the only surface in the cell is where it is zero, so a march may go straight to that
// point or to the cell's far side (shaders/common/sdf_cells.glsl, sdfDistanceAlong): a ray
// grazing a floor to the horizon crosses each cell in one step instead of many.
constexpr std::uint32_t kSdfCellAffine = 0x80000000u;

// A lower bound of a field from the boxes of its shapes: at every point y outside `box` the
// field is at least distance(y, box) - drop (SdfCellGrid::floor, sdfProgramFloor).
struct SdfFieldFloor {
    Aabb box;
    float drop = 0.0f;
};

// A plane of the root's chain of unions, taken out of the lists (see the top): its instruction
// in SdfCellGrid::code and its field, affine in the world point p: dot(field.xyz, p) + field.w.
// `leads`: it comes before every operand the lists hold, so where it and a list's surface are
// equally near its surface is the one kept (a union keeps the first of equal operands).
constexpr int kSdfCellPlanes = 4; // at most; more stay in the lists
struct SdfCellPlane {
    std::uint32_t instruction = 0;
    glm::vec4 field{0.0f};
    bool leads = false;
};

struct SdfWordRange {
    std::uint32_t first = 0, count = 0;
};

struct SdfCellGrid {
    int levels = 0;         // 0: no grid (everything runs the whole program)
    glm::vec3 origin{0.0f}; // the grid is the cube [origin, origin + size]
    float size = 0.0f;
    std::vector<std::uint32_t> words;
    // The list points outside the grid run, in words: the whole program's operands of its top
    // chain of unions that outsideFloor does not stand for and that are not the grid's planes
    // (an infinite repetition; none in a bounded scene, nor in one whose only unbounded
    // operands are planes). It holds no bounding hierarchy (unless sdfCellsNeedHierarchy).
    std::uint32_t outsideOffset = 0; // in words
    std::uint32_t outsideLength = 0; // in entries
    int outsideStack = 0;            // its value stack's depth (sdfListStackDepth)
    int outsidePointStack = 0;       // and point stack's (sdfListPointStackDepth)
    // How every list is read (the cells' and the outside one): the cells of a program of a
    // least-of-shapes form (sdfIsLeastOfShapes) list its shapes without their unions, which
    // the lean loop of sdf_cells.glsl would only step over; the others' lists are postfix in
    // pairs, each combine fused with the instruction before it (SdfListReading::PostfixPairs).
    SdfListReading reading = SdfListReading::PostfixPairs;
    std::vector<GpuSdfInstruction> code; // program.instructions + the added ones
    // The root chain's planes, which no list holds: the field at p is the least of the planes'
    // and the list's (sdfCellsDistance). A cell whose program was one of them is affine with an
    // empty list: the plane nearest at p is then that one (the others are above it in the cell).
    std::vector<SdfCellPlane> planes;
    // The whole program's floor, when it has one: its tree's root's, of the floors the pruning
    // drops subtrees by (also read through a bounding hierarchy, which sdfProgramFloor refuses).
    // Far cells, whose program is a constant, may take the larger of the two (sdf_cells.glsl).
    std::optional<SdfFieldFloor> floor;
    // What the outside list leaves out, by its floor: outside the grid the field is the least of
    // the list's value, the planes' and the floor's distance, distance(y, box) - drop
    // (sdfCellOutsideFloor; never within a margin of zero there). The root's floor when the whole
    // program has one that keeps the margin.
    std::optional<SdfFieldFloor> outsideFloor;
    SdfCellStats stats;
    // The words the last build or re-prune wrote, in order: all of them after a build; after a
    // re-prune into the grid it last wrote, the blocks of cells that changed and the lists from
    // the first new one to the end (so a GPU copy of the old words needs only these).
    std::vector<SdfWordRange> changedWords;
    std::uint64_t packStamp = 0;    // which pack wrote the words (0: none)
    std::uint64_t changedSince = 0; // the pack changedWords count from (0: all words changed)
};

// The most instructions a point of `grid` reads: its longest list, a cell's or the outside one
// (which decides the map's SdfCellFit, sdf/glsl_codegen.hpp).
inline int sdfLongestCellList(const SdfCellGrid& grid) {
    return std::max(grid.stats.maxLength, int(grid.outsideLength));
}
// The deepest value stack a point of `grid` needs, its lists' and the outside list's (which
// decides whether the map holds its stacks in variables: SdfCellFit, sdf/glsl_codegen.hpp).
inline int sdfDeepestCellStack(const SdfCellGrid& grid) {
    return std::max(grid.stats.maxStack, grid.outsideStack);
}
inline int sdfDeepestCellPointStack(const SdfCellGrid& grid) {
    return std::max(grid.stats.maxPointStack, grid.outsidePointStack);
}

// A lower bound of a whole program's field from the boxes of its shapes (the floors cell
// pruning drops subtrees by): at every point y outside `box` the field is at least
// distance(y, box) - drop. nullopt when the program has none (a shape without an exact
// formula or under a non-uniform scale, a point modifier, a bounding hierarchy).
std::optional<SdfFieldFloor> sdfProgramFloor(const std::vector<GpuSdfInstruction>& code);

// Whether the cells' lists of `code` need the bounding hierarchy's instructions (the shader's
// branches for them): only when the program has a hierarchy and cannot be read back into a
// tree within the stack. Depends on the program's structure alone, not on its numbers.
bool sdfCellsNeedHierarchy(const std::vector<GpuSdfInstruction>& code);

// The content box of a tree: the union of the world boxes of its bounded parts (unbounded
// groups are looked into; the rest of an unbounded part is left out). Empty when nothing is
// bounded.
Aabb sdfContentBox(const SdfNode& root);

// What a grid was built from, kept to prune it again after an edit (repruneSdfCells).
struct SdfCellState;
struct SdfCellStateDeleter {
    void operator()(SdfCellState* state) const;
};
using SdfCellStatePtr = std::unique_ptr<SdfCellState, SdfCellStateDeleter>;

// Prunes `program` (with or without its bounding hierarchy) over the cube around `content`.
// No grid (levels 0) when `content` is empty or the program cannot be split into a tree.
// With `keep`, what it was built from goes there (null when there is no grid).
SdfCellGrid buildSdfCells(const SdfProgram& program, const Aabb& content,
                          const SdfCellOptions& options = {}, SdfCellStatePtr* keep = nullptr);

// Prunes `grid` again for `edited`: the program the state was built from with only numbers
// changed (the parameters, transforms and materials of shapes, the kind of a shape, the
// parameters of operations and modifiers), in the same grid cube. Only cells whose parent
// cell's pruned program holds a changed node, or changed itself, are pruned again (a moved
// shape: the cells around its old and new place, and the coarse cells above them); the result
// is what a full build gives but for the order in which the cell budget is spent. False when
// the structure differs, an edit changes which operands are the grid's planes (a plane retyped,
// a shape made a plane), or a cell's program would be deeper than the stack: build again, the
// state is spent.
bool repruneSdfCells(SdfCellState& state, const SdfProgram& edited, SdfCellGrid& grid);

// The list of the program that runs at p (the cell's, or the outside list outside the grid):
// its offset in grid.words and its length, computed as the shader does.
struct SdfCellRange {
    std::uint32_t offset = 0;
    std::uint32_t length = 0;
    int level = 0;       // of the cell (its edge: grid.size / 4^level); 0 outside the grid
    bool affine = false; // kSdfCellAffine
};
SdfCellRange sdfCellRange(const SdfCellGrid& grid, glm::vec3 p);
// What the field at p is at least beyond the list of sdfCellRange(grid, p): outside the grid,
// the distance to what the outside list leaves out (outsideFloor); +infinity elsewhere. The
// cells' value at p is the least of the two (common/sdf_cells.glsl, sdfCellDistance).
float sdfCellOutsideFloor(const SdfCellGrid& grid, glm::vec3 p);
// The words of the list of `r` (read as grid.reading), and the instructions the list at p runs
// (sdfListProgram).
std::span<const std::uint32_t> sdfCellWords(const SdfCellGrid& grid, const SdfCellRange& r);
std::vector<GpuSdfInstruction> sdfCellProgram(const SdfCellGrid& grid, glm::vec3 p);
// The cells' field at p as the shader reads it (common/sdf_cells.glsl): the list of
// sdfCellRange(grid, p), with the outside floor outside the grid, united with the grid's planes
// (but for the program's floor, which the shader may take in a far cell instead of its
// constant: both are lower bounds there); and its surface (material and id: the planes' and the
// list's, the first of equal ones as the union keeps it). `program` is the one the grid was
// built from.
float sdfCellsDistance(const SdfProgram& program, const SdfCellGrid& grid, glm::vec3 p);
SdfSurface sdfCellsSurface(const SdfProgram& program, const SdfCellGrid& grid,
                           std::span<const Material> materials, glm::vec3 p);

} // namespace rmsc
