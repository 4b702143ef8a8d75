// Emission in the SDF compiler (compiler.cpp): the planned tree (sdf_plan.hpp) as postfix
// instructions, as it is (sdf_emit.cpp) or with the bounding-volume hierarchy over the plain
// unions at its top (sdf_bvh.cpp). Internal to the sdf layer.
#pragma once

#include "sdf/program.hpp"
#include "sdf_plan.hpp"

#include <vector>

namespace rmsc::compiler {

// `planned` and its subtree as they are: point frame, modifier chain, shape or children folded
// with the group's op, the cut children subtracted last.
void emit(const PlannedNode& planned, std::vector<GpuSdfInstruction>& out);

// The whole program: the top plain unions through the hierarchy when they have enough exact,
// bounded parts (the others first, unconditionally: unbounded ones are usually floors, near
// everything), else the tree as it is.
void emitProgram(const PlannedNode& root, bool useBounds, std::vector<GpuSdfInstruction>& out);

} // namespace rmsc::compiler
