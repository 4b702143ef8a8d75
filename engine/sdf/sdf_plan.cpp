// The planning pass of the SDF compiler: see sdf_plan.hpp.
#include "sdf_plan.hpp"

#include "core/number_text.hpp"
#include "core/object_ids.hpp"
#include "sdf/compiler.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"

#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rmsc::compiler {
namespace {

// A node needs its own point frame when a modifier reads or changes the point.
bool needsPointFrame(const SdfNode& node) {
    for (const SdfModifier& m : node.modifiers) {
        const ModifierSpec& spec = modifierSpec(m.type);
        if (spec.stage == ModifierStage::Point || spec.readsPoint) return true;
    }
    return false;
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

} // namespace

int neighbourCells(const SdfModifier& m) {
    const ModifierSpec& spec = modifierSpec(m.type);
    return spec.cells ? spec.cells(m) : 1;
}

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

bool isUniformScale(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    const glm::dmat3 a = glm::transpose(l) * l;
    const double s = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    const double tolerance = 1e-6 * s;
    return std::abs(a[0][0] - s) <= tolerance && std::abs(a[1][1] - s) <= tolerance &&
           std::abs(a[2][2] - s) <= tolerance && std::abs(a[0][1]) <= tolerance &&
           std::abs(a[0][2]) <= tolerance && std::abs(a[1][2]) <= tolerance;
}

PlannedNode Planner::plan(const SdfNode& node, const glm::dmat4& parentWorld, double spaceScale,
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
    planned.world = parentWorld * (&node == objectSpaceRoot_ ? glm::dmat4(1.0)
                                                             : glm::dmat4(node.transform.matrix()));
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
            body.instructions =
                std::min(body.instructions + child.instructionCount + (i > 0 ? 1 : 0), kCountCap);
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

std::string Planner::shellBlocker(const SdfNode& group) {
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
            return lead + "its group " + group.pointer + " has a \"cut\" child (" + child.pointer +
                   "), which could not cut the shell";
    return {};
}

void Planner::planShell(const SdfNode& node, const glm::dmat4& parentWorld,
                        std::uint32_t material) {
    const std::string& where = node.shell->pointer;
    if (!shellBlocker_.empty()) diagnostics_.error(file_, where, shellBlocker_);
    if (node.cut)
        diagnostics_.error(file_, where,
                           "a shell cannot be \"cut\": it is drawn on its own and cannot "
                           "cut its siblings");
    shells_.push_back({&node, parentWorld, material, std::uint32_t(nodePointers_.size())});
    countIds(node, true);
}

void Planner::countIds(const SdfNode& node, bool isShellRoot) {
    if (!isShellRoot && node.shell)
        diagnostics_.error(file_, node.shell->pointer,
                           "a shell inside a shell (" + shells_.back().node->pointer +
                               "); mark only one of them");
    nodePointers_.push_back(node.pointer);
    for (const SdfNode& child : node.children)
        countIds(child, false);
}

bool Planner::invertFrame(const glm::dmat4& m, glm::vec4 rows[3], double& scale) {
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

void Planner::resolveShape(PlannedNode& planned, const glm::dmat4& world, double spaceScale) {
    double scale = 1.0;
    const bool finite = invertFrame(world, planned.worldToLocal, scale);
    planned.distanceScale = float(scale * spaceScale);
    if (!finite)
        diagnostics_.error(file_, planned.node->pointer,
                           "the shape's transform (with its groups') cannot be inverted; "
                           "is a scale 0?");
}

void Planner::checkGroup(const SdfNode& node) {
    if (node.children.empty())
        diagnostics_.error(file_, node.pointer,
                           "the " + operationLabel(node.op) + " group has no children");
    if (operationSpec(node.op).combination == SdfOpCombination::Subtraction &&
        node.children.size() == 1)
        diagnostics_.error(file_, node.pointer,
                           "a " + operationLabel(node.op) +
                               " needs at least two children (the shape and what to "
                               "subtract from it), got one");
    const double leastSmoothness = smoothnessParam().range.min;
    if (takesSmoothness(node.op) &&
        !(std::isfinite(node.smoothness) && node.smoothness >= leastSmoothness))
        diagnostics_.error(
            file_, node.pointer,
            "the smoothness (radius) of a " + operationLabel(node.op) +
                " must be a finite number >= " + shortestNumberText(leastSmoothness) + ", got " +
                shortestNumberText(node.smoothness));
}

void Planner::order(SdfOp op, std::vector<PlannedNode>& children) {
    if (op != SdfOp::Union && op != SdfOp::Intersection && op != SdfOp::Xor) return;
    std::stable_sort(
        children.begin(), children.end(),
        [](const PlannedNode& x, const PlannedNode& y) { return x.stackNeed > y.stackNeed; });
}

} // namespace rmsc::compiler
