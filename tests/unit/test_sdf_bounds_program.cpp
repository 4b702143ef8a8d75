// The compiler's bounding hierarchy (SdfCompileOptions::bounds): the plain unions at the top of
// the tree become a hierarchy of box tests that skip far parts. Where every part is an exact
// distance the value is the same as without it; where parts are lower bounds it is never less
// than without it and never more than the true distance, so the same rays hit the same
// surfaces; and far parts are really skipped.
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"
#include "sdf/glsl_codegen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace rmsc;

namespace {

struct Programs {
    SdfProgram bounded, plain;
};

Programs compileBoth(const std::string& sdf) {
    Diagnostics d;
    const std::optional<Scene> scene = parseScene(
        R"({"version": 1, "materials": {"a": {}, "b": {}}, "sdf": )" + sdf + "}", "test.json", d);
    EXPECT_TRUE(scene) << d.format();
    if (!scene) return {};
    std::optional<SdfProgram> bounded = compileSdf(*scene->sdf, 2, "test.json", d);
    std::optional<SdfProgram> plain = compileSdf(*scene->sdf, 2, "test.json", d, {.bounds = false});
    EXPECT_TRUE(bounded && plain) << d.format();
    return {bounded ? *bounded : SdfProgram{}, plain ? *plain : SdfProgram{}};
}

// An n x n x n grid of alternating spheres and boxes, spacing 1, centred on the origin.
std::string grid(int n, const std::string& extra = "") {
    std::string children;
    for (int i = 0; i < n * n * n; ++i) {
        const float x = float(i % n) - 0.5f * float(n - 1);
        const float y = float(i / n % n) - 0.5f * float(n - 1);
        const float z = float(i / (n * n)) - 0.5f * float(n - 1);
        const std::string at =
            "[" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "]";
        children +=
            (children.empty() ? "" : ", ") +
            (i % 2 ? R"({"shape": "box", "half_extents": [0.2, 0.25, 0.3], "position": )" + at + "}"
                   : R"({"shape": "sphere", "radius": 0.3, "position": )" + at + "}");
    }
    return R"({"op": "union", "children": [)" + children + extra + "]}";
}

glm::vec3 samplePoint(int i, float extent) {
    return extent * glm::vec3(std::sin(i * 12.9898f) * 0.97f, std::sin(i * 78.233f + 1.0f) * 0.97f,
                              std::sin(i * 37.719f + 2.0f) * 0.97f);
}

int count(const SdfProgram& program, SdfOpcode opcode) {
    int n = 0;
    for (const GpuSdfInstruction& in : program.instructions)
        n += SdfOpcode(in.opcode) == opcode;
    return n;
}

} // namespace

TEST(SdfBoundsProgram, ExactPartsGiveExactlyTheSameDistancesAndSurfaces) {
    // A grid, a nested plain union moved as one, a smooth union part and an unbounded plane.
    const Programs p = compileBoth(grid(3, R"(,
        {"op": "union", "position": [3, 0, 0], "rotation": [0, 30, 0], "children": [
            {"shape": "torus"}, {"shape": "sphere", "radius": 0.2, "position": [0, 1, 0]}]},
        {"op": "smooth_union", "smoothness": 0.3, "position": [-3, 0, 0], "material": "b",
         "children": [{"shape": "sphere"}, {"shape": "box", "position": [0.5, 0, 0]}]},
        {"shape": "plane", "normal": [0, 1, 0], "offset": 3})"));
    EXPECT_GT(count(p.bounded, SdfOpcode::BoundSkip), 5);
    EXPECT_EQ(count(p.bounded, SdfOpcode::Accumulate), 27 + 2 + 1 + 1);
    EXPECT_EQ(count(p.plain, SdfOpcode::BoundSkip), 0);
    const std::vector<Material> materials(3);
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 q = samplePoint(i, 4.0f);
        const float bounded = sdfDistance(p.bounded, q);
        ASSERT_EQ(bounded, sdfDistance(p.plain, q)) << "at " << q.x << ", " << q.y << ", " << q.z;
        EXPECT_EQ(sdfSurface(p.bounded, materials, q).objectId,
                  sdfSurface(p.plain, materials, q).objectId);
    }
}

TEST(SdfBoundsProgram, LowerBoundPartsStaySafeAndRaysHitTheSameSurfaces) {
    // Twisted and non-uniformly scaled parts: their fields are lower bounds of the distance.
    const Programs p = compileBoth(grid(2, R"(,
        {"shape": "box", "half_extents": [0.2, 0.6, 0.2], "position": [2.5, 0, 0],
         "modifiers": [{"type": "twist", "amount": 90, "radius": 0.3}]},
        {"shape": "sphere", "position": [-2.5, 0, 0], "scale": [1, 0.3, 2]})"));
    RenderSettings settings;
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 q = samplePoint(i, 3.5f);
        EXPECT_GE(sdfDistance(p.bounded, q), sdfDistance(p.plain, q));
        const glm::vec3 origin(q.x, q.y, 6.0f);
        const glm::vec3 target(q.x * 0.85f, q.y * 0.25f, 0.0f); // across the row of parts
        const glm::vec3 direction = glm::normalize(target - origin);
        const std::optional<SdfHit> a = sdfCastRay(p.bounded, settings, origin, direction, 0, 20);
        const std::optional<SdfHit> b = sdfCastRay(p.plain, settings, origin, direction, 0, 20);
        ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
        if (!a) continue;
        ++hits;
        EXPECT_NEAR(a->t, b->t, 5e-3f) << "ray " << i;
    }
    EXPECT_GT(hits, 40);
}

// The point of the hierarchy: far parts are not evaluated. In a 1,000-shape grid a point
// evaluates a few tens of shapes, not 1,000, and 37 times the shapes of a 27-shape grid cost
// a few times the evaluations (measured: 26.5 against 8.2; without SeedBest, 48 against 8.2).
TEST(SdfBoundsProgram, FarPartsAreSkipped) {
    const Programs big = compileBoth(grid(10));
    const Programs small = compileBoth(grid(3));
    auto averageEvaluations = [](const SdfProgram& program, float extent) {
        long total = 0;
        for (int i = 0; i < 200; ++i) {
            int evaluations = 0;
            sdfDistance(program, samplePoint(i, extent), &evaluations);
            total += evaluations;
        }
        return double(total) / 200.0;
    };
    const double bigBounded = averageEvaluations(big.bounded, 5.0f);
    const double bigPlain = averageEvaluations(big.plain, 5.0f);
    const double smallBounded = averageEvaluations(small.bounded, 1.5f);
    EXPECT_EQ(bigPlain, 1000.0);
    EXPECT_LT(bigBounded, 35.0) << "the hierarchy should skip almost every shape";
    EXPECT_LT(bigBounded, 4.5 * smallBounded) << "37x the shapes, evaluations grow slowly";
}

// Parts whose shapes are united smoothly (or chamfered, or rounded) are not exact, but their
// floors bound them (sdfProgramFloor): a box test against the floor's box grown by its drop
// skips them exactly, so the values stay the same, and a large part is worth a box test even
// when the union has fewer parts than the hierarchy needs otherwise: a plane and two trees of
// 32 spheres (the benchmarks' binary trees, whose whole program ran past the cells' grid).
TEST(SdfBoundsProgram, SmoothlyUnitedPartsAreSkippedByTheirFloors) {
    const auto tree = [](float x, const char* op) {
        std::string children;
        for (int i = 0; i < 32; ++i)
            children += std::string(i ? ", " : "") + R"({"shape": "sphere", "radius": 0.12, )" +
                        R"("position": [)" + std::to_string(x + 0.1f * float(i % 8)) + ", 0.1, " +
                        std::to_string(0.1f * float(i / 8)) + "]}";
        return std::string(R"({"op": ")") + op + R"(", "smoothness": 0.05, "children": [)" +
               children + "]}";
    };
    const Programs p =
        compileBoth(R"({"op": "union", "children": [
        {"shape": "plane", "normal": [0, 1, 0], "offset": 0}, )" +
                    tree(-2.0f, "smooth_union") + ", " + tree(2.0f, "round_union") + "]}");
    EXPECT_EQ(count(p.bounded, SdfOpcode::BoundSkip), 3); // each tree, and both
    EXPECT_EQ(count(p.plain, SdfOpcode::BoundSkip), 0);
    const std::vector<Material> materials(3);
    long boundedEvaluations = 0, plainEvaluations = 0;
    for (int i = 0; i < 3000; ++i) {
        // Near the trees and far from them (up to 40 units: past a cell grid around them).
        const glm::vec3 q = samplePoint(i, i % 2 ? 3.0f : 40.0f);
        int a = 0, b = 0;
        const float bounded = sdfDistance(p.bounded, q, &a);
        ASSERT_EQ(bounded, sdfDistance(p.plain, q, &b))
            << "at " << q.x << ", " << q.y << ", " << q.z;
        EXPECT_EQ(sdfSurface(p.bounded, materials, q).objectId,
                  sdfSurface(p.plain, materials, q).objectId);
        boundedEvaluations += a;
        plainEvaluations += b;
    }
    // Half the points are within 3 units of the trees, where they evaluate one or both: measured
    // 35.2 shapes a point on average against 65.
    EXPECT_EQ(plainEvaluations, 3000 * 65);
    EXPECT_LT(boundedEvaluations, plainEvaluations * 6 / 10);
}

TEST(SdfBoundsProgram, FewPartsAndNonUnionRootsCompileAsTheyAre) {
    const Programs three = compileBoth(R"({"op": "union", "children": [
        {"shape": "sphere"}, {"shape": "box"}, {"shape": "torus"}]})");
    EXPECT_EQ(three.bounded.instructions.size(), three.plain.instructions.size());
    const Programs smooth = compileBoth(R"({"op": "smooth_union", "smoothness": 0.1, "children": [
        {"shape": "sphere"}, {"shape": "box"}, {"shape": "torus"}, {"shape": "capsule"}]})");
    EXPECT_EQ(count(smooth.bounded, SdfOpcode::BoundSkip), 0);
}

// Generated code evaluates every part (box tests cost more than they save on llvmpipe), still
// uniting them into the same value; only the interpreter skips.
TEST(SdfBoundsProgram, GeneratedCodeEvaluatesEveryPart) {
    const Programs p = compileBoth(grid(2));
    int shapes = 0;
    for (const GpuSdfInstruction& in : p.bounded.instructions)
        shapes += SdfOpcode(in.opcode) == SdfOpcode::Shape;
    ASSERT_GT(count(p.bounded, SdfOpcode::BoundSkip), 0);
    for (SdfStrategy strategy : {SdfStrategy::Baked, SdfStrategy::Buffer}) {
        const std::string map = generateSdfMap(p.bounded, strategy);
        EXPECT_EQ(map.find("sdfBoxDistance("), std::string::npos);
        EXPECT_EQ(map.find("sdfSeedDistance("), std::string::npos);
        EXPECT_NE(map.find("best = min(best, s0);"), std::string::npos);
        EXPECT_NE(map.find("return best;"), std::string::npos);
        std::size_t evaluations = 0;
        for (std::size_t at = map.find("SDF_COUNT_EVALUATION;"); at != std::string::npos;
             at = map.find("SDF_COUNT_EVALUATION;", at + 1))
            ++evaluations;
        EXPECT_EQ(evaluations, 2u * std::size_t(shapes)) << "every shape, distance and surface";
    }
}
