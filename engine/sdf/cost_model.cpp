// The cost model of a compiled SDF program: see sdf/cost_model.hpp.
#include "sdf/cost_model.hpp"

#include "core/object_ids.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/primitives.hpp"
#include "sdf/sdf_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace rmsc {
namespace {

// A shape whose catalogue row has an "iterations" parameter runs its loop that many times.
double shapeCost(const GpuSdfInstruction& in) {
    if (in.kind >= std::uint32_t(PrimitiveId::Count)) return 1.0;
    const PrimitiveSpec& spec = primitiveSpec(PrimitiveId(in.kind));
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
        if (spec.params[i].name != std::string_view("iterations")) continue;
        const int k = paramOffset(spec, int(i));
        const float iterations = in.params[k / 4][k % 4];
        return std::isfinite(iterations) ? std::max(1.0, std::floor(double(iterations))) : 1.0;
    }
    return 1.0;
}

struct Tally {
    double cost = 0.0;
    long evaluations = 0;
};

SdfEvaluationCost summarize(const std::unordered_map<std::uint32_t, Tally>& byNode, double total) {
    SdfEvaluationCost out;
    out.perEvaluation = total;
    for (const auto& [id, tally] : byNode)
        if (tally.cost > out.costliestCost ||
            (tally.cost == out.costliestCost && id < out.costliestId && tally.cost > 0.0)) {
            out.costliestId = id;
            out.costliestCost = tally.cost;
            out.costliestEvaluations = tally.evaluations;
        }
    return out;
}

void add(std::unordered_map<std::uint32_t, Tally>& byNode, double& total,
         const GpuSdfInstruction& in) {
    const double cost = sdfInstructionCost(in);
    total += cost;
    if (in.objectId < kSdfIdBase) return; // the bounding hierarchy's instructions: no node
    Tally& tally = byNode[in.objectId];
    tally.cost += cost;
    const SdfOpcode opcode = SdfOpcode(in.opcode);
    tally.evaluations += opcode == SdfOpcode::Shape || opcode == SdfOpcode::Profile;
}

} // namespace

double sdfInstructionCost(const GpuSdfInstruction& in) {
    switch (SdfOpcode(in.opcode)) {
    case SdfOpcode::Shape:
        return shapeCost(in);
    case SdfOpcode::Profile:
        return SdfProfileType(in.kind) == SdfProfileType::Polygon
                   ? 1.0 + std::floor(std::max(0.0, double(in.params[2].y)) / 4.0)
                   : 1.0;
    case SdfOpcode::DistanceModifier:
        return SdfDistanceModifierKind(in.kind) == SdfDistanceModifierKind::Displace ? 8.0 : 1.0;
    default:
        return 1.0;
    }
}

SdfEvaluationCost sdfEvaluationCost(std::span<const GpuSdfInstruction> code) {
    std::unordered_map<std::uint32_t, Tally> byNode;
    double total = 0.0;
    for (const GpuSdfInstruction& in : code)
        add(byNode, total, in);
    return summarize(byNode, total);
}

SdfEvaluationCost sdfEvaluationCost(std::span<const GpuSdfInstruction> code,
                                    std::span<const std::uint32_t> indices) {
    std::unordered_map<std::uint32_t, Tally> byNode;
    double total = 0.0;
    for (std::uint32_t i : indices)
        if (i < code.size()) add(byNode, total, code[i]);
    return summarize(byNode, total);
}

SdfEvaluationCost sdfCellsCost(const SdfCellGrid& grid) {
    SdfEvaluationCost worst;
    if (grid.levels == 0) return worst;
    std::unordered_set<std::uint32_t> seen; // list offsets already costed (cells share lists)
    std::vector<std::uint32_t> blocks{0};
    std::unordered_set<std::uint32_t> visitedBlocks{0};
    while (!blocks.empty()) {
        const std::size_t base = std::size_t(blocks.back()) * 128;
        blocks.pop_back();
        for (std::size_t c = 0; c < 64 && base + 2 * c + 1 < grid.words.size(); ++c) {
            const std::uint32_t entry = grid.words[base + 2 * c];
            if (entry & kSdfCellRefined) {
                const std::uint32_t block = entry & ~kSdfCellRefined;
                if (visitedBlocks.insert(block).second) blocks.push_back(block);
                continue;
            }
            const std::uint32_t length = grid.words[base + 2 * c + 1] & ~kSdfCellAffine;
            if (!seen.insert(entry).second || std::size_t(entry) + length > grid.words.size())
                continue;
            // The list and the grid's planes, which every point evaluates besides it.
            std::vector<std::uint32_t> evaluated(grid.words.begin() + entry,
                                                 grid.words.begin() + entry + length);
            for (const SdfCellPlane& plane : grid.planes)
                evaluated.push_back(plane.instruction);
            const SdfEvaluationCost cell = sdfEvaluationCost(grid.code, evaluated);
            if (cell.perEvaluation > worst.perEvaluation) worst = cell;
        }
    }
    return worst;
}

long sdfGeneratedStatements(const SdfProgram& program) {
    long statements = 0;
    for (const GpuSdfInstruction& in : program.instructions) {
        const SdfOpcode opcode = SdfOpcode(in.opcode);
        statements += opcode != SdfOpcode::BoundSkip && opcode != SdfOpcode::SeedBest;
    }
    return statements;
}

std::string costText(double cost) {
    char text[32];
    if (cost < 1e4)
        std::snprintf(text, sizeof text, "%.0f", cost);
    else if (cost < 1e6)
        std::snprintf(text, sizeof text, "%.1f k", cost / 1e3);
    else if (cost < 1e9)
        std::snprintf(text, sizeof text, "%.1f M", cost / 1e6);
    else
        std::snprintf(text, sizeof text, "%.1f G", cost / 1e9);
    return text;
}

} // namespace rmsc
