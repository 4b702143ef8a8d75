// The SDF cost model (sdf/cost_model.hpp) and the cost check of prepared scenes
// (prepare/sdf_cost.hpp): instruction costs, neighbour checks and fractal iterations multiplying
// a step, the node that costs most, the cells' longest program standing for a large scene's
// step, the generated-code budget sending long programs to the cells, and the refusal of a
// scene over the pixel budget at the costliest node.
#include "prepare/prepared_scene.hpp"
#include "prepare/sdf_cost.hpp"
#include "scene/scene_json.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/cost_model.hpp"
#include "sdf/glsl_codegen.hpp"
#include "sdf_text.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace rmsc;

namespace {

// A sphere inside `depth` groups, each repeating its child on three axes with the neighbour
// check (eight cells each).
std::string nestedRepeats(int depth) {
    std::string node = R"({"shape": "sphere", "radius": 0.2})";
    for (int i = 0; i < depth; ++i)
        node = R"({"op": "union", "modifiers": [{"type": "repeat", "period": [1, 1, 1],
                   "neighbours": true}], "children": [)" +
               node + "]}";
    return node;
}

std::string unionOf(int count, const std::string& modifiers) {
    std::string children;
    for (int i = 0; i < count; ++i) {
        if (i) children += ",";
        children += R"({"shape": "sphere", "radius": 0.3, "position": [)" + std::to_string(i % 20) +
                    ", 0, " + std::to_string(i / 20) + "]" + modifiers + "}";
    }
    return R"({"op": "union", "children": [)" + children + "]}";
}

std::optional<PreparedScene> openText(const std::string& sceneText, Diagnostics& diagnostics) {
    std::optional<Scene> scene = parseScene(sceneText, "cost.json", diagnostics);
    if (!scene) return std::nullopt;
    std::optional<PreparedScene> prepared =
        prepareScene(std::move(*scene), diskFileSource(), diagnostics);
    if (prepared && !checkSdfCost(*prepared, diagnostics)) return std::nullopt;
    return prepared;
}

} // namespace

TEST(SdfCostModel, PlainInstructionsCostOneEach) {
    const SdfProgram sphere = test::compileSdfText(R"({"shape": "sphere"})");
    EXPECT_DOUBLE_EQ(sdfEvaluationCost(sphere.instructions).perEvaluation, 1.0);
    const SdfProgram pair = test::compileSdfText(
        R"({"op": "smooth_union", "smoothness": 0.1, "children": [{"shape": "sphere"},
            {"shape": "box", "position": [1, 0, 0]}]})");
    EXPECT_DOUBLE_EQ(sdfEvaluationCost(pair.instructions).perEvaluation,
                     3.0); // two shapes, a combine
}

TEST(SdfCostModel, FractalsCostTheirIterations) {
    for (int iterations : {1, 8, 16}) {
        const SdfProgram bulb = test::compileSdfText(R"({"shape": "mandelbulb", "iterations": )" +
                                                     std::to_string(iterations) + "}");
        EXPECT_DOUBLE_EQ(sdfEvaluationCost(bulb.instructions).perEvaluation, double(iterations));
    }
}

TEST(SdfCostModel, NeighbourChecksMultiplyAndTheInnermostRepetitionIsNamed) {
    const SdfProgram one = test::compileSdfText(nestedRepeats(1));
    const SdfProgram four = test::compileSdfText(nestedRepeats(4));
    const SdfEvaluationCost cost = sdfEvaluationCost(four.instructions);
    // Every instruction once: the program is straight-line, the copies are emitted.
    EXPECT_DOUBLE_EQ(cost.perEvaluation, double(four.instructions.size()));
    EXPECT_GT(cost.perEvaluation, 20000.0); // the issue's "about 22,000 instructions per step"
    EXPECT_GT(cost.perEvaluation, 400.0 * sdfEvaluationCost(one.instructions).perEvaluation);
    // The innermost repetition costs most: its point frames, cell moves and unions of eight
    // cells, run 8^3 times by the repetitions around it (the sphere is evaluated 8^4 times but
    // is one instruction a copy).
    ASSERT_GE(cost.costliestId, kSdfIdBase);
    EXPECT_EQ(four.nodePointers[cost.costliestId - kSdfIdBase],
              "/sdf/children/0/children/0/children/0");
    EXPECT_EQ(cost.costliestEvaluations, 0); // a group: no shape of its own
    long sphereCopies = 0;
    for (const GpuSdfInstruction& in : four.instructions)
        sphereCopies += SdfOpcode(in.opcode) == SdfOpcode::Shape;
    EXPECT_EQ(sphereCopies, 4096);
    EXPECT_GT(cost.costliestCost, 3.0 * 4096.0);
}

TEST(SdfCostModel, GeneratedStatementsLeaveOutBoxTests) {
    const SdfProgram program = test::compileSdfText(unionOf(40, ""));
    long boxTests = 0;
    for (const GpuSdfInstruction& in : program.instructions)
        boxTests += SdfOpcode(in.opcode) == SdfOpcode::BoundSkip ||
                    SdfOpcode(in.opcode) == SdfOpcode::SeedBest;
    ASSERT_GT(boxTests, 0);
    EXPECT_EQ(sdfGeneratedStatements(program), long(program.instructions.size()) - boxTests);
}

TEST(SdfCostModel, LongGeneratedCodeGoesToTheCells) {
    // 150 spheres (well under the 160-shape limit) stay generated code; twisted, each is five
    // statements (point frame, twist, shape, point frame back, union) and the tree goes to the
    // cells.
    const SdfProgram plain = test::compileSdfText(unionOf(150, ""));
    const SdfProgram twisted = test::compileSdfText(
        unionOf(150, R"(, "modifiers": [{"type": "twist", "amount": 30, "radius": 0.3}])"));
    EXPECT_LE(sdfGeneratedStatements(plain), limits::kGeneratedCodeStatements);
    EXPECT_GT(sdfGeneratedStatements(twisted), limits::kGeneratedCodeStatements);
    EXPECT_EQ(effectiveSdfStrategy(plain, SdfStrategy::Baked), SdfStrategy::Baked);
    EXPECT_EQ(effectiveSdfStrategy(twisted, SdfStrategy::Baked), SdfStrategy::Cells);
    EXPECT_EQ(effectiveSdfStrategy(twisted, SdfStrategy::Buffer), SdfStrategy::Cells);
}

TEST(SdfCostModel, CellsCostTheirLongestProgram) {
    const SdfProgram program = test::compileSdfText(unionOf(300, ""));
    Diagnostics diagnostics;
    const std::optional<Scene> scene =
        parseScene(R"({"version": 1, "sdf": )" + unionOf(300, "") + "}", "grid.json", diagnostics);
    ASSERT_TRUE(scene);
    const SdfCellGrid grid = buildSdfCells(program, sdfContentBox(*scene->sdf));
    ASSERT_GT(grid.levels, 0);
    const SdfEvaluationCost cells = sdfCellsCost(grid);
    // Plain shapes and unions cost one each: the longest program's cost is its length.
    EXPECT_DOUBLE_EQ(cells.perEvaluation, double(grid.stats.maxLength));
    EXPECT_LT(cells.perEvaluation, sdfEvaluationCost(program.instructions).perEvaluation / 20.0);
    EXPECT_GE(cells.costliestId, kSdfIdBase);
}

TEST(SdfSceneCost, NestedNeighbourRepeatsAreRefusedAtTheCostliestNode) {
    Diagnostics diagnostics;
    EXPECT_FALSE(openText(R"({"version": 1, "sdf": )" + nestedRepeats(4) + "}", diagnostics));
    ASSERT_EQ(diagnostics.errorCount(), 1) << diagnostics.format();
    const Diagnostic& d = diagnostics.items[0];
    EXPECT_EQ(d.location, "/sdf/children/0/children/0/children/0");
    EXPECT_NE(d.message.find("\"SDF cost per pixel\""), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("times max_steps 256"), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("over the budget of 1.0 M"), std::string::npos) << d.message;
}

TEST(SdfSceneCost, AFractalCostsItsIterations) {
    // 16 mandelbulbs of 16 iterations: over 256 a step, over the budget at 4096 steps and
    // within it at 2048.
    std::string bulbs;
    for (int i = 0; i < 16; ++i)
        bulbs += std::string(i ? "," : "") + R"({"shape": "mandelbulb", "iterations": 16,
                 "position": [)" +
                 std::to_string(3 * i) + ", 0, 0]}";
    const std::string sdf = R"({"op": "union", "children": [)" + bulbs + "]}";
    Diagnostics over;
    EXPECT_FALSE(
        openText(R"({"version": 1, "render": {"max_steps": 4096}, "sdf": )" + sdf + "}", over));
    ASSERT_EQ(over.errorCount(), 1) << over.format();
    EXPECT_EQ(over.items[0].location.rfind("/sdf/children/", 0), 0u) << over.format();
    Diagnostics fits;
    EXPECT_TRUE(
        openText(R"({"version": 1, "render": {"max_steps": 2048}, "sdf": )" + sdf + "}", fits))
        << fits.format();
}

TEST(SdfSceneCost, TheBudgetIsPerPixelSoFewerStepsFit) {
    // The same tree at 32 steps a ray: 22 k x 32 is within the budget.
    Diagnostics diagnostics;
    const auto prepared =
        openText(R"({"version": 1, "render": {"max_steps": 32}, "sdf": )" + nestedRepeats(4) + "}",
                 diagnostics);
    ASSERT_TRUE(prepared) << diagnostics.format();
    EXPECT_FALSE(prepared->sdfCost.cells);
    EXPECT_DOUBLE_EQ(prepared->sdfCost.perPixel, prepared->sdfCost.perStep * 32.0);
    EXPECT_LE(prepared->sdfCost.perPixel, double(limits::kSdfPixelCost));
}

TEST(SdfSceneCost, LargeScenesAreCostedByTheirCellsAndKeepThem) {
    // 600 spheres: the whole program over the budget at 4096 steps, the cells within it.
    Diagnostics diagnostics;
    const auto prepared = openText(R"({"version": 1, "render": {"max_steps": 4096}, "sdf": )" +
                                       unionOf(600, "") + "}",
                                   diagnostics);
    ASSERT_TRUE(prepared) << diagnostics.format();
    EXPECT_GT(sdfEvaluationCost(prepared->sdf.instructions).perEvaluation * 4096.0,
              double(limits::kSdfPixelCost));
    EXPECT_TRUE(prepared->sdfCost.cells);
    ASSERT_TRUE(prepared->sdfCells);
    EXPECT_DOUBLE_EQ(prepared->sdfCost.perStep, double(prepared->sdfCells->stats.maxLength));
    EXPECT_LE(prepared->sdfCost.perPixel, double(limits::kSdfPixelCost));
}
