// Per-cell pruning (sdf/cell_pruning.hpp) against the whole program on the CPU evaluator: at
// random points of every cell of random trees (every operation, smooth ones included,
// modifiers, subtraction, cut children, planes), the cell's program gives the whole program's
// distance, object id and blended colour.
#include "sdf/cell_pruning.hpp"

#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"
#include "sdf/glsl_codegen.hpp"
#include "sdf/operations.hpp"
#include "sdf/sdf_functions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>
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
        const std::vector<GpuSdfInstruction> list = sdfCellProgram(grid, p);
        const float edge = grid.size / float(1 << (2 * range.level));
        const float whole = sdfDistance(c.program, p);
        if (std::abs(whole) > edge && s % 10 != 0) continue;
        const float pruned = sdfCellsDistance(c.program, grid, p);
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
        const SdfSurface b = sdfCellsSurface(c.program, grid, materials, p);
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

// Deep binary trees of unions and smooth unions over scattered spheres, as people build them
// (the bench trees): a subtree is dropped where it is above its threshold, the least upper end
// of what it competes with on the way to the root plus the blends' margins
// (operandThresholds), not only where its sibling is below it. Without far constants a cell's
// program is the whole program everywhere in the cell: distance, object id and colour at
// random points of the grid, near the surface or not.
TEST(CellPruning, DeepSmoothTreesDropWhatIsAboveItsThreshold) {
    std::mt19937 rng(20261205);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * u(rng); };
    // Spheres split in halves along x, y and z in turn (a k-d tree).
    const std::function<std::string(std::vector<glm::vec3>, int)> build =
        [&](std::vector<glm::vec3> centres, int depth) -> std::string {
        std::ostringstream s;
        if (centres.size() == 1) {
            const glm::vec3 p = centres[0];
            s << R"({"shape": "sphere", "radius": )" << uniform(0.1f, 0.25f) << R"(, "position": [)"
              << p.x << ", " << p.y << ", " << p.z << R"(], "material": "m)" << rng() % 3 << "\"}";
            return s.str();
        }
        const int axis = depth % 3;
        std::sort(centres.begin(), centres.end(),
                  [&](glm::vec3 l, glm::vec3 r) { return l[axis] < r[axis]; });
        const auto half = centres.begin() + std::ptrdiff_t(centres.size() / 2);
        const bool smooth = depth % 2 == 1 || rng() % 4 == 0;
        s << R"({"op": ")" << (smooth ? "smooth_union" : "union") << "\"";
        if (smooth) {
            s << R"(, "smoothness": )" << uniform(0.02f, 0.2f);
            if (rng() % 2) s << R"(, "blend": "circular")";
        }
        s << R"(, "children": [)" << build({centres.begin(), half}, depth + 1) << ", "
          << build({half, centres.end()}, depth + 1) << "]}";
        return s.str();
    };
    const std::vector<Material> materials = testMaterials();
    int checked = 0;
    double meanLength = 0.0;
    constexpr int kTrees = 6;
    for (int t = 0; t < kTrees; ++t) {
        std::vector<glm::vec3> centres(std::size_t(32 + 16 * t));
        for (glm::vec3& p : centres)
            p = glm::vec3(uniform(-2.0f, 2.0f), uniform(-2.0f, 2.0f), uniform(-2.0f, 2.0f));
        const std::string sdf = build(centres, 0);
        const std::optional<Compiled> c = compileText(sdf, t % 2 == 0);
        ASSERT_TRUE(c) << sdf;
        SdfCellOptions options;
        options.levels = 3;
        options.outerLevels = 0; // the finest cells a 64th of the content
        options.refineLeaves = 2;
        options.farConstants = false;
        const SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf), options);
        ASSERT_GT(grid.levels, 0);
        meanLength += grid.stats.meanLength / double(c->program.instructions.size()) / kTrees;
        for (int i = 0; i < 3000; ++i) {
            const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
            const std::vector<GpuSdfInstruction> list = sdfCellProgram(grid, p);
            const float whole = sdfDistance(c->program, p);
            ASSERT_NEAR(sdfCellsDistance(c->program, grid, p), whole,
                        1e-5f * (1.0f + std::abs(whole)))
                << sdf << " at " << p.x << " " << p.y << " " << p.z << ", cell program of "
                << list.size() << " instructions";
            const SdfSurface a = sdfSurface(c->program, materials, p);
            const SdfSurface b = sdfCellsSurface(c->program, grid, materials, p);
            ASSERT_EQ(a.objectId, b.objectId) << sdf;
            ASSERT_NEAR(glm::length(a.baseColor - b.baseColor), 0.0f, 1e-4f) << sdf;
            ++checked;
        }
    }
    EXPECT_EQ(checked, kTrees * 3000);
    // The cells are pruned: their programs are a small part of the whole (measured: 2.6%).
    EXPECT_LT(meanLength, 0.1);
}

// Cells marked affine (kSdfCellAffine: the march crosses them in one step, to the plane or to
// their far side) hold no surface but the plane's, and their program is affine along any
// segment in them: at random points of random trees over a tilted, moved and scaled plane.
TEST(CellPruning, CellsMarkedAffineHoldOnlyAPlane) {
    RandomTree random{std::mt19937(20261204)};
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int affinePoints = 0, trees = 0, emptyLists = 0;
    for (int t = 0; t < 24; ++t) {
        const std::string sdf =
            R"({"children": [{"shape": "plane", "normal": [0.2, 1, -0.1], "offset": 0.9, )" +
            random.transform() + "}, " + random.group(2) + "]}";
        const std::optional<Compiled> c = compileText(sdf, false);
        if (!c) continue;
        SdfCellOptions options;
        options.levels = 3;
        options.farConstants = t % 2 == 0;
        const SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf), options);
        if (grid.levels == 0) continue;
        ++trees;
        EXPECT_GT(grid.stats.affineCells, 0) << sdf;
        // The plane is the grid's (the root's operand), and the field the shader evaluates for
        // it is its instruction's, tilted, moved and scaled as it is.
        ASSERT_EQ(grid.planes.size(), 1u) << sdf;
        for (int s = 0; s < 100; ++s) {
            const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
            const glm::vec4 field = grid.planes[0].field;
            const float exact =
                sdfLeafDistance(c->program, grid.code[grid.planes[0].instruction], p);
            ASSERT_NEAR(glm::dot(glm::vec3(field), p) + field.w, exact,
                        1e-5f * (1.0f + std::abs(exact)))
                << sdf;
        }
        for (int s = 0; s < 4000; ++s) {
            const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
            const SdfCellRange range = sdfCellRange(grid, p);
            if (!range.affine) continue;
            ++affinePoints;
            emptyLists += range.length == 0; // the plane one of the grid's, in no list
            const float edge = grid.size / float(1 << (2 * range.level));
            const glm::vec3 corner =
                grid.origin + glm::floor((p - grid.origin) / edge) * edge; // the cell's
            const auto cellProgram = [&](glm::vec3 q) {
                return sdfCellsDistance(c->program, grid, q);
            };
            // Affine: the value halfway between p and another point of the cell is the mean.
            const glm::vec3 q = corner + glm::vec3(u(rng), u(rng), u(rng)) * edge;
            const float mean = 0.5f * (cellProgram(p) + cellProgram(q));
            EXPECT_NEAR(cellProgram(0.5f * (p + q)), mean, 1e-4f * (1.0f + std::abs(mean)))
                << sdf << ": a cell marked affine whose program is not";
            // The only surface: the whole program is on the same side as the plane.
            const float plane = cellProgram(p), whole = sdfDistance(c->program, p);
            if (std::abs(plane) > 1e-4f * edge) {
                EXPECT_EQ(plane > 0.0f, whole > 0.0f)
                    << sdf << ": another surface in a cell marked affine";
            }
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(trees, 12) << "(trees that compile)";
    EXPECT_GT(affinePoints, trees * 1000) << "(of 4,000 points a tree: most of the grid)";
    EXPECT_GT(emptyLists, affinePoints / 2) << "(the plane's cells list nothing)";
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

// The map's loop (sdf/glsl_codegen.hpp, SdfCellFit::shortLists) follows the longest list a point
// reads: one instruction per iteration for a grid of spheres apart, two where 80 spheres overlap in
// a smooth union (the cells where they meet list them all) and where there is no grid (every point
// runs the outside list, the whole program).
TEST(CellPruning, TheLongestListDecidesTheLoop) {
    std::ostringstream apart, together;
    apart << R"({"children": [)";
    together << R"({"op": "smooth_union", "smoothness": 0.1, "children": [)";
    for (int i = 0; i < 80; ++i) {
        apart << (i ? ", " : "") << R"({"shape": "sphere", "radius": 0.3, "position": [)"
              << (i % 10) - 5 << ", 0, " << (i / 10) - 5 << "]}";
        together << (i ? ", " : "") << R"({"shape": "sphere", "radius": 0.3, "position": [)"
                 << 0.001 * i << ", 0, 0]}";
    }
    apart << "]}";
    together << "]}";
    const std::optional<Compiled> a = compileText(apart.str(), false);
    const std::optional<Compiled> t = compileText(together.str(), false);
    ASSERT_TRUE(a && t);
    const SdfCellGrid short_ = buildSdfCells(a->program, sdfContentBox(*a->scene.sdf));
    EXPECT_GT(short_.levels, 0);
    EXPECT_LE(sdfLongestCellList(short_), kSdfShortCellList);
    EXPECT_TRUE(sdfCellFit(short_).shortLists);

    const SdfCellGrid overlapping = buildSdfCells(t->program, sdfContentBox(*t->scene.sdf));
    EXPECT_GT(overlapping.levels, 0);
    EXPECT_GT(overlapping.stats.maxLength, kSdfShortCellList);
    EXPECT_EQ(sdfLongestCellList(overlapping), overlapping.stats.maxLength);
    EXPECT_FALSE(sdfCellFit(overlapping).shortLists);

    const SdfCellGrid none = buildSdfCells(a->program, Aabb{});
    EXPECT_EQ(none.levels, 0);
    EXPECT_EQ(none.stats.maxLength, 0);
    EXPECT_GT(int(none.outsideLength), kSdfShortCellList);
    EXPECT_FALSE(sdfCellFit(none).shortLists);
}

// The map holds its value stacks in variables (sdf/glsl_codegen.hpp, SdfCellFit::shallowStacks)
// only where every list a point reads is at most kSdfRegisterStack deep: the deepest stack the
// grid reports is that of the deepest list at any point, and of the outside list. Seven spheres
// nested to the right, op(s0, op(s1, ... op(s5, s6))), all near one point, are listed whole in
// the cells there: seven leaves before the first combine. The same seven as one smooth union
// combine as they come: two deep.
TEST(CellPruning, TheDeepestListDecidesTheStacks) {
    const int spheres = 7;
    auto sphere = [](int i) {
        return R"({"shape": "sphere", "radius": 0.3, "position": [)" + std::to_string(0.01 * i) +
               ", 0, 0]}";
    };
    std::string nested = sphere(spheres - 1), flat = sphere(0);
    for (int i = spheres - 2; i >= 0; --i)
        nested = R"({"op": "smooth_union", "smoothness": 0.1, "children": [)" + sphere(i) + ", " +
                 nested + "]}";
    for (int i = 1; i < spheres; ++i)
        flat += ", " + sphere(i);
    const std::optional<Compiled> deep = compileText(nested, false);
    const std::optional<Compiled> shallow = compileText(
        R"({"op": "smooth_union", "smoothness": 0.1, "children": [)" + flat + "]}", false);
    ASSERT_TRUE(deep && shallow);

    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const auto& [compiled, depth] : {std::pair{&*deep, spheres}, std::pair{&*shallow, 2}}) {
        const SdfCellGrid grid =
            buildSdfCells(compiled->program, sdfContentBox(*compiled->scene.sdf));
        ASSERT_GT(grid.levels, 0);
        EXPECT_EQ(grid.stats.maxStack, depth);
        EXPECT_EQ(sdfDeepestCellStack(grid), depth);
        EXPECT_EQ(sdfCellFit(grid).shallowStacks, depth <= kSdfRegisterStack);
        // The cell at the spheres' middle lists them all; no cell lists a deeper one.
        const std::span<const std::uint32_t> middle =
            sdfCellWords(grid, sdfCellRange(grid, glm::vec3(0.03f, 0.0f, 0.0f)));
        EXPECT_EQ(sdfListStackDepth(grid.code, middle, grid.reading), depth);
        for (int i = 0; i < 2000; ++i) {
            const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
            ASSERT_LE(sdfListStackDepth(grid.code, sdfCellWords(grid, sdfCellRange(grid, p)),
                                        grid.reading),
                      depth);
        }
        // Without a grid every point runs the outside list, the whole program.
        const SdfCellGrid none = buildSdfCells(compiled->program, Aabb{});
        EXPECT_EQ(none.levels, 0);
        EXPECT_EQ(none.stats.maxStack, 0);
        EXPECT_EQ(sdfDeepestCellStack(none), depth);
    }
    EXPECT_GT(spheres, kSdfRegisterStack); // (the nested tree is too deep for the variables)
}

// A list's stack depth as the shader counts it: a shape pushes, a combine (its own instruction
// in a postfix list, an entry's in pairs) and Accumulate pop; a least-of-shapes list needs none.
TEST(CellPruning, AListsStackDepthFollowsItsReading) {
    std::vector<GpuSdfInstruction> code(3);
    code[0].opcode = code[1].opcode = std::uint32_t(SdfOpcode::Shape);
    code[2].opcode = std::uint32_t(SdfOpcode::Combine);
    const std::vector<std::uint32_t> flat{0, 1, 2, 0, 2, 1, 2}, nested{0, 1, 0, 1, 2, 2, 2};
    EXPECT_EQ(sdfListStackDepth(code, flat, SdfListReading::Postfix), 2);
    EXPECT_EQ(sdfListStackDepth(code, nested, SdfListReading::Postfix), 4);
    EXPECT_EQ(sdfListStackDepth(code, nested, SdfListReading::LeastOfShapes), 0);
    for (const auto& [list, depth] : {std::pair{&flat, 2}, std::pair{&nested, 4}}) {
        std::vector<std::uint32_t> pairs;
        sdfPairList(code, *list, pairs);
        EXPECT_EQ(sdfListStackDepth(code, pairs, SdfListReading::PostfixPairs), depth);
    }
    code.push_back(code[0]);
    code.back().opcode = std::uint32_t(SdfOpcode::Accumulate);
    const std::vector<std::uint32_t> parts{0, 3, 0, 1, 2, 3, 0, 3};
    EXPECT_EQ(sdfListStackDepth(code, parts, SdfListReading::Postfix), 2);

    // Point frames: PushPoint pushes a point, PopPoint pops it, whatever the reading.
    code.push_back(code[0]);
    code.back().opcode = std::uint32_t(SdfOpcode::PushPoint);
    code.push_back(code[0]);
    code.back().opcode = std::uint32_t(SdfOpcode::PopPoint);
    const std::vector<std::uint32_t> frames{4, 4, 0, 5, 4, 1, 5, 2, 5};
    EXPECT_EQ(sdfListPointStackDepth(code, frames, SdfListReading::Postfix), 2);
    EXPECT_EQ(sdfListStackDepth(code, frames, SdfListReading::Postfix), 2);
    std::vector<std::uint32_t> pairs;
    sdfPairList(code, frames, pairs);
    EXPECT_EQ(sdfListPointStackDepth(code, pairs, SdfListReading::PostfixPairs), 2);
}

// The point stack decides too: a sphere in five nested groups, each twisted (a point modifier:
// the group's point is pushed, sdf/sdf_emit.cpp) and holding a second sphere, is five points
// deep in the cells by the innermost sphere; SdfCellFit keeps its stacks in arrays. Four groups
// fit.
TEST(CellPruning, TheDeepestPointStackDecidesTheStacksToo) {
    for (const int groups : {4, 5}) {
        std::string tree = R"({"shape": "sphere", "radius": 0.3})";
        for (int i = 0; i < groups; ++i)
            tree = R"({"op": "smooth_union", "smoothness": 0.1, "modifiers": [{"type": "twist",
                "amount": )" +
                   std::to_string(10 + 5 * i) + R"(, "radius": 0.5}], "children": [)" + tree +
                   R"(, {"shape": "sphere", "radius": 0.2, "position": [0.4, 0, 0]}]})";
        const std::optional<Compiled> compiled = compileText(tree, false);
        ASSERT_TRUE(compiled);
        const SdfCellGrid grid =
            buildSdfCells(compiled->program, sdfContentBox(*compiled->scene.sdf));
        ASSERT_GT(grid.levels, 0);
        EXPECT_EQ(sdfDeepestCellPointStack(grid), groups);
        EXPECT_LE(sdfDeepestCellStack(grid), kSdfRegisterStack);
        EXPECT_EQ(sdfCellFit(grid).shallowStacks, groups <= kSdfRegisterPointStack);
    }
}

// The lists two grids over the same cube run at random points of it: equal everywhere.
void expectSameLists(const SdfCellGrid& a, const SdfCellGrid& b, std::mt19937& rng,
                     const std::string& what) {
    ASSERT_EQ(a.origin, b.origin);
    ASSERT_EQ(a.size, b.size);
    ASSERT_EQ(a.code.size(), b.code.size());
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 p = a.origin + glm::vec3(u(rng), u(rng), u(rng)) * a.size;
        const std::span<const std::uint32_t> la = sdfCellWords(a, sdfCellRange(a, p)),
                                             lb = sdfCellWords(b, sdfCellRange(b, p));
        ASSERT_TRUE(std::equal(la.begin(), la.end(), lb.begin(), lb.end()))
            << what << " at " << p.x << " " << p.y << " " << p.z << ": " << la.size() << " and "
            << lb.size() << " words";
    }
    for (std::size_t i = 0; i < a.code.size(); ++i)
        ASSERT_EQ(std::memcmp(&a.code[i], &b.code[i], sizeof a.code[i]), 0) << what << " " << i;
}

// The words before a re-prune with the ranges it says it changed copied in are the words after
// it (what a GPU copy of the grid is updated by: render/gpu_scene.hpp, updateSdfCells).
void expectChangedWordsComplete(const std::vector<std::uint32_t>& before, const SdfCellGrid& after,
                                const std::string& what) {
    std::vector<std::uint32_t> patched = before;
    patched.resize(after.words.size());
    for (const SdfWordRange& range : after.changedWords) {
        ASSERT_LE(std::size_t(range.first) + range.count, after.words.size()) << what;
        std::copy_n(after.words.begin() + range.first, range.count, patched.begin() + range.first);
    }
    EXPECT_TRUE(patched == after.words) << what;
}

// An edit of numbers (a shape moved, resized or retyped, an operation's smoothness) pruned
// again from the kept state gives the cells a full build of the edited program gives, and they
// agree with the whole edited program.
TEST(CellPruning, AnEditPrunedAgainEqualsAFullBuild) {
    RandomTree random{std::mt19937(20261202)};
    std::mt19937 rng(5);
    int edits = 0;
    for (int t = 0; t < 24; ++t) {
        std::string sdf = random.group(3);
        if (t % 3 == 0)
            sdf = R"({"children": [{"shape": "plane", "normal": [0, 1, 0], "offset": 1.2}, )" +
                  sdf + "]}";
        const std::optional<Compiled> c = compileText(sdf, t % 2 == 0);
        if (!c) continue;
        const Aabb box = sdfContentBox(*c->scene.sdf);
        SdfCellOptions options;
        options.levels = 3;
        options.refineLeaves = 1;
        options.farConstants = t % 4 < 2;
        SdfCellStatePtr state;
        SdfCellGrid grid = buildSdfCells(c->program, box, options, &state);
        if (grid.levels == 0) continue;
        ASSERT_TRUE(state);
        // Three edits in a row on the same state.
        Compiled edited = *c;
        for (int e = 0; e < 3; ++e) {
            std::vector<GpuSdfInstruction>& code = edited.program.instructions;
            std::vector<std::size_t> shapes, smooth;
            for (std::size_t i = 0; i < code.size(); ++i) {
                if (SdfOpcode(code[i].opcode) == SdfOpcode::Shape) shapes.push_back(i);
                if (SdfOpcode(code[i].opcode) == SdfOpcode::Combine && code[i].params[0].x > 0)
                    smooth.push_back(i);
            }
            ASSERT_FALSE(shapes.empty());
            GpuSdfInstruction& in = code[shapes[std::size_t(random.pick(int(shapes.size())))]];
            switch (random.pick(3)) {
            case 0: // moved
                in.worldToLocal[random.pick(3)].w += random.uniform(-1.0f, 1.0f);
                break;
            case 1: // resized
                in.misc.x *= random.uniform(0.5f, 2.0f);
                break;
            default: // a smoothness changed, else moved
                if (!smooth.empty())
                    code[smooth[std::size_t(random.pick(int(smooth.size())))]].params[0].x *= 2.0f;
                else
                    in.worldToLocal[0].w += 0.5f;
            }
            const std::vector<std::uint32_t> old = grid.words;
            ASSERT_TRUE(repruneSdfCells(*state, edited.program, grid)) << sdf;
            expectChangedWordsComplete(old, grid, sdf);
            const SdfCellGrid full = buildSdfCells(edited.program, box, options);
            ASSERT_EQ(full.levels, grid.levels);
            expectSameLists(grid, full, rng, sdf);
            EXPECT_EQ(grid.stats.leafCells, full.stats.leafCells) << sdf;
            EXPECT_EQ(grid.stats.maxLength, full.stats.maxLength) << sdf;
            EXPECT_DOUBLE_EQ(grid.stats.meanLeaves, full.stats.meanLeaves) << sdf;
            EXPECT_EQ(grid.stats.cellsPerLevel, full.stats.cellsPerLevel) << sdf;
            expectCellsAgree(edited, grid, rng, 300, sdf);
            if (HasFailure()) return;
            ++edits;
        }
    }
    EXPECT_GT(edits, 40);
}

// Builds the cells of `before` with a kept state, prunes them again for `after` (numbers
// changed only) and checks the result against a full build of `after` at random points.
struct Repruned {
    SdfCellStatePtr state;
    SdfCellGrid grid;
    std::size_t fullCells = 0; // cells the full build of `before` pruned
};

Repruned expectRepruneEqualsAFullBuild(const Compiled& before, const Compiled& after, unsigned seed,
                                       const std::string& what) {
    const Aabb box = sdfContentBox(*before.scene.sdf);
    Repruned r;
    r.grid = buildSdfCells(before.program, box, {}, &r.state);
    EXPECT_TRUE(r.state) << what;
    if (!r.state) return r;
    r.fullCells = r.grid.stats.prunedCells;
    const std::vector<std::uint32_t> old = r.grid.words;
    EXPECT_TRUE(repruneSdfCells(*r.state, after.program, r.grid)) << what;
    expectChangedWordsComplete(old, r.grid, what);
    // Only a small part of the words is written again: 8.5% measured on the 400-sphere grid,
    // 16% on the groups without floors (whose coarse cells hold every group).
    std::size_t written = 0;
    for (const SdfWordRange& range : r.grid.changedWords)
        written += range.count;
    EXPECT_LT(written * 5, r.grid.words.size()) << what;
    EXPECT_GT(r.grid.stats.prunedCells, 0u) << what;
    std::mt19937 rng(seed);
    expectSameLists(r.grid, buildSdfCells(after.program, box), rng, what);
    EXPECT_EQ(expectCellsAgree(after, r.grid, rng, 2000, what), 2000);
    return r;
}

// One sphere of a grid of 400 moved: the cells around its old and new place are pruned again,
// a small part of what a full build prunes; a change of structure is refused.
TEST(CellPruning, MovingOneShapePrunesFewCellsAgain) {
    const auto gridText = [](float moved) {
        std::ostringstream s;
        s << R"({"children": [)";
        for (int i = 0; i < 400; ++i)
            s << (i ? ", " : "") << R"({"shape": "sphere", "radius": 0.3, "position": [)"
              << (i % 20) - 10 + (i == 210 ? moved : 0.0f) << ", 0, " << (i / 20) - 10 << "]}";
        s << "]}";
        return s.str();
    };
    const std::optional<Compiled> c = compileText(gridText(0.0f), false);
    const std::optional<Compiled> moved = compileText(gridText(0.6f), false);
    ASSERT_TRUE(c && moved);
    Repruned r = expectRepruneEqualsAFullBuild(*c, *moved, 9, "moved");
    ASSERT_TRUE(r.state);
    EXPECT_LT(r.grid.stats.prunedCells * 6, r.fullCells);
    SdfCellState& state = *r.state;
    SdfCellGrid& grid = r.grid;
    // Nothing changed: nothing pruned.
    ASSERT_TRUE(repruneSdfCells(state, moved->program, grid));
    EXPECT_EQ(grid.stats.prunedCells, 0u);
    // One sphere more is another structure.
    const std::optional<Compiled> more =
        compileText(gridText(0.0f).insert(14, R"({"shape": "sphere", "radius": 0.1}, )"), false);
    ASSERT_TRUE(more);
    EXPECT_FALSE(repruneSdfCells(state, more->program, grid));
}

// Far cells keep their constants through an edit only where the constant a full build makes
// is the same (repruneSdfCells: farConstantStands): shapes of a scattered union moved (near and
// far, into the empty space around the others and back), resized and retyped one at a time,
// each edit pruned again from the state the last one left and compared with a full build.
TEST(CellPruning, FarCellsKeepTheirConstantsThroughAnEditOnlyWhereTheyStand) {
    RandomTree random{std::mt19937(23)};
    const int count = 48;
    std::vector<glm::vec3> position(static_cast<std::size_t>(count));
    std::vector<float> radius(static_cast<std::size_t>(count));
    std::vector<int> kind(std::size_t(count), 0);
    for (int i = 0; i < count; ++i) {
        position[std::size_t(i)] = {random.uniform(-3, 3), random.uniform(-0.3f, 0.3f),
                                    random.uniform(-3, 3)};
        radius[std::size_t(i)] = random.uniform(0.1f, 0.3f);
    }
    position[0] = {0.0f, 2.5f, 0.0f}; // one above the others, the nearest to the cells there
    const auto text = [&] {
        std::ostringstream s;
        s << R"({"children": [)";
        for (int i = 0; i < count; ++i) {
            const std::size_t k = std::size_t(i);
            s << (i ? ", " : "") << "{\"shape\": "
              << (kind[k] ? R"("box", "half_extents": [)" : R"("sphere", "radius": )") << radius[k];
            if (kind[k]) s << ", " << radius[k] << ", " << radius[k] << "]";
            s << ", \"position\": [" << position[k].x << ", " << position[k].y << ", "
              << position[k].z << "]}";
        }
        s << "]}";
        return s.str();
    };
    // The content's box stays the first one's (a re-prune keeps its grid): the edits keep every
    // shape inside it.
    const std::optional<Compiled> first = compileText(text(), false);
    ASSERT_TRUE(first);
    const Aabb box = sdfContentBox(*first->scene.sdf);
    SdfCellOptions options;
    options.levels = 4;
    SdfCellStatePtr state;
    SdfCellGrid grid = buildSdfCells(first->program, box, options, &state);
    ASSERT_TRUE(state);
    std::mt19937 rng(5);
    std::size_t repruned = 0, full = 0;
    for (int e = 0; e < 30; ++e) {
        const std::size_t k = e % 5 == 0 ? 0 : std::size_t(random.pick(count));
        switch (e % 3) {
        case 0: // far: to the other side, or up above the others and back
            position[k] = e % 2 ? glm::vec3(random.uniform(-3, 3), random.uniform(-0.3f, 2.5f),
                                            random.uniform(-3, 3))
                                : glm::vec3(-position[k].x, position[k].y, -position[k].z);
            break;
        case 1: // near
            position[k].x = std::clamp(position[k].x + random.uniform(-0.3f, 0.3f), -3.0f, 3.0f);
            break;
        default:
            radius[k] = random.uniform(0.1f, 0.3f);
            kind[k] = random.pick(2);
        }
        const std::string what = "edit " + std::to_string(e) + " of shape " + std::to_string(k);
        const std::optional<Compiled> edited = compileText(text(), false);
        ASSERT_TRUE(edited);
        ASSERT_TRUE(repruneSdfCells(*state, edited->program, grid)) << what;
        const SdfCellGrid fresh = buildSdfCells(edited->program, box, options);
        expectSameLists(grid, fresh, rng, what);
        EXPECT_EQ(grid.stats.cellsPerLevel, fresh.stats.cellsPerLevel) << what;
        EXPECT_EQ(grid.stats.affineCells, fresh.stats.affineCells) << what;
        EXPECT_DOUBLE_EQ(grid.stats.meanLeaves, fresh.stats.meanLeaves) << what;
        if (HasFailure()) return;
        repruned += grid.stats.prunedCells;
        full += fresh.stats.prunedCells;
    }
    // The edits pruned 73,680 cells again where the full builds pruned 473,152; without the
    // far constants kept, 171,602.
    EXPECT_LT(repruned * 5, full);
}

// The same for a union of groups that have no floor (a twisted capsule in each): an edit must
// not prune every cell again because the groups are evaluated everywhere.
TEST(CellPruning, MovingOneShapeAmongGroupsWithoutFloorsPrunesFewCellsAgain) {
    const auto groupsText = [](float moved) {
        std::ostringstream s;
        s << R"({"children": [)";
        for (int i = 0; i < 100; ++i)
            s << (i ? ", " : "") << R"({"position": [)" << (i % 10) * 2 - 10 << ", 0, "
              << (i / 10) * 2 - 10 << R"(], "children": [{"shape": "sphere", "radius": 0.3, )"
              << R"("position": [)" << (i == 45 ? moved : 0.0f) << R"(, 0, 0]}, )"
              << R"({"shape": "capsule", "half_height": 0.3, "radius": 0.15, )"
              << R"("position": [0.7, 0, 0], )"
              << R"("modifiers": [{"type": "twist", "amount": 60, "radius": 0.15}]}]})";
        s << "]}";
        return s.str();
    };
    const std::optional<Compiled> c = compileText(groupsText(0.0f), false);
    const std::optional<Compiled> moved = compileText(groupsText(0.4f), false);
    ASSERT_TRUE(c && moved);
    const Repruned r = expectRepruneEqualsAFullBuild(*c, *moved, 11, "moved group");
    // 19% of the cells here (the coarse cells hold every group); every cell, evaluating all
    // the groups everywhere.
    EXPECT_LT(r.grid.stats.prunedCells * 4, r.fullCells);
}

// Outside its floor's box a program is at least the distance to the box less the drop
// (sdfProgramFloor). At random points around the floor's box: is it?
void expectFloorHolds(const SdfProgram& program, const SdfFieldFloor& floor, std::mt19937& rng,
                      const std::string& what, float* deepest = nullptr) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), far(0.0f, 1.5f);
    const glm::vec3 centre = floor.box.center(), half = floor.box.halfSize();
    for (int i = 0; i < 3000; ++i) {
        // On the box's faces' axes too, where a box's distance is a round shape's.
        glm::vec3 direction(u(rng), u(rng), u(rng));
        if (i % 3 == 0) {
            direction = glm::vec3(0.0f);
            direction[i % 9 / 3] = i % 2 ? 1.0f : -1.0f;
        }
        if (glm::length(direction) < 1e-3f) continue;
        direction = glm::normalize(direction);
        const glm::vec3 reach = glm::abs(direction) / glm::max(half, glm::vec3(1e-6f));
        const glm::vec3 onFace = centre + direction / std::max({reach.x, reach.y, reach.z});
        const glm::vec3 p = onFace + direction * far(rng);
        const glm::vec3 away = glm::max(glm::max(floor.box.min - p, p - floor.box.max), 0.0f);
        const float boxDistance = glm::length(away);
        if (boxDistance <= 0.0f) continue;
        const float field = sdfDistance(program, p);
        ASSERT_GE(field, boxDistance - floor.drop - 1e-5f) << what << " at " << i;
        if (deepest) *deepest = std::max(*deepest, boxDistance - field);
    }
}

// A chain of smooth unions, as a group's children are folded, dips below the least of its
// operands by at most its largest smoothness, however long it is (smoothChainDrop in
// engine/sdf/cell_pruning.cpp): its floor's drop is that, where each union's own rule added
// k / 4 a link (the molecule of 1,000 spheres: 30 units). Spheres at one place make the chain dip
// the most (towards the least minus k), and the floor still holds; so it does on random trees
// of smooth and plain unions, chains of chains among them, and on random trees of every
// operation.
TEST(CellPruning, AChainOfSmoothUnionsDropsByItsSmoothnessNotItsLength) {
    std::mt19937 rng(2026120801);
    const auto chain = [](const std::string& blend, int n) {
        std::ostringstream s;
        s << R"({"op": "smooth_union", "smoothness": 0.2, "blend": ")" << blend
          << R"(", "children": [)";
        for (int i = 0; i < n; ++i)
            s << (i ? ", " : "") << R"({"shape": "sphere", "radius": 0.3, "position": [0, 0, 0]})";
        s << "]}";
        return s.str();
    };
    for (const std::string blend : {"polynomial", "circular"}) {
        const auto floorOf = [&](const std::string& sdf, float most, float dips) {
            const std::optional<Compiled> c = compileText(sdf, false);
            ASSERT_TRUE(c);
            const std::optional<SdfFieldFloor> floor = sdfProgramFloor(c->program.instructions);
            ASSERT_TRUE(floor) << blend;
            EXPECT_LE(floor->drop, most + 1e-6f) << blend;
            float deepest = 0.0f;
            expectFloorHolds(c->program, *floor, rng, blend, &deepest);
            EXPECT_GT(deepest, dips) << blend; // the bound is tight
        };
        // One chain: the rule alone gave 200 k / 4 = 10. It dips nearly k.
        floorOf(chain(blend, 200), 0.2f, 0.9f * 0.2f);
        // Two such chains smoothly united: both dip nearly k, then their union as much again as
        // the rule adds (k / 4, or k (1 - 1 / sqrt 2) circular): a chain's bound needs one
        // operand that is no chain.
        const float link = blend == "circular" ? 1.0f - 1.0f / std::sqrt(2.0f) : 0.25f;
        floorOf(R"({"op": "smooth_union", "smoothness": 0.2, "blend": ")" + blend +
                    R"(", "children": [)" + chain(blend, 100) + ", " + chain(blend, 100) + "]}",
                (1.0f + link) * 0.2f, 1.15f * 0.2f);
    }
    RandomTree unions{std::mt19937(20261208)};
    unions.ops = {"smooth_union", "union"};
    RandomTree any{std::mt19937(20261209)};
    int floors = 0;
    for (int t = 0; t < 80; ++t) {
        const std::string sdf = t % 2 ? unions.group(3) : any.group(3);
        const std::optional<Compiled> c = compileText(sdf, false);
        if (!c) continue;
        const std::optional<SdfFieldFloor> floor = sdfProgramFloor(c->program.instructions);
        if (!floor) continue;
        ++floors;
        expectFloorHolds(c->program, *floor, rng, sdf);
        if (HasFailure()) return;
    }
    EXPECT_GE(floors, 29); // of the 80 trees, those with a floor: 29
}

// Outside the grid run the whole program's unbounded operands (here a plane: one of the grid's
// planes, so the outside list is empty) and the floor of the rest stands for them
// (SdfCellGrid::outsideFloor): the least of the two is never above the whole program's
// distance, equals it (and its object id) wherever the plane is the nearer, and stays a margin
// above zero, so no march meets the content out there. No bounding
// hierarchy in the list, built from the tree with or without one; an edit keeps all of it.
TEST(CellPruning, TheOutsideRunsTheUnboundedOperandsAndTheRestsFloor) {
    const auto text = [](float moved) {
        std::ostringstream s;
        s << R"({"children": [{"shape": "plane", "normal": [0, 1, 0], "offset": -1})";
        for (int i = 0; i < 16; ++i)
            s << R"(, {"shape": ")" << (i % 2 ? "sphere" : "box") << R"(", "position": [)"
              << (i % 4) * 0.8f + (i == 5 ? moved : 0.0f) << ", 0, " << (i / 4) * 0.8f
              << R"(], "material": "m)" << i % 3 << "\"}";
        s << "]}";
        return s.str();
    };
    const std::vector<Material> materials = testMaterials();
    const auto expectOutside = [&](const SdfCellGrid& grid, const SdfProgram& whole,
                                   const std::string& what) {
        EXPECT_EQ(grid.outsideLength, 0u) << what;
        ASSERT_EQ(grid.planes.size(), 1u) << what;
        const GpuSdfInstruction& plane = grid.code[grid.planes[0].instruction];
        EXPECT_EQ(SdfOpcode(plane.opcode), SdfOpcode::Shape) << what;
        EXPECT_EQ(PrimitiveId(plane.kind), PrimitiveId::Plane) << what;
        ASSERT_TRUE(grid.outsideFloor) << what;
        std::mt19937 rng(9);
        std::uniform_real_distribution<float> u(-1.0f, 2.0f), near(-0.05f, 0.05f);
        int checked = 0, listNearer = 0, hits = 0;
        for (int i = 0; i < 6000; ++i) {
            glm::vec3 p = grid.origin + grid.size * glm::vec3(u(rng), u(rng), u(rng));
            if (i % 2) p.y = -1.0f + near(rng); // at the plane (y = -1)
            const SdfCellRange range = sdfCellRange(grid, p);
            if (range.level != 0) continue;
            const float listed = sdfLeafDistance(whole, plane, p);
            const float floor = sdfCellOutsideFloor(grid, p);
            const float cells = sdfCellsDistance(whole, grid, p), exact = sdfDistance(whole, p);
            ASSERT_EQ(cells, std::min(listed, floor)) << what;
            ASSERT_LE(cells, exact + 1e-5f * (1.0f + std::abs(exact))) << what;
            ASSERT_GT(floor, 0.01f * grid.size) << what;
            ++checked;
            if (listed >= floor) continue;
            ++listNearer;
            ASSERT_FLOAT_EQ(cells, exact) << what; // the same plane, read the same way
            const SdfSurface a = sdfSurface(whole, materials, p);
            const SdfSurface b = sdfCellsSurface(whole, grid, materials, p);
            ASSERT_EQ(a.objectId, b.objectId) << what;
            hits += std::abs(exact) < 0.05f;
        }
        EXPECT_GT(checked, 3000) << what;
        EXPECT_GT(listNearer, 1000) << what;
        EXPECT_GT(hits, 500) << what;
        // Inside the grid nothing changes: no floor there.
        EXPECT_EQ(sdfCellOutsideFloor(grid, grid.origin + glm::vec3(0.5f * grid.size)), INFINITY);
    };
    const std::string sdf = text(0.0f), movedText = text(0.3f);
    for (const bool bounded : {false, true}) {
        const std::optional<Compiled> c = compileText(sdf, bounded),
                                      moved = compileText(movedText, bounded);
        ASSERT_TRUE(c && moved);
        const std::string what = bounded ? "with a hierarchy" : "without";
        EXPECT_EQ(sdfCellsNeedHierarchy(c->program.instructions), false) << what;
        SdfCellOptions options;
        options.levels = 2;
        SdfCellStatePtr state;
        SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf), options, &state);
        ASSERT_GT(grid.levels, 0);
        expectOutside(grid, c->program, what);
        std::mt19937 rng(4);
        EXPECT_EQ(expectCellsAgree(*c, grid, rng, 1000, what), 1000);
        // The sphere moved, an edit of numbers: pruned again, in place.
        const std::size_t codeBefore = grid.code.size();
        ASSERT_TRUE(repruneSdfCells(*state, moved->program, grid));
        // The code's length stays (the GPU's buffers are written in place after such an edit).
        EXPECT_EQ(grid.code.size(), codeBefore);
        expectOutside(grid, moved->program, what + ", moved");
        EXPECT_EQ(expectCellsAgree(*moved, grid, rng, 1000, what + ", moved"), 1000);
    }
}

// The planes of the root's chain of unions (at most kSdfCellPlanes of them) are the grid's and in
// no list; a plane elsewhere in the tree, and those past the first four, stay in the lists. The
// cells agree with the whole program, before and after a plane is moved (pruned again in
// place, its field made again); retyping one of the grid's planes, or making a shape a plane,
// changes which planes the lists leave out: the re-prune refuses it (the caller builds again).
TEST(CellPruning, TheRootsPlanesAreInNoList) {
    const auto text = [](float wall, const char* firstKind, const char* lastKind) {
        std::ostringstream s;
        s << R"({"children": [{"shape": ")" << firstKind
          << R"(", "normal": [0, 1, 0], "offset": -1, "material": "m1"}, )"
          << R"({"shape": "plane", "normal": [1, 0, 0.3], "offset": )" << wall
          << R"(, "material": "m2"}, )";
        for (int i = 0; i < 3; ++i) // far-off planes: a union of five in all
            s << R"({"shape": "plane", "normal": [0, -1, 0], "offset": -)" << 20 + i << "}, ";
        s << R"({"op": "subtraction", "children": [{"shape": "box", "half_extents": [0.5, 0.5, 0.5]},)"
          << R"( {"shape": "plane", "normal": [0, 0, 1], "offset": 0.2}]}, )";
        for (int i = 0; i < 8; ++i)
            s << R"({"shape": "sphere", "radius": 0.3, "position": [)" << (i % 4) * 0.8f << ", 0, "
              << (i / 4) * 0.8f << R"(], "material": "m)" << i % 3 << "\"}, ";
        s << R"({"shape": ")" << lastKind << R"(", "normal": [0, 0, -1], "offset": 4}]})";
        return s.str();
    };
    const std::optional<Compiled> c = compileText(text(-1.5f, "plane", "plane"), false),
                                  moved = compileText(text(-1.2f, "plane", "plane"), false),
                                  retyped = compileText(text(-1.5f, "box", "plane"), false);
    ASSERT_TRUE(c && moved && retyped);
    SdfCellOptions options;
    options.levels = 3;
    SdfCellStatePtr state;
    SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf), options, &state);
    ASSERT_GT(grid.levels, 0);
    ASSERT_EQ(grid.planes.size(), std::size_t(kSdfCellPlanes));
    const auto isPlane = [&](const GpuSdfInstruction& in) {
        return SdfOpcode(in.opcode) == SdfOpcode::Shape &&
               PrimitiveId(in.kind) == PrimitiveId::Plane;
    };
    for (const SdfCellPlane& plane : grid.planes)
        ASSERT_TRUE(isPlane(grid.code[plane.instruction]));
    // The shader reads as many of the header's planes as the map's SDF_CELLS_PLANES says: every
    // plane the grid holds, whatever the program (seven plane instructions here: four), and none
    // in a program without one.
    const auto planesRead = [](const SdfProgram& program) {
        const std::string map = generateSdfMap(program, SdfStrategy::Cells);
        const std::string define = "#define SDF_CELLS_PLANES ";
        const std::size_t at = map.find(define);
        return at == std::string::npos ? 0 : std::stoi(map.substr(at + define.size()));
    };
    EXPECT_EQ(planesRead(c->program), kSdfCellPlanes);
    const std::optional<Compiled> floorOnly = compileText(
        R"({"children": [{"shape": "plane", "normal": [0, 1, 0], "offset": -1},
            {"shape": "sphere", "radius": 0.3}, {"shape": "box", "half_extents": [0.2, 0.2, 0.2],
             "position": [1, 0, 0]}]})",
        false);
    const std::optional<Compiled> noPlane = compileText(
        R"({"children": [{"shape": "sphere", "radius": 0.3},
            {"shape": "box", "half_extents": [0.2, 0.2, 0.2], "position": [1, 0, 0]}]})",
        false);
    ASSERT_TRUE(floorOnly && noPlane);
    const SdfCellGrid floorGrid =
        buildSdfCells(floorOnly->program, sdfContentBox(*floorOnly->scene.sdf), options);
    ASSERT_EQ(floorGrid.planes.size(), 1u);
    EXPECT_EQ(planesRead(floorOnly->program), 1);
    EXPECT_EQ(planesRead(noPlane->program), 0);
    // Every plane a list runs is one of the two the grid does not hold.
    const auto gridPlane = [&](const GpuSdfInstruction& in) {
        return std::any_of(grid.planes.begin(), grid.planes.end(), [&](const SdfCellPlane& plane) {
            return std::memcmp(&grid.code[plane.instruction], &in, sizeof in) == 0;
        });
    };
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int listedPlanes = 0;
    for (int n = 0; n < 3000; ++n) {
        const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
        for (const GpuSdfInstruction& in : sdfCellProgram(grid, p)) {
            ASSERT_FALSE(gridPlane(in));
            listedPlanes += isPlane(in);
        }
    }
    EXPECT_GT(listedPlanes, 0) << "the subtracted plane and the fifth stay in the lists";
    EXPECT_EQ(expectCellsAgree(*c, grid, rng, 2000, "planes"), 2000);
    ASSERT_TRUE(repruneSdfCells(*state, moved->program, grid));
    EXPECT_EQ(expectCellsAgree(*moved, grid, rng, 2000, "a plane moved"), 2000);
    EXPECT_FALSE(repruneSdfCells(*state, retyped->program, grid));
    // A shape made a plane: the grid would take it in place of the fifth.
    SdfCellStatePtr again;
    grid = buildSdfCells(retyped->program, sdfContentBox(*retyped->scene.sdf), options, &again);
    ASSERT_EQ(grid.planes.size(), std::size_t(kSdfCellPlanes));
    EXPECT_EQ(expectCellsAgree(*retyped, grid, rng, 2000, "a plane retyped"), 2000);
    EXPECT_FALSE(repruneSdfCells(*again, c->program, grid));
}

// Where a grid plane and a list are equally near, the surface is the one the union keeps, the
// first of equal operands: a floor before the rest keeps its material over an equal copy of it
// that the lists hold (past the four planes the grid takes), and over a later plane.
TEST(CellPruning, APlaneFirstOfEqualOnesKeepsItsSurface) {
    std::ostringstream s;
    s << R"({"children": [{"shape": "plane", "normal": [0, 1, 0], "offset": -1, "material": "m1"},)"
      << R"( {"shape": "sphere", "radius": 0.4, "material": "m0"},)";
    for (int i = 0; i < 3; ++i)
        s << R"( {"shape": "plane", "normal": [0, -1, 0], "offset": -)" << 20 + i << "},";
    s << R"( {"shape": "plane", "normal": [0, 1, 0], "offset": -1, "material": "m2"}]})";
    const std::optional<Compiled> c = compileText(s.str(), false);
    ASSERT_TRUE(c);
    SdfCellOptions options;
    options.levels = 3;
    const SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf), options);
    ASSERT_GT(grid.levels, 0);
    ASSERT_EQ(grid.planes.size(), std::size_t(kSdfCellPlanes));
    EXPECT_TRUE(grid.planes[0].leads);
    EXPECT_FALSE(grid.planes[1].leads); // after the sphere
    const std::vector<Material> materials = testMaterials();
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int onTheFloor = 0;
    for (int n = 0; n < 500; ++n) {
        glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
        p.y = -1.0f + 0.1f * (u(rng) - 0.5f); // about the floor, where the two are equal
        const SdfSurface a = sdfSurface(c->program, materials, p);
        const SdfSurface b = sdfCellsSurface(c->program, grid, materials, p);
        ASSERT_EQ(a.objectId, b.objectId) << p.x << " " << p.y << " " << p.z;
        ASSERT_EQ(a.baseColor, b.baseColor);
        onTheFloor += a.objectId == grid.code[grid.planes[0].instruction].objectId;
    }
    EXPECT_GT(onTheFloor, 400); // (near the sphere, the sphere)
    EXPECT_EQ(expectCellsAgree(*c, grid, rng, 1000, "equal planes"), 1000);
}

// A postfix list in pairs (SdfListReading::PostfixPairs) is the same program: the instructions
// it runs are the list's (its combines' operation, curve and smoothness held in the entries), and
// it gives the list's value. Every combine is in an entry, in that of the instruction before it
// wherever that one has none (the fewest entries); where the list has a BoundSkip (whose skips
// count entries) every combine has an entry of its own.
TEST(CellPruning, AListInPairsIsItsPostfixProgram) {
    RandomTree random{std::mt19937(20261207)};
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    int fused = 0, alone = 0, circular = 0;
    for (int t = 0; t < 40; ++t) {
        const std::string sdf = random.group(3);
        const bool bounded = t % 2 == 1;
        const std::optional<Compiled> c =
            compileText(R"({"children": [)" + sdf + ", " + random.shape() + "]}", bounded);
        if (!c) continue; // e.g. a subtraction of only cut children
        const std::vector<GpuSdfInstruction>& code = c->program.instructions;
        std::vector<std::uint32_t> list(code.size());
        std::iota(list.begin(), list.end(), 0u);
        const auto isCombine = [&](const GpuSdfInstruction& in) {
            return SdfOpcode(in.opcode) == SdfOpcode::Combine;
        };
        const bool skips = std::any_of(code.begin(), code.end(), [&](const GpuSdfInstruction& in) {
            return SdfOpcode(in.opcode) == SdfOpcode::BoundSkip;
        });
        std::vector<std::uint32_t> pairs{7u}; // (appended after what is there)
        sdfPairList(code, list, pairs);
        pairs.erase(pairs.begin());
        ASSERT_EQ(pairs.size() % 2, 0u);
        std::vector<GpuSdfInstruction> run;
        sdfListProgram(code, pairs, SdfListReading::PostfixPairs, run);
        ASSERT_EQ(run.size(), code.size()) << sdf;
        ASSERT_EQ(sdfListInstructionCount(code, pairs, SdfListReading::PostfixPairs), code.size());
        for (std::size_t n = 0; n < code.size(); ++n) {
            if (!isCombine(code[n])) {
                ASSERT_EQ(std::memcmp(&run[n], &code[n], sizeof code[n]), 0) << sdf << " " << n;
                continue;
            }
            ASSERT_TRUE(isCombine(run[n])) << sdf << " " << n;
            ASSERT_EQ(run[n].kind, code[n].kind) << sdf << " " << n;
            ASSERT_EQ(run[n].params[0].x, code[n].params[0].x) << sdf << " " << n;
            ASSERT_EQ(run[n].params[0].y, code[n].params[0].y) << sdf << " " << n;
            circular += code[n].params[0].y == 1.0f;
        }
        const std::size_t entries = pairs.size() / 2;
        for (std::size_t n = 0; n < entries; ++n) {
            const std::uint32_t i = sdfEntryIndex(pairs[2 * n]);
            const bool combine = sdfEntryCombine(pairs[2 * n]) != 0;
            if (combine) (isCombine(code[i]) ? alone : fused) += 1;
            if (isCombine(code[i])) { // its own entry: the one before it had a combine
                ASSERT_TRUE(combine) << sdf;
                if (!skips) {
                    ASSERT_TRUE(n > 0 && sdfEntryCombine(pairs[2 * n - 2]) != 0) << sdf;
                }
            }
        }
        if (skips) {
            EXPECT_EQ(entries, list.size()) << sdf;
        }
        for (int n = 0; n < 50; ++n) {
            const glm::vec3 p(u(random.rng), u(random.rng), u(random.rng));
            ASSERT_EQ(sdfDistanceOrdered(c->program, code, pairs, p, nullptr,
                                         SdfListReading::PostfixPairs),
                      sdfDistance(c->program, p))
                << sdf;
        }
    }
    EXPECT_GE(fused, 750); // (757, 159 and 61 measured)
    EXPECT_GE(alone, 150);
    EXPECT_GE(circular, 60);
    // Two spheres and their blend: two entries, the blend in the second sphere's.
    const std::optional<Compiled> two = compileText(
        R"({"op": "smooth_union", "smoothness": 0.25, "blend": "circular", "children": [
        {"shape": "sphere"}, {"shape": "sphere", "position": [1, 0, 0]}]})",
        false);
    ASSERT_TRUE(two);
    ASSERT_EQ(two->program.instructions.size(), 3u);
    std::vector<std::uint32_t> pairs;
    sdfPairList(two->program.instructions, std::vector<std::uint32_t>{0, 1, 2}, pairs);
    const std::uint32_t smoothUnion = 1 + 2 * std::uint32_t(SdfOp::SmoothUnion) + 1;
    EXPECT_EQ(pairs, (std::vector<std::uint32_t>{0, 0, 1 | smoothUnion << kSdfEntryIndexBits,
                                                 0x3e800000u /* 0.25f */}));
}

// A union of shapes, with or without its bounding hierarchy, lists only the shapes each cell
// needs (no unions: the lean loop of sdf_cells.glsl reads a running minimum), and nothing
// outside the grid, where the union's floor stands for it; read so, both agree with the whole
// program (outside: a bound above zero). A tree with any other operation keeps its postfix lists.
TEST(CellPruning, AUnionOfShapesListsOnlyShapes) {
    std::ostringstream text;
    text << R"({"children": [)";
    for (int i = 0; i < 40; ++i)
        text << (i ? ", " : "") << R"({"shape": ")" << (i % 3 ? "sphere" : "box")
             << R"(", "position": [)" << (i % 7) * 0.7f << ", " << (i % 3) * 0.4f << ", "
             << (i / 7) * 0.7f << R"(], "material": "m)" << i % 3 << "\"}";
    text << "]}";
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(-0.1f, 1.1f);
    for (const bool bounded : {false, true}) {
        const std::optional<Compiled> c = compileText(text.str(), bounded);
        ASSERT_TRUE(c);
        ASSERT_TRUE(sdfIsLeastOfShapes(c->program));
        SdfCellOptions options;
        options.levels = 3;
        const SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf), options);
        ASSERT_GT(grid.levels, 0);
        EXPECT_EQ(grid.reading, SdfListReading::LeastOfShapes);
        int cells = 0, outside = 0;
        for (int n = 0; n < 4000; ++n) {
            const glm::vec3 p = grid.origin + glm::vec3(u(rng), u(rng), u(rng)) * grid.size;
            const SdfCellRange range = sdfCellRange(grid, p);
            (range.level == 0 ? outside : cells) += 1;
            for (std::uint32_t k = 0; k < range.length; ++k) {
                const SdfOpcode opcode = SdfOpcode(grid.code[grid.words[range.offset + k]].opcode);
                ASSERT_TRUE(opcode != SdfOpcode::Combine && opcode != SdfOpcode::Accumulate)
                    << "bounded " << bounded << ", level " << range.level;
            }
            const std::span<const std::uint32_t> list =
                std::span(grid.words).subspan(range.offset, range.length);
            const float whole = sdfDistance(c->program, p);
            const float read =
                std::min(sdfDistanceOrdered(c->program, grid.code, list, p, nullptr, grid.reading),
                         sdfCellOutsideFloor(grid, p));
            if (range.level == 0) {
                ASSERT_EQ(range.length, 0u) << bounded;
                ASSERT_LE(read, whole + 1e-5f * (1.0f + std::abs(whole))) << bounded;
                ASSERT_GT(read, 0.01f * grid.size) << bounded; // the floor's margin
            } else if (whole < grid.size / float(1 << (2 * range.level)))
                ASSERT_NEAR(read, whole, 1e-5f * (1.0f + std::abs(whole))) << bounded;
            else // a far cell's constant: a bound
                ASSERT_LE(read, whole + 1e-5f * (1.0f + std::abs(whole))) << bounded;
        }
        EXPECT_GT(cells, 1000);
        EXPECT_GT(outside, 1000);
        EXPECT_EQ(expectCellsAgree(*c, grid, rng, 1000, bounded ? "bounded" : "flat"), 1000);
    }
    // A smooth union among them: a postfix program, its unions listed.
    const std::string smooth = R"({"children": [{"shape": "sphere"}, {"op": "smooth_union",
        "smoothness": 0.2, "children": [{"shape": "box", "position": [0.8, 0, 0]},
        {"shape": "sphere", "position": [1.4, 0, 0]}]}]})";
    const std::optional<Compiled> c = compileText(smooth, false);
    ASSERT_TRUE(c);
    EXPECT_FALSE(sdfIsLeastOfShapes(c->program));
    const SdfCellGrid grid = buildSdfCells(c->program, sdfContentBox(*c->scene.sdf));
    EXPECT_EQ(grid.reading, SdfListReading::PostfixPairs);
    bool combines = false;
    for (const GpuSdfInstruction& in : sdfCellProgram(grid, glm::vec3(1.1f, 0.0f, 0.0f)))
        combines = combines || SdfOpcode(in.opcode) == SdfOpcode::Combine;
    EXPECT_TRUE(combines);
    EXPECT_EQ(expectCellsAgree(*c, grid, rng, 500, "smooth"), 500);
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
