// The cost model of a compiled SDF program: what one evaluation of the map costs in the worst
// case (every instruction run, no box test skipping anything), in instructions, and what the
// generated-code strategies cost the shader compiler. The interpreter and generated code both
// evaluate the postfix program once per march step, so a step costs one evaluation and a pixel
// at most max_steps of them; rmsc refuses a scene whose pixel costs more than
// limits::kSdfPixelCost (prepare/prepared_scene.cpp) and draws a tree whose generated code
// would exceed limits::kGeneratedCodeStatements with the per-cell programs instead
// (sdf/glsl_codegen.hpp).
#pragma once

#include "sdf/program.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace rmsc {

// One instruction's cost in units of a plain instruction (a sphere, a union). Fractal shapes
// cost one unit per iteration, a polygon profile one per 4 points, a noise displacement 8 (the
// eight lattice corners of its value noise); box tests, point frames and every other modifier
// or operation 1. Neighbour checks of repetitions and polar copies cost what the compiler emits
// for them: the rest of the node's chain once per cell.
double sdfInstructionCost(const GpuSdfInstruction& instruction);

// The worst-case cost of one evaluation of a list of instructions, and the node that costs most
// in it: the SDF node (by object id) whose instructions cost the most together, and how many of
// its shapes the list evaluates (a shape inside neighbour-checked repetitions is evaluated once
// per cell of each: 8 x 8 x 8 x 8 times under four of them).
struct SdfEvaluationCost {
    double perEvaluation = 0.0;
    std::uint32_t costliestId = 0; // object id (kSdfIdBase + pre-order index); 0: empty
    double costliestCost = 0.0;
    long costliestEvaluations = 0; // Shape / Profile instructions of that node
};
SdfEvaluationCost sdfEvaluationCost(std::span<const GpuSdfInstruction> code);
// The same for the instructions code[i] of `indices` (a cell's program, sdf/cell_pruning.hpp).
SdfEvaluationCost sdfEvaluationCost(std::span<const GpuSdfInstruction> code,
                                    std::span<const std::uint32_t> indices);

struct SdfCellGrid;
// The costliest program of a cell grid's leaf cells (sdf/cell_pruning.hpp): what a step costs
// under the Cells strategy inside the grid. Outside it the whole program runs, but a ray there
// is far from everything and leaves in a few steps, so it is not counted. perEvaluation 0 for
// a grid without levels.
SdfEvaluationCost sdfCellsCost(const SdfCellGrid& grid);

// Statements the generated strategies (Buffer, Baked) write for `program`: one per instruction
// but the box tests and seeds, which generated code leaves to the interpreter. Each costs the
// shader compiler about the same time and memory, inlined at every place the shaders evaluate
// the map.
long sdfGeneratedStatements(const SdfProgram& program);

// "1.2 k", "3.4 M": an approximate count for messages.
std::string costText(double cost);

} // namespace rmsc
