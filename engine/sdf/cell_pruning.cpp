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
void appendOutsideList(SdfCellGrid& grid, std::size_t instructions) {
    grid.outsideOffset = std::uint32_t(grid.words.size());
    grid.outsideLength = std::uint32_t(instructions);
    for (std::uint32_t i = 0; i < instructions; ++i)
        grid.words.push_back(i);
}

} // namespace

Aabb sdfContentBox(const SdfNode& root) {
    Aabb box;
    collectContent(root, glm::mat4(1.0f), box);
    return box;
}

SdfCellGrid buildSdfCells(const SdfProgram& program, const Aabb& content,
                          const SdfCellOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    SdfCellGrid grid;
    grid.code = program.instructions;
    if (content.empty() || program.instructions.empty() || options.levels < 1) {
        appendOutsideList(grid, program.instructions.size());
        return grid;
    }
    // The union the accumulated parts of a bounding hierarchy are folded with.
    GpuSdfInstruction unite;
    unite.opcode = std::uint32_t(SdfOpcode::Combine);
    unite.kind = std::uint32_t(SdfOp::Union);
    const std::uint32_t unionInstruction = std::uint32_t(grid.code.size());
    grid.code.push_back(unite);
    ProgramTree tree;
    if (!readTree(program.instructions, unionInstruction, tree) || tree.nodes.empty()) {
        grid.code = program.instructions;
        appendOutsideList(grid, program.instructions.size());
        return grid;
    }
    const int levels = std::clamp(options.levels, 1, 6);
    const glm::vec3 half = content.halfSize();
    const float extent = std::max(std::max(half.x, half.y), std::max(half.z, 1e-3f)) * 1.02f *
                         float(1 << (2 * std::clamp(options.outerLevels, 0, levels - 1)));
    grid.origin = content.center() - glm::vec3(extent);
    grid.size = 2.0f * extent;

    std::vector<std::uint32_t> constants; // kFarSteps per level
    for (int level = 1; level <= levels; ++level)
        for (int m = 1; m <= kFarSteps; ++m) {
            constants.push_back(std::uint32_t(grid.code.size()));
            grid.code.push_back(
                constantInstruction(float(m) * grid.size / float(1 << (2 * level))));
        }
    std::vector<std::uint32_t> identity(grid.code.size());
    std::iota(identity.begin(), identity.end(), 0u);
    const Pruner pruner{program, grid.code, tree, identity, 1e-5f * grid.size};

    PrunedTree whole(tree.nodes.size());
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
        whole[i] = {int(i), tree.nodes[i].a, tree.nodes[i].b};

    struct Task {
        glm::ivec3 cell; // at its level
        const PrunedTree* parent;
        std::size_t entry; // its entry in `entries` (2 words)
    };
    std::vector<std::uint32_t> entries(128, 0);
    std::vector<std::uint32_t> lists;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> shared; // hash -> offsets
    std::vector<Task> tasks;
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x)
                tasks.push_back({{x, y, z}, &whole, std::size_t(2 * (x + 4 * y + 16 * z))});
    std::vector<CellResult> previous; // the refined cells' results, parents of `tasks`
    long totalLength = 0, totalLeaves = 0;
    std::size_t cellCount = 64;
    bool tooDeep = false;
    const int threadCount = options.threads > 0
                                ? options.threads
                                : std::max(1, int(std::thread::hardware_concurrency()));
    for (int level = 1; level <= levels && !tasks.empty(); ++level) {
        grid.stats.cellsPerLevel.push_back(int(tasks.size()));
        const float cellSize = grid.size / float(1 << (2 * level));
        std::vector<CellResult> results(tasks.size());
        std::atomic<std::size_t> next{0};
        const auto work = [&] {
            std::vector<float> value;
            std::vector<SdfInterval> range;
            std::vector<SdfPruneSide> side;
            for (std::size_t t; (t = next.fetch_add(1)) < tasks.size();) {
                const glm::vec3 centre = grid.origin + (glm::vec3(tasks[t].cell) + 0.5f) * cellSize;
                pruneCell(pruner, *tasks[t].parent, centre, cellSize,
                          &constants[std::size_t(kFarSteps * (level - 1))],
                          options.farConstants ? options.refineLeaves : -1, results[t], value,
                          range, side);
                // Only cells that may be refined keep their pruned tree (memory: the finest
                // level holds most cells).
                if (level == levels || results[t].leaves <= options.refineLeaves)
                    PrunedTree().swap(results[t].pruned);
            }
        };
        std::vector<std::thread> workers;
        for (int w = 1; w < std::min(threadCount, int(tasks.size())); ++w)
            workers.emplace_back(work);
        work();
        for (std::thread& w : workers)
            w.join();

        std::vector<Task> children;
        std::vector<CellResult> refined;
        std::vector<std::size_t> refinedTasks; // with their blocks in order, from firstBlock
        const std::size_t firstBlock = entries.size() / 128;
        // Which cells to refine: those with more shapes than options.refineLeaves, within the
        // cell budget; cells near the surface first, then those with the most shapes.
        std::vector<std::size_t> candidates;
        for (std::size_t t = 0; t < tasks.size(); ++t)
            if (level < levels && !results[t].far && results[t].leaves > options.refineLeaves)
                candidates.push_back(t);
        std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
            const bool nearA = results[a].near, nearB = results[b].near;
            if (nearA != nearB) return nearA;
            if (results[a].leaves != results[b].leaves)
                return results[a].leaves > results[b].leaves;
            return a < b;
        });
        const std::size_t room =
            options.maxCells > cellCount ? (options.maxCells - cellCount) / 64 : 0;
        if (candidates.size() > room) candidates.resize(room);
        std::sort(candidates.begin(), candidates.end());
        cellCount += 64 * candidates.size();
        std::vector<bool> refine(tasks.size(), false);
        for (std::size_t t : candidates)
            refine[t] = true;
        for (std::size_t t = 0; t < tasks.size(); ++t) {
            CellResult& r = results[t];
            if (refine[t]) {
                entries[tasks[t].entry] =
                    kSdfCellRefined | std::uint32_t(firstBlock + refinedTasks.size());
                refinedTasks.push_back(t);
                refined.push_back(std::move(r));
                continue;
            }
            if (stackDepth(grid.code, r.list) > kSdfMaxStack) tooDeep = true;
            ++grid.stats.leafCells;
            totalLength += long(r.list.size());
            totalLeaves += r.leaves;
            grid.stats.maxLength = std::max(grid.stats.maxLength, int(r.list.size()));
            std::vector<std::uint32_t>& same = shared[hashList(r.list)];
            std::uint32_t offset = ~0u;
            for (std::uint32_t o : same)
                if (o + r.list.size() <= lists.size() &&
                    std::equal(r.list.begin(), r.list.end(), lists.begin() + o))
                    offset = o;
            if (offset == ~0u) {
                offset = std::uint32_t(lists.size());
                lists.insert(lists.end(), r.list.begin(), r.list.end());
                same.push_back(offset);
                ++grid.stats.uniquePrograms;
            }
            entries[tasks[t].entry] = offset; // made absolute below
            entries[tasks[t].entry + 1] = std::uint32_t(r.list.size());
        }
        // The refined cells' children, each refined cell's 64 in its block.
        entries.resize(entries.size() + 128 * refinedTasks.size(), 0);
        for (std::size_t k = 0; k < refinedTasks.size(); ++k) {
            const Task& parent = tasks[refinedTasks[k]];
            for (int z = 0; z < 4; ++z)
                for (int y = 0; y < 4; ++y)
                    for (int x = 0; x < 4; ++x)
                        children.push_back(
                            {parent.cell * 4 + glm::ivec3(x, y, z), &refined[k].pruned,
                             (firstBlock + k) * 128 + std::size_t(2 * (x + 4 * y + 16 * z))});
        }
        previous = std::move(refined); // keeps the parents alive for the next level
        tasks = std::move(children);
    }
    if (tooDeep) { // a pruned part deeper than the stack (the fold of accumulated parts)
        grid.code = program.instructions;
        grid.stats = {};
        appendOutsideList(grid, program.instructions.size());
        return grid;
    }
    // Lists after the entries; the whole program's list last.
    const std::uint32_t base = std::uint32_t(entries.size());
    for (std::size_t e = 0; e < entries.size(); e += 2)
        if (!(entries[e] & kSdfCellRefined)) entries[e] += base;
    grid.words = std::move(entries);
    grid.words.insert(grid.words.end(), lists.begin(), lists.end());
    appendOutsideList(grid, program.instructions.size());
    grid.levels = levels;
    grid.stats.meanLength = grid.stats.leafCells ? double(totalLength) / grid.stats.leafCells : 0.0;
    grid.stats.meanLeaves = grid.stats.leafCells ? double(totalLeaves) / grid.stats.leafCells : 0.0;
    grid.stats.bytes = grid.words.size() * sizeof(std::uint32_t);
    grid.stats.buildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    return grid;
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
