// Per-cell pruning (sdf/cell_pruning.hpp) against the whole program on the CPU evaluator: at
// random points of every cell of random trees (every operation, smooth ones included,
// modifiers, subtraction, cut children, planes), the cell's program gives the whole program's
// distance, object id and blended colour.
#include "sdf/cell_pruning.hpp"

#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"
#include "sdf/operations.hpp"
#include "sdf/sdf_functions.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

namespace rmsc {
namespace {

struct RandomTree {
    std::mt19937 rng;
    std::vector<std::string> ops = operationNames();

    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }

    std::string vec3(float lo, float hi) {
        std::ostringstream s;
        s << "[" << uniform(lo, hi) << ", " << uniform(lo, hi) << ", " << uniform(lo, hi) << "]";
        return s.str();
    }

    std::string transform() {
        std::ostringstream s;
        s << "\"position\": " << vec3(-1.5f, 1.5f);
        if (pick(2)) s << ", \"rotation\": " << vec3(-90.0f, 90.0f);
        if (pick(3) == 0) s << ", \"scale\": " << uniform(0.5f, 1.5f);
        return s.str();
    }

    std::string modifiers() {
        switch (pick(8)) {
        case 0:
            return R"(, "modifiers": [{"type": "round", "radius": 0.05}])";
        case 1:
            return R"(, "modifiers": [{"type": "onion", "thickness": 0.04}])";
        case 2:
            return R"(, "modifiers": [{"type": "twist", "amount": 40, "radius": 0.6}])";
        case 3:
            return R"(, "modifiers": [{"type": "repeat", "period": [0.9, 0, 0.9], "count": [3, 0, 2], "neighbours": true}])";
        case 4:
            return R"(, "modifiers": [{"type": "mirror", "axes": "x"}])";
        default:
            return "";
        }
    }

    std::string shape() {
        std::ostringstream s;
        s << "{";
        switch (pick(4)) {
        case 0:
            s << R"("shape": "sphere", "radius": )" << uniform(0.1f, 0.5f);
            break;
        case 1:
            s << R"("shape": "box", "half_extents": )" << vec3(0.1f, 0.4f);
            break;
        case 2:
            s << R"("shape": "torus", "major_radius": )" << uniform(0.2f, 0.4f)
              << R"(, "minor_radius": )" << uniform(0.05f, 0.15f);
            break;
        default:
            s << R"("shape": "capsule", "half_height": )" << uniform(0.1f, 0.4f)
              << R"(, "radius": )" << uniform(0.05f, 0.2f);
        }
        s << ", " << transform() << ", \"material\": \"m" << pick(3) << "\"" << modifiers() << "}";
        return s.str();
    }

    std::string group(int depth) {
        std::ostringstream s;
        const std::string& op = ops[std::size_t(pick(int(ops.size())))];
        s << R"({"op": ")" << op << "\"";
        if (takesSmoothness(findOperation(op)->op))
            s << ", \"smoothness\": " << uniform(0.05f, 0.3f);
        if (takesBlend(findOperation(op)->op) && pick(2)) s << R"(, "blend": "circular")";
        if (pick(2)) s << ", " << transform();
        s << ", \"children\": [";
        const int n = 2 + pick(3);
        for (int i = 0; i < n; ++i) {
            if (i) s << ", ";
            std::string child = depth > 0 && pick(2) ? group(depth - 1) : shape();
            if (i > 0 && pick(6) == 0) child.insert(1, "\"cut\": true, ");
            s << child;
        }
        s << "]}";
        return s.str();
    }
};

struct Compiled {
    Scene scene;
    SdfProgram program;
};

std::optional<Compiled> compileText(const std::string& sdf, bool bounds) {
    Diagnostics diagnostics;
    const std::string text = R"({"version": 1, "materials": {"m0": {"base_color": "#ff0000"},
        "m1": {"base_color": "#00ff00"}, "m2": {"base_color": "#0000ff"}}, "sdf": )" +
                             sdf + "}";
    std::optional<Scene> scene = parseScene(text, "t.json", diagnostics);
    if (!scene || !scene->sdf) return std::nullopt;
    SdfCompileOptions options;
    options.bounds = bounds;
    std::optional<SdfProgram> program = compileSdf(*scene->sdf, 3, "t.json", diagnostics, options);
    if (!program) return std::nullopt;
    return Compiled{std::move(*scene), std::move(*program)};
}

std::vector<Material> testMaterials() {
    std::vector<Material> m(4);
    m[0].baseColor = {1, 0, 0};
    m[1].baseColor = {0, 1, 0};
    m[2].baseColor = {0, 0, 1};
    return m;
}

// Every point p of the grid: the cell's program against the whole one. Returns points checked.
int expectCellsAgree(const Compiled& c, const SdfCellGrid& grid, std::mt19937& rng, int samples,
                     const std::string& what) {
    const std::vector<Material> materials = testMaterials();
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int checked = 0;
    // Candidates everywhere; those near the surface (where pruning decides what is seen) all
    // checked, one in ten of the others.
    for (int s = 0; s < 10 * samples && checked < samples; ++s) {
        const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
        const SdfCellRange range = sdfCellRange(grid, p);
        const std::span<const std::uint32_t> list =
            std::span(grid.words).subspan(range.offset, range.length);
        const float edge = grid.size / float(1 << (2 * range.level));
        const float whole = sdfDistance(c.program, p);
        if (std::abs(whole) > edge && s % 10 != 0) continue;
        const float pruned = sdfDistanceOrdered(c.program, grid.code, list, p);
        if (whole >= edge) { // may be a far cell's bound: never above the distance
            EXPECT_LE(pruned, whole + 1e-5f * (1.0f + std::abs(whole))) << what;
            EXPECT_GT(pruned, 0.0f) << what;
            if (::testing::Test::HasFailure()) return checked;
            ++checked;
            continue;
        }
        EXPECT_NEAR(pruned, whole, 1e-5f * (1.0f + std::abs(whole)))
            << what << " at " << p.x << " " << p.y << " " << p.z << ", cell program of "
            << list.size() << " instructions";
        const SdfSurface a = sdfSurface(c.program, materials, p);
        const SdfSurface b = sdfSurfaceOrdered(c.program, grid.code, list, materials, p);
        EXPECT_EQ(a.objectId, b.objectId) << what;
        EXPECT_NEAR(glm::length(a.baseColor - b.baseColor), 0.0f, 1e-4f) << what;
        if (::testing::Test::HasFailure()) return checked;
        ++checked;
    }
    return checked;
}

TEST(CellPruning, RandomTreesAgreeWithTheWholeProgramInEveryCell) {
    RandomTree random{std::mt19937(20261201)};
    std::mt19937 points(7);
    int trees = 0, pruning = 0;
    for (int t = 0; t < 60; ++t) {
        std::string sdf = random.group(3);
        if (t % 3 == 0) // a plane under it: unbounded content
            sdf = R"({"children": [{"shape": "plane", "normal": [0, 1, 0], "offset": 1.2}, )" +
                  sdf + "]}";
        for (bool bounds : {false, true}) {
            const std::optional<Compiled> c = compileText(sdf, bounds);
            if (!c) continue; // e.g. a subtraction of only cut children
            const Aabb box = sdfContentBox(*c->scene.sdf);
            SdfCellOptions options;
            options.levels = 2;
            options.refineLeaves = 1;
            options.farConstants = t % 2 == 0; // both kinds of far cells
            const SdfCellGrid grid = buildSdfCells(c->program, box, options);
            if (grid.levels == 0) continue;
            ++trees;
            if (grid.stats.meanLength < double(c->program.instructions.size())) ++pruning;
            expectCellsAgree(*c, grid, points, 1000, sdf);
            if (HasFailure()) return;
        }
    }
    // The trees are pruned at all: most cells' programs are shorter than the whole.
    EXPECT_GT(trees, 80);
    EXPECT_GT(pruning, trees / 2);
}

// A grid of far-apart spheres: a cell holds a few, and its program has only those.
TEST(CellPruning, AGridOfSpheresPrunesToTheNearOnes) {
    std::ostringstream s;
    s << R"({"children": [)";
    for (int i = 0; i < 400; ++i)
        s << (i ? ", " : "") << R"({"shape": "sphere", "radius": 0.3, "position": [)"
          << (i % 20) - 10 << ", 0, " << (i / 20) - 10 << "]}";
    s << "]}";
    for (bool bounds : {false, true}) {
        const std::optional<Compiled> c = compileText(s.str(), bounds);
        ASSERT_TRUE(c);
        const SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf));
        ASSERT_EQ(grid.levels, SdfCellOptions{}.levels);
        EXPECT_LT(grid.stats.meanLeaves, 8.0);
        EXPECT_LT(grid.stats.maxLength, 40);
        std::mt19937 rng(3);
        EXPECT_EQ(expectCellsAgree(*c, grid, rng, 3000, "grid"), 3000);
    }
}

TEST(CellPruning, OperationRulesHoldAtTheirEdges) {
    // Union of a near and a far operand: only the near one where the far one cannot reach.
    EXPECT_EQ(sdfOperationPrune(SdfOp::Union, {2, 3}, {0, 1}, 0), SdfPruneSide::B);
    EXPECT_EQ(sdfOperationPrune(SdfOp::Union, {0.5f, 3}, {0, 1}, 0), SdfPruneSide::Both);
    // A smooth union needs the blend's width between them.
    EXPECT_EQ(sdfOperationPrune(SdfOp::SmoothUnion, {1.5f, 3}, {0, 1}, 0.4f), SdfPruneSide::B);
    EXPECT_EQ(sdfOperationPrune(SdfOp::SmoothUnion, {1.2f, 3}, {0, 1}, 0.4f), SdfPruneSide::Both);
    // A cut far outside the first operand's surface drops; one reaching into it does not.
    EXPECT_EQ(sdfOperationPrune(SdfOp::Subtraction, {-0.5f, 0.5f}, {1, 2}, 0), SdfPruneSide::A);
    EXPECT_EQ(sdfOperationPrune(SdfOp::Subtraction, {-0.5f, 0.5f}, {0.2f, 2}, 0),
              SdfPruneSide::Both);
    // For every rule: where it says an operand, sdfCombine equals that operand at sampled
    // points of the intervals.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f), w(0.0f, 1.5f), t(0.0f, 1.0f);
    int decided = 0;
    for (const OperationSpec& spec : operationCatalogue())
        for (int i = 0; i < 20000; ++i) {
            const float k = 0.05f + t(rng);
            const SdfInterval a{u(rng), 0}, b{u(rng), 0};
            const SdfInterval ia{a.lo, a.lo + w(rng)}, ib{b.lo, b.lo + w(rng)};
            const SdfPruneSide side = sdfOperationPrune(spec.op, ia, ib, k);
            if (side == SdfPruneSide::Both) continue;
            ++decided;
            const glm::vec4 params(k, 0, 0, 0);
            for (int j = 0; j < 8; ++j) {
                const float x = ia.lo + t(rng) * (ia.hi - ia.lo);
                const float y = ib.lo + t(rng) * (ib.hi - ib.lo);
                float weight = 0.0f;
                const float v = sdfCombine(spec.op, x, y, params, weight);
                const float expected = side == SdfPruneSide::A ? x : y;
                ASSERT_NEAR(v, expected, 1e-5f) << spec.name << " a " << x << " b " << y;
                if (spec.combination != SdfOpCombination::Subtraction) {
                    ASSERT_EQ(weight, side == SdfPruneSide::A ? 1.0f : 0.0f) << spec.name;
                }
            }
        }
    EXPECT_GT(decided, 50000);
}

} // namespace
} // namespace rmsc
