// Per-cell pruning (sdf/cell_pruning.hpp): the program read back into a tree, each operation's
// pruning rule, and the cell hierarchy built level by level on worker threads.
#include "sdf/cell_pruning.hpp"

#include "sdf/cpu_eval.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/sdf_functions.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>
#include <optional>
#include <thread>
#include <unordered_map>

namespace rmsc {

// ---- Each operation's rule ----
//
// sdfCombine (sdf/sdf_functions.cpp) gives each formula; the conditions below are where it
// provably equals one operand (value, and the weight that picks the material and the id).
// Smooth minimum: exactly min(a, b), weight 0 or 1, where |a - b| >= k (both blends). Chamfer
// union min(a, b, (a + b - k)/sqrt 2) is b where a > b and a >= k + (sqrt 2 - 1) b; the chamfer
// subtraction and intersection likewise. Round union max(k, min(a, b)) - |max(k - a, k - b, 0)|
// is b where a > b and a >= k; round subtraction is a where b >= k and (a >= -k or a > -b);
// round intersection is b where b > a and a <= -k. Xor is the union where both are positive.
SdfPruneSide sdfOperationPrune(SdfOp op, SdfInterval a, SdfInterval b, float k) {
    constexpr float kTan22 = 0.41421356f; // sqrt 2 - 1
    switch (op) {
    case SdfOp::Union:
        if (a.lo > b.hi) return SdfPruneSide::B;
        if (b.lo > a.hi) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    case SdfOp::Xor:
        if (a.lo > 0.0f && b.lo > 0.0f) return sdfOperationPrune(SdfOp::Union, a, b, k);
        return SdfPruneSide::Both;
    case SdfOp::Subtraction:
        return a.lo + b.lo > 0.0f ? SdfPruneSide::A : SdfPruneSide::Both;
    case SdfOp::Intersection:
        if (b.lo > a.hi) return SdfPruneSide::B;
        if (a.lo > b.hi) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    case SdfOp::SmoothUnion:
        if (a.lo - b.hi > k) return SdfPruneSide::B;
        if (b.lo - a.hi > k) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    case SdfOp::SmoothSubtraction:
        return a.lo + b.lo > k ? SdfPruneSide::A : SdfPruneSide::Both;
    case SdfOp::SmoothIntersection:
        if (b.lo - a.hi > k) return SdfPruneSide::B;
        if (a.lo - b.hi > k) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    case SdfOp::ChamferUnion:
        if (a.lo > b.hi && a.lo - kTan22 * b.hi > k) return SdfPruneSide::B;
        if (b.lo > a.hi && b.lo - kTan22 * a.hi > k) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    case SdfOp::ChamferSubtraction:
        return a.lo + b.lo > 0.0f && kTan22 * a.lo + b.lo > k ? SdfPruneSide::A
                                                              : SdfPruneSide::Both;
    case SdfOp::ChamferIntersection:
        if (b.lo > a.hi && kTan22 * b.lo - a.hi > k) return SdfPruneSide::B;
        if (a.lo > b.hi && kTan22 * a.lo - b.hi > k) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    case SdfOp::RoundUnion:
        if (a.lo > b.hi && a.lo > k) return SdfPruneSide::B;
        if (b.lo > a.hi && b.lo > k) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    case SdfOp::RoundSubtraction:
        return b.lo > k && (a.lo > -k || a.lo + b.lo > 0.0f) ? SdfPruneSide::A : SdfPruneSide::Both;
    case SdfOp::RoundIntersection:
        if (b.lo > a.hi && a.hi < -k) return SdfPruneSide::B;
        if (a.lo > b.hi && b.hi < -k) return SdfPruneSide::A;
        return SdfPruneSide::Both;
    }
    return SdfPruneSide::Both;
}

SdfInterval sdfOperationInterval(SdfOp op, SdfInterval a, SdfInterval b,
                                 const glm::vec4& opParams) {
    float w = 0.0f;
    const auto f = [&](float x, float y) { return sdfCombine(op, x, y, opParams, w); };
    switch (operationSpec(op).combination) {
    case SdfOpCombination::Union:
    case SdfOpCombination::Intersection:
        return {f(a.lo, b.lo), f(a.hi, b.hi)}; // increasing in both
    case SdfOpCombination::Subtraction:
        return {f(a.lo, b.hi), f(a.hi, b.lo)}; // increasing in a, decreasing in b
    case SdfOpCombination::Xor: {
        // max(min(a, b), -max(a, b)), each part's interval.
        const float innerLo = std::min(a.lo, b.lo), innerHi = std::min(a.hi, b.hi);
        const float outerLo = -std::max(a.hi, b.hi), outerHi = -std::max(a.lo, b.lo);
        return {std::max(innerLo, outerLo), std::max(innerHi, outerHi)};
    }
    }
    return {-INFINITY, INFINITY};
}

namespace {

// ---- The program as a tree ----

// A leaf is a shape, a profile, or a node with its own point frame (PushPoint to PopPoint,
// taken whole: the point modifiers inside may fold space, so their parts are not bounded one by
// one); a unary node a distance modifier; a combine node an operation on two subtrees.
enum class NodeKind : std::uint8_t { Leaf, Unary, Combine };

struct TreeNode {
    NodeKind kind = NodeKind::Leaf;
    std::uint32_t begin = 0, end = 0; // Leaf: its instructions
    std::uint32_t instruction = 0;    // Unary, Combine: its own
    int a = -1, b = -1;               // operands (a only for Unary)
    int leaves = 0;                   // shape evaluations of a leaf
};

struct ProgramTree {
    std::vector<TreeNode> nodes; // post-order: operands before the node; the root last
};

bool isLeafOpcode(std::uint32_t opcode) {
    return opcode == std::uint32_t(SdfOpcode::Shape) || opcode == std::uint32_t(SdfOpcode::Profile);
}

// Reads the postfix program back into a tree. The parts a bounding hierarchy accumulates are
// folded left to right with the union instruction at `unionInstruction` (the order in which
// Accumulate keeps the first of equal parts). False when the program has no tree of this form.
bool readTree(const std::vector<GpuSdfInstruction>& code, std::uint32_t unionInstruction,
              ProgramTree& tree) {
    std::vector<int> stack, parts;
    auto push = [&](TreeNode node) {
        tree.nodes.push_back(node);
        stack.push_back(int(tree.nodes.size()) - 1);
    };
    for (std::uint32_t i = 0; i < code.size(); ++i) {
        const SdfOpcode opcode = SdfOpcode(code[i].opcode);
        switch (opcode) {
        case SdfOpcode::Shape:
        case SdfOpcode::Profile:
            push({NodeKind::Leaf, i, i + 1, 0, -1, -1, 1});
            break;
        case SdfOpcode::PushPoint: {
            int depth = 0, values = 0, leaves = 0;
            std::uint32_t j = i;
            for (; j < code.size(); ++j) {
                const SdfOpcode op = SdfOpcode(code[j].opcode);
                if (op == SdfOpcode::PushPoint) ++depth;
                if (op == SdfOpcode::PopPoint && --depth == 0) break;
                if (isLeafOpcode(code[j].opcode)) ++values, ++leaves;
                if (op == SdfOpcode::Combine) --values;
                if (op == SdfOpcode::BoundSkip || op == SdfOpcode::Accumulate ||
                    op == SdfOpcode::SeedBest)
                    return false;
            }
            if (j == code.size() || values != 1) return false;
            push({NodeKind::Leaf, i, j + 1, 0, -1, -1, leaves});
            i = j;
            break;
        }
        case SdfOpcode::DistanceModifier: {
            if (stack.empty()) return false;
            const int a = stack.back();
            stack.pop_back();
            push({NodeKind::Unary, 0, 0, i, a, -1, 0});
            break;
        }
        case SdfOpcode::Combine: {
            if (stack.size() < 2) return false;
            const int b = stack.back();
            stack.pop_back();
            const int a = stack.back();
            stack.pop_back();
            push({NodeKind::Combine, 0, 0, i, a, b, 0});
            break;
        }
        case SdfOpcode::Accumulate:
            if (stack.empty()) return false;
            parts.push_back(stack.back());
            stack.pop_back();
            break;
        case SdfOpcode::BoundSkip:
        case SdfOpcode::SeedBest:
            break;
        case SdfOpcode::PointModifier:
        case SdfOpcode::PopPoint:
            return false;
        }
    }
    if (parts.empty()) return stack.size() == 1;
    if (!stack.empty()) return false;
    int root = parts[0];
    for (std::size_t p = 1; p < parts.size(); ++p) {
        tree.nodes.push_back({NodeKind::Combine, 0, 0, unionInstruction, root, parts[p], 0});
        root = int(tree.nodes.size()) - 1;
    }
    return true;
}

// ---- Lower bounds from boxes ----
//
// A node's floor: its field is at least distance(y, box) - drop at every point y outside the
// box. A leaf has one when its distance is exact (an exact primitive under a similarity
// transform: its value is the distance to its surface, which lies in its box); an operation
// or a distance modifier derives one from its operands' (operationFloor, the modifier row's
// packedGrowth). Pruning a cell, a subtree whose floor at the cell's centre already decides an
// operation is dropped unevaluated: with a value v at least the floor, the interval v +- the
// cell's reach would have decided it too, so the result is the same, computed for fewer nodes.
// (What makes a cell of a 10,000-shape union cost its near shapes, not all of them.)
struct NodeFloor {
    Aabb box;
    float drop = 0.0f;
    bool valid = false;
    // A chain of smooth unions (smoothChainDrop): the largest drop of its other operands, and
    // its largest smoothness; chainBase < 0 where the node is no such chain.
    float chainBase = -1.0f;
    float chainSmoothness = 0.0f;
};

// The drop of a chain of smooth unions, each with one operand that is no such chain
// (((a u b) u c) u d ...: how a group's children are folded). Each union dips up to k/4 below
// the least of its operands (operationFloor), which a chain of a thousand added up to 250 k (the
// 1,000-sphere molecule's floor dropped 30 units: no floor at all). But the smooth minimum,
// polynomial or circular (shaders/common/sdf_functions.glsl, sdfSmoothMin), is the least of its
// operands where they are k or more apart, and grows with each of them. So with every other
// operand at least m = distance(y, box) - base (base: the largest of their drops), and the chain
// below at least m - K (K: the chain's largest smoothness; by induction, a lone operand being at
// least m), the union is at least smin_k(m - K, m) = m - K: the chain's drop is at most
// base + K, however long it is.
void smoothChainDrop(const NodeFloor& a, const NodeFloor& b, float k, NodeFloor& f) {
    if (a.chainBase >= 0.0f && b.chainBase >= 0.0f) return; // two chains: the rule's drop
    const float base = std::max(a.chainBase >= 0.0f ? a.chainBase : a.drop,
                                b.chainBase >= 0.0f ? b.chainBase : b.drop);
    f.chainBase = base;
    f.chainSmoothness = std::max({k, a.chainSmoothness, b.chainSmoothness});
    f.drop = std::min(f.drop, base + f.chainSmoothness);
}

// The affine matrix whose rows are worldToLocal, inverted: local to world.
glm::mat4 localToWorld(const GpuSdfInstruction& in) {
    const glm::mat4 toLocal =
        glm::transpose(glm::mat4(in.worldToLocal[0], in.worldToLocal[1], in.worldToLocal[2],
                                 glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)));
    return glm::inverse(toLocal);
}

NodeFloor leafFloor(const GpuSdfInstruction& in) {
    if (SdfOpcode(in.opcode) != SdfOpcode::Shape || in.kind >= std::uint32_t(PrimitiveId::Count))
        return {};
    const PrimitiveSpec& spec = primitiveSpec(PrimitiveId(in.kind));
    if (!spec.exact || spec.stepScale != 1.0f) return {};
    // A similarity: rows of equal length 1 / s, at right angles, and the distance scale s.
    const glm::vec3 r0(in.worldToLocal[0]), r1(in.worldToLocal[1]), r2(in.worldToLocal[2]);
    const float l0 = glm::length(r0), l1 = glm::length(r1), l2 = glm::length(r2);
    const float tolerance = 1e-4f * l0;
    if (!(l0 > 0.0f) || std::abs(l1 - l0) > tolerance || std::abs(l2 - l0) > tolerance ||
        std::abs(glm::dot(r0, r1)) > tolerance * l0 ||
        std::abs(glm::dot(r0, r2)) > tolerance * l0 ||
        std::abs(glm::dot(r1, r2)) > tolerance * l0 || std::abs(in.misc.x * l0 - 1.0f) > 1e-4f)
        return {};
    PrimitiveParams params{};
    for (int k = 0; k < kMaxPrimitiveFloats; ++k)
        params[std::size_t(k)] = in.params[k / 4][k % 4];
    const SdfBounds local = primitiveBounds(spec.id, params);
    if (!local.bounded || local.box.empty()) return {};
    return {transformAabb(local.box, localToWorld(in)), 0.0f, true};
}

// Node i's floor from its instructions and its children's floors.
NodeFloor nodeFloor(const std::vector<GpuSdfInstruction>& code, const ProgramTree& tree,
                    const std::vector<NodeFloor>& floors, std::size_t i) {
    const TreeNode& t = tree.nodes[i];
    NodeFloor f;
    switch (t.kind) {
    case NodeKind::Leaf:
        if (t.end - t.begin == 1) f = leafFloor(code[t.begin]);
        break;
    case NodeKind::Unary: {
        const ModifierSpec& spec =
            modifierOfKind(ModifierStage::Distance, code[t.instruction].kind);
        const NodeFloor& a = floors[std::size_t(t.a)];
        if (a.valid && spec.packedGrowth)
            f = {a.box, a.drop + spec.packedGrowth(code[t.instruction].params), true};
        break;
    }
    case NodeKind::Combine: {
        const GpuSdfInstruction& in = code[t.instruction];
        const NodeFloor &a = floors[std::size_t(t.a)], &b = floors[std::size_t(t.b)];
        const SdfOperationFloor rule =
            operationFloor(SdfOp(in.kind),
                           in.params[0].y > 0.5f ? SmoothBlend::Circular : SmoothBlend::Polynomial);
        const float k = std::abs(in.params[0].x);
        if (rule.box == SdfFloorBox::FirstOperand) {
            f = a;
        } else if (rule.box == SdfFloorBox::EitherOperand) {
            f = a.valid ? a : b;
        } else if (a.valid && b.valid) {
            f.box = a.box;
            f.box.add(b.box);
            f.drop = rule.dropScale * std::max(a.drop, b.drop) + rule.smoothnessDrop * k;
            f.valid = true;
            const OperationSpec& spec = operationSpec(SdfOp(in.kind));
            if (spec.combination == SdfOpCombination::Union && spec.seam == SdfOpSeam::Smooth)
                smoothChainDrop(a, b, k, f);
        }
        break;
    }
    }
    return f;
}

std::vector<NodeFloor> nodeFloors(const std::vector<GpuSdfInstruction>& code,
                                  const ProgramTree& tree) {
    std::vector<NodeFloor> floors(tree.nodes.size());
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
        floors[i] = nodeFloor(code, tree, floors, i);
    return floors;
}

// The floors after an edit of numbers, made again only for the `changed` nodes and those
// above them (children come before their parents in the tree).
void updateNodeFloors(const std::vector<GpuSdfInstruction>& code, const ProgramTree& tree,
                      const std::vector<char>& changed, std::vector<NodeFloor>& floors) {
    std::vector<char> again(changed);
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const TreeNode& t = tree.nodes[i];
        if (t.kind != NodeKind::Leaf)
            again[i] = again[i] || again[std::size_t(t.a)] ||
                       (t.kind == NodeKind::Combine && again[std::size_t(t.b)]);
        if (again[i]) floors[i] = nodeFloor(code, tree, floors, i);
    }
}

// The floor of `f` at point c: a lower bound of the node's value there, or -infinity where the
// floor says nothing (no floor, or c inside its box).
float floorAt(const NodeFloor& f, glm::vec3 c) {
    if (!f.valid) return -INFINITY;
    const glm::vec3 q = glm::max(glm::max(f.box.min - c, c - f.box.max), glm::vec3(0.0f));
    const float d = glm::length(q);
    return d > 0.0f ? d - f.drop : -INFINITY;
}

// The least that a node's interval at a cell of centre c and reach r could start at, from its
// floor (-infinity: unknown), with the margins of the interval (CellEvaluator::around).
float floorLow(const NodeFloor& f, glm::vec3 c, float r, float slack) {
    const float low = floorAt(f, c);
    return low - 1e-6f * std::abs(low) - r - slack;
}

// A program pruned to a region: the tree's nodes it keeps, in post-order (root last), each with
// the operands it keeps (indices into the same list).
struct PrunedNode {
    int node = 0;
    int a = -1, b = -1;
};
using PrunedTree = std::vector<PrunedNode>;

struct Pruner {
    const SdfProgram& program;
    const std::vector<GpuSdfInstruction>& code;
    const ProgramTree& tree;
    const std::vector<std::uint32_t>& identity; // 0, 1, 2, ...: the leaves' instruction lists
    const std::vector<NodeFloor>& floors;       // per tree node
    float slack = 0.0f;                         // added to every interval (rounding)
};

// What pruning one cell works in, reused from cell to cell by a thread.
struct CellScratch {
    std::vector<float> value;
    std::vector<SdfInterval> range;
    std::vector<SdfPruneSide> side;
    std::vector<char> state; // per node of the parent tree: kUnseen, kEvaluated or kDropped
    std::vector<int> chain, operands;
    float rootLeastHi = NAN; // the top chain of unions' least upper end, when the root is one
};
constexpr char kUnseen = 0, kEvaluated = 1, kDropped = 2;

struct CellResult {
    PrunedTree pruned;
    std::vector<std::uint32_t> list; // instruction indices, postfix
    int leaves = 0;
    bool far = false;  // a far cell's constant (SdfCellOptions::farConstants)
    bool near = false; // the surface may be within the cell's edge of it
    // The least upper end of the operands of the tree's top chain of unions (NaN when the
    // tree's root is no such chain): an operand of that chain whose floor is above it is
    // dropped here whatever it does (repruneSdfCells).
    float unionThreshold = NAN;
    float leastLow = NAN;   // pruneCellDirect: the least lower end over every operand
    bool unchanged = false; // repruneSdfCells: the cell's old result stands
};

// Far cells: where the whole program is at least `edge` (the cell's edge length) everywhere in
// the cell, a constant lower bound of it stands for the program: m * edge for m = 1 .. kFarSteps
// (a plane instruction read at the origin of its frame: -offset), so few constants serve every
// far cell of a level, and a march crosses a far cell in a step or two.
constexpr int kFarSteps = 16;

GpuSdfInstruction constantInstruction(float value) {
    GpuSdfInstruction in;
    in.opcode = std::uint32_t(SdfOpcode::Shape);
    in.kind = std::uint32_t(PrimitiveId::Plane);
    in.params[0] = glm::vec4(0.0f, 1.0f, 0.0f, -value); // worldToLocal all zero: q = 0
    in.misc.x = 1.0f;
    in.objectId = 0; // never a hit: the value is at least a cell's edge
    return in;
}

// Is the list one plane instruction (kSdfCellAffine)? A plane is affine in its frame's point,
// which is affine in the world point (sdPlane, and the far cells' constants whose frame maps
// every point to the origin).
bool isOnePlane(const std::vector<GpuSdfInstruction>& code, const std::uint32_t* list,
                std::uint32_t length) {
    if (length != 1 || list[0] >= code.size()) return false;
    const GpuSdfInstruction& in = code[list[0]];
    return SdfOpcode(in.opcode) == SdfOpcode::Shape && PrimitiveId(in.kind) == PrimitiveId::Plane;
}

// The values and intervals of a parent tree's nodes at a cell, computed as far as pruning needs
// them: an operand whose floor decides its operation is dropped unevaluated (see NodeFloor).
struct CellEvaluator {
    const Pruner& pr;
    const PrunedTree& in;
    glm::vec3 c;   // the cell's centre
    float r = 0.0; // half its diagonal
    CellScratch& s;

    const TreeNode& treeNode(int i) const {
        return pr.tree.nodes[std::size_t(in[std::size_t(i)].node)];
    }
    const GpuSdfInstruction& instruction(int i) const { return pr.code[treeNode(i).instruction]; }
    bool isUnion(int i) const {
        const TreeNode& t = treeNode(i);
        return t.kind == NodeKind::Combine && SdfOp(pr.code[t.instruction].kind) == SdfOp::Union;
    }
    // Every value within the cell: v at the centre, +- the reach (1-Lipschitz fields).
    SdfInterval around(float v) const {
        const float e = r + pr.slack + 1e-6f * std::abs(v);
        return {v - e, v + e};
    }
    // The least that node i's interval could start at, from its floor (-infinity: unknown).
    float floorLow(int i) const {
        return rmsc::floorLow(pr.floors[std::size_t(in[std::size_t(i)].node)], c, r, pr.slack);
    }
    void set(int i, float v, SdfInterval range) {
        s.value[std::size_t(i)] = v;
        s.range[std::size_t(i)] = range;
        s.state[std::size_t(i)] = kEvaluated;
    }

    void evaluate(int i) {
        if (s.state[std::size_t(i)] != kUnseen) return;
        const PrunedNode& pn = in[std::size_t(i)];
        const TreeNode& t = treeNode(i);
        switch (t.kind) {
        case NodeKind::Leaf: {
            const float v = t.end - t.begin == 1
                                ? sdfLeafDistance(pr.program, pr.code[t.begin], c)
                                : sdfDistanceOrdered(
                                      pr.program, pr.code,
                                      std::span(pr.identity).subspan(t.begin, t.end - t.begin), c);
            set(i, v, around(v));
            return;
        }
        case NodeKind::Unary: {
            evaluate(pn.a);
            const GpuSdfInstruction& in4 = pr.code[t.instruction];
            const float v = modifierOfKind(ModifierStage::Distance, in4.kind)
                                .changeDistance(s.value[std::size_t(pn.a)], c, in4.params);
            set(i, v, around(v));
            return;
        }
        case NodeKind::Combine:
            if (isUnion(i))
                evaluateUnions(i);
            else
                evaluateOperation(i);
            return;
        }
    }

    // An operation other than a plain union: the operand nearer by its floor first; the other
    // is dropped unevaluated when its floor already decides the operation for the first (each
    // rule that keeps one side reads only the other side's lower end, and grows with it).
    void evaluateOperation(int i) {
        const PrunedNode& pn = in[std::size_t(i)];
        const GpuSdfInstruction& in4 = instruction(i);
        const SdfOp op = SdfOp(in4.kind);
        const float k = in4.params[0].x;
        const std::size_t a = std::size_t(pn.a), b = std::size_t(pn.b);
        const float floorA = floorLow(pn.a), floorB = floorLow(pn.b);
        SdfPruneSide side = SdfPruneSide::Both;
        if (!(floorB < floorA)) {
            evaluate(pn.a);
            if (floorB > -INFINITY &&
                sdfOperationPrune(op, s.range[a], {floorB, INFINITY}, k) == SdfPruneSide::A) {
                side = SdfPruneSide::A;
                s.state[b] = kDropped;
            }
        } else {
            evaluate(pn.b);
            if (floorA > -INFINITY &&
                sdfOperationPrune(op, {floorA, INFINITY}, s.range[b], k) == SdfPruneSide::B) {
                side = SdfPruneSide::B;
                s.state[a] = kDropped;
            }
        }
        if (side == SdfPruneSide::Both) {
            evaluate(pn.a);
            evaluate(pn.b);
            side = sdfOperationPrune(op, s.range[a], s.range[b], k);
        }
        s.side[std::size_t(i)] = side;
        if (side == SdfPruneSide::A) {
            set(i, s.value[a], s.range[a]);
        } else if (side == SdfPruneSide::B) {
            set(i, s.value[b], s.range[b]);
        } else {
            float w = 0.0f;
            set(i, sdfCombine(op, s.value[a], s.value[b], in4.params[0], w),
                sdfOperationInterval(op, s.range[a], s.range[b], in4.params[0]));
        }
    }

    // A chain of plain unions ((o1 u o2) u o3) ... as one n-ary union: an operand is dropped
    // where it is above another everywhere in the cell (its lower end above the least upper
    // end: see `emit` below), so once the nearest operand (by floor) is evaluated, an operand
    // whose floor is above its upper end is dropped unevaluated. Every node of the chain gets
    // the union's value and interval.
    void evaluateUnions(int top) {
        std::vector<int>& chain = s.chain;
        std::vector<int>& operands = s.operands;
        chain.clear();
        int bottom = top;
        for (; isUnion(bottom); bottom = in[std::size_t(bottom)].a)
            chain.push_back(bottom);
        // (Copied: evaluating an operand reuses the scratch lists for its own chains.)
        std::vector<int> nodes(chain);
        std::vector<std::pair<float, int>> order;
        order.reserve(chain.size() + 1);
        order.push_back({floorLow(bottom), bottom});
        for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
            const int o = in[std::size_t(*it)].b;
            order.push_back({floorLow(o), o});
        }
        (void)operands;
        const auto nearest = std::min_element(order.begin(), order.end());
        std::iter_swap(order.begin(), nearest);
        float leastHi = INFINITY;
        float value = INFINITY;
        SdfInterval range{INFINITY, INFINITY};
        for (const auto& [low, o] : order) {
            if (low > leastHi) {
                s.state[std::size_t(o)] = kDropped;
                continue;
            }
            evaluate(o);
            const SdfInterval& ro = s.range[std::size_t(o)];
            leastHi = std::min(leastHi, ro.hi);
            value = std::min(value, s.value[std::size_t(o)]);
            range = {std::min(range.lo, ro.lo), std::min(range.hi, ro.hi)};
        }
        for (int node : nodes)
            set(node, value, range);
        if (top == int(in.size()) - 1) s.rootLeastHi = leastHi;
    }
};

// Thresholds, top down: a node whose value is above its threshold `t` at a point does not
// change the root's value or material there, whatever it is replaced with that is no lower.
// The root's threshold is +infinity. An operation that is monotone in both operands, exactly
// one of them where the other is k or more above it (weight 0 or 1), and never more than d
// below the lesser of the two (union: k = d = 0; smooth union: k and, for the dip, k/4 or
// k(1 - 1/sqrt 2): operationFloor) gives operand a the threshold min(hi(b) + k, t + d + k):
// where a is above it, either a >= b + k and the result is b's alone, or both are above t + d
// and so is the result. An operand whose interval over the cell lies above its threshold is
// dropped: the result only grows where it is above its own threshold, so the root is
// unchanged in the whole cell, values and materials alike. (When every operand is above its
// threshold, the operation is above its own everywhere: one of them stays and the rest drop.)
// This prunes what an operand-by-operand rule cannot: two far spheres smoothly united deep in
// a tree whose other half is near. Other operations give their operands +infinity.
struct OperandThresholds {
    float a = INFINITY, b = INFINITY;
};

OperandThresholds operandThresholds(const GpuSdfInstruction& in, float threshold, SdfInterval a,
                                    SdfInterval b) {
    const float k = in.params[0].x;
    if (SdfOp(in.kind) != SdfOp::SmoothUnion || !(k > 0.0f)) return {};
    const SmoothBlend blend =
        in.params[0].y > 0.5f ? SmoothBlend::Circular : SmoothBlend::Polynomial;
    const float d = operationFloor(SdfOp::SmoothUnion, blend).smoothnessDrop * k;
    const float above = threshold + d + k;
    return {std::min(b.hi + k, above), std::min(a.hi + k, above)};
}

// Prunes `in` at the cell of centre c and reach r (half its diagonal): out.list, out.pruned and
// out.leaves; returns the root's value interval over the cell.
SdfInterval evaluateAndEmit(const Pruner& pr, const PrunedTree& in, glm::vec3 c, float r,
                            CellScratch& scratch, CellResult& out) {
    const std::size_t n = in.size();
    scratch.value.resize(n);
    scratch.range.resize(n);
    scratch.side.assign(n, SdfPruneSide::Both);
    scratch.state.assign(n, kUnseen);
    scratch.rootLeastHi = NAN;
    CellEvaluator evaluator{pr, in, c, r, scratch};
    evaluator.evaluate(int(n) - 1);
    out.unionThreshold = scratch.rootLeastHi;
    const std::vector<SdfInterval>& range = scratch.range;
    const std::vector<SdfPruneSide>& side = scratch.side;
    const std::vector<char>& state = scratch.state;
    out.pruned.clear();
    out.list.clear();
    out.leaves = 0;
    // Emit what is kept, operands first.
    const auto isUnion = [&](int i) {
        const TreeNode& t = pr.tree.nodes[std::size_t(in[std::size_t(i)].node)];
        return t.kind == NodeKind::Combine && SdfOp(pr.code[t.instruction].kind) == SdfOp::Union;
    };
    const auto emit = [&](auto& self, int i, float threshold) -> int {
        const PrunedNode& pn = in[std::size_t(i)];
        const TreeNode& t = pr.tree.nodes[std::size_t(pn.node)];
        if (isUnion(i)) {
            // A chain of plain unions ((o1 u o2) u o3) ...: an operand drops where it is above
            // another operand everywhere in the cell (above the least upper bound), or above
            // the chain's threshold and the other operands' upper ends (see `threshold`); the
            // kept ones are united in their order with the chain's own union nodes, bottom up.
            std::vector<int> chain; // union nodes, top down
            int bottom = i;
            for (; isUnion(bottom); bottom = in[std::size_t(bottom)].a)
                chain.push_back(bottom);
            std::vector<int> operands{bottom};
            for (auto it = chain.rbegin(); it != chain.rend(); ++it)
                operands.push_back(in[std::size_t(*it)].b);
            float leastHi = INFINITY, nextHi = INFINITY; // the two least upper ends
            int least = -1, lowest = -1;                 // its operand; the least lower end's
            for (int o : operands) {
                if (state[std::size_t(o)] != kEvaluated) continue;
                const SdfInterval& ro = range[std::size_t(o)];
                if (ro.hi < leastHi) {
                    nextHi = leastHi;
                    leastHi = ro.hi;
                    least = o;
                } else {
                    nextHi = std::min(nextHi, ro.hi);
                }
                if (lowest < 0 || ro.lo < range[std::size_t(lowest)].lo) lowest = o;
            }
            const auto operandThreshold = [&](int o) {
                return std::min(threshold, o == least ? nextHi : leastHi);
            };
            const auto kept = [&](int o) {
                if (state[std::size_t(o)] != kEvaluated) return false;
                const float lo = range[std::size_t(o)].lo;
                return lo <= leastHi && (lo <= operandThreshold(o) || o == lowest);
            };
            // Every operand above its threshold: the lowest stays (see `threshold`).
            bool anyBelow = false;
            for (int o : operands)
                anyBelow = anyBelow || (state[std::size_t(o)] == kEvaluated &&
                                        range[std::size_t(o)].lo <= leastHi &&
                                        range[std::size_t(o)].lo <= operandThreshold(o));
            if (anyBelow) lowest = -1;
            // Each union made is the chain's union whose operands reach as far up as its own
            // do (operand p's: chain[size - p]), so its floor still bounds it.
            int result = -1;
            for (std::size_t p = 0; p < operands.size(); ++p) {
                const int o = operands[p];
                if (!kept(o)) continue;
                const int e = self(self, o, operandThreshold(o));
                if (result < 0) {
                    result = e;
                    continue;
                }
                const int node = in[std::size_t(chain[chain.size() - p])].node;
                out.list.push_back(pr.tree.nodes[std::size_t(node)].instruction);
                out.pruned.push_back({node, result, e});
                result = int(out.pruned.size()) - 1;
            }
            return result;
        }
        if (t.kind == NodeKind::Combine && side[std::size_t(i)] != SdfPruneSide::Both)
            return self(self, side[std::size_t(i)] == SdfPruneSide::A ? pn.a : pn.b, threshold);
        PrunedNode kept{pn.node, -1, -1};
        if (t.kind == NodeKind::Leaf) {
            for (std::uint32_t k = t.begin; k < t.end; ++k)
                out.list.push_back(k);
            out.leaves += t.leaves;
        } else if (t.kind == NodeKind::Unary) {
            kept.a = self(self, pn.a, INFINITY);
            out.list.push_back(t.instruction);
        } else {
            const OperandThresholds o =
                operandThresholds(pr.code[t.instruction], threshold, range[std::size_t(pn.a)],
                                  range[std::size_t(pn.b)]);
            const SdfInterval &ra = range[std::size_t(pn.a)], &rb = range[std::size_t(pn.b)];
            const bool dropA = ra.lo > o.a, dropB = rb.lo > o.b;
            if (dropA && (!dropB || rb.lo < ra.lo)) return self(self, pn.b, o.b);
            if (dropB) return self(self, pn.a, o.a);
            kept.a = self(self, pn.a, o.a);
            kept.b = self(self, pn.b, o.b);
            out.list.push_back(t.instruction);
        }
        out.pruned.push_back(kept);
        return int(out.pruned.size()) - 1;
    };
    emit(emit, int(n) - 1, INFINITY);
    return range[n - 1];
}

// A far cell whose program is long takes a constant lower bound instead (shortLeaves < 0:
// never; soft shadows and the cone pass read the values, so the renderer keeps them exact).
// `low`: the least value in the cell.
void settleFar(float low, float edge, const std::uint32_t* constants, int shortLeaves,
               CellResult& out) {
    out.near = low < edge;
    out.far = shortLeaves >= 0 && low >= edge;
    if (out.far && out.leaves > shortLeaves) {
        const int m = std::min(int(low / edge), kFarSteps);
        out.pruned.clear();
        out.list.assign(1, constants[m - 1]);
        out.leaves = 1;
    }
}

// Prunes `in` to the cell of centre c and edge length `edge`; `constants` are the far cells'
// kFarSteps constants of the cell's level (instruction indices).
void pruneCell(const Pruner& pr, const PrunedTree& in, glm::vec3 c, float edge,
               const std::uint32_t* constants, int shortLeaves, CellResult& out,
               CellScratch& scratch) {
    out.unchanged = false;
    const SdfInterval root = evaluateAndEmit(pr, in, c, 0.8660254f * edge, scratch, out);
    settleFar(root.lo, edge, constants, shortLeaves, out);
}

// ---- A large top union, pruned straight from the whole of it ----
//
// Pruned from its parent's tree, a cell costs what its parent keeps: the coarse cells around
// a union of thousands of objects keep thousands, and an edit that reaches them prunes them
// again. When the tree's root is a chain of plain unions whose operands are small (the scene's
// objects), each cell is pruned from the whole chain instead: a bounding-volume hierarchy over
// the operands' floors finds, nearest first, the few operands that can matter, so a cell costs
// what it keeps, whatever its level, and needs nothing of its parent. A cell that only has to
// be refined (or made a far constant) stops counting once it keeps too many to be a leaf.
struct DirectChain {
    std::vector<int> operands;      // tree nodes, in chain order
    std::vector<int> unions;        // the chain's union nodes, bottom up
    std::vector<PrunedTree> wholes; // each operand's whole subtree (nodes of the tree)
    std::vector<int> single;        // an operand that is one instruction: it; else -1
    std::vector<int> unbounded;     // operands without a floor (evaluated in every cell)
    struct Node {
        Aabb box;
        float drop = 0.0f;
        bool valid = true;         // false: an operand's floor is gone (an edit made it inexact)
        int left = -1, right = -1; // children (an inner node), or -1
        int first = 0, count = 0;  // a leaf: its operands, order[first .. first + count)
    };
    std::vector<Node> nodes; // children after their parents; the root first (when any)
    std::vector<int> order;  // operand positions
};

// Operands whose whole subtree is at most this many nodes make a chain direct.
constexpr std::size_t kDirectOperandNodes = 64;
// Operands without a floor are evaluated in every cell of a direct chain: a chain with more of
// them is pruned from each cell's parent instead (1,000 mixed shapes in 250 groups, none with a
// floor: every one of 1.27 million cells evaluated all 250 groups, 128 s, where pruning from
// the parents takes 1.4 s).
constexpr std::size_t kDirectMostUnbounded = 8;

// The node's box and drop from its children or operands (children first: call in reverse).
void fitNode(DirectChain& d, const std::vector<NodeFloor>& floors, DirectChain::Node& node) {
    node.box = Aabb{};
    node.drop = 0.0f;
    node.valid = true;
    const auto add = [&](const Aabb& box, float drop, bool valid) {
        node.box.add(box);
        node.drop = std::max(node.drop, drop);
        node.valid = node.valid && valid;
    };
    if (node.left >= 0) {
        for (int child : {node.left, node.right}) {
            const DirectChain::Node& n = d.nodes[std::size_t(child)];
            add(n.box, n.drop, n.valid);
        }
        return;
    }
    for (int k = node.first; k < node.first + node.count; ++k) {
        const NodeFloor& f = floors[std::size_t(d.operands[std::size_t(d.order[std::size_t(k)])])];
        add(f.box, f.drop, f.valid);
    }
}

void refitDirectChain(DirectChain& d, const std::vector<NodeFloor>& floors) {
    for (auto it = d.nodes.rbegin(); it != d.nodes.rend(); ++it)
        fitNode(d, floors, *it);
}

std::optional<DirectChain> directChain(const ProgramTree& tree,
                                       const std::vector<GpuSdfInstruction>& code,
                                       const std::vector<NodeFloor>& floors) {
    const std::size_t count = tree.nodes.size();
    const auto isUnion = [&](int i) {
        const TreeNode& t = tree.nodes[std::size_t(i)];
        return t.kind == NodeKind::Combine && SdfOp(code[t.instruction].kind) == SdfOp::Union;
    };
    if (count == 0 || !isUnion(int(count) - 1)) return std::nullopt;
    DirectChain d;
    int bottom = int(count) - 1;
    std::vector<int> topDown;
    for (; isUnion(bottom); bottom = tree.nodes[std::size_t(bottom)].a)
        topDown.push_back(bottom);
    d.unions.assign(topDown.rbegin(), topDown.rend());
    d.operands.push_back(bottom);
    for (int u : d.unions)
        d.operands.push_back(tree.nodes[std::size_t(u)].b);
    for (int o : d.operands) {
        // A subtree is the run of post-order nodes that ends at its root and starts at its
        // leftmost leaf.
        int first = o;
        while (tree.nodes[std::size_t(first)].kind != NodeKind::Leaf)
            first = tree.nodes[std::size_t(first)].a;
        if (std::size_t(o - first + 1) > kDirectOperandNodes) return std::nullopt;
        PrunedTree whole;
        for (int n = first; n <= o; ++n) {
            const TreeNode& t = tree.nodes[std::size_t(n)];
            whole.push_back({n, t.a < 0 ? -1 : t.a - first, t.b < 0 ? -1 : t.b - first});
        }
        d.wholes.push_back(std::move(whole));
        const TreeNode& t = tree.nodes[std::size_t(o)];
        d.single.push_back(t.kind == NodeKind::Leaf && t.end - t.begin == 1 ? int(t.begin) : -1);
    }
    std::vector<int> bounded;
    for (int pos = 0; pos < int(d.operands.size()); ++pos)
        (floors[std::size_t(d.operands[std::size_t(pos)])].valid ? bounded : d.unbounded)
            .push_back(pos);
    if (d.unbounded.size() > kDirectMostUnbounded) return std::nullopt;
    d.order = bounded;
    if (bounded.empty()) return d;
    // Median splits along the longest axis of the boxes' centres, four operands a leaf.
    const auto centre = [&](int pos) {
        return floors[std::size_t(d.operands[std::size_t(pos)])].box.center();
    };
    struct Range {
        int node, first, count;
    };
    d.nodes.push_back({});
    std::vector<Range> todo{{0, 0, int(d.order.size())}};
    while (!todo.empty()) {
        const Range range = todo.back();
        todo.pop_back();
        DirectChain::Node& node = d.nodes[std::size_t(range.node)];
        if (range.count <= 4) {
            node.first = range.first;
            node.count = range.count;
            continue;
        }
        Aabb centres;
        for (int k = range.first; k < range.first + range.count; ++k)
            centres.add(centre(d.order[std::size_t(k)]));
        const glm::vec3 size = centres.max - centres.min;
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
        const auto begin = d.order.begin() + range.first;
        const auto middle = begin + range.count / 2;
        std::nth_element(begin, middle, begin + range.count, [&](int a, int b) {
            return centre(a)[axis] < centre(b)[axis] ||
                   (centre(a)[axis] == centre(b)[axis] && a < b);
        });
        const int left = int(d.nodes.size());
        node.left = left;
        node.right = left + 1;
        d.nodes.push_back({});
        d.nodes.push_back({});
        todo.push_back({left, range.first, range.count / 2});
        todo.push_back({left + 1, range.first + range.count / 2, range.count - range.count / 2});
    }
    refitDirectChain(d, floors);
    return d;
}

// One operand evaluated at a cell.
struct DirectOperand {
    int position = 0;
    SdfInterval range;
    std::size_t listFirst = 0, listCount = 0; // in DirectScratch::lists
    int leaves = 0;
};

struct DirectScratch {
    CellScratch cell;
    CellResult operand;
    std::vector<std::pair<float, int>> heap; // (floor low, hierarchy node or -1 - position)
    std::vector<DirectOperand> seen;
    std::vector<std::uint32_t> lists;
};

// Prunes the cell of centre c and edge `edge` from the whole chain (DirectChain). `refineAbove`:
// when the cell keeps more shape evaluations than this, it is refined (>= 0: not the finest
// level), so its program is not needed.
void pruneCellDirect(const Pruner& pr, const DirectChain& d, glm::vec3 c, float edge,
                     const std::uint32_t* constants, int shortLeaves, int refineAbove,
                     CellResult& out, DirectScratch& scratch) {
    const float r = 0.8660254f * edge;
    const float reach = r + pr.slack; // the least half-width of an operand's interval
    out.unchanged = false;
    out.pruned.clear();
    out.list.clear();
    out.leaves = 0;
    std::vector<std::pair<float, int>>& heap = scratch.heap;
    std::vector<DirectOperand>& seen = scratch.seen;
    heap.clear();
    seen.clear();
    scratch.lists.clear();
    float minLo = INFINITY, leastHi = INFINITY;
    const auto evaluate = [&](int pos) {
        DirectOperand o;
        o.position = pos;
        o.listFirst = scratch.lists.size();
        const int single = d.single[std::size_t(pos)];
        if (single >= 0) {
            const float v = sdfLeafDistance(pr.program, pr.code[std::size_t(single)], c);
            const float e = reach + 1e-6f * std::abs(v);
            o.range = {v - e, v + e};
            scratch.lists.push_back(std::uint32_t(single));
            o.leaves = 1;
        } else {
            o.range = evaluateAndEmit(pr, d.wholes[std::size_t(pos)], c, r, scratch.cell,
                                      scratch.operand);
            scratch.lists.insert(scratch.lists.end(), scratch.operand.list.begin(),
                                 scratch.operand.list.end());
            o.leaves = scratch.operand.leaves;
        }
        o.listCount = scratch.lists.size() - o.listFirst;
        minLo = std::min(minLo, o.range.lo);
        leastHi = std::min(leastHi, o.range.hi);
        seen.push_back(o);
    };
    const auto push = [&](float low, int entry) {
        heap.push_back({low, entry});
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
    };
    const auto expand = [&](int entry) {
        if (entry < 0) {
            evaluate(-1 - entry);
            return;
        }
        const DirectChain::Node& node = d.nodes[std::size_t(entry)];
        if (node.left >= 0) {
            for (int child : {node.left, node.right}) {
                const DirectChain::Node& n = d.nodes[std::size_t(child)];
                push(floorLow({n.box, n.drop, n.valid}, c, r, pr.slack), child);
            }
            return;
        }
        for (int k = node.first; k < node.first + node.count; ++k) {
            const int pos = d.order[std::size_t(k)];
            push(floorLow(pr.floors[std::size_t(d.operands[std::size_t(pos)])], c, r, pr.slack),
                 -1 - pos);
        }
    };
    for (int pos : d.unbounded)
        evaluate(pos);
    if (!d.nodes.empty())
        push(floorLow({d.nodes[0].box, d.nodes[0].drop, d.nodes[0].valid}, c, r, pr.slack), 0);
    // The least lower end and the least upper end over every operand: an operand not yet seen
    // starts no lower than its floor and ends at least 2 reach above it.
    while (!heap.empty() &&
           (heap.front().first < minLo || heap.front().first + 2.0f * reach < leastHi)) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const int entry = heap.back().second;
        heap.pop_back();
        expand(entry);
    }
    out.unionThreshold = leastHi;
    out.leastLow = minLo;
    // The operands kept: every one whose lower end is at most leastHi. A cell with more than
    // `limit` shape evaluations is refined or made a far constant: no need to know them all.
    out.near = minLo < edge;
    out.far = shortLeaves >= 0 && minLo >= edge;
    const int limit = out.far ? shortLeaves : refineAbove;
    int kept = 0;
    const auto countKept = [&] {
        kept = 0;
        for (const DirectOperand& o : seen)
            if (o.range.lo <= leastHi) kept += o.leaves;
    };
    countKept();
    while (!heap.empty() && heap.front().first <= leastHi && (limit < 0 || kept <= limit)) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>());
        const int entry = heap.back().second;
        heap.pop_back();
        const std::size_t before = seen.size();
        expand(entry);
        if (seen.size() > before && seen.back().range.lo <= leastHi) kept += seen.back().leaves;
    }
    if (limit >= 0 && kept > limit) {
        out.leaves = kept; // at least
        if (out.far) {
            const int m = std::min(int(minLo / edge), kFarSteps);
            out.list.assign(1, constants[m - 1]);
            out.leaves = 1;
        }
        return;
    }
    // A leaf cell: the kept operands in the chain's order, united bottom up by its unions.
    std::sort(seen.begin(), seen.end(), [](const DirectOperand& a, const DirectOperand& b) {
        return a.position < b.position;
    });
    std::size_t used = 0;
    for (const DirectOperand& o : seen) {
        if (o.range.lo > leastHi) continue;
        out.list.insert(out.list.end(), scratch.lists.begin() + std::ptrdiff_t(o.listFirst),
                        scratch.lists.begin() + std::ptrdiff_t(o.listFirst + o.listCount));
        out.leaves += o.leaves;
        if (used++ > 0)
            out.list.push_back(pr.tree.nodes[std::size_t(d.unions[used - 2])].instruction);
    }
}

// The value-stack depth a postfix list needs.
int stackDepth(const std::vector<GpuSdfInstruction>& code, std::span<const std::uint32_t> list) {
    return sdfListStackDepth(code, list, SdfListReading::Postfix);
}

void collectContent(const SdfNode& node, const glm::mat4& parentToWorld, Aabb& box) {
    if (node.shell) return; // drawn by its own pass
    const SdfBounds bounds = sdfNodeBounds(node);
    if (bounds.bounded) {
        box.add(transformAabb(bounds.box, parentToWorld));
        return;
    }
    if (!node.isGroup) return;
    for (const SdfModifier& m : node.modifiers)
        if (isPointModifier(m.type)) return;
    const glm::mat4 toWorld = parentToWorld * node.transform.matrix();
    for (const SdfNode& child : node.children)
        if (!child.cut) collectContent(child, toWorld, box);
}

std::uint64_t hashList(std::span<const std::uint32_t> list) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a
    for (std::uint32_t v : list) {
        h ^= v;
        h *= 1099511628211ull;
    }
    return h;
}

// `list` in words, read as grid.reading.
void appendOutsideList(SdfCellGrid& grid, std::span<const std::uint32_t> list) {
    grid.outsideOffset = std::uint32_t(grid.words.size());
    grid.outsideLength = std::uint32_t(sdfListEntries(list.size(), grid.reading));
    grid.outsideStack = sdfListStackDepth(grid.code, list, grid.reading);
    grid.outsidePointStack = sdfListPointStackDepth(grid.code, list, grid.reading);
    grid.words.insert(grid.words.end(), list.begin(), list.end());
}

// Does a list read as the least of its shapes (SdfListReading::LeastOfShapes) need instruction
// i? Its unions and Accumulate do nothing there.
bool neededByLeastOfShapes(const GpuSdfInstruction& in) {
    const SdfOpcode opcode = SdfOpcode(in.opcode);
    return opcode != SdfOpcode::Combine && opcode != SdfOpcode::Accumulate;
}

// The postfix list of the subtree at `root` (its leaves' instructions, then each node's own
// after its operands), appended to `out`; without recursion (a chain of thousands of
// operations is as deep).
void appendPostfix(const ProgramTree& tree, int root, std::vector<std::uint32_t>& out) {
    std::vector<std::pair<int, bool>> todo{{root, false}}; // (node, its operands listed)
    while (!todo.empty()) {
        const auto [n, operandsListed] = todo.back();
        todo.pop_back();
        const TreeNode& t = tree.nodes[std::size_t(n)];
        if (t.kind == NodeKind::Leaf) {
            for (std::uint32_t k = t.begin; k < t.end; ++k)
                out.push_back(k);
        } else if (operandsListed) {
            out.push_back(t.instruction);
        } else {
            todo.push_back({n, true});
            if (t.kind == NodeKind::Combine) todo.push_back({t.b, false});
            todo.push_back({t.a, false});
        }
    }
}

bool hasBoundingHierarchy(const std::vector<GpuSdfInstruction>& code) {
    return std::any_of(code.begin(), code.end(), [](const GpuSdfInstruction& in) {
        const SdfOpcode op = SdfOpcode(in.opcode);
        return op == SdfOpcode::BoundSkip || op == SdfOpcode::SeedBest ||
               op == SdfOpcode::Accumulate;
    });
}

GpuSdfInstruction unionInstruction() {
    GpuSdfInstruction unite;
    unite.opcode = std::uint32_t(SdfOpcode::Combine);
    unite.kind = std::uint32_t(SdfOp::Union);
    return unite;
}

// The whole program as a list without its bounding hierarchy: its tree in postfix, the parts
// the hierarchy accumulates folded with a union appended to `code` (the program's instructions).
// The program itself when it has no hierarchy; nullopt when its tree cannot be read, or needs
// a deeper stack than the program.
std::optional<std::vector<std::uint32_t>> wholeTreeList(std::vector<GpuSdfInstruction>& code) {
    std::vector<std::uint32_t> list(code.size());
    std::iota(list.begin(), list.end(), 0u);
    if (!hasBoundingHierarchy(code)) return list;
    const std::uint32_t unite = std::uint32_t(code.size());
    ProgramTree tree;
    if (!readTree(code, unite, tree) || tree.nodes.empty()) return std::nullopt;
    code.push_back(unionInstruction());
    list.clear();
    appendPostfix(tree, int(tree.nodes.size()) - 1, list);
    if (stackDepth(code, list) > kSdfMaxStack) return std::nullopt;
    return list;
}

// No grid: every point runs the whole program (without its hierarchy where it reads so, as
// sdfCellsNeedHierarchy tells the shader).
void wholeProgramOnly(SdfCellGrid& grid, const SdfProgram& program) {
    grid.levels = 0;
    grid.code = program.instructions;
    grid.words.clear();
    grid.planes.clear();
    grid.floor.reset();
    grid.outsideFloor.reset();
    grid.reading = SdfListReading::PostfixPairs;
    std::optional<std::vector<std::uint32_t>> list = wholeTreeList(grid.code);
    if (!list) {
        grid.code = program.instructions;
        list.emplace(program.instructions.size());
        std::iota(list->begin(), list->end(), 0u);
    }
    std::vector<std::uint32_t> pairs;
    sdfPairList(grid.code, *list, pairs);
    appendOutsideList(grid, pairs);
}

} // namespace

std::optional<SdfFieldFloor> sdfProgramFloor(const std::vector<GpuSdfInstruction>& code) {
    ProgramTree tree;
    if (code.empty() || !readTree(code, std::uint32_t(code.size()), tree) || tree.nodes.empty())
        return std::nullopt;
    for (const GpuSdfInstruction& in : code)
        if (SdfOpcode(in.opcode) == SdfOpcode::BoundSkip ||
            SdfOpcode(in.opcode) == SdfOpcode::SeedBest ||
            SdfOpcode(in.opcode) == SdfOpcode::Accumulate)
            return std::nullopt;
    const NodeFloor root = nodeFloors(code, tree).back();
    if (!root.valid || root.box.empty()) return std::nullopt;
    return SdfFieldFloor{root.box, root.drop};
}

bool sdfCellsNeedHierarchy(const std::vector<GpuSdfInstruction>& code) {
    std::vector<GpuSdfInstruction> copy = code;
    return !wholeTreeList(copy);
}

Aabb sdfContentBox(const SdfNode& root) {
    Aabb box;
    collectContent(root, glm::mat4(1.0f), box);
    return box;
}

// ---- The cell hierarchy, kept to prune it again after an edit ----

// What a grid was built from. Cells are numbered by their entry (cell k: entries 2k, 2k + 1);
// block b holds cells 64 b .. 64 b + 63, the children of one refined cell (block 0: the first
// level). A leaf cell's entry is (offset in `lists`, length); a refined one's
// (kSdfCellRefined | its block, 0).
struct SdfCellState {
    SdfProgram program; // as pruned: the edits' numbers
    std::vector<GpuSdfInstruction> code;
    ProgramTree tree;
    std::vector<std::uint32_t> identity;
    std::vector<NodeFloor> floors;        // per tree node
    std::optional<DirectChain> direct;    // the top chain, when cells are pruned from it whole
    std::vector<std::uint32_t> constants; // kFarSteps per level
    SdfCellOptions options;
    std::uint32_t unionInstruction = 0; // in code: the union the outside list unites with
    std::vector<std::uint32_t> planes;  // in code: the root chain's planes (SdfCellGrid::planes)
    std::size_t leadingPlanes = 0;      // how many of them come before every listed operand
    std::vector<std::uint32_t> listScratch; // setLeafCell's list without the planes
    std::vector<char> stackScratch;         // and withoutPlanes' stack
    // What points outside the grid run (setOutsideList) and the floor of what it leaves out.
    std::vector<std::uint32_t> outsideList;
    std::optional<SdfFieldFloor> outsideFloor;
    // The program is of a least-of-shapes form (sdfIsLeastOfShapes): the lists leave their
    // unions out (SdfListReading::LeastOfShapes).
    bool leastOfShapes = false;
    // Else they are in entries of two words (SdfListReading::PostfixPairs).
    SdfListReading reading() const {
        return leastOfShapes ? SdfListReading::LeastOfShapes : SdfListReading::PostfixPairs;
    }
    std::vector<std::uint32_t> storedScratch; // setLeafCell's list as stored (s.reading())
    int levels = 0;
    glm::vec3 origin{0.0f};
    float size = 0.0f;

    struct Block {
        int level = 1;       // of its cells
        glm::ivec3 first{0}; // the cell coordinates of its cell 0, at its level
        PrunedTree parent;   // the refined cell's pruned tree: where its cells start from
        bool live = true;    // false: freed (its cell became a leaf again), reused first
    };
    std::vector<Block> blocks;
    std::vector<std::uint32_t> freeBlocks;
    std::vector<std::uint32_t> entries;
    std::vector<std::uint32_t> cellLeaves; // per cell: shape evaluations of its program
    std::vector<float> unionThresholds;    // per cell: CellResult::unionThreshold
    std::vector<float> leastLows;          // per cell: CellResult::leastLow
    std::vector<std::uint32_t> lists;      // the leaf cells' lists, equal ones shared
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> shared; // hash -> offsets
    std::size_t listsAtCompaction = 0;
    std::size_t uniquePrograms = 0;
    std::size_t liveCells = 0;
    std::size_t prunedCells = 0; // by the last build or re-prune
    bool tooDeep = false;        // a pruned part deeper than the stack: no grid
    // Keep the refined cells' trees for repruneSdfCells; without, each goes once its block is
    // pruned (memory).
    bool keepTrees = true;

    // What the last packGrid wrote, so that the next one writes only what changed: the grid it
    // wrote (SdfCellGrid::packStamp), where its lists start (after the entries and room for an
    // eighth more blocks) and how many list words it held, each block's statistics, and which
    // blocks' entries changed since.
    struct BlockStats {
        int leafCells = 0, maxLength = 0, maxStack = 0, maxPointStack = 0, affineCells = 0;
        long length = 0, instructions = 0, leaves = 0;
    };
    std::uint64_t packStamp = 0;
    std::size_t packedBase = 0, packedLists = 0;
    std::vector<BlockStats> blockStats;
    std::vector<char> blockChanged;
    bool listsMoved = true; // the lists were stored again (compactLists): every entry changed
};

void SdfCellStateDeleter::operator()(SdfCellState* state) const {
    delete state;
}

namespace {

float cellEdge(const SdfCellState& s, int level) {
    return s.size / float(1 << (2 * level));
}

void markBlockChanged(SdfCellState& s, std::uint32_t b) {
    if (s.blockChanged.size() <= b) s.blockChanged.resize(s.blocks.size(), 1);
    s.blockChanged[b] = 1;
}

std::uint32_t allocateBlock(SdfCellState& s, int level, glm::ivec3 first, PrunedTree parent) {
    std::uint32_t b;
    if (!s.freeBlocks.empty()) {
        b = s.freeBlocks.back();
        s.freeBlocks.pop_back();
    } else {
        b = std::uint32_t(s.blocks.size());
        s.blocks.emplace_back();
        s.entries.resize(s.entries.size() + 128, 0);
        s.cellLeaves.resize(s.cellLeaves.size() + 64, 0);
        s.unionThresholds.resize(s.unionThresholds.size() + 64, NAN);
        s.leastLows.resize(s.leastLows.size() + 64, NAN);
    }
    s.blocks[b] = {level, first, std::move(parent), true};
    s.liveCells += 64;
    markBlockChanged(s, b);
    return b;
}

void freeBlock(SdfCellState& s, std::uint32_t b) {
    for (std::uint32_t k = 64 * b; k < 64 * b + 64; ++k)
        if (s.entries[2 * k] & kSdfCellRefined) freeBlock(s, s.entries[2 * k] & ~kSdfCellRefined);
    s.blocks[b].live = false;
    markBlockChanged(s, b);
    PrunedTree().swap(s.blocks[b].parent);
    s.freeBlocks.push_back(b);
    s.liveCells -= 64;
}

// The operands of the tree's top chain of unions, in order: the root's operands through every
// union that has no floor (a bounded chain is one operand).
std::vector<int> topChainOperands(const SdfCellState& s) {
    const std::vector<TreeNode>& nodes = s.tree.nodes;
    std::vector<int> operands, todo{int(nodes.size()) - 1};
    while (!todo.empty()) {
        const int n = todo.back();
        todo.pop_back();
        const TreeNode& t = nodes[std::size_t(n)];
        const bool bounded = s.floors[std::size_t(n)].valid;
        if (!bounded && t.kind == NodeKind::Combine &&
            SdfOp(s.code[t.instruction].kind) == SdfOp::Union) {
            todo.push_back(t.b);
            todo.push_back(t.a);
        } else {
            operands.push_back(n);
        }
    }
    return operands;
}

// The planes the lists leave out (SdfCellGrid::planes): the top chain's operands that are one
// plane instruction, the first kSdfCellPlanes of them; and in `leading`, how many of them come
// before every operand the lists hold (SdfCellPlane::leads).
std::vector<std::uint32_t> topPlanes(const SdfCellState& s, std::size_t* leading = nullptr) {
    std::vector<std::uint32_t> planes;
    bool listedBefore = false;
    for (int o : topChainOperands(s)) {
        const TreeNode& t = s.tree.nodes[std::size_t(o)];
        if (t.kind == NodeKind::Leaf && t.end == t.begin + 1 && isOnePlane(s.code, &t.begin, 1) &&
            planes.size() < std::size_t(kSdfCellPlanes)) {
            planes.push_back(t.begin);
            if (leading && !listedBefore) *leading = planes.size();
        } else {
            listedBefore = true;
        }
    }
    return planes;
}

// A plane instruction's field as an affine function of the world point: sdPlane (sdf/
// primitives.cpp) of the frame's point q = worldToLocal (p, 1), times the distance scale, is
// dot(n, q) / |n| - offset times the scale: dot(xyz, p) + w.
glm::vec4 planeField(const GpuSdfInstruction& in) {
    const glm::vec3 n =
        glm::vec3(in.params[0]) / std::max(glm::length(glm::vec3(in.params[0])), 1e-6f);
    const glm::vec4 along =
        n.x * in.worldToLocal[0] + n.y * in.worldToLocal[1] + n.z * in.worldToLocal[2];
    return in.misc.x * glm::vec4(glm::vec3(along), along.w - in.params[0].w);
}

// `list` without the grid's planes and the unions that took them in (each plane is an operand of
// a plain union, which then stands for its other operand), in `out`. `outOfList`: scratch.
void withoutPlanes(const SdfCellState& s, std::span<const std::uint32_t> list,
                   std::vector<std::uint32_t>& out, std::vector<char>& outOfList) {
    out.clear();
    if (s.planes.empty()) {
        out.assign(list.begin(), list.end());
        return;
    }
    outOfList.clear(); // per value-stack entry: a plane taken out (or only planes)
    for (std::uint32_t i : list) {
        const GpuSdfInstruction& in = s.code[i];
        if (isLeafOpcode(in.opcode)) {
            const bool plane = std::find(s.planes.begin(), s.planes.end(), i) != s.planes.end();
            outOfList.push_back(plane);
            if (!plane) out.push_back(i);
        } else if (SdfOpcode(in.opcode) == SdfOpcode::Combine && outOfList.size() >= 2) {
            const bool b = outOfList.back();
            outOfList.pop_back();
            const bool a = outOfList.back();
            if (!a && !b) out.push_back(i); // (a plane's operation is a plain union)
            outOfList.back() = a && b;
        } else {
            out.push_back(i);
        }
    }
}

// The offset of `list` in s.lists, shared with an equal list when there is one.
std::uint32_t storeList(SdfCellState& s, std::span<const std::uint32_t> list) {
    std::vector<std::uint32_t>& same = s.shared[hashList(list)];
    for (std::uint32_t o : same)
        if (o + list.size() <= s.lists.size() &&
            std::equal(list.begin(), list.end(), s.lists.begin() + o))
            return o;
    const std::uint32_t offset = std::uint32_t(s.lists.size());
    s.lists.insert(s.lists.end(), list.begin(), list.end());
    same.push_back(offset);
    ++s.uniquePrograms;
    return offset;
}

void setLeafCell(SdfCellState& s, std::uint32_t k, const CellResult& r) {
    withoutPlanes(s, r.list, s.listScratch, s.stackScratch);
    std::span<const std::uint32_t> list = s.listScratch;
    s.storedScratch.clear();
    if (s.leastOfShapes) { // the running minimum needs no unions, nor a stack
        for (std::uint32_t i : list)
            if (neededByLeastOfShapes(s.code[i])) s.storedScratch.push_back(i);
    } else {
        if (stackDepth(s.code, list) > kSdfMaxStack) s.tooDeep = true;
        sdfPairList(s.code, list, s.storedScratch);
    }
    list = s.storedScratch;
    s.entries[2 * k] = storeList(s, list);
    // Affine when its program is one plane: a constant, a plane the lists hold, or one of the
    // grid's planes (then the list is empty).
    s.entries[2 * k + 1] =
        std::uint32_t(sdfListEntries(list.size(), s.reading())) |
        (isOnePlane(s.code, r.list.data(), std::uint32_t(r.list.size())) ? kSdfCellAffine : 0u);
    s.cellLeaves[k] = std::uint32_t(r.leaves);
    markBlockChanged(s, k / 64);
}

// Edits leave lists no cell uses; once they are as many as the rest, the lists are stored again.
void compactLists(SdfCellState& s) {
    if (s.lists.size() < 2 * s.listsAtCompaction + (1u << 20)) return;
    std::vector<std::uint32_t> old = std::move(s.lists);
    s.lists.clear();
    s.shared.clear();
    s.uniquePrograms = 0;
    for (std::uint32_t b = 0; b < s.blocks.size(); ++b)
        if (s.blocks[b].live)
            for (std::uint32_t k = 64 * b; k < 64 * b + 64; ++k)
                if (!(s.entries[2 * k] & kSdfCellRefined))
                    s.entries[2 * k] = storeList(
                        s, std::span(old).subspan(
                               s.entries[2 * k],
                               sdfListWords(s.entries[2 * k + 1] & ~kSdfCellAffine, s.reading())));
    s.listsAtCompaction = s.lists.size();
    s.listsMoved = true;
}

bool holdsChanged(const PrunedTree& tree, const std::vector<char>& changed) {
    for (const PrunedNode& n : tree)
        if (changed[std::size_t(n.node)]) return true;
    return false;
}

bool sameTree(const PrunedTree& a, const PrunedTree& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const PrunedNode& x, const PrunedNode& y) {
                          return x.node == y.node && x.a == y.a && x.b == y.b;
                      });
}

// What an edit of numbers changed, for repruneSdfCells: the operands of the tree's top chain
// of unions that hold a changed node ("tops"), with their floors before the edit. Where a
// block's parent tree differs from before only within those tops (and in the chain's unions,
// which follow from how many operands are kept), a cell of it where every top is dropped by its
// floor, before and after, keeps its old result: the other operands and their values are what
// they were, and a dropped operand changes nothing (see CellResult::unionThreshold).
struct EditScope {
    std::vector<int> tops;             // tree nodes
    std::vector<NodeFloor> topsBefore; // their floors before the edit
    std::vector<char> skipped;         // per tree node: a top's node, or a union of the chain
    // When the one top is an operand of a direct chain (DirectChain) that is one shape
    // instruction, as when one shape of a large union is moved: that instruction's index and
    // what it was before the edit (see farConstantStands).
    std::optional<std::uint32_t> shape;
    GpuSdfInstruction shapeBefore;
};

// The scope of an edit whose changed nodes all lie under operands of the tree's top chain of
// unions; none when the root is no such chain.
std::optional<EditScope> editScope(const ProgramTree& tree,
                                   const std::vector<GpuSdfInstruction>& code,
                                   const std::vector<char>& changed) {
    const std::size_t count = tree.nodes.size();
    const auto isUnion = [&](std::size_t i) {
        return tree.nodes[i].kind == NodeKind::Combine &&
               SdfOp(code[tree.nodes[i].instruction].kind) == SdfOp::Union;
    };
    if (count == 0 || !isUnion(count - 1)) return std::nullopt;
    EditScope scope;
    scope.skipped.assign(count, 0);
    std::vector<int> top(count, -1); // the chain's operand above each node
    std::vector<int> operands;
    int bottom = int(count) - 1;
    for (; isUnion(std::size_t(bottom)); bottom = tree.nodes[std::size_t(bottom)].a) {
        scope.skipped[std::size_t(bottom)] = 1;
        operands.push_back(tree.nodes[std::size_t(bottom)].b);
    }
    operands.push_back(bottom);
    for (int o : operands) {
        // A subtree is the run of post-order nodes that ends at its root and starts at its
        // leftmost leaf.
        int first = o;
        while (tree.nodes[std::size_t(first)].kind != NodeKind::Leaf)
            first = tree.nodes[std::size_t(first)].a;
        for (int n = first; n <= o; ++n)
            top[std::size_t(n)] = o;
    }
    for (std::size_t n = 0; n < count; ++n) {
        if (!changed[n]) continue;
        if (top[n] < 0) return std::nullopt;
        if (std::find(scope.tops.begin(), scope.tops.end(), top[n]) == scope.tops.end())
            scope.tops.push_back(top[n]);
    }
    for (int o : scope.tops) {
        int first = o;
        while (tree.nodes[std::size_t(first)].kind != NodeKind::Leaf)
            first = tree.nodes[std::size_t(first)].a;
        for (int n = first; n <= o; ++n)
            scope.skipped[std::size_t(n)] = 1;
    }
    return scope;
}

// A block to prune: new (every cell is made), or pruned before (`floorsDecide`: its cells may
// keep their results by the EditScope test).
struct PendingBlock {
    std::uint32_t block = 0;
    bool fresh = false;
    bool floorsDecide = false;
    bool operator<(const PendingBlock& o) const { return block < o.block; }
};

// Do trees a and b hold the same nodes, in the same order, but for those `skipped`?
bool sameBeyond(const PrunedTree& a, const PrunedTree& b, const std::vector<char>& skipped) {
    std::size_t i = 0, j = 0;
    for (;;) {
        while (i < a.size() && skipped[std::size_t(a[i].node)])
            ++i;
        while (j < b.size() && skipped[std::size_t(b[j].node)])
            ++j;
        if (i == a.size() || j == b.size()) return i == a.size() && j == b.size();
        if (a[i].node != b[j].node) return false;
        ++i, ++j;
    }
}

// Is every top of `scope` dropped by its floor at the cell, before and after the edit?
bool topsDropped(const SdfCellState& s, const EditScope& scope, glm::vec3 centre, float r,
                 float slack, float threshold) {
    if (!(threshold == threshold)) return false; // NaN: the root is no chain of unions
    // With a margin of the rounding slack: a top dropped here by it is dropped in every cell
    // within this one too (their floors are no lower, their thresholds no higher, but for the
    // intervals' relative rounding term), which keep their results with this one's.
    const float above = threshold + slack;
    for (std::size_t t = 0; t < scope.tops.size(); ++t)
        if (!(floorLow(scope.topsBefore[t], centre, r, slack) > above) ||
            !(floorLow(s.floors[std::size_t(scope.tops[t])], centre, r, slack) > above))
            return false;
    return true;
}

// Does the far constant of cell k (at `level`, centre c, edge length `edge`) stand after an
// edit of one shape operand of the direct chain (EditScope::shape)? pruneCellDirect makes a
// cell a far constant from three numbers over every operand: the least lower end (its step
// m = min(int(lo / edge), kFarSteps) picks the constant), the least upper end (which operands
// are kept) and how many shapes are kept (more than `shortLeaves`). The shape's interval before
// and after the edit, computed as pruneCellDirect computes it, shows whether each stands:
// - the least lower end (kept as the cell's leastLow): the shape's lower end was above it, so
//   the others' made it, and the least of it and the shape's after is in the same step;
// - the least upper end (kept as its unionThreshold): the shape's upper end was above it, so
//   the others' made it, and is no lower after;
// - the count: the same other operands are kept; the shape is kept after, or was not before.
// (Operands' intervals are as wide as a shape's or wider, so the first follows from the
// second but for rounding; it is checked all the same.) A far cell of a large union's empty
// surroundings holds hundreds of shapes within its least upper end, so moving one shape
// changes none of the three in most of them.
bool farConstantStands(const SdfCellState& s, const Pruner& pr, const EditScope& scope,
                       std::uint32_t k, int level, glm::vec3 c, float edge) {
    if (!scope.shape) return false;
    const std::uint32_t entry = s.entries[2 * k], length = s.entries[2 * k + 1] & ~kSdfCellAffine;
    if ((entry & kSdfCellRefined) || length != 1) return false;
    const std::uint32_t* constants = &s.constants[std::size_t(kFarSteps * (level - 1))];
    if (std::find(constants, constants + kFarSteps, s.lists[entry]) == constants + kFarSteps)
        return false;
    const float leastLo = s.leastLows[k], leastHi = s.unionThresholds[k];
    const float reach = 0.8660254f * edge + pr.slack; // as pruneCellDirect's
    const auto range = [&](const GpuSdfInstruction& in) {
        const float v = sdfLeafDistance(pr.program, in, c);
        const float e = reach + 1e-6f * std::abs(v);
        return SdfInterval{v - e, v + e};
    };
    const auto step = [&](float lo) { return std::min(int(lo / edge), kFarSteps); };
    const SdfInterval before = range(scope.shapeBefore), after = range(pr.code[*scope.shape]);
    if (!(before.lo > leastLo) || step(std::min(leastLo, after.lo)) != step(leastLo)) return false;
    if (!(before.hi > leastHi) || !(after.hi >= leastHi)) return false;
    return after.lo <= leastHi || !(before.lo <= leastHi);
}

// Prunes the cells of `pending` blocks level by level: each block's 64 cells from its parent
// tree. `fresh` blocks are new (every cell of theirs is made); in the others a refined cell's
// children are pruned again only when its new tree holds a node of `changed` or differs from
// its old one: a cell's program is a function of its parent's tree and of the values of that
// tree's nodes, so with the same tree and none of it changed it is what it was. (The tree
// itself is not enough alone: a node dropped in both may still have decided what was kept.)
// With a `scope`, cells whose old result provably stands are not pruned at all (EditScope).
void pruneBlocks(SdfCellState& s, std::vector<PendingBlock> pending,
                 const std::vector<char>& changed, const EditScope* scope = nullptr) {
    const Pruner pruner{s.program, s.code, s.tree, s.identity, s.floors, 1e-5f * s.size};
    const SdfCellOptions& o = s.options;
    const int threadCount =
        o.threads > 0 ? o.threads : std::max(1, int(std::thread::hardware_concurrency()));
    // A level's blocks a part at a time: the results of a part are all in memory at once.
    constexpr std::size_t kPartBlocks = 2048;
    while (!pending.empty()) {
        std::vector<PendingBlock> children;
        for (std::size_t first = 0; first < pending.size(); first += kPartBlocks) {
            const std::span<const PendingBlock> part(pending.data() + first,
                                                     std::min(kPartBlocks, pending.size() - first));
            const std::size_t cellCount = 64 * part.size();
            std::vector<CellResult> results(cellCount);
            std::atomic<std::size_t> next{0}, pruned{0};
            const auto work = [&] {
                CellScratch scratch;
                DirectScratch directScratch;
                for (std::size_t t; (t = next.fetch_add(1)) < cellCount;) {
                    const PendingBlock& pendingBlock = part[t / 64];
                    const SdfCellState::Block& block = s.blocks[pendingBlock.block];
                    const int j = int(t % 64);
                    const glm::ivec3 cell = block.first + glm::ivec3(j % 4, (j / 4) % 4, j / 16);
                    const float edge = cellEdge(s, block.level);
                    const glm::vec3 centre = s.origin + (glm::vec3(cell) + 0.5f) * edge;
                    const std::uint32_t k = 64 * pendingBlock.block + std::uint32_t(j);
                    if (pendingBlock.floorsDecide && scope &&
                        (topsDropped(s, *scope, centre, 0.8660254f * edge, pruner.slack,
                                     s.unionThresholds[k]) ||
                         (s.direct && o.farConstants &&
                          farConstantStands(s, pruner, *scope, k, block.level, centre, edge)))) {
                        results[t].unchanged = true;
                        continue;
                    }
                    ++pruned;
                    const std::uint32_t* constants =
                        &s.constants[std::size_t(kFarSteps * (block.level - 1))];
                    const int shortLeaves = o.farConstants ? o.refineLeaves : -1;
                    if (s.direct)
                        pruneCellDirect(pruner, *s.direct, centre, edge, constants, shortLeaves,
                                        block.level < s.levels ? o.refineLeaves : -1, results[t],
                                        directScratch);
                    else
                        pruneCell(pruner, block.parent, centre, edge, constants, shortLeaves,
                                  results[t], scratch);
                    // Only cells that may be refined keep their pruned tree (memory: the finest
                    // level holds most cells).
                    if (block.level == s.levels || results[t].leaves <= o.refineLeaves)
                        PrunedTree().swap(results[t].pruned);
                }
            };
            std::vector<std::thread> workers;
            for (int w = 1; w < std::min(threadCount, int(cellCount)); ++w)
                workers.emplace_back(work);
            work();
            for (std::thread& w : workers)
                w.join();
            s.prunedCells += pruned;

            // Cells to refine anew: within the cell budget, those near the surface first, then
            // those with the most shapes.
            std::vector<std::size_t> candidates;
            for (std::size_t t = 0; t < cellCount; ++t) {
                const PendingBlock& pendingBlock = part[t / 64];
                const std::uint32_t b = pendingBlock.block;
                const std::uint32_t k = 64 * b + std::uint32_t(t % 64);
                CellResult& r = results[t];
                if (r.unchanged) continue;
                s.unionThresholds[k] = r.unionThreshold;
                s.leastLows[k] = r.leastLow;
                const bool refine =
                    s.blocks[b].level < s.levels && !r.far && r.leaves > o.refineLeaves;
                const bool wasRefined = !pendingBlock.fresh && (s.entries[2 * k] & kSdfCellRefined);
                if (wasRefined) {
                    const std::uint32_t child = s.entries[2 * k] & ~kSdfCellRefined;
                    if (refine && s.direct) { // its cells need nothing of it: each decides
                        children.push_back({child, false, scope != nullptr});
                        continue;
                    }
                    if (refine) {
                        PrunedTree& old = s.blocks[child].parent;
                        const bool same = sameTree(old, r.pruned);
                        if (!same || holdsChanged(r.pruned, changed)) {
                            const bool decide =
                                scope && (same || sameBeyond(old, r.pruned, scope->skipped));
                            old = std::move(r.pruned);
                            children.push_back({child, false, decide});
                        }
                        continue;
                    }
                    freeBlock(s, child);
                }
                if (refine)
                    candidates.push_back(t);
                else
                    setLeafCell(s, k, r);
            }
            std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
                const bool nearA = results[a].near, nearB = results[b].near;
                if (nearA != nearB) return nearA;
                if (results[a].leaves != results[b].leaves)
                    return results[a].leaves > results[b].leaves;
                return a < b;
            });
            const std::size_t room = o.maxCells > s.liveCells ? (o.maxCells - s.liveCells) / 64 : 0;
            for (std::size_t c = 0; c < candidates.size(); ++c) {
                const std::size_t t = candidates[c];
                const std::uint32_t b = part[t / 64].block;
                const std::uint32_t k = 64 * b + std::uint32_t(t % 64);
                if (c >= room) {
                    setLeafCell(s, k, results[t]);
                    continue;
                }
                const int j = int(t % 64);
                const glm::ivec3 cell = s.blocks[b].first + glm::ivec3(j % 4, (j / 4) % 4, j / 16);
                const std::uint32_t child =
                    allocateBlock(s, s.blocks[b].level + 1, cell * 4, std::move(results[t].pruned));
                s.entries[2 * k] = kSdfCellRefined | child;
                s.entries[2 * k + 1] = 0;
                markBlockChanged(s, b);
                children.push_back({child, true, false});
            }
            if (!s.keepTrees)
                for (const PendingBlock& pendingBlock : part)
                    PrunedTree().swap(s.blocks[pendingBlock.block].parent);
        }
        // Blocks in order, as a full build makes them (the next level's cells likewise).
        std::sort(children.begin(), children.end());
        pending = std::move(children);
    }
}

// The grid as the GPU reads it: the cell entries, the lists after them (offsets made absolute),
// the whole program's list last; and its statistics. When `grid` is what the state's last pack
// wrote and the entries and lists stayed in place (an edit: its new lists go after the old
// ones), only the changed blocks and the words after the old lists are written, and
// grid.changedWords says which; otherwise everything is.
void packGrid(SdfCellState& s, SdfCellGrid& grid) {
    static std::atomic<std::uint64_t> stamps{0};
    grid.code = s.code;
    grid.stats = {};
    grid.changedWords.clear();
    if (s.tooDeep) { // a pruned part deeper than the stack (the fold of accumulated parts)
        wholeProgramOnly(grid, s.program);
        grid.changedWords.push_back({0, std::uint32_t(grid.words.size())});
        grid.packStamp = grid.changedSince = 0;
        return;
    }
    const bool inPlace = grid.packStamp != 0 && grid.packStamp == s.packStamp && !s.listsMoved &&
                         grid.levels == s.levels && s.entries.size() <= s.packedBase &&
                         s.lists.size() >= s.packedLists &&
                         grid.words.size() >= s.packedBase + s.packedLists;
    grid.levels = s.levels;
    grid.origin = s.origin;
    grid.size = s.size;
    grid.floor.reset(); // the root's, made again after an edit (updateNodeFloors)
    if (!s.floors.empty() && s.floors.back().valid && !s.floors.back().box.empty())
        grid.floor = SdfFieldFloor{s.floors.back().box, s.floors.back().drop};
    grid.outsideFloor = s.outsideFloor;
    grid.planes.clear();
    for (std::size_t k = 0; k < s.planes.size(); ++k)
        grid.planes.push_back({s.planes[k], planeField(s.code[s.planes[k]]), k < s.leadingPlanes});
    const std::size_t blockCount = s.blocks.size();
    const std::uint32_t base =
        std::uint32_t(inPlace ? s.packedBase : 128 * (blockCount + (blockCount + 7) / 8));
    s.blockStats.resize(blockCount);
    s.blockChanged.resize(blockCount, 1);
    // Reserved whole first, with room for a quarter more lists (an edit's new lists go after the
    // old ones, as in the GPU's buffer): growing a large grid's words in steps would copy them,
    // and hold two copies at once. What is never used is never touched (costs no memory).
    if (!inPlace) {
        grid.words.clear();
        grid.words.reserve(base + s.lists.size() + s.lists.size() / 4 + s.outsideList.size());
        grid.words.assign(base, 0u);
    }
    grid.words.resize(base + s.lists.size());
    for (std::uint32_t b = 0; b < blockCount; ++b) {
        if (inPlace && !s.blockChanged[b]) continue;
        s.blockChanged[b] = 0;
        if (inPlace) {
            std::vector<SdfWordRange>& changed = grid.changedWords;
            if (!changed.empty() && changed.back().first + changed.back().count == 128 * b)
                changed.back().count += 128;
            else
                changed.push_back({128 * b, 128});
        }
        SdfCellState::BlockStats& stats = s.blockStats[b];
        stats = {};
        if (!s.blocks[b].live) {
            std::fill_n(grid.words.begin() + 128 * b, 128, 0u);
            continue;
        }
        for (std::uint32_t k = 64 * b; k < 64 * b + 64; ++k) {
            const std::uint32_t e = s.entries[2 * k], word = s.entries[2 * k + 1];
            const std::uint32_t length = word & ~kSdfCellAffine;
            grid.words[2 * k] = e & kSdfCellRefined ? e : e + base;
            grid.words[2 * k + 1] = word;
            if (e & kSdfCellRefined) continue;
            if (word & kSdfCellAffine) ++stats.affineCells;
            ++stats.leafCells;
            stats.length += long(length);
            const std::span<const std::uint32_t> list =
                std::span(s.lists).subspan(e, sdfListWords(length, s.reading()));
            stats.instructions += long(sdfListInstructionCount(s.code, list, s.reading()));
            stats.maxStack = std::max(stats.maxStack, sdfListStackDepth(s.code, list, s.reading()));
            stats.maxPointStack =
                std::max(stats.maxPointStack, sdfListPointStackDepth(s.code, list, s.reading()));
            stats.leaves += long(s.cellLeaves[k]);
            stats.maxLength = std::max(stats.maxLength, int(length));
        }
    }
    const std::size_t listsFrom = inPlace ? s.packedLists : 0;
    std::copy(s.lists.begin() + std::ptrdiff_t(listsFrom), s.lists.end(),
              grid.words.begin() + base + std::ptrdiff_t(listsFrom));
    grid.reading = s.reading();
    appendOutsideList(grid, s.outsideList);
    const std::uint32_t tail = inPlace ? base + std::uint32_t(listsFrom) : 0;
    if (grid.words.size() > tail)
        grid.changedWords.push_back({tail, std::uint32_t(grid.words.size()) - tail});
    s.packedBase = base;
    s.packedLists = s.lists.size();
    s.listsMoved = false;
    grid.changedSince = inPlace ? grid.packStamp : 0;
    s.packStamp = grid.packStamp = ++stamps;

    grid.stats.cellsPerLevel.assign(std::size_t(s.levels), 0);
    long totalLength = 0, totalInstructions = 0, totalLeaves = 0;
    for (std::uint32_t b = 0; b < blockCount; ++b) {
        if (!s.blocks[b].live) continue;
        grid.stats.cellsPerLevel[std::size_t(s.blocks[b].level - 1)] += 64;
        const SdfCellState::BlockStats& stats = s.blockStats[b];
        grid.stats.leafCells += stats.leafCells;
        grid.stats.affineCells += stats.affineCells;
        totalLength += stats.length;
        totalInstructions += stats.instructions;
        totalLeaves += stats.leaves;
        grid.stats.maxLength = std::max(grid.stats.maxLength, stats.maxLength);
        grid.stats.maxStack = std::max(grid.stats.maxStack, stats.maxStack);
        grid.stats.maxPointStack = std::max(grid.stats.maxPointStack, stats.maxPointStack);
    }
    while (!grid.stats.cellsPerLevel.empty() && grid.stats.cellsPerLevel.back() == 0)
        grid.stats.cellsPerLevel.pop_back();
    grid.stats.uniquePrograms = s.uniquePrograms;
    grid.stats.prunedCells = s.prunedCells;
    grid.stats.meanLength = grid.stats.leafCells ? double(totalLength) / grid.stats.leafCells : 0.0;
    grid.stats.meanInstructions =
        grid.stats.leafCells ? double(totalInstructions) / grid.stats.leafCells : 0.0;
    grid.stats.meanLeaves = grid.stats.leafCells ? double(totalLeaves) / grid.stats.leafCells : 0.0;
    grid.stats.bytes = grid.words.size() * sizeof(std::uint32_t);
}

// What points outside the grid run: the tree without the operands of its top chain of unions
// whose floors bound them there (the content: every operand but the planes and other unbounded
// ones) and without the grid's planes (s.planes, which every point runs), in s.outsideList, and one
// floor for those it leaves out, in s.outsideFloor (their boxes' union, the largest drop). At a
// point outside the grid the field is the least of the list's value and the operands', which is at
// least the floor's distance; the shader takes the least of the list and that distance
// (common/sdf_cells.glsl, sdfCellDistance): a lower bound, equal to the field wherever the list is
// nearer, which is everywhere a march outside the grid can meet a surface. The floor stays a margin
// away from the grid's faces (so nothing outside the grid reads as a hit on it), else nothing is
// left out. The list holds no bounding hierarchy: the cells' shader leaves its branches out (each
// costs every step on llvmpipe). A grid whose whole program is bounded runs nothing outside (its
// floor alone: the grids).
constexpr float kOutsideFloorMargin = 0.01f; // of the grid's edge

void setOutsideList(SdfCellState& s) {
    s.outsideList.clear();
    s.outsideFloor.reset();
    const std::vector<int> operands = topChainOperands(s);
    const auto floored = [&](int o) {
        const NodeFloor& f = s.floors[std::size_t(o)];
        return f.valid && !f.box.empty();
    };
    SdfFieldFloor left{Aabb{}, 0.0f};
    for (int o : operands)
        if (floored(o)) {
            left.box.add(s.floors[std::size_t(o)].box);
            left.drop = std::max(left.drop, s.floors[std::size_t(o)].drop);
        }
    const glm::vec3 gaps = glm::min(left.box.min - s.origin, s.origin + s.size - left.box.max);
    const float gap = std::min(std::min(gaps.x, gaps.y), gaps.z);
    const bool leaveOut = !left.box.empty() && gap - left.drop > kOutsideFloorMargin * s.size;
    if (leaveOut) s.outsideFloor = left;
    std::size_t united = 0;
    std::vector<std::uint32_t> list;
    for (int o : operands) {
        if (leaveOut && floored(o)) continue;
        appendPostfix(s.tree, o, list);
        if (united++ > 0) list.push_back(s.unionInstruction);
    }
    withoutPlanes(s, list, s.outsideList, s.stackScratch);
    if (s.leastOfShapes) {
        std::erase_if(s.outsideList,
                      [&](std::uint32_t i) { return !neededByLeastOfShapes(s.code[i]); });
        return;
    }
    if (stackDepth(s.code, s.outsideList) > kSdfMaxStack) s.tooDeep = true;
    list.clear();
    sdfPairList(s.code, s.outsideList, list);
    s.outsideList = std::move(list);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

SdfCellGrid buildSdfCells(const SdfProgram& program, const Aabb& content,
                          const SdfCellOptions& options, SdfCellStatePtr* keep) {
    const auto started = std::chrono::steady_clock::now();
    if (keep) keep->reset();
    SdfCellGrid grid;
    if (content.empty() || program.instructions.empty() || options.levels < 1) {
        wholeProgramOnly(grid, program);
        return grid;
    }
    SdfCellStatePtr state(new SdfCellState);
    SdfCellState& s = *state;
    s.program = program;
    // The program, the union below and the far constants, reserved whole: a large scene's code
    // is not copied as it grows.
    s.code.reserve(program.instructions.size() + 1 + 6 * kFarSteps);
    s.code = program.instructions;
    s.options = options;
    s.keepTrees = keep != nullptr;
    // The union the accumulated parts of a bounding hierarchy are folded with (and the outside
    // list's operands).
    s.unionInstruction = std::uint32_t(s.code.size());
    s.code.push_back(unionInstruction());
    if (!readTree(program.instructions, s.unionInstruction, s.tree) || s.tree.nodes.empty()) {
        wholeProgramOnly(grid, program);
        return grid;
    }
    s.floors = nodeFloors(s.code, s.tree);
    s.direct = directChain(s.tree, s.code, s.floors);
    s.levels = std::clamp(options.levels, 1, 6);
    const glm::vec3 half = content.halfSize();
    const float extent = std::max(std::max(half.x, half.y), std::max(half.z, 1e-3f)) * 1.02f *
                         float(1 << (2 * std::clamp(options.outerLevels, 0, s.levels - 1)));
    s.origin = content.center() - glm::vec3(extent);
    s.size = 2.0f * extent;
    for (int level = 1; level <= s.levels; ++level)
        for (int m = 1; m <= kFarSteps; ++m) {
            s.constants.push_back(std::uint32_t(s.code.size()));
            s.code.push_back(constantInstruction(float(m) * cellEdge(s, level)));
        }
    s.identity.resize(s.code.size());
    std::iota(s.identity.begin(), s.identity.end(), 0u);
    s.leastOfShapes = sdfIsLeastOfShapes(s.program);
    s.planes = topPlanes(s, &s.leadingPlanes);
    setOutsideList(s);

    // The per-cell arrays grow a block at a time up to the cell budget: reserved for it once,
    // they are never copied as they grow (two copies at once), and the part never used is never
    // touched, so it costs no memory.
    const std::size_t cellRoom = std::min(options.maxCells, std::size_t(limits::kSdfCells)) + 64;
    s.blocks.reserve(cellRoom / 64);
    s.entries.reserve(2 * cellRoom);
    s.cellLeaves.reserve(cellRoom);
    s.unionThresholds.reserve(cellRoom);
    s.leastLows.reserve(cellRoom);

    PrunedTree whole;
    if (!s.direct) {
        whole.resize(s.tree.nodes.size());
        for (std::size_t i = 0; i < s.tree.nodes.size(); ++i)
            whole[i] = {int(i), s.tree.nodes[i].a, s.tree.nodes[i].b};
    }
    allocateBlock(s, 1, glm::ivec3(0), std::move(whole));
    pruneBlocks(s, {{0u, true, false}}, std::vector<char>(s.tree.nodes.size(), 0));
    s.listsAtCompaction = s.lists.size();
    packGrid(s, grid);
    grid.stats.buildMs = millisecondsSince(started);
    if (keep && !s.tooDeep) *keep = std::move(state);
    return grid;
}

bool repruneSdfCells(SdfCellState& s, const SdfProgram& edited, SdfCellGrid& grid) {
    const auto started = std::chrono::steady_clock::now();
    const std::vector<GpuSdfInstruction>& before = s.program.instructions;
    const std::vector<GpuSdfInstruction>& after = edited.instructions;
    if (after.size() != before.size() || edited.data.size() != s.program.data.size()) return false;
    // The same structure: every instruction the same but for the numbers of shapes,
    // profiles, operations and modifiers, and the kind of shape.
    std::vector<char> differs(after.size(), 0);
    for (std::size_t i = 0; i < after.size(); ++i) {
        const GpuSdfInstruction &a = before[i], &b = after[i];
        if (a.opcode != b.opcode) return false;
        if (!isLeafOpcode(a.opcode) && a.kind != b.kind &&
            SdfOpcode(a.opcode) != SdfOpcode::BoundSkip)
            return false;
        differs[i] = std::memcmp(&a, &b, sizeof a) != 0;
    }
    const bool dataDiffers = edited.data != s.program.data;
    std::vector<char> changed(s.tree.nodes.size(), 0);
    bool any = false;
    for (std::size_t n = 0; n < s.tree.nodes.size(); ++n) {
        const TreeNode& t = s.tree.nodes[n];
        if (t.kind == NodeKind::Leaf) {
            for (std::uint32_t i = t.begin; i < t.end && !changed[n]; ++i)
                changed[n] =
                    differs[i] || (dataDiffers && SdfOpcode(after[i].opcode) == SdfOpcode::Profile);
        } else if (t.instruction < after.size()) {
            changed[n] = differs[t.instruction];
        }
        any = any || changed[n];
    }
    std::optional<EditScope> scope = editScope(s.tree, s.code, changed);
    if (scope)
        for (int top : scope->tops)
            scope->topsBefore.push_back(s.floors[std::size_t(top)]);
    if (scope && s.direct && scope->tops.size() == 1 && !dataDiffers) {
        const DirectChain& d = *s.direct;
        const auto at = std::find(d.operands.begin(), d.operands.end(), scope->tops[0]);
        const int single =
            at == d.operands.end() ? -1 : d.single[std::size_t(at - d.operands.begin())];
        if (single >= 0 && SdfOpcode(before[std::size_t(single)].opcode) == SdfOpcode::Shape &&
            before[std::size_t(single)].kind == after[std::size_t(single)].kind) {
            scope->shape = std::uint32_t(single);
            scope->shapeBefore = before[std::size_t(single)];
        }
    }
    s.program.data = edited.data;
    std::copy(after.begin(), after.end(), s.code.begin());
    std::copy(after.begin(), after.end(), s.program.instructions.begin());
    updateNodeFloors(s.code, s.tree, changed, s.floors);
    if (s.direct) refitDirectChain(*s.direct, s.floors);
    if (topPlanes(s) != s.planes) return false; // a plane retyped, or a shape made a plane
    setOutsideList(s);
    s.prunedCells = 0;
    if (any) {
        pruneBlocks(s, {{0u, false, bool(scope)}}, changed, scope ? &*scope : nullptr);
        compactLists(s);
    }
    if (s.tooDeep) return false;
    packGrid(s, grid);
    grid.stats.buildMs = millisecondsSince(started);
    return true;
}

SdfCellRange sdfCellRange(const SdfCellGrid& grid, glm::vec3 p) {
    const SdfCellRange outside{grid.outsideOffset, grid.outsideLength};
    if (grid.levels == 0) return outside;
    const glm::vec3 u = (p - grid.origin) / grid.size;
    if (!(u.x >= 0.0f && u.y >= 0.0f && u.z >= 0.0f && u.x < 1.0f && u.y < 1.0f && u.z < 1.0f))
        return outside;
    const std::uint32_t n = 1u << (2 * grid.levels);
    const glm::uvec3 c = glm::min(glm::uvec3(u * float(n)), glm::uvec3(n - 1));
    std::uint32_t block = 0;
    for (int level = 0; level < grid.levels; ++level) {
        const int shift = 2 * (grid.levels - 1 - level);
        const glm::uvec3 d = (c >> glm::uvec3(shift)) & glm::uvec3(3);
        const std::size_t w = 2 * (std::size_t(block) * 64 + d.x + 4 * d.y + 16 * d.z);
        const std::uint32_t e = grid.words[w];
        if (!(e & kSdfCellRefined)) {
            const std::uint32_t length = grid.words[w + 1];
            return {e, length & ~kSdfCellAffine, level + 1, (length & kSdfCellAffine) != 0};
        }
        block = e & ~kSdfCellRefined;
    }
    return outside;
}

float sdfCellOutsideFloor(const SdfCellGrid& grid, glm::vec3 p) {
    if (!grid.outsideFloor || grid.levels == 0 || sdfCellRange(grid, p).level != 0) return INFINITY;
    // (Never inside the box, where floorAt says nothing: the box keeps a margin from the grid.)
    return floorAt({grid.outsideFloor->box, grid.outsideFloor->drop, true}, p);
}

std::span<const std::uint32_t> sdfCellWords(const SdfCellGrid& grid, const SdfCellRange& r) {
    return std::span(grid.words).subspan(r.offset, sdfListWords(r.length, grid.reading));
}

std::vector<GpuSdfInstruction> sdfCellProgram(const SdfCellGrid& grid, glm::vec3 p) {
    std::vector<GpuSdfInstruction> program;
    if (grid.levels > 0)
        sdfListProgram(grid.code, sdfCellWords(grid, sdfCellRange(grid, p)), grid.reading, program);
    return program;
}

float sdfCellsDistance(const SdfProgram& program, const SdfCellGrid& grid, glm::vec3 p) {
    const auto list = sdfCellWords(grid, sdfCellRange(grid, p));
    float d = list.empty() ? INFINITY
                           : sdfDistanceOrdered(program, grid.code, list, p, nullptr, grid.reading);
    d = std::min(d, sdfCellOutsideFloor(grid, p));
    for (const SdfCellPlane& plane : grid.planes)
        d = std::min(d, sdfLeafDistance(program, grid.code[plane.instruction], p));
    return d;
}

SdfSurface sdfCellsSurface(const SdfProgram& program, const SdfCellGrid& grid,
                           std::span<const Material> materials, glm::vec3 p) {
    const auto list = sdfCellWords(grid, sdfCellRange(grid, p));
    SdfSurface surface;
    surface.distance = INFINITY;
    if (!list.empty())
        surface = sdfSurfaceOrdered(program, grid.code, list, materials, p, grid.reading);
    bool fromPlane = false; // (planes are in the chain's order: the first of equal ones stays)
    for (const SdfCellPlane& plane : grid.planes) {
        const SdfSurface s =
            sdfSurfaceOrdered(program, grid.code, std::span(&plane.instruction, 1), materials, p);
        if (s.distance < surface.distance ||
            (plane.leads && !fromPlane && s.distance == surface.distance)) {
            surface = s;
            fromPlane = true;
        }
    }
    return surface;
}

} // namespace rmsc
