// The worst-case cost of drawing a prepared scene's SDF objects (sdf/cost_model.hpp): what one
// march step costs with the strategy the scene is drawn with by default (generated code, or the
// per-cell programs above the generated-code limits), the scene's shells included, and what a
// pixel costs at the scene's max_steps. A scene over limits::kSdfPixelCost is refused, naming
// the node that costs most, so that no scene file can make a frame run for minutes (or trip a
// GPU driver's watchdog). Explicitly requested strategies (`--sdf-strategy interpreter`) are the
// caller's choice and are not checked.
#pragma once

#include "core/diagnostics.hpp"

#include <string>

namespace rmsc {

struct PreparedScene;

struct SdfSceneCost {
    bool cells = false;           // the step cost is that of the longest per-cell program
    double perStep = 0.0;         // worst case, in instructions (sdfInstructionCost)
    double perPixel = 0.0;        // perStep times max_steps
    long generatedStatements = 0; // of the scene's program (the generated strategies' size)
    bool drawnByCells = false;    // the default strategy falls back to the per-cell programs
    std::string costliestPointer; // the node that costs most, "" without an SDF tree
    double costliestCost = 0.0;
    long costliestEvaluations = 0;
};

// Computes the cost of `prepared` (pruning its program into cells when only the cells keep it
// within the budget: the grid is kept in prepared.sdfCells for the renderer) and refuses it,
// with an error at the costliest node, when the pixel cost is over the budget. False if refused.
bool checkSdfCost(PreparedScene& prepared, Diagnostics& diagnostics);

// "SDF cost: 1.2 k instructions a march step (the longest cell program), 310 k a pixel at
// max_steps 256": the line `rmsc validate` prints.
std::string sdfCostSummary(const SdfSceneCost& cost, int maxSteps);

} // namespace rmsc
