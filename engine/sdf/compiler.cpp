// The SDF compiler: flattens the SDF tree into the postfix program of sdf/program.hpp. A first
// pass resolves transforms, materials, object ids and the stack each subtree needs (and finds
// every error); a second pass emits the instructions, deepest subtree first where the operation
// allows it (Sethi-Ullman order).
#include "sdf/compiler.hpp"

#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rmsc {
namespace {

// A node with everything resolved, children in the order they are emitted.
struct PlannedNode {
    const SdfNode* node = nullptr;
    std::uint32_t objectId = 0;
    std::uint32_t material = 0;
    glm::dmat4 world{1.0};
    // Shapes: rows of world^-1 and the distance scale (see resolveShape).
    glm::vec4 worldToLocal[3]{};
    float distanceScale = 1.0f;
    int stackNeed = 0;         // entries the subtree needs on the stack
    long instructionCount = 0; // instructions the subtree compiles to
    std::vector<PlannedNode> children;
};

bool isSmooth(SdfOp op) {
    return op == SdfOp::SmoothUnion || op == SdfOp::SmoothSubtraction ||
           op == SdfOp::SmoothIntersection;
}

std::string opName(SdfOp op) {
    switch (op) {
    case SdfOp::Union:
        return "union";
    case SdfOp::Subtraction:
        return "subtraction";
    case SdfOp::Intersection:
        return "intersection";
    case SdfOp::SmoothUnion:
        return "smooth union";
    case SdfOp::SmoothSubtraction:
        return "smooth subtraction";
    case SdfOp::SmoothIntersection:
        return "smooth intersection";
    }
    return "operation";
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

    // Resolves `node` and its subtree. `parentWorld` and `parentMaterial` are the parent group's
    // resolved transform and material. Object ids count every node in pre-order (file order).
    PlannedNode plan(const SdfNode& node, const glm::dmat4& parentWorld,
                     std::uint32_t parentMaterial) {
        PlannedNode planned;
        planned.node = &node;
        planned.objectId = kSdfIdBase + std::uint32_t(nodePointers_.size());
        nodePointers_.push_back(node.pointer);
        planned.material = node.material >= 0 ? std::uint32_t(node.material) : parentMaterial;
        planned.world = parentWorld * glm::dmat4(node.transform.matrix());

        if (!node.isGroup) {
            resolveShape(planned);
            planned.stackNeed = 1;
            planned.instructionCount = 1;
            return planned;
        }

        checkGroup(node);
        for (const SdfNode& child : node.children)
            planned.children.push_back(plan(child, planned.world, planned.material));
        order(node.op, planned.children);

        // A left fold c0 c1 OP c2 OP ...: c0 needs its own stack, every later child one more
        // for the result held below it.
        for (std::size_t i = 0; i < planned.children.size(); ++i) {
            const PlannedNode& child = planned.children[i];
            planned.stackNeed = std::max(planned.stackNeed, child.stackNeed + (i > 0 ? 1 : 0));
            planned.instructionCount += child.instructionCount + (i > 0 ? 1 : 0);
        }
        if (planned.stackNeed > kSdfMaxStack && firstOverflow_.empty()) {
            bool childOverflows = false;
            for (const PlannedNode& child : planned.children)
                childOverflows = childOverflows || child.stackNeed > kSdfMaxStack;
            if (!childOverflows) firstOverflow_ = node.pointer;
        }
        return planned;
    }

    // The pointer of the first group (in the order groups finish planning) that needs more than
    // kSdfMaxStack while none of its children does: where the limit is crossed. "" if none.
    const std::string& firstOverflow() const { return firstOverflow_; }

  private:
    // The primitive is evaluated at q = world^-1 p. A local distance d maps to world units
    // within [d * smallest, d * largest] scale factor; d * smallest is exact for a uniform scale
    // and a lower bound (safe for sphere tracing, never overshooting) for a non-uniform one.
    void resolveShape(PlannedNode& planned) {
        const double scale = smallestScaleFactor(planned.world);
        const glm::dmat4 worldToLocal = glm::inverse(planned.world);
        bool finite = std::isfinite(scale) && scale > 1e-12;
        for (int row = 0; row < 3; ++row) {
            const glm::dvec4 r = glm::row(worldToLocal, row);
            finite = finite && std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) &&
                     std::isfinite(r.w);
            planned.worldToLocal[row] = glm::vec4(r);
        }
        planned.distanceScale = float(scale);
        if (!finite)
            diagnostics_.error(file_, planned.node->pointer,
                               "the shape's transform (with its groups') cannot be inverted; "
                               "is a scale 0?");
    }

    void checkGroup(const SdfNode& node) {
        if (node.children.empty())
            diagnostics_.error(file_, node.pointer,
                               "the " + opName(node.op) + " group has no children");
        if ((node.op == SdfOp::Subtraction || node.op == SdfOp::SmoothSubtraction) &&
            node.children.size() == 1)
            diagnostics_.error(file_, node.pointer,
                               "a " + opName(node.op) +
                                   " needs at least two children (the shape and what to "
                                   "subtract from it), got one");
        if (isSmooth(node.op) && !(std::isfinite(node.smoothness) && node.smoothness > 0.0f))
            diagnostics_.error(file_, node.pointer,
                               "the smoothness of a " + opName(node.op) +
                                   " must be a finite number > 0, got " +
                                   std::to_string(node.smoothness));
    }

    // Emission order of a group's children. Union and intersection are commutative and
    // associative, so the deepest child goes first (Sethi-Ullman): the fold then needs
    // max(deepest, 1 + second deepest). Subtraction keeps its first child; the order of the
    // subtracted ones would not change the stack the fold needs, so they keep file order. Smooth
    // operations are not associative (smin(smin(a, b), c) != smin(a, smin(b, c))) and keep file
    // order.
    static void order(SdfOp op, std::vector<PlannedNode>& children) {
        if (op != SdfOp::Union && op != SdfOp::Intersection) return;
        std::stable_sort(
            children.begin(), children.end(),
            [](const PlannedNode& x, const PlannedNode& y) { return x.stackNeed > y.stackNeed; });
    }

    const std::string& file_;
    Diagnostics& diagnostics_;
    std::vector<std::string>& nodePointers_;
    std::string firstOverflow_;
};

GpuSdfInstruction shapeInstruction(const PlannedNode& planned) {
    const SdfNode& node = *planned.node;
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
    instruction.misc =
        glm::vec4(planned.distanceScale * primitiveSpec(node.primitive).stepScale, 0.0f, 0.0f, 0.0f);
    return instruction;
}

void emit(const PlannedNode& planned, std::vector<GpuSdfInstruction>& out) {
    const SdfNode& node = *planned.node;
    if (!node.isGroup) {
        out.push_back(shapeInstruction(planned));
        return;
    }
    for (std::size_t i = 0; i < planned.children.size(); ++i) {
        emit(planned.children[i], out);
        if (i == 0) continue;
        GpuSdfInstruction combine;
        combine.opcode = std::uint32_t(SdfOpcode::Combine);
        combine.kind = std::uint32_t(node.op);
        combine.material = planned.material;
        combine.objectId = planned.objectId; // informational; the shapes' ids are shown
        combine.params[0].x = node.smoothness;
        out.push_back(combine);
    }
}

} // namespace

std::optional<SdfProgram> compileSdf(const SdfNode& root, std::uint32_t defaultMaterial,
                                     const std::string& file, Diagnostics& diagnostics) {
    const int errorsBefore = diagnostics.errorCount();
    SdfProgram program;
    Planner planner(file, diagnostics, program.nodePointers);
    const PlannedNode planned = planner.plan(root, glm::dmat4(1.0), defaultMaterial);

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

    program.instructions.reserve(std::size_t(planned.instructionCount));
    emit(planned, program.instructions);
    program.stackDepth = planned.stackNeed;
    return program;
}

} // namespace rmsc
