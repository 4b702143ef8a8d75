// Per-cell pruning (sdf/cell_pruning.hpp): the program read back into a tree, each operation's
// pruning rule, and the cell hierarchy built level by level on worker threads.
#include "sdf/cell_pruning.hpp"

#include "sdf/cpu_eval.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/sdf_functions.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>
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
    float slack = 0.0f;                         // added to every interval (rounding)
};

struct CellResult {
    PrunedTree pruned;
    std::vector<std::uint32_t> list; // instruction indices, postfix
    int leaves = 0;
    bool far = false;  // a far cell's constant (SdfCellOptions::farConstants)
    bool near = false; // the surface may be within the cell's edge of it
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

// Prunes `in` to the cell of centre c and edge length `edge`; `constants` are the far cells'
// kFarSteps constants of the cell's level (instruction indices).
void pruneCell(const Pruner& pr, const PrunedTree& in, glm::vec3 c, float edge,
               const std::uint32_t* constants, int shortLeaves, CellResult& out,
               std::vector<float>& value, std::vector<SdfInterval>& range,
               std::vector<SdfPruneSide>& side) {
    const std::size_t n = in.size();
    const float r = 0.8660254f * edge; // half the diagonal
    value.resize(n);
    range.resize(n);
    side.assign(n, SdfPruneSide::Both);
    for (std::size_t i = 0; i < n; ++i) {
        const PrunedNode& pn = in[i];
        const TreeNode& t = pr.tree.nodes[std::size_t(pn.node)];
        const auto around = [&](float v) {
            const float e = r + pr.slack + 1e-6f * std::abs(v);
            return SdfInterval{v - e, v + e};
        };
        switch (t.kind) {
        case NodeKind::Leaf: {
            const float v = t.end - t.begin == 1
                                ? sdfLeafDistance(pr.program, pr.code[t.begin], c)
                                : sdfDistanceOrdered(
                                      pr.program, pr.code,
                                      std::span(pr.identity).subspan(t.begin, t.end - t.begin), c);
            value[i] = v;
            range[i] = around(v);
            break;
        }
        case NodeKind::Unary: {
            const GpuSdfInstruction& in4 = pr.code[t.instruction];
            const float v = modifierOfKind(ModifierStage::Distance, in4.kind)
                                .changeDistance(value[std::size_t(pn.a)], c, in4.params);
            value[i] = v;
            range[i] = around(v);
            break;
        }
        case NodeKind::Combine: {
            const GpuSdfInstruction& in4 = pr.code[t.instruction];
            const SdfOp op = SdfOp(in4.kind);
            const std::size_t a = std::size_t(pn.a), b = std::size_t(pn.b);
            // Chains of plain unions are pruned as one n-ary union when emitted (below).
            if (op != SdfOp::Union)
                side[i] = sdfOperationPrune(op, range[a], range[b], in4.params[0].x);
            if (side[i] == SdfPruneSide::A) {
                value[i] = value[a];
                range[i] = range[a];
            } else if (side[i] == SdfPruneSide::B) {
                value[i] = value[b];
                range[i] = range[b];
            } else {
                float w = 0.0f;
                value[i] = sdfCombine(op, value[a], value[b], in4.params[0], w);
                range[i] = sdfOperationInterval(op, range[a], range[b], in4.params[0]);
            }
            break;
        }
        }
    }
    out.pruned.clear();
    out.list.clear();
    out.leaves = 0;
    // Emit what is kept, operands first.
    const auto isUnion = [&](int i) {
        const TreeNode& t = pr.tree.nodes[std::size_t(in[std::size_t(i)].node)];
        return t.kind == NodeKind::Combine && SdfOp(pr.code[t.instruction].kind) == SdfOp::Union;
    };
    const auto emit = [&](auto& self, int i) -> int {
        const PrunedNode& pn = in[std::size_t(i)];
        const TreeNode& t = pr.tree.nodes[std::size_t(pn.node)];
        if (isUnion(i)) {
            // A chain of plain unions ((o1 u o2) u o3) ...: an operand drops where it is above
            // another operand everywhere in the cell (above the least upper bound); the kept
            // ones are united in their order with the chain's own union nodes, bottom up.
            std::vector<int> chain; // union nodes, top down
            int bottom = i;
            for (; isUnion(bottom); bottom = in[std::size_t(bottom)].a)
                chain.push_back(bottom);
            std::vector<int> operands{bottom};
            for (auto it = chain.rbegin(); it != chain.rend(); ++it)
                operands.push_back(in[std::size_t(*it)].b);
            float leastHi = INFINITY;
            for (int o : operands)
                leastHi = std::min(leastHi, range[std::size_t(o)].hi);
            int result = -1;
            std::size_t used = 0;
            for (int o : operands) {
                if (range[std::size_t(o)].lo > leastHi) continue;
                const int e = self(self, o);
                if (result < 0) {
                    result = e;
                    continue;
                }
                const int node = in[std::size_t(chain[chain.size() - 1 - used++])].node;
                out.list.push_back(pr.tree.nodes[std::size_t(node)].instruction);
                out.pruned.push_back({node, result, e});
                result = int(out.pruned.size()) - 1;
            }
            return result;
        }
        if (t.kind == NodeKind::Combine && side[std::size_t(i)] != SdfPruneSide::Both)
            return self(self, side[std::size_t(i)] == SdfPruneSide::A ? pn.a : pn.b);
        PrunedNode kept{pn.node, -1, -1};
        if (t.kind == NodeKind::Leaf) {
            for (std::uint32_t k = t.begin; k < t.end; ++k)
                out.list.push_back(k);
            out.leaves += t.leaves;
        } else {
            kept.a = self(self, pn.a);
            if (t.kind == NodeKind::Combine) kept.b = self(self, pn.b);
            out.list.push_back(t.instruction);
        }
        out.pruned.push_back(kept);
        return int(out.pruned.size()) - 1;
    };
    emit(emit, int(n) - 1);
    out.near = range[n - 1].lo < edge;
    // A far cell whose program is long takes a constant lower bound instead (shortLeaves < 0:
    // never; soft shadows and the cone pass read the values, so the renderer keeps them exact).
    out.far = shortLeaves >= 0 && range[n - 1].lo >= edge;
    if (out.far && out.leaves > shortLeaves) {
        const int m = std::min(int(range[n - 1].lo / edge), kFarSteps);
        out.pruned.clear();
        out.list.assign(1, constants[m - 1]);
        out.leaves = 1;
    }
}

// The value-stack depth a list needs.
int stackDepth(const std::vector<GpuSdfInstruction>& code, std::span<const std::uint32_t> list) {
    int top = 0, most = 0;
    for (std::uint32_t i : list) {
        if (isLeafOpcode(code[i].opcode))
            most = std::max(most, ++top);
        else if (SdfOpcode(code[i].opcode) == SdfOpcode::Combine)
            --top;
    }
    return most;
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

// The whole program's list (the identity) after everything else, for points outside the grid.
void appendOutsideList(SdfCellGrid& grid, std::size_t instructions, std::uint32_t first = 0) {
    grid.outsideOffset = std::uint32_t(grid.words.size());
    grid.outsideLength = std::uint32_t(instructions);
    for (std::uint32_t i = 0; i < instructions; ++i)
        grid.words.push_back(first + i);
}

} // namespace

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
    std::vector<std::uint32_t> constants; // kFarSteps per level
    SdfCellOptions options;
    // Where the program run outside the grid starts in `code` and its length: the program
    // itself, or the one given to run there (after the constants).
    std::uint32_t outsideFirst = 0, outsideLength = 0;
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
};

void SdfCellStateDeleter::operator()(SdfCellState* state) const {
    delete state;
}

namespace {

float cellEdge(const SdfCellState& s, int level) {
    return s.size / float(1 << (2 * level));
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
    }
    s.blocks[b] = {level, first, std::move(parent), true};
    s.liveCells += 64;
    return b;
}

void freeBlock(SdfCellState& s, std::uint32_t b) {
    for (std::uint32_t k = 64 * b; k < 64 * b + 64; ++k)
        if (s.entries[2 * k] & kSdfCellRefined) freeBlock(s, s.entries[2 * k] & ~kSdfCellRefined);
    s.blocks[b].live = false;
    PrunedTree().swap(s.blocks[b].parent);
    s.freeBlocks.push_back(b);
    s.liveCells -= 64;
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
    if (stackDepth(s.code, r.list) > kSdfMaxStack) s.tooDeep = true;
    s.entries[2 * k] = storeList(s, r.list);
    s.entries[2 * k + 1] = std::uint32_t(r.list.size());
    s.cellLeaves[k] = std::uint32_t(r.leaves);
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
                        s, std::span(old).subspan(s.entries[2 * k], s.entries[2 * k + 1]));
    s.listsAtCompaction = s.lists.size();
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

// Prunes the cells of `pending` blocks level by level: each block's 64 cells from its parent
// tree. `fresh` blocks are new (every cell of theirs is made); in the others a refined cell's
// children are pruned again only when its new tree holds a node of `changed` or differs from
// its old one: a cell's program is a function of its parent's tree and of the values of that
// tree's nodes, so with the same tree and none of it changed it is what it was. (The tree
// itself is not enough alone: a node dropped in both may still have decided what was kept.)
void pruneBlocks(SdfCellState& s, std::vector<std::pair<std::uint32_t, bool>> pending,
                 const std::vector<char>& changed) {
    const Pruner pruner{s.program, s.code, s.tree, s.identity, 1e-5f * s.size};
    const SdfCellOptions& o = s.options;
    const int threadCount =
        o.threads > 0 ? o.threads : std::max(1, int(std::thread::hardware_concurrency()));
    // A level's blocks a part at a time: the results of a part are all in memory at once.
    constexpr std::size_t kPartBlocks = 2048;
    while (!pending.empty()) {
        std::vector<std::pair<std::uint32_t, bool>> children;
        for (std::size_t first = 0; first < pending.size(); first += kPartBlocks) {
            const std::span<const std::pair<std::uint32_t, bool>> part(
                pending.data() + first, std::min(kPartBlocks, pending.size() - first));
            const std::size_t cellCount = 64 * part.size();
            s.prunedCells += cellCount;
            std::vector<CellResult> results(cellCount);
            std::atomic<std::size_t> next{0};
            const auto work = [&] {
                std::vector<float> value;
                std::vector<SdfInterval> range;
                std::vector<SdfPruneSide> side;
                for (std::size_t t; (t = next.fetch_add(1)) < cellCount;) {
                    const SdfCellState::Block& block = s.blocks[part[t / 64].first];
                    const int j = int(t % 64);
                    const glm::ivec3 cell = block.first + glm::ivec3(j % 4, (j / 4) % 4, j / 16);
                    const float edge = cellEdge(s, block.level);
                    const glm::vec3 centre = s.origin + (glm::vec3(cell) + 0.5f) * edge;
                    pruneCell(pruner, block.parent, centre, edge,
                              &s.constants[std::size_t(kFarSteps * (block.level - 1))],
                              o.farConstants ? o.refineLeaves : -1, results[t], value, range, side);
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

            // Cells to refine anew: within the cell budget, those near the surface first, then
            // those with the most shapes.
            std::vector<std::size_t> candidates;
            for (std::size_t t = 0; t < cellCount; ++t) {
                const auto [b, fresh] = part[t / 64];
                const std::uint32_t k = 64 * b + std::uint32_t(t % 64);
                CellResult& r = results[t];
                const bool refine =
                    s.blocks[b].level < s.levels && !r.far && r.leaves > o.refineLeaves;
                const bool wasRefined = !fresh && (s.entries[2 * k] & kSdfCellRefined);
                if (wasRefined) {
                    const std::uint32_t child = s.entries[2 * k] & ~kSdfCellRefined;
                    if (refine) {
                        if (holdsChanged(r.pruned, changed) ||
                            !sameTree(s.blocks[child].parent, r.pruned)) {
                            s.blocks[child].parent = std::move(r.pruned);
                            children.push_back({child, false});
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
                const auto [b, fresh] = part[t / 64];
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
                children.push_back({child, true});
            }
            if (!s.keepTrees)
                for (const auto& [b, fresh] : part)
                    PrunedTree().swap(s.blocks[b].parent);
        }
        // Blocks in order, as a full build makes them (the next level's cells likewise).
        std::sort(children.begin(), children.end());
        pending = std::move(children);
    }
}

// The grid as the GPU reads it: the cell entries, the lists after them (offsets made absolute),
// the whole program's list last; and its statistics.
void packGrid(const SdfCellState& s, SdfCellGrid& grid) {
    grid.code = s.code;
    grid.stats = {};
    if (s.tooDeep) { // a pruned part deeper than the stack (the fold of accumulated parts)
        grid.levels = 0;
        grid.code = s.program.instructions;
        grid.words.clear();
        appendOutsideList(grid, s.program.instructions.size());
        return;
    }
    grid.levels = s.levels;
    grid.origin = s.origin;
    grid.size = s.size;
    const std::uint32_t base = std::uint32_t(s.entries.size());
    grid.words.resize(s.entries.size() + s.lists.size());
    grid.stats.cellsPerLevel.assign(std::size_t(s.levels), 0);
    long totalLength = 0, totalLeaves = 0;
    for (std::uint32_t b = 0; b < s.blocks.size(); ++b) {
        if (!s.blocks[b].live) {
            std::fill_n(grid.words.begin() + 128 * b, 128, 0u);
            continue;
        }
        grid.stats.cellsPerLevel[std::size_t(s.blocks[b].level - 1)] += 64;
        for (std::uint32_t k = 64 * b; k < 64 * b + 64; ++k) {
            const std::uint32_t e = s.entries[2 * k], length = s.entries[2 * k + 1];
            grid.words[2 * k] = e & kSdfCellRefined ? e : e + base;
            grid.words[2 * k + 1] = length;
            if (e & kSdfCellRefined) continue;
            ++grid.stats.leafCells;
            totalLength += long(length);
            totalLeaves += long(s.cellLeaves[k]);
            grid.stats.maxLength = std::max(grid.stats.maxLength, int(length));
        }
    }
    while (!grid.stats.cellsPerLevel.empty() && grid.stats.cellsPerLevel.back() == 0)
        grid.stats.cellsPerLevel.pop_back();
    std::copy(s.lists.begin(), s.lists.end(), grid.words.begin() + base);
    appendOutsideList(grid, s.outsideLength, s.outsideFirst);
    grid.stats.uniquePrograms = s.uniquePrograms;
    grid.stats.prunedCells = s.prunedCells;
    grid.stats.meanLength = grid.stats.leafCells ? double(totalLength) / grid.stats.leafCells : 0.0;
    grid.stats.meanLeaves = grid.stats.leafCells ? double(totalLeaves) / grid.stats.leafCells : 0.0;
    grid.stats.bytes = grid.words.size() * sizeof(std::uint32_t);
}

// `outside` after the constants (when it reads the same data as the program: a bounding
// hierarchy orders the same parts otherwise), else the program itself, for points outside.
void setOutsideProgram(SdfCellState& s, std::size_t treeCode, const SdfProgram* outside) {
    s.code.resize(treeCode);
    if (outside && !outside->instructions.empty() && outside->data == s.program.data) {
        s.outsideFirst = std::uint32_t(treeCode);
        s.outsideLength = std::uint32_t(outside->instructions.size());
        s.code.insert(s.code.end(), outside->instructions.begin(), outside->instructions.end());
    } else {
        s.outsideFirst = 0;
        s.outsideLength = std::uint32_t(s.program.instructions.size());
    }
    s.identity.resize(s.code.size());
    std::iota(s.identity.begin(), s.identity.end(), 0u);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

SdfCellGrid buildSdfCells(const SdfProgram& program, const Aabb& content,
                          const SdfCellOptions& options, SdfCellStatePtr* keep,
                          const SdfProgram* outside) {
    const auto started = std::chrono::steady_clock::now();
    if (keep) keep->reset();
    SdfCellGrid grid;
    grid.code = program.instructions;
    if (content.empty() || program.instructions.empty() || options.levels < 1) {
        appendOutsideList(grid, program.instructions.size());
        return grid;
    }
    SdfCellStatePtr state(new SdfCellState);
    SdfCellState& s = *state;
    s.program = program;
    s.code = program.instructions;
    s.options = options;
    s.keepTrees = keep != nullptr;
    // The union the accumulated parts of a bounding hierarchy are folded with.
    GpuSdfInstruction unite;
    unite.opcode = std::uint32_t(SdfOpcode::Combine);
    unite.kind = std::uint32_t(SdfOp::Union);
    const std::uint32_t unionInstruction = std::uint32_t(s.code.size());
    s.code.push_back(unite);
    if (!readTree(program.instructions, unionInstruction, s.tree) || s.tree.nodes.empty()) {
        appendOutsideList(grid, program.instructions.size());
        return grid;
    }
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
    setOutsideProgram(s, s.code.size(), outside);

    PrunedTree whole(s.tree.nodes.size());
    for (std::size_t i = 0; i < s.tree.nodes.size(); ++i)
        whole[i] = {int(i), s.tree.nodes[i].a, s.tree.nodes[i].b};
    allocateBlock(s, 1, glm::ivec3(0), std::move(whole));
    pruneBlocks(s, {{0u, true}}, std::vector<char>(s.tree.nodes.size(), 0));
    s.listsAtCompaction = s.lists.size();
    packGrid(s, grid);
    grid.stats.buildMs = millisecondsSince(started);
    if (keep && !s.tooDeep) *keep = std::move(state);
    return grid;
}

bool repruneSdfCells(SdfCellState& s, const SdfProgram& edited, SdfCellGrid& grid,
                     const SdfProgram* outside) {
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
    s.program.data = edited.data;
    std::copy(after.begin(), after.end(), s.code.begin());
    std::copy(after.begin(), after.end(), s.program.instructions.begin());
    setOutsideProgram(s, s.constants.back() + 1, outside);
    s.prunedCells = 0;
    if (any) {
        pruneBlocks(s, {{0u, false}}, changed);
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
        if (!(e & kSdfCellRefined)) return {e, grid.words[w + 1], level + 1};
        block = e & ~kSdfCellRefined;
    }
    return outside;
}

std::span<const std::uint32_t> sdfCellProgram(const SdfCellGrid& grid, glm::vec3 p) {
    if (grid.levels == 0) return {};
    const SdfCellRange r = sdfCellRange(grid, p);
    return std::span(grid.words).subspan(r.offset, r.length);
}

} // namespace rmsc
