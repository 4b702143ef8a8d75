// The bounding-volume hierarchy of the SDF compiler: the plain unions at the top of the planned
// tree (sdf_plan.hpp) emitted as a hierarchy of their exact parts' boxes, and of the boxes of
// their smoothly united parts' floors (BoundSkip, SeedBest, Accumulate), so a point far from a
// part skips it and the value stays what it would be without.
#include "sdf_emit.hpp"

#include "sdf/bounds.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"

#include <algorithm>
#include <span>

namespace rmsc::compiler {
namespace {

// Fewer parts than this at the top are evaluated as they are: box tests would cost more than
// they save, unless one of them is large (a tree of thousands of smoothly united spheres over a
// plane: two parts beside the plane, each skipped by the points far from it).
constexpr std::size_t kMinBoundedParts = 4;
constexpr std::size_t kLargePartInstructions = 16;

// A part of the top union: a subtree whose value is united into the program's running best.
struct UnionPart {
    const PlannedNode* node = nullptr;
    Aabb box; // in the frame of the current point; empty when unbounded or not exact
};

// Is the part's value its exact distance outside its box? Then a box at least `best` away
// proves the part's value is too, and skipping it leaves the result exactly as it was. Exact:
// shapes with exact formulas (and every profile solid) under uniform scale, united by plain
// unions; not: modifiers, other operations (their max() is a bound outside), bounds formulas.
// Parts that are not exact are evaluated at every point, outside the hierarchy.
bool isExactPart(const PlannedNode& planned) {
    const SdfNode& node = *planned.node;
    if (!node.modifiers.empty() || planned.cut) return false;
    if (!node.isGroup)
        return (node.profile || primitiveSpec(node.primitive).exact) &&
               isUniformScale(planned.world);
    if (node.op != SdfOp::Union) return false;
    for (const PlannedNode& child : planned.children)
        if (!isExactPart(child)) return false;
    return true;
}

// A union of exact shapes whose seams may be smooth, chamfered or rounded: its value is at most
// the minimum of its shapes' (each union operation's curve dips below the minimum, never
// above), and at least distance(y, box) - drop outside the box of its floor (sdfProgramFloor),
// where its surface lies. So a box test against that box grown by the drop in every direction
// (a cube of half-size drop holds the ball of radius drop: the grown box is no farther than
// distance - drop) skips it exactly, and the farthest point of that box bounds its value from
// above (SeedBest), as for an exact part.
bool isFlooredUnionPart(const PlannedNode& planned) {
    const SdfNode& node = *planned.node;
    if (!node.modifiers.empty() || planned.cut) return false;
    if (!node.isGroup)
        return (node.profile || primitiveSpec(node.primitive).exact) &&
               isUniformScale(planned.world);
    if (operationSpec(node.op).combination != SdfOpCombination::Union) return false;
    for (const PlannedNode& child : planned.children)
        if (!isFlooredUnionPart(child)) return false;
    return true;
}

// The box a floored union part is tested against (see isFlooredUnionPart); empty without one.
Aabb flooredPartBox(const PlannedNode& planned) {
    std::vector<GpuSdfInstruction> body;
    emit(planned, body);
    const std::optional<SdfFieldFloor> floor = sdfProgramFloor(body);
    if (!floor) return {};
    return {floor->box.min - glm::vec3(floor->drop), floor->box.max + glm::vec3(floor->drop)};
}

// A group whose children are simply united: every child's value ends up in the minimum.
bool isPlainUnion(const PlannedNode& planned) {
    const SdfNode& node = *planned.node;
    if (!node.isGroup || node.op != SdfOp::Union || planned.hasPointFrame ||
        !node.modifiers.empty())
        return false;
    for (const PlannedNode& child : planned.children)
        if (child.cut) return false;
    return true;
}

// The parts below the plain unions from `planned` down, with their boxes (sdf/bounds.hpp) in
// the current point's frame.
void collectParts(const PlannedNode& planned, std::vector<UnionPart>& parts) {
    if (isPlainUnion(planned)) {
        for (const PlannedNode& child : planned.children)
            collectParts(child, parts);
        return;
    }
    // Field units per unit of the parent's frame: the frame's scale to world units.
    const float fieldScale = float(planned.spaceScale * smallestScaleFactor(planned.parentWorld));
    const SdfBounds bounds = sdfNodeLocalBounds(*planned.node, fieldScale);
    UnionPart part{&planned, {}};
    if (bounds.bounded && !bounds.box.empty()) {
        if (isExactPart(planned))
            part.box = transformAabb(bounds.box, glm::mat4(planned.world));
        else if (planned.spaceScale == 1.0 && isFlooredUnionPart(planned))
            part.box = flooredPartBox(planned);
    }
    parts.push_back(part);
}

GpuSdfInstruction boundSkip(const Aabb& box, double spaceScale, std::size_t skipped) {
    GpuSdfInstruction instruction;
    instruction.opcode = std::uint32_t(SdfOpcode::BoundSkip);
    instruction.kind = std::uint32_t(skipped);
    instruction.params[0] = glm::vec4(box.center(), 0.0f);
    instruction.params[1] = glm::vec4(box.halfSize(), 0.0f);
    instruction.misc.x = float(spaceScale);
    return instruction;
}

GpuSdfInstruction seedBest(const Aabb& a, const Aabb& b, double spaceScale) {
    GpuSdfInstruction instruction;
    instruction.opcode = std::uint32_t(SdfOpcode::SeedBest);
    const glm::vec3 ca = a.center(), ha = a.halfSize(), cb = b.center(), hb = b.halfSize();
    instruction.params[0] = glm::vec4(ca, ha.x);
    instruction.params[1] = glm::vec4(ha.y, ha.z, cb.x, cb.y);
    instruction.params[2] = glm::vec4(cb.z, hb);
    instruction.misc.x = float(spaceScale);
    return instruction;
}

GpuSdfInstruction accumulate() {
    GpuSdfInstruction instruction;
    instruction.opcode = std::uint32_t(SdfOpcode::Accumulate);
    return instruction;
}

// Emits `parts` as a hierarchy: each node's box test skips its subtree when the box is no
// nearer than the best so far. Split at the median of the boxes' centres along the axis where
// they spread most (the classic median-split BVH build, e.g. Pharr, Jakob and Humphreys,
// "Physically Based Rendering", 4th ed., section 7.3).
void emitHierarchy(std::span<UnionPart> parts, double spaceScale,
                   std::vector<GpuSdfInstruction>& out) {
    if (parts.size() == 1) {
        std::vector<GpuSdfInstruction> body;
        emit(*parts[0].node, body);
        body.push_back(accumulate());
        // One primitive costs about what its box test would: test boxes of larger parts only.
        if (body.size() > 2) out.push_back(boundSkip(parts[0].box, spaceScale, body.size()));
        out.insert(out.end(), body.begin(), body.end());
        return;
    }
    Aabb box, centres;
    for (const UnionPart& part : parts) {
        box.add(part.box);
        centres.add(part.box.center());
    }
    const glm::vec3 spread = centres.max - centres.min;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0
                     : spread.y >= spread.z                       ? 1
                                                                  : 2;
    const std::size_t half = parts.size() / 2;
    std::nth_element(parts.begin(), parts.begin() + std::ptrdiff_t(half), parts.end(),
                     [axis](const UnionPart& a, const UnionPart& b) {
                         return a.box.center()[axis] < b.box.center()[axis];
                     });
    Aabb first, second;
    for (const UnionPart& part : parts.first(half))
        first.add(part.box);
    for (const UnionPart& part : parts.subspan(half))
        second.add(part.box);
    std::vector<GpuSdfInstruction> body;
    body.push_back(seedBest(first, second, spaceScale));
    emitHierarchy(parts.first(half), spaceScale, body);
    emitHierarchy(parts.subspan(half), spaceScale, body);
    out.push_back(boundSkip(box, spaceScale, body.size()));
    out.insert(out.end(), body.begin(), body.end());
}

} // namespace

void emitProgram(const PlannedNode& root, bool useBounds, std::vector<GpuSdfInstruction>& out) {
    std::vector<UnionPart> parts;
    if (useBounds) collectParts(root, parts);
    const auto boxed = std::count_if(parts.begin(), parts.end(),
                                     [](const UnionPart& part) { return !part.box.empty(); });
    const bool large = std::any_of(parts.begin(), parts.end(), [](const UnionPart& part) {
        if (part.box.empty()) return false;
        std::vector<GpuSdfInstruction> body;
        emit(*part.node, body);
        return body.size() >= kLargePartInstructions;
    });
    if (std::size_t(boxed) < kMinBoundedParts && !large) {
        emit(root, out);
        return;
    }
    std::vector<UnionPart> bounded;
    for (const UnionPart& part : parts) {
        if (!part.box.empty()) {
            bounded.push_back(part);
            continue;
        }
        emit(*part.node, out);
        out.push_back(accumulate());
    }
    if (!bounded.empty()) emitHierarchy(bounded, root.spaceScale, out);
}

} // namespace rmsc::compiler
