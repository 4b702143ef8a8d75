// Emission in the SDF compiler: a planned node (sdf_plan.hpp) as instructions: shapes and
// profiles, point frames, point and distance modifiers (the neighbour check of repetitions
// included), and the combines that fold a group's children.
#include "sdf_emit.hpp"

#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"

namespace rmsc::compiler {
namespace {

// The cut nodes of a group are subtracted with the subtraction of the group's seam.
SdfOp cutOp(SdfOp op) {
    return withCombination(op, SdfOpCombination::Subtraction);
}

GpuSdfInstruction profileInstruction(const PlannedNode& planned) {
    const SdfProfile& profile = *planned.node->profile;
    GpuSdfInstruction instruction;
    instruction.opcode = std::uint32_t(SdfOpcode::Profile);
    instruction.kind = std::uint32_t(profile.type);
    instruction.material = planned.material;
    instruction.objectId = planned.objectId;
    instruction.params[0] = glm::vec4(profile.radius, profile.halfSize, 0.0f);
    const bool extrusion = profile.solid == SdfProfileSolid::Extrusion;
    instruction.params[1] =
        glm::vec4(extrusion ? 0.0f : 1.0f, extrusion ? 0.5f * profile.depth : profile.offset, 0, 0);
    instruction.params[2] =
        glm::vec4(float(planned.dataOffset), float(profile.points.size()), 0.0f, 0.0f);
    for (int row = 0; row < 3; ++row)
        instruction.worldToLocal[row] = planned.worldToLocal[row];
    instruction.misc = glm::vec4(planned.distanceScale, 0.0f, 0.0f, 0.0f);
    return instruction;
}

GpuSdfInstruction shapeInstruction(const PlannedNode& planned) {
    const SdfNode& node = *planned.node;
    if (node.profile) return profileInstruction(planned);
    GpuSdfInstruction instruction;
    instruction.opcode = std::uint32_t(SdfOpcode::Shape);
    instruction.kind = std::uint32_t(node.primitive);
    instruction.material = planned.material;
    instruction.objectId = planned.objectId;
    instruction.params[0] =
        glm::vec4(node.params[0], node.params[1], node.params[2], node.params[3]);
    instruction.params[1] =
        glm::vec4(node.params[4], node.params[5], node.params[6], node.params[7]);
    instruction.params[2] =
        glm::vec4(node.params[8], node.params[9], node.params[10], node.params[11]);
    for (int row = 0; row < 3; ++row)
        instruction.worldToLocal[row] = planned.worldToLocal[row];
    instruction.misc = glm::vec4(planned.distanceScale * primitiveSpec(node.primitive).stepScale,
                                 0.0f, 0.0f, 0.0f);
    return instruction;
}

GpuSdfInstruction pointInstruction(SdfOpcode opcode, const PlannedNode& planned) {
    GpuSdfInstruction instruction;
    instruction.opcode = std::uint32_t(opcode);
    instruction.material = planned.material;
    instruction.objectId = planned.objectId;
    return instruction;
}

// A PushPoint into the node's frame (rows), or one that only saves the point (identity).
GpuSdfInstruction pushPoint(const PlannedNode& planned, const glm::vec4* rows) {
    GpuSdfInstruction instruction = pointInstruction(SdfOpcode::PushPoint, planned);
    for (int row = 0; row < 3; ++row)
        instruction.worldToLocal[row] = rows ? rows[row] : glm::vec4(glm::vec3(0.0f), 0.0f);
    if (!rows)
        for (int row = 0; row < 3; ++row)
            instruction.worldToLocal[row][row] = 1.0f;
    return instruction;
}

// A point modifier; `cell` selects the neighbour cell of a checked repetition (bit per
// repeated axis, in x, y, z order), -1 for none.
GpuSdfInstruction pointModifierInstruction(const SdfModifier& m, const PlannedNode& planned,
                                           int cell) {
    GpuSdfInstruction instruction = pointInstruction(SdfOpcode::PointModifier, planned);
    instruction.kind = modifierKind(m.type);
    modifierSpec(m.type).pack(m, 1.0f, cell, instruction.params);
    return instruction;
}

// A distance modifier, its lengths converted to the units of the node's field.
GpuSdfInstruction distanceModifierInstruction(const SdfModifier& m, const PlannedNode& planned) {
    GpuSdfInstruction instruction = pointInstruction(SdfOpcode::DistanceModifier, planned);
    instruction.kind = modifierKind(m.type);
    modifierSpec(m.type).pack(m, float(planned.nodeScale), -1, instruction.params);
    return instruction;
}

GpuSdfInstruction combineInstruction(const PlannedNode& planned, SdfOp op) {
    const SdfNode& node = *planned.node;
    GpuSdfInstruction combine;
    combine.opcode = std::uint32_t(SdfOpcode::Combine);
    combine.kind = std::uint32_t(op);
    combine.material = planned.material;
    combine.objectId = planned.objectId; // informational; the shapes' ids are shown
    combine.params[0].x = node.smoothness;
    combine.params[0].y = float(node.blend); // SmoothBlend: 0 polynomial, 1 circular
    return combine;
}

// The node itself: its shape, or its children folded with the group's op, the cut children
// subtracted last.
void emitBody(const PlannedNode& planned, std::vector<GpuSdfInstruction>& out) {
    const SdfNode& node = *planned.node;
    if (!node.isGroup) {
        out.push_back(shapeInstruction(planned));
        return;
    }
    for (std::size_t i = 0; i < planned.children.size(); ++i) {
        emit(planned.children[i], out);
        if (i == 0) continue;
        out.push_back(
            combineInstruction(planned, planned.children[i].cut ? cutOp(node.op) : node.op));
    }
}

// The node's modifier chain from modifier i on (see chainCost): point modifiers in list order,
// then the body and the distance modifiers in list order.
void emitChain(const PlannedNode& planned, std::size_t i, std::vector<GpuSdfInstruction>& out) {
    const std::vector<SdfModifier>& modifiers = planned.node->modifiers;
    if (i == modifiers.size()) {
        emitBody(planned, out);
        for (const SdfModifier& m : modifiers)
            if (!isPointModifier(m.type)) out.push_back(distanceModifierInstruction(m, planned));
        return;
    }
    const SdfModifier& m = modifiers[i];
    if (!isPointModifier(m.type)) {
        emitChain(planned, i + 1, out);
        return;
    }
    const int cells = neighbourCells(m);
    if (cells == 1) {
        out.push_back(pointModifierInstruction(m, planned, -1));
        emitChain(planned, i + 1, out);
        return;
    }
    // Neighbour check: the rest of the chain once per cell, united (Quilez, "Domain
    // repetition", https://iquilezles.org/articles/sdfrepetition/).
    for (int cell = 0; cell < cells; ++cell) {
        out.push_back(pushPoint(planned, nullptr));
        out.push_back(pointModifierInstruction(m, planned, cell));
        emitChain(planned, i + 1, out);
        out.push_back(pointInstruction(SdfOpcode::PopPoint, planned));
        if (cell > 0) out.push_back(combineInstruction(planned, SdfOp::Union));
    }
}

} // namespace

void emit(const PlannedNode& planned, std::vector<GpuSdfInstruction>& out) {
    if (planned.hasPointFrame) out.push_back(pushPoint(planned, planned.pushRows));
    emitChain(planned, 0, out);
    if (planned.hasPointFrame) out.push_back(pointInstruction(SdfOpcode::PopPoint, planned));
}

} // namespace rmsc::compiler
