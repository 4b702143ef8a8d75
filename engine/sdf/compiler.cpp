// The SDF compiler: flattens the SDF tree into the postfix program of sdf/program.hpp. A first
// pass resolves transforms, materials, object ids and the stack each subtree needs (and finds
// every error); a second pass emits the instructions, deepest subtree first where the operation
// allows it (Sethi-Ullman order).
#include "sdf/compiler.hpp"

#include "core/object_ids.hpp"
#include "sdf/bounds.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"

#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace rmsc {
namespace {

// A node with everything resolved, children in the order they are emitted.
struct PlannedNode {
    const SdfNode* node = nullptr;
    std::uint32_t objectId = 0;
    std::uint32_t material = 0;
    // The node's local frame to the frame of the current point: world space, or below a node
    // with its own point frame (hasPointFrame), that node's modified local frame.
    glm::dmat4 world{1.0};
    glm::dmat4 parentWorld{1.0}; // the parent's frame to the frame of the current point
    double spaceScale = 1.0;     // world units per unit of the current point's frame
    // Shapes: rows of world^-1 and the distance scale (see resolveShape).
    glm::vec4 worldToLocal[3]{};
    float distanceScale = 1.0f;
    // Nodes with point modifiers or displacement evaluate their subtree in their own frame:
    // PushPoint (rows of world^-1), the point modifiers, the subtree, PopPoint.
    bool hasPointFrame = false;
    glm::vec4 pushRows[3]{};
    // World units of the node's field per unit of its local (modified) frame, Lipschitz
    // corrections included: converts the lengths of distance modifiers.
    double nodeScale = 1.0;
    bool cut = false;
    std::uint32_t dataOffset = 0; // profile polygons: first point in SdfProgram::data
    int stackNeed = 0;            // entries the subtree needs on the stack
    int pointNeed = 0;            // entries the subtree needs on the point stack
    long instructionCount = 0;    // instructions the subtree compiles to
    bool skipped = false;         // a shell, or a group of shells only: not in this program
    std::vector<PlannedNode> children;
};

// Where a shell sits in the tree, found while planning the scene's program.
struct ShellSite {
    const SdfNode* node = nullptr;
    glm::dmat4 parentWorld{1.0}; // the parent's frame to world (shells sit in plain unions)
    std::uint32_t parentMaterial = 0;
    std::uint32_t idBase = 0; // pre-order index of the shell node in the whole tree
};

// The cut nodes of a group are subtracted with the subtraction of the group's seam.
SdfOp cutOp(SdfOp op) {
    return withCombination(op, SdfOpCombination::Subtraction);
}

// A node needs its own point frame when a modifier reads or changes the point.
bool needsPointFrame(const SdfNode& node) {
    for (const SdfModifier& m : node.modifiers) {
        const ModifierSpec& spec = modifierSpec(m.type);
        if (spec.stage == ModifierStage::Point || spec.readsPoint) return true;
    }
    return false;
}

// Cells a point modifier evaluates the rest of its chain in (ModifierSpec::cells).
int neighbourCells(const SdfModifier& m) {
    const ModifierSpec& spec = modifierSpec(m.type);
    return spec.cells ? spec.cells(m) : 1;
}

constexpr long kCountCap = 1L << 40; // instruction counts saturate here (no overflow)

// Instructions, value stack and point stack a node's modifier chain needs from modifier `i` on,
// around a body (the node itself plus its distance modifiers) needing `body`. A repetition with
// the neighbour check evaluates the rest of the chain once per cell: PushPoint, Repeat, rest,
// PopPoint, and a union for every cell after the first.
struct ChainCost {
    long instructions = 0;
    int stack = 0;
    int points = 0;
};
ChainCost chainCost(const std::vector<SdfModifier>& modifiers, std::size_t i, ChainCost body) {
    if (i == modifiers.size()) return body;
    const ChainCost rest = chainCost(modifiers, i + 1, body);
    if (!isPointModifier(modifiers[i].type)) return rest;
    const long cells = neighbourCells(modifiers[i]);
    if (cells == 1) return {std::min(rest.instructions + 1, kCountCap), rest.stack, rest.points};
    return {std::min(cells * (rest.instructions + 3) + cells - 1, kCountCap), rest.stack + 1,
            rest.points + 1};
}

// Smallest singular value of the linear part of `m`: the least a world-space length can shrink
// to. It is the square root of the smallest eigenvalue of the symmetric A = L^T L, found with the
// closed form for symmetric 3x3 matrices (O. K. Smith, "Eigenvalues of a symmetric 3 x 3
// matrix", Communications of the ACM 4(4), 1961).
double smallestScaleFactor(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    const glm::dmat3 a = glm::transpose(l) * l;
    const double offDiagonal = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    const double diagonal = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) +
                            (a[2][2] - q) * (a[2][2] - q);
    const double p = std::sqrt((diagonal + 2.0 * offDiagonal) / 6.0);
    double smallest = 0.0;
    if (p <= 1e-12 * std::max(q, 1e-300)) {
        smallest = q; // A is a multiple of the identity: uniform scale
    } else {
        const glm::dmat3 b = (a - glm::dmat3(q)) * (1.0 / p);
        const double r = std::clamp(glm::determinant(b) / 2.0, -1.0, 1.0);
        const double phi = std::acos(r) / 3.0;
        smallest = q + 2.0 * p * std::cos(phi + 2.0 * std::numbers::pi / 3.0);
    }
    return std::sqrt(std::max(smallest, 0.0));
}

class Planner {
  public:
    Planner(const std::string& file, Diagnostics& diagnostics,
            std::vector<std::string>& nodePointers)
        : file_(file), diagnostics_(diagnostics), nodePointers_(nodePointers) {}

    // Leave shells out of the program and list them (shells()) instead.
    void splitShells() { splitShells_ = true; }
    // Plan `root` in its own frame (its transform not applied) with ids from `idBase` on: a
    // shell's program, in object space.
    void planInObjectSpace(const SdfNode& root, std::uint32_t idBase) {
        objectSpaceRoot_ = &root;
        idBase_ = idBase;
    }
    const std::vector<ShellSite>& shells() const { return shells_; }

    // Resolves `node` and its subtree. `parentWorld` maps the parent's frame to the current
    // point's frame, `spaceScale` is the world units per unit of the current point's frame,
    // `parentMaterial` the parent's resolved material. Object ids count every node in pre-order
    // (file order).
    PlannedNode plan(const SdfNode& node, const glm::dmat4& parentWorld, double spaceScale,
                     std::uint32_t parentMaterial) {
        PlannedNode planned;
        planned.node = &node;
        planned.material = node.material >= 0 ? std::uint32_t(node.material) : parentMaterial;
        if (splitShells_ && node.shell) {
            planShell(node, parentWorld, planned.material);
            planned.skipped = true;
            return planned;
        }
        planned.objectId = kSdfIdBase + idBase_ + std::uint32_t(nodePointers_.size());
        nodePointers_.push_back(node.pointer);
        planned.parentWorld = parentWorld;
        planned.spaceScale = spaceScale;
        planned.world =
            parentWorld *
            (&node == objectSpaceRoot_ ? glm::dmat4(1.0) : glm::dmat4(node.transform.matrix()));
        planned.cut = node.cut;
        planned.hasPointFrame = needsPointFrame(node);

        // Below a node with its own frame, children see the modified local point.
        glm::dmat4 childWorld = planned.world;
        double childScale = spaceScale;
        if (planned.hasPointFrame) {
            double scale = 1.0;
            if (!invertFrame(planned.world, planned.pushRows, scale))
                diagnostics_.error(file_, node.pointer,
                                   "the node's transform (with its groups') cannot be "
                                   "inverted; is a scale 0?");
            planned.nodeScale = spaceScale * scale / sdfFieldShrink(node.modifiers);
            childWorld = glm::dmat4(1.0);
            childScale = planned.nodeScale;
        } else {
            planned.nodeScale = spaceScale * smallestScaleFactor(planned.world);
        }

        ChainCost body;
        if (!node.isGroup) {
            resolveShape(planned, childWorld, childScale);
            if (node.profile && node.profile->type == SdfProfileType::Polygon) {
                planned.dataOffset = std::uint32_t(data_.size());
                if (node.profile->points.size() < 3)
                    diagnostics_.error(file_, node.pointer,
                                       "a polygon profile needs at least 3 points, got " +
                                           std::to_string(node.profile->points.size()));
                for (const glm::vec2& point : node.profile->points)
                    data_.emplace_back(point, 0.0f, 0.0f);
            }
            body = {1, 1, 0};
        } else {
            checkGroup(node);
            std::vector<PlannedNode> kept;
            std::vector<PlannedNode> cuts;
            const std::string outerBlocker = shellBlocker_;
            if (shellBlocker_.empty()) shellBlocker_ = shellBlocker(node);
            bool skippedChild = false;
            for (const SdfNode& child : node.children) {
                PlannedNode c = plan(child, childWorld, childScale, planned.material);
                skippedChild = skippedChild || c.skipped;
                if (!c.skipped) (c.cut ? cuts : kept).push_back(std::move(c));
            }
            shellBlocker_ = outerBlocker;
            if (skippedChild && kept.empty() && cuts.empty()) {
                planned.skipped = true; // only shells below: nothing left for this program
                return planned;
            }
            if (kept.empty() && !cuts.empty())
                diagnostics_.error(file_, node.pointer,
                                   "every child of the group is marked \"cut\"; at least one "
                                   "must not be (it is what the cut nodes are subtracted from)");
            // The kept children combine with the group's op, then each cut one is subtracted.
            order(node.op, kept);
            planned.children = std::move(kept);
            for (PlannedNode& c : cuts)
                planned.children.push_back(std::move(c));

            // A left fold c0 c1 OP c2 OP ...: c0 needs its own stack, every later child one
            // more for the result held below it.
            for (std::size_t i = 0; i < planned.children.size(); ++i) {
                const PlannedNode& child = planned.children[i];
                body.stack = std::max(body.stack, child.stackNeed + (i > 0 ? 1 : 0));
                body.points = std::max(body.points, child.pointNeed);
                body.instructions = std::min(
                    body.instructions + child.instructionCount + (i > 0 ? 1 : 0), kCountCap);
            }
        }
        for (const SdfModifier& m : node.modifiers)
            if (!isPointModifier(m.type)) ++body.instructions;
        const ChainCost chain = chainCost(node.modifiers, 0, body);
        planned.stackNeed = chain.stack;
        planned.pointNeed = chain.points + (planned.hasPointFrame ? 1 : 0);
        planned.instructionCount = chain.instructions + (planned.hasPointFrame ? 2 : 0);

        if (planned.stackNeed > kSdfMaxStack && firstOverflow_.empty()) {
            bool childOverflows = false;
            for (const PlannedNode& child : planned.children)
                childOverflows = childOverflows || child.stackNeed > kSdfMaxStack;
            if (!childOverflows) firstOverflow_ = node.pointer;
        }
        if (planned.pointNeed > kSdfMaxPointStack && firstPointOverflow_.empty()) {
            bool childOverflows = false;
            for (const PlannedNode& child : planned.children)
                childOverflows = childOverflows || child.pointNeed > kSdfMaxPointStack;
            if (!childOverflows) firstPointOverflow_ = node.pointer;
        }
        return planned;
    }

    // The pointer of the first group (in the order groups finish planning) that needs more than
    // kSdfMaxStack while none of its children does: where the limit is crossed. "" if none.
    const std::string& firstOverflow() const { return firstOverflow_; }
    // The same for the point stack (kSdfMaxPointStack).
    const std::string& firstPointOverflow() const { return firstPointOverflow_; }

  private:
    // Why a shell cannot sit below `group` ("" if it can). A shell is composited with the rest
    // of the scene through the depth buffer, which is a plain union.
    static std::string shellBlocker(const SdfNode& group) {
        const std::string lead = "a shell is drawn on its own and meets the rest of the scene "
                                 "through the depth buffer (a plain union), so it can only sit "
                                 "in plain union groups without modifiers; ";
        if (group.op != SdfOp::Union)
            return lead + "its group " + group.pointer + " is a " + operationLabel(group.op);
        if (!group.modifiers.empty())
            return lead + "its group " + group.pointer +
                   " has modifiers, which would not "
                   "reach the shell";
        for (const SdfNode& child : group.children)
            if (child.cut)
                return lead + "its group " + group.pointer + " has a \"cut\" child (" +
                       child.pointer + "), which could not cut the shell";
        return {};
    }

    // Records a shell found in the scene's program and counts its subtree's ids.
    void planShell(const SdfNode& node, const glm::dmat4& parentWorld, std::uint32_t material) {
        const std::string& where = node.shell->pointer;
        if (!shellBlocker_.empty()) diagnostics_.error(file_, where, shellBlocker_);
        if (node.cut)
            diagnostics_.error(file_, where,
                               "a shell cannot be \"cut\": it is drawn on its own and cannot "
                               "cut its siblings");
        shells_.push_back({&node, parentWorld, material, std::uint32_t(nodePointers_.size())});
        countIds(node, true);
    }

    // Gives the subtree's nodes their pre-order ids; nested shells are an error.
    void countIds(const SdfNode& node, bool isShellRoot) {
        if (!isShellRoot && node.shell)
            diagnostics_.error(file_, node.shell->pointer,
                               "a shell inside a shell (" + shells_.back().node->pointer +
                                   "); mark only one of them");
        nodePointers_.push_back(node.pointer);
        for (const SdfNode& child : node.children)
            countIds(child, false);
    }

    // Rows of m^-1 and the smallest scale factor of m; false if m cannot be inverted.
    static bool invertFrame(const glm::dmat4& m, glm::vec4 rows[3], double& scale) {
        scale = smallestScaleFactor(m);
        const glm::dmat4 inverse = glm::inverse(m);
        bool finite = std::isfinite(scale) && scale > 1e-12;
        for (int row = 0; row < 3; ++row) {
            const glm::dvec4 r = glm::row(inverse, row);
            finite = finite && std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) &&
                     std::isfinite(r.w);
            rows[row] = glm::vec4(r);
        }
        return finite;
    }

    // The primitive is evaluated at q = world^-1 p (`world`: the shape's frame to the current
    // point's frame, the identity when the shape has its own point frame). A local distance d
    // maps to world units within [d * smallest, d * largest] scale factor, times `spaceScale`
    // (world units per unit of the current point's frame, Lipschitz corrections included);
    // d * smallest is exact for a uniform scale and a lower bound (safe for sphere tracing,
    // never overshooting) for a non-uniform one.
    void resolveShape(PlannedNode& planned, const glm::dmat4& world, double spaceScale) {
        double scale = 1.0;
        const bool finite = invertFrame(world, planned.worldToLocal, scale);
        planned.distanceScale = float(scale * spaceScale);
        if (!finite)
            diagnostics_.error(file_, planned.node->pointer,
                               "the shape's transform (with its groups') cannot be inverted; "
                               "is a scale 0?");
    }

    void checkGroup(const SdfNode& node) {
        if (node.children.empty())
            diagnostics_.error(file_, node.pointer,
                               "the " + operationLabel(node.op) + " group has no children");
        if (operationSpec(node.op).combination == SdfOpCombination::Subtraction &&
            node.children.size() == 1)
            diagnostics_.error(file_, node.pointer,
                               "a " + operationLabel(node.op) +
                                   " needs at least two children (the shape and what to "
                                   "subtract from it), got one");
        if (takesSmoothness(node.op) && !(std::isfinite(node.smoothness) && node.smoothness > 0.0f))
            diagnostics_.error(file_, node.pointer,
                               "the smoothness (radius) of a " + operationLabel(node.op) +
                                   " must be a finite number > 0, got " +
                                   std::to_string(node.smoothness));
    }

    // Emission order of a group's children. Union and intersection are commutative and
    // associative, so the deepest child goes first (Sethi-Ullman): the fold then needs
    // max(deepest, 1 + second deepest). So is xor: for exact children it gives
    // sign(a) sign(b) min(|a|, |b|), which folds to sign(a b c) min(|a|, |b|, |c|) in any order.
    // Subtraction keeps its first child; the order of the subtracted ones would not change the
    // stack the fold needs, so they keep file order. Smooth, chamfer and round operations are not
    // associative (smin(smin(a, b), c) != smin(a, smin(b, c))) and keep file order.
    static void order(SdfOp op, std::vector<PlannedNode>& children) {
        if (op != SdfOp::Union && op != SdfOp::Intersection && op != SdfOp::Xor) return;
        std::stable_sort(
            children.begin(), children.end(),
            [](const PlannedNode& x, const PlannedNode& y) { return x.stackNeed > y.stackNeed; });
    }

    const std::string& file_;
    Diagnostics& diagnostics_;
    std::vector<std::string>& nodePointers_;
    std::string firstOverflow_;
    std::string firstPointOverflow_;
    bool splitShells_ = false;
    const SdfNode* objectSpaceRoot_ = nullptr;
    std::uint32_t idBase_ = 0;
    std::vector<ShellSite> shells_;
    std::string shellBlocker_; // why a shell cannot sit here ("" if it can)

  public:
    std::vector<glm::vec4> data_; // SdfProgram::data, filled while planning
};

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

void emit(const PlannedNode& planned, std::vector<GpuSdfInstruction>& out);

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

void emit(const PlannedNode& planned, std::vector<GpuSdfInstruction>& out) {
    if (planned.hasPointFrame) out.push_back(pushPoint(planned, planned.pushRows));
    emitChain(planned, 0, out);
    if (planned.hasPointFrame) out.push_back(pointInstruction(SdfOpcode::PopPoint, planned));
}

// ---- Bounds: a bounding-volume hierarchy over the plain unions at the top of the tree ----

// Fewer parts than this at the top are evaluated as they are: box tests would cost more than
// they save.
constexpr std::size_t kMinBoundedParts = 4;

// A part of the top union: a subtree whose value is united into the program's running best.
struct UnionPart {
    const PlannedNode* node = nullptr;
    Aabb box; // in the frame of the current point; empty when unbounded or not exact
};

// Does `m` scale every direction alike (a rotation times a uniform scale)?
bool isUniformScale(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    const glm::dmat3 a = glm::transpose(l) * l;
    const double s = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    const double tolerance = 1e-6 * s;
    return std::abs(a[0][0] - s) <= tolerance && std::abs(a[1][1] - s) <= tolerance &&
           std::abs(a[2][2] - s) <= tolerance && std::abs(a[0][1]) <= tolerance &&
           std::abs(a[0][2]) <= tolerance && std::abs(a[1][2]) <= tolerance;
}

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
    if (bounds.bounded && !bounds.box.empty() && isExactPart(planned))
        part.box = transformAabb(bounds.box, glm::mat4(planned.world));
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

// The whole program: the top plain unions through the hierarchy when they have enough exact,
// bounded parts (the others first, unconditionally: unbounded ones are usually floors, near
// everything), else the tree as it is.
void emitProgram(const PlannedNode& root, bool useBounds, std::vector<GpuSdfInstruction>& out) {
    std::vector<UnionPart> parts;
    if (useBounds) collectParts(root, parts);
    const auto boxed = std::count_if(parts.begin(), parts.end(),
                                     [](const UnionPart& part) { return !part.box.empty(); });
    if (std::size_t(boxed) < kMinBoundedParts) {
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

} // namespace

namespace {

// Checks the limits of a planned program and emits it (nullopt when there were errors).
std::optional<SdfProgram> finishProgram(Planner& planner, const PlannedNode& planned,
                                        const SdfNode& root, SdfProgram program,
                                        const std::string& file, Diagnostics& diagnostics,
                                        int errorsBefore, const SdfCompileOptions& options) {
    if (root.cut && !root.shell) // a cut shell is reported where the shell is found
        diagnostics.error(file, root.pointer,
                          "the root node cannot be \"cut\": it has no siblings to be cut from");
    if (planned.pointNeed > kSdfMaxPointStack) {
        diagnostics.error(
            file, root.pointer,
            "the SDF tree needs a point stack of " + std::to_string(planned.pointNeed) +
                " entries, the shader supports " + std::to_string(kSdfMaxPointStack) + " (" +
                std::to_string(planned.pointNeed - kSdfMaxPointStack) +
                " over); it first goes over at " + planner.firstPointOverflow() +
                " (every node with point modifiers or displacement, and every repetition with "
                "the neighbour check, nests one entry)");
    }
    if (planner.data_.size() > std::size_t(kSdfMaxData)) {
        diagnostics.error(file, root.pointer,
                          "the SDF tree's polygon profiles have " +
                              std::to_string(planner.data_.size()) + " points in all, the " +
                              "data buffer holds " + std::to_string(kSdfMaxData) + " (" +
                              std::to_string(planner.data_.size() - kSdfMaxData) + " over)");
    }

    if (planned.stackNeed > kSdfMaxStack) {
        diagnostics.error(file, root.pointer,
                          "the SDF tree needs a stack of " + std::to_string(planned.stackNeed) +
                              " entries, the shader supports " + std::to_string(kSdfMaxStack) +
                              " (" + std::to_string(planned.stackNeed - kSdfMaxStack) +
                              " over); it first goes over at " + planner.firstOverflow() +
                              " (smooth operations and the first child of a subtraction keep "
                              "their order: nest groups in their first child)");
    }
    if (planned.instructionCount > kSdfMaxInstructions) {
        diagnostics.error(
            file, root.pointer,
            "the SDF tree compiles to " + std::to_string(planned.instructionCount) +
                " instructions, the shader supports " + std::to_string(kSdfMaxInstructions) + " (" +
                std::to_string(planned.instructionCount - kSdfMaxInstructions) + " over)");
    }
    if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
    if (planned.skipped) return program; // everything is in shells

    program.instructions.reserve(std::size_t(planned.instructionCount));
    emitProgram(planned, options.bounds, program.instructions);
    if (program.instructions.size() > std::size_t(kSdfMaxInstructions)) {
        // The hierarchy's box tests do not fit beside the tree: the tree as it is does.
        program.instructions.clear();
        emit(planned, program.instructions);
    }
    program.stackDepth = planned.stackNeed;
    program.pointStackDepth = planned.pointNeed;
    program.data = std::move(planner.data_);
    return program;
}

} // namespace

double sdfFieldShrink(const std::vector<SdfModifier>& modifiers) {
    double lipschitz = 1.0;
    double gradient = 1.0;
    for (const SdfModifier& m : modifiers) {
        const ModifierSpec& spec = modifierSpec(m.type);
        if (spec.lipschitz) lipschitz *= spec.lipschitz(m);
        if (spec.gradientGain) gradient += spec.gradientGain(m);
    }
    return lipschitz * gradient;
}

std::optional<SdfProgram> compileSdf(const SdfNode& root, std::uint32_t defaultMaterial,
                                     const std::string& file, Diagnostics& diagnostics,
                                     const SdfCompileOptions& options) {
    const int errorsBefore = diagnostics.errorCount();
    SdfProgram program;
    Planner planner(file, diagnostics, program.nodePointers);
    const PlannedNode planned = planner.plan(root, glm::dmat4(1.0), 1.0, defaultMaterial);
    return finishProgram(planner, planned, root, std::move(program), file, diagnostics,
                         errorsBefore, options);
}

std::optional<CompiledSdfScene> compileSdfScene(const SdfNode& root, std::uint32_t defaultMaterial,
                                                const std::string& file, Diagnostics& diagnostics,
                                                const SdfCompileOptions& options) {
    const int errorsBefore = diagnostics.errorCount();
    CompiledSdfScene compiled;
    SdfProgram program;
    Planner planner(file, diagnostics, program.nodePointers);
    planner.splitShells();
    const PlannedNode planned = planner.plan(root, glm::dmat4(1.0), 1.0, defaultMaterial);
    std::optional<SdfProgram> main = finishProgram(planner, planned, root, std::move(program), file,
                                                   diagnostics, errorsBefore, options);
    if (!main) return std::nullopt;
    compiled.main = std::move(*main);

    for (const ShellSite& site : planner.shells()) {
        const int shellErrorsBefore = diagnostics.errorCount();
        SdfShellProgram shell;
        shell.node = site.node;
        shell.pointer = site.node->pointer;
        const glm::dmat4 objectToWorld =
            site.parentWorld * glm::dmat4(site.node->transform.matrix());
        shell.objectToWorld = glm::mat4(objectToWorld);
        shell.worldToObject = glm::mat4(glm::inverse(objectToWorld));
        shell.distanceScale = float(smallestScaleFactor(objectToWorld));
        shell.parentFieldScale = float(smallestScaleFactor(site.parentWorld));
        if (!(shell.distanceScale > 1e-12f) || !std::isfinite(shell.distanceScale))
            diagnostics.error(file, site.node->pointer,
                              "the shell's transform (with its groups') cannot be inverted; is "
                              "a scale 0?");
        // The hierarchy's exactness needs the world distance to be the object distance times
        // one scale: a shell stretched unevenly gets none.
        SdfCompileOptions shellOptions = options;
        shellOptions.bounds = options.bounds && isUniformScale(objectToWorld);
        SdfProgram shellProgram;
        Planner shellPlanner(file, diagnostics, shellProgram.nodePointers);
        shellPlanner.planInObjectSpace(*site.node, site.idBase);
        // Distances in world units, as in the scene's program (the smoothness of operations and
        // the lengths of modifiers are world units): object units times the frame's scale.
        const PlannedNode plannedShell = shellPlanner.plan(
            *site.node, glm::dmat4(1.0), double(shell.distanceScale), site.parentMaterial);
        std::optional<SdfProgram> compiledShell =
            finishProgram(shellPlanner, plannedShell, *site.node, std::move(shellProgram), file,
                          diagnostics, shellErrorsBefore, shellOptions);
        if (!compiledShell) continue;
        int leaves = 0;
        for (const GpuSdfInstruction& in : compiledShell->instructions)
            leaves += SdfOpcode(in.opcode) == SdfOpcode::Shape ||
                      SdfOpcode(in.opcode) == SdfOpcode::Profile;
        if (leaves > kMaxShellShapes) {
            diagnostics.error(file, site.node->shell->pointer,
                              "a shell holds at most " + std::to_string(kMaxShellShapes) +
                                  " shapes (its shader is generated), this one has " +
                                  std::to_string(leaves) + "; split it into several shells");
            continue;
        }
        shell.program = std::move(*compiledShell);
        compiled.shells.push_back(std::move(shell));
    }
    if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
    return compiled;
}

} // namespace rmsc
