// The worst-case cost of a prepared scene's SDF objects, and the refusal over the budget: see
// prepare/sdf_cost.hpp.
#include "prepare/sdf_cost.hpp"

#include "core/limits.hpp"
#include "core/object_ids.hpp"
#include "prepare/prepared_scene.hpp"
#include "sdf/cost_model.hpp"
#include "sdf/glsl_codegen.hpp"

#include <cstring>

namespace rmsc {
namespace {

void take(SdfSceneCost& cost, const SdfEvaluationCost& part, const SdfProgram& main) {
    cost.perStep += part.perEvaluation;
    if (part.costliestCost <= cost.costliestCost || part.costliestId < kSdfIdBase) return;
    const std::size_t index = part.costliestId - kSdfIdBase;
    cost.costliestPointer = index < main.nodePointers.size() ? main.nodePointers[index] : "/sdf";
    cost.costliestCost = part.costliestCost;
    cost.costliestEvaluations = part.costliestEvaluations;
}

} // namespace

bool checkSdfCost(PreparedScene& prepared, Diagnostics& diagnostics) {
    SdfSceneCost cost;
    const SdfProgram& main = prepared.sdf;
    const double steps = double(prepared.scene.render.maxSteps);
    cost.generatedStatements = sdfGeneratedStatements(main);
    // Shells are always generated code; a pixel may march every one of them.
    for (const PreparedShell& shell : prepared.shells)
        take(cost, sdfEvaluationCost(shell.compiled.program.instructions), main);
    const SdfSceneCost shells = cost;
    take(cost, sdfEvaluationCost(main.instructions), main);
    if (cost.perStep * steps > double(limits::kSdfPixelCost) && !main.instructions.empty() &&
        effectiveSdfStrategy(main, SdfStrategy::Baked) == SdfStrategy::Cells) {
        // Drawn by the per-cell programs: a step costs the longest of them.
        auto grid = std::make_shared<SdfCellGrid>(
            buildSdfCells(main, prepared.scene.sdf ? sdfContentBox(*prepared.scene.sdf) : Aabb{}));
        if (grid->levels > 0) {
            cost = shells;
            cost.generatedStatements = sdfGeneratedStatements(main);
            cost.cells = true;
            take(cost, sdfCellsCost(*grid), main);
            prepared.sdfCells = std::move(grid);
        }
    }
    cost.drawnByCells = !main.instructions.empty() &&
                        effectiveSdfStrategy(main, SdfStrategy::Baked) == SdfStrategy::Cells;
    cost.perPixel = cost.perStep * steps;
    prepared.sdfCost = cost;
    if (cost.perPixel <= double(limits::kSdfPixelCost)) return true;
    const std::string where = cost.costliestPointer.empty() ? "/sdf" : cost.costliestPointer;
    const std::string evaluated =
        cost.costliestEvaluations > 1
            ? ", its shape evaluated " + std::to_string(cost.costliestEvaluations) + " times"
            : "";
    diagnostics.error(prepared.scene.file.string(), where,
                      "the SDF objects cost up to " + costText(cost.perPixel) +
                          " instructions a pixel (" + costText(cost.perStep) + " a march step" +
                          (cost.cells ? " in the costliest cell" : "") + " times max_steps " +
                          std::to_string(prepared.scene.render.maxSteps) +
                          "), over the budget of " + costText(double(limits::kSdfPixelCost)) +
                          " (the limit \"SDF cost per pixel\"); this node costs most: " +
                          costText(cost.costliestCost) + " a step" + evaluated +
                          " (a neighbour-checked repetition evaluates its content once per "
                          "cell, nested ones multiply; a fractal costs its iterations); lower "
                          "max_steps or simplify it");
    return false;
}

std::string sdfCostSummary(const SdfSceneCost& cost, int maxSteps) {
    return "SDF cost: " + costText(cost.perStep) + " instructions a march step" +
           (cost.cells ? " (the longest cell program)" : "") + ", " + costText(cost.perPixel) +
           " a pixel at max_steps " + std::to_string(maxSteps) + " (budget " +
           costText(double(limits::kSdfPixelCost)) + "), " +
           std::to_string(cost.generatedStatements) + " statements of generated code" +
           (cost.drawnByCells ? " (drawn by its per-cell programs instead)" : "");
}

} // namespace rmsc
