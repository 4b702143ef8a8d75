// The forms of compiled program that the lean loops run (sdf/program.hpp): the tests that choose
// them, for the generated GLSL (sdf/glsl_codegen.cpp) and for the cells' lists
// (sdf/cell_pruning.cpp) alike.
#include "sdf/program.hpp"
#include "sdf/sdf_tree.hpp"

namespace rmsc {

bool sdfIsPartsOnly(const SdfProgram& program) {
    const std::vector<GpuSdfInstruction>& code = program.instructions;
    for (std::size_t i = 0; i < code.size(); ++i) {
        const SdfOpcode opcode = SdfOpcode(code[i].opcode);
        if (opcode == SdfOpcode::BoundSkip || opcode == SdfOpcode::SeedBest) continue;
        const bool leaf = opcode == SdfOpcode::Shape || opcode == SdfOpcode::Profile;
        if (!leaf || i + 1 == code.size() || SdfOpcode(code[i + 1].opcode) != SdfOpcode::Accumulate)
            return false;
        ++i; // its Accumulate
    }
    return !code.empty();
}

bool sdfIsUnionOfShapes(const SdfProgram& program) {
    for (const GpuSdfInstruction& in : program.instructions) {
        const SdfOpcode opcode = SdfOpcode(in.opcode);
        if (opcode == SdfOpcode::Shape || opcode == SdfOpcode::Profile) continue;
        if (opcode != SdfOpcode::Combine || SdfOp(in.kind) != SdfOp::Union) return false;
    }
    return !program.instructions.empty();
}

} // namespace rmsc
