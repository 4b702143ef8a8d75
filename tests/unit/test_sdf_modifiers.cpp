// Modifiers, cut nodes and profile solids: property tests on the CPU evaluator (repetition,
// mirror, polar repetition, rounding, onion, elongation, taper, the step corrections of twist,
// bend, taper and displacement against a brute-force surface distance, cut = explicit subtraction),
// the instructions the compiler emits for them and its limits, and the scene reader's errors.
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"
#include "sdf/modifiers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

using namespace rmsc;

namespace {

std::string sceneWithSdf(const std::string& sdf) {
    return R"({"version": 1, "materials": {"red": {}, "blue": {}}, "sdf": )" + sdf + "}";
}

// Reads and compiles an "sdf" node written as JSON; fails the test on any error.
SdfProgram compileJson(const std::string& sdf) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = parseScene(sceneWithSdf(sdf), "test.json", diagnostics);
    EXPECT_TRUE(scene && scene->sdf) << diagnostics.format();
    if (!scene || !scene->sdf) return {};
    const std::optional<SdfProgram> program =
        compileSdf(*scene->sdf, std::uint32_t(scene->materials.size()), "test.json", diagnostics);
    EXPECT_TRUE(program) << diagnostics.format();
    return program ? *program : SdfProgram{};
}

// The modifiers of a sphere read from a JSON array of modifiers.
std::vector<SdfModifier> compileJsonModifiers(const std::string& modifiers) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene =
        parseScene(sceneWithSdf(R"({"shape": "sphere", "modifiers": )" + modifiers + "}"), "m.json",
                   diagnostics);
    EXPECT_TRUE(scene && scene->sdf) << diagnostics.format();
    return scene && scene->sdf ? scene->sdf->modifiers : std::vector<SdfModifier>{};
}

// The diagnostics of reading (and, if that succeeds, compiling) a scene that must fail.
Diagnostics failuresOf(const std::string& sdf) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = parseScene(sceneWithSdf(sdf), "bad.json", diagnostics);
    if (scene && scene->sdf) {
        EXPECT_FALSE(compileSdf(*scene->sdf, 2, "bad.json", diagnostics)) << sdf;
    }
    EXPECT_TRUE(diagnostics.hasErrors()) << sdf;
    return diagnostics;
}

// Expects an error at `location` whose message contains `words`.
void expectError(const std::string& sdf, const std::string& location, const std::string& words) {
    const Diagnostics d = failuresOf(sdf);
    bool found = false;
    for (const Diagnostic& item : d.items)
        found = found || (item.severity == Severity::Error && item.location == location &&
                          item.message.find(words) != std::string::npos);
    EXPECT_TRUE(found) << "expected an error at " << location << " containing \"" << words
                       << "\"; got:\n"
                       << d.format();
}

std::vector<glm::vec3> randomPoints(int count, glm::vec3 lo, glm::vec3 hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> points;
    for (int i = 0; i < count; ++i)
        points.push_back(lo + (hi - lo) * glm::vec3(u(rng), u(rng), u(rng)));
    return points;
}

// Points of the zero set of `program` inside the box [lo, hi]: every sign change along the
// edges of a grid of spacing h, located by bisection. Only the sign of the field is used, which
// the step corrections do not change, so the points lie on the true surface.
std::vector<glm::vec3> surfacePoints(const SdfProgram& program, glm::vec3 lo, glm::vec3 hi,
                                     float h) {
    const glm::ivec3 n = glm::ivec3((hi - lo) / h) + 1;
    std::vector<float> values(std::size_t(n.x * n.y * n.z));
    auto at = [&](int x, int y, int z) { return lo + h * glm::vec3(x, y, z); };
    auto index = [&](int x, int y, int z) { return std::size_t((z * n.y + y) * n.x + x); };
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                values[index(x, y, z)] = sdfDistance(program, at(x, y, z));
    std::vector<glm::vec3> points;
    const glm::ivec3 steps[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                for (const glm::ivec3& s : steps) {
                    const glm::ivec3 e = glm::ivec3(x, y, z) + s;
                    if (e.x >= n.x || e.y >= n.y || e.z >= n.z) continue;
                    if ((values[index(x, y, z)] < 0.0f) == (values[index(e.x, e.y, e.z)] < 0.0f))
                        continue;
                    glm::vec3 a = at(x, y, z);
                    glm::vec3 b = at(e.x, e.y, e.z);
                    const bool aInside = values[index(x, y, z)] < 0.0f;
                    for (int i = 0; i < 24; ++i) {
                        const glm::vec3 m = 0.5f * (a + b);
                        ((sdfDistance(program, m) < 0.0f) == aInside ? a : b) = m;
                    }
                    points.push_back(0.5f * (a + b));
                }
    return points;
}

// Checks that `program` never overestimates the distance to its surface (inside [lo, hi]) at
// sampled outside points, and that the field times `lipschitz` (the correction undone) does
// overestimate somewhere, so the correction is needed and the check can see it.
void expectSafeBound(const SdfProgram& program, glm::vec3 lo, glm::vec3 hi, double lipschitz) {
    const std::vector<glm::vec3> surface = surfacePoints(program, lo, hi, 0.02f);
    ASSERT_GT(surface.size(), 1000u);
    int outside = 0;
    int uncorrectedOverestimates = 0;
    float worst = -1e9f;
    for (const glm::vec3& p : randomPoints(400, lo - 0.3f, hi + 0.3f, 7)) {
        const float estimate = sdfDistance(program, p);
        if (estimate <= 0.0f) continue;
        ++outside;
        float brute = 1e30f;
        for (const glm::vec3& s : surface)
            brute = std::min(brute, glm::length(p - s));
        // brute >= the true distance (it measures to points on the surface).
        worst = std::max(worst, estimate - brute);
        EXPECT_LE(estimate, brute + 1e-4f) << "at " << p.x << ", " << p.y << ", " << p.z;
        if (float(estimate * lipschitz) > brute + 1e-3f) ++uncorrectedOverestimates;
    }
    EXPECT_GT(outside, 100);
    EXPECT_GT(uncorrectedOverestimates, 0) << "the correction was not needed here";
}

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

} // namespace

TEST(SdfModifiers, RepeatedFieldEqualsTheOriginalInsideCellZero) {
    const std::string shape =
        R"({"shape": "box", "half_extents": [0.2, 0.3, 0.1], "position": [0.1, 0, 0.05])";
    const SdfProgram original = compileJson(shape + "}");
    const SdfProgram repeated =
        compileJson(R"({"modifiers": [{"type": "repeat", "period": [1, 0, 1.5]}], "children": [)" +
                    shape + "}]}");
    for (const glm::vec3& p : randomPoints(200, {-0.5f, -2, -0.75f}, {0.5f, 2, 0.75f}, 1)) {
        EXPECT_NEAR(sdfDistance(repeated, p), sdfDistance(original, p), 1e-5f);
        // Every cell is a copy: shifted by whole periods the field is the same.
        EXPECT_NEAR(sdfDistance(repeated, p + glm::vec3(3, 0, -4.5f)), sdfDistance(original, p),
                    1e-4f);
    }
    // y has period 0: not repeated.
    EXPECT_NEAR(sdfDistance(repeated, {0.1f, 5, 0.05f}), 4.7f, 1e-5f);
}

TEST(SdfModifiers, LimitedRepetitionStopsAfterTheCount) {
    // 3 copies along x at -1, 0, 1 (odd count: cell 0 is centred on the origin).
    const SdfProgram program = compileJson(
        R"({"shape": "sphere", "radius": 0.25,
            "modifiers": [{"type": "repeat", "period": [1, 0, 0], "count": [3, 0, 0]}]})");
    EXPECT_NEAR(sdfDistance(program, {0, 0, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(program, {1, 0, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(program, {-1, 0, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(program, {5, 0, 0}), 3.75f, 1e-5f);  // nearest copy at x = 1
    EXPECT_NEAR(sdfDistance(program, {-4, 0, 0}), 2.75f, 1e-5f); // nearest copy at x = -1
    // Even counts are centred too: 2 copies at -0.5 and 0.5.
    const SdfProgram two = compileJson(
        R"({"shape": "sphere", "radius": 0.25,
            "modifiers": [{"type": "repeat", "period": [1, 0, 0], "count": [2, 0, 0]}]})");
    EXPECT_NEAR(sdfDistance(two, {0.5f, 0, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(two, {-0.5f, 0, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(two, {3, 0, 0}), 2.25f, 1e-5f);
}

TEST(SdfModifiers, NeighbourCheckFindsContentReachingIntoTheNextCell) {
    // A sphere off centre in its cell reaches over the cell border at x = 0.5. The field of the
    // repetition must equal the union of all copies, computed here directly.
    auto explicitUnion = [](glm::vec3 p) {
        float d = 1e30f;
        for (int i = -6; i <= 6; ++i)
            for (int k = -6; k <= 6; ++k)
                d = std::min(d, glm::length(p - glm::vec3(i + 0.35f, 0, 1.2f * k)) - 0.3f);
        return d;
    };
    const std::string body = R"("children": [{"shape": "sphere", "radius": 0.3,
                                              "position": [0.35, 0, 0]}]})";
    const SdfProgram checked = compileJson(
        R"({"modifiers": [{"type": "repeat", "period": [1, 0, 1.2], "neighbours": true}], )" +
        body);
    const SdfProgram unchecked =
        compileJson(R"({"modifiers": [{"type": "repeat", "period": [1, 0, 1.2]}], )" + body);
    int uncheckedWrong = 0;
    for (const glm::vec3& p : randomPoints(300, {-3, -0.5f, -3}, {3, 0.5f, 3}, 2)) {
        EXPECT_NEAR(sdfDistance(checked, p), explicitUnion(p), 1e-4f);
        if (std::abs(sdfDistance(unchecked, p) - explicitUnion(p)) > 1e-3f) ++uncheckedWrong;
    }
    EXPECT_GT(uncheckedWrong, 10); // without the check the field is wrong near the border
}

TEST(SdfModifiers, MirrorIsSymmetric) {
    const std::string shape = R"({"shape": "box", "half_extents": [0.2, 0.3, 0.1],
                                  "position": [0.5, 0.2, 0.3], "rotation": [10, 20, 30]})";
    const SdfProgram original = compileJson(shape);
    const SdfProgram mirrored = compileJson(
        R"({"modifiers": [{"type": "mirror", "axes": "xz"}], "children": [)" + shape + "]}");
    for (const glm::vec3& p : randomPoints(200, {-2, -2, -2}, {2, 2, 2}, 3)) {
        const float d = sdfDistance(mirrored, p);
        EXPECT_NEAR(sdfDistance(mirrored, {-p.x, p.y, p.z}), d, 1e-6f);
        EXPECT_NEAR(sdfDistance(mirrored, {p.x, p.y, -p.z}), d, 1e-6f);
        EXPECT_NEAR(d,
                    sdfDistance(original, glm::abs(p) * glm::vec3(1, 0, 1) + glm::vec3(0, p.y, 0)),
                    1e-6f);
    }
}

TEST(SdfModifiers, PolarRepetitionIsRotationallySymmetric) {
    const std::string shape = R"({"shape": "box", "half_extents": [0.1, 0.3, 0.05],
                                  "position": [0.6, 0, 0], "rotation": [0, 10, 0]})";
    const SdfProgram original = compileJson(shape);
    const SdfProgram polar =
        compileJson(R"({"modifiers": [{"type": "polar", "count": 7, "axis": "y"}], "children": [)" +
                    shape + "]}");
    const float turn = float(2.0 * std::numbers::pi / 7.0);
    for (const glm::vec3& p : randomPoints(200, {-1.5f, -1, -1.5f}, {1.5f, 1, 1.5f}, 4)) {
        const glm::vec3 rotated(std::cos(turn) * p.x - std::sin(turn) * p.z, p.y,
                                std::sin(turn) * p.x + std::cos(turn) * p.z);
        EXPECT_NEAR(sdfDistance(polar, rotated), sdfDistance(polar, p), 2e-5f);
        // Inside the sector around +x the copy is the original.
        const float angle = std::atan2(p.z, p.x);
        if (std::abs(angle) < 0.5f * turn - 1e-3f) {
            EXPECT_NEAR(sdfDistance(polar, p), sdfDistance(original, p), 2e-5f);
        }
    }
}

TEST(SdfModifiers, RoundingSubtractsTheRadiusInLocalUnits) {
    const std::string box =
        R"("shape": "box", "half_extents": [0.3, 0.2, 0.4], "position": [0.1, 0, 0])";
    const SdfProgram plain = compileJson("{" + box + "}");
    const SdfProgram rounded =
        compileJson("{" + box + R"(, "modifiers": [{"type": "round", "radius": 0.05}]})");
    // Scaled by 2: the radius is in the shape's units, 0.1 in the world.
    const SdfProgram scaledPlain = compileJson("{" + box + R"(, "scale": 2})");
    const SdfProgram scaledRounded = compileJson(
        "{" + box + R"(, "scale": 2, "modifiers": [{"type": "round", "radius": 0.05}]})");
    for (const glm::vec3& p : randomPoints(100, {-2, -2, -2}, {2, 2, 2}, 5)) {
        EXPECT_NEAR(sdfDistance(rounded, p), sdfDistance(plain, p) - 0.05f, 1e-6f);
        EXPECT_NEAR(sdfDistance(scaledRounded, p), sdfDistance(scaledPlain, p) - 0.1f, 1e-5f);
    }
}

TEST(SdfModifiers, OnionIsAShellAndNests) {
    const std::string sphere = R"("shape": "sphere", "radius": 0.5)";
    const SdfProgram plain = compileJson("{" + sphere + "}");
    const SdfProgram once =
        compileJson("{" + sphere + R"(, "modifiers": [{"type": "onion", "thickness": 0.1}]})");
    const SdfProgram twice = compileJson(
        "{" + sphere +
        R"(, "modifiers": [{"type": "onion", "thickness": 0.1}, {"type": "onion", "thickness": 0.02}]})");
    for (const glm::vec3& p : randomPoints(100, {-1, -1, -1}, {1, 1, 1}, 6)) {
        const float d = sdfDistance(plain, p);
        EXPECT_NEAR(sdfDistance(once, p), std::abs(d) - 0.1f, 1e-6f);
        EXPECT_NEAR(sdfDistance(twice, p), std::abs(std::abs(d) - 0.1f) - 0.02f, 1e-6f);
    }
    // The centre of the sphere is outside the shell, 0.4 from it.
    EXPECT_NEAR(sdfDistance(once, {0, 0, 0}), 0.4f, 1e-6f);
}

TEST(SdfModifiers, ElongationStretchesTheMiddle) {
    // A sphere elongated by 0.5 along x is a capsule from x = -0.5 to 0.5.
    const SdfProgram program = compileJson(
        R"({"shape": "sphere", "radius": 0.2, "position": [0, 1, 0],
            "modifiers": [{"type": "elongate", "half_extents": [0.5, 0, 0]}]})");
    for (const glm::vec3& p : randomPoints(200, {-2, -1, -2}, {2, 3, 2}, 8)) {
        const glm::vec3 q = p - glm::vec3(0, 1, 0);
        const float capsule = glm::length(q - glm::vec3(std::clamp(q.x, -0.5f, 0.5f), 0, 0)) - 0.2f;
        EXPECT_NEAR(sdfDistance(program, p), capsule, 1e-5f);
    }
}

TEST(SdfModifiers, TwistNeverOverestimates) {
    const SdfProgram program = compileJson(
        R"({"shape": "box", "half_extents": [0.25, 0.6, 0.25],
            "modifiers": [{"type": "twist", "amount": 120, "radius": 0.36}]})");
    const double kr = radians(120) * 0.36;
    expectSafeBound(program, {-0.45f, -0.65f, -0.45f}, {0.45f, 0.65f, 0.45f},
                    kr / 2 + std::sqrt(1 + kr * kr / 4));
}

TEST(SdfModifiers, BendNeverOverestimates) {
    const SdfProgram program = compileJson(
        R"({"shape": "box", "half_extents": [0.6, 0.1, 0.2],
            "modifiers": [{"type": "bend", "amount": 70, "radius": 0.61}]})");
    expectSafeBound(program, {-0.75f, -0.75f, -0.25f}, {0.75f, 0.75f, 0.25f},
                    1 + radians(70) * 0.61);
}

TEST(SdfModifiers, TaperScalesXAndZLinearlyAlongY) {
    // A capped cylinder of radius 0.25 and half height 0.5, tapered by 0.8 per unit: at height
    // y its radius is 0.25 (1 + 0.8 y) up to |y| = radius 0.4, and constant beyond.
    const SdfProgram program = compileJson(
        R"({"shape": "capped_cylinder", "radius": 0.25, "half_height": 0.5,
            "modifiers": [{"type": "taper", "amount": 0.8, "radius": 0.4}]})");
    for (const float y : {-0.45f, -0.3f, 0.0f, 0.2f, 0.35f, 0.45f}) {
        const float radius = 0.25f * (1.0f + 0.8f * std::clamp(y, -0.4f, 0.4f));
        for (const float angle : {0.0f, 1.0f, 2.5f, 4.0f}) {
            const glm::vec3 direction(std::cos(angle), 0.0f, std::sin(angle));
            const glm::vec3 on = direction * radius + glm::vec3(0.0f, y, 0.0f);
            EXPECT_NEAR(sdfDistance(program, on), 0.0f, 1e-5f) << y << " " << angle;
            EXPECT_LT(sdfDistance(program, on - 0.01f * direction), 0.0f) << y;
            EXPECT_GT(sdfDistance(program, on + 0.01f * direction), 0.0f) << y;
        }
    }
    // Amount 0 leaves the content as it was.
    const SdfProgram plain = compileJson(R"({"shape": "capped_cylinder", "radius": 0.25})");
    const SdfProgram zero = compileJson(
        R"({"shape": "capped_cylinder", "radius": 0.25, "modifiers": [{"type": "taper", "amount": 0}]})");
    for (const glm::vec3& p : randomPoints(50, glm::vec3(-1.0f), glm::vec3(1.0f), 3))
        EXPECT_EQ(sdfDistance(zero, p), sdfDistance(plain, p));
}

TEST(SdfModifiers, TaperNeverOverestimates) {
    const SdfProgram program = compileJson(
        R"({"shape": "box", "half_extents": [0.2, 0.5, 0.2],
            "modifiers": [{"type": "taper", "amount": -1.2, "radius": 0.5}]})");
    const double kr = double(1.2f) * 0.5; // as the reader stores it
    const double m = 1.0 / (1.0 - kr);
    const double trace = m * m * (1.0 + kr * kr) + 1.0;
    const double lipschitz = std::sqrt(0.5 * (trace + std::sqrt(trace * trace - 4.0 * m * m)));
    EXPECT_NEAR(sdfFieldShrink(
                    compileJsonModifiers(R"([{"type": "taper", "amount": -1.2, "radius": 0.5}])")),
                lipschitz, 1e-9);
    expectSafeBound(program, {-0.35f, -0.55f, -0.35f}, {0.35f, 0.55f, 0.35f}, lipschitz);
}

TEST(SdfModifiers, DisplacementNeverOverestimates) {
    const SdfProgram program = compileJson(
        R"({"shape": "sphere", "radius": 0.45,
            "modifiers": [{"type": "displace", "amplitude": 0.06, "frequency": 5}]})");
    expectSafeBound(program, {-0.55f, -0.55f, -0.55f}, {0.55f, 0.55f, 0.55f},
                    1 + 0.06 * 5 * 3 * std::sqrt(3.0));
    // The surface moves: the displaced field is not the sphere's.
    int moved = 0;
    for (const glm::vec3& p : randomPoints(50, {-1, -1, -1}, {1, 1, 1}, 9))
        if (std::abs(sdfDistance(program, p) * (1 + 0.06f * 5 * 3 * std::sqrt(3.0f)) -
                     (glm::length(p) - 0.45f)) > 1e-3f)
            ++moved;
    EXPECT_GT(moved, 40);
}

TEST(SdfModifiers, CutEqualsExplicitSubtraction) {
    const std::string a = R"({"shape": "box", "half_extents": [0.5, 0.5, 0.5]})";
    const std::string b = R"({"shape": "sphere", "radius": 0.4, "position": [0.5, 0.5, 0]})";
    const std::string c = R"({"shape": "sphere", "radius": 0.3, "position": [-0.6, 0, 0]})";
    const std::string cutB =
        R"({"shape": "sphere", "radius": 0.4, "position": [0.5, 0.5, 0], "cut": true})";
    const SdfProgram withCut = compileJson(R"({"children": [)" + a + "," + cutB + "," + c + "]}");
    const SdfProgram explicitly = compileJson(
        R"({"op": "subtraction", "children": [{"children": [)" + a + "," + c + "]}," + b + "]}");
    for (const glm::vec3& p : randomPoints(200, {-1.5f, -1.5f, -1.5f}, {1.5f, 1.5f, 1.5f}, 10))
        EXPECT_NEAR(sdfDistance(withCut, p), sdfDistance(explicitly, p), 1e-6f);
}

TEST(SdfModifiers, ModifiersOnAGroupActInTheGroupsFrame) {
    // A group moved to x = 2 and scaled by 0.5, mirrored in its own x: its child at local
    // x = 1 appears at world x = 2.5 and (mirrored) x = 1.5, radius 0.25 in the world.
    const SdfProgram program = compileJson(
        R"({"position": [2, 0, 0], "scale": 0.5, "modifiers": [{"type": "mirror", "axes": "x"}],
            "children": [{"shape": "sphere", "radius": 0.5, "position": [1, 0, 0]}]})");
    EXPECT_NEAR(sdfDistance(program, {2.5f, 0, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(program, {1.5f, 0, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(program, {2.5f, 1, 0}), 0.75f, 1e-6f);
    EXPECT_NEAR(sdfDistance(program, {2, 0, 0}), 0.25f, 1e-6f);
}

TEST(SdfModifiers, SurfaceCarriesMaterialsThroughModifiers) {
    const SdfProgram program = compileJson(
        R"({"children": [
             {"shape": "sphere", "radius": 0.3, "material": "red",
              "modifiers": [{"type": "repeat", "period": [1, 0, 0], "count": [3, 0, 0], "neighbours": true},
                            {"type": "twist", "amount": 10}]},
             {"shape": "box", "half_extents": [0.2, 0.2, 0.2], "position": [0, 2, 0], "material": "blue",
              "modifiers": [{"type": "round", "radius": 0.05}]}]})");
    std::vector<Material> materials(3);
    materials[0].baseColor = {1, 0, 0};
    materials[1].baseColor = {0, 0, 1};
    const SdfSurface red = sdfSurface(program, materials, {1.0f, 0.29f, 0});
    EXPECT_EQ(red.baseColor, glm::vec3(1, 0, 0));
    EXPECT_EQ(red.objectId, kSdfIdBase + 1);
    EXPECT_NEAR(red.distance, sdfDistance(program, {1.0f, 0.29f, 0}), 1e-6f);
    const SdfSurface blue = sdfSurface(program, materials, {0, 2.25f, 0});
    EXPECT_EQ(blue.baseColor, glm::vec3(0, 0, 1));
    EXPECT_NEAR(blue.distance, 0.0f, 1e-6f);
}

TEST(SdfProfiles, ExtrudedRectangleIsABox) {
    const SdfProgram extrusion = compileJson(
        R"({"shape": "extrusion", "depth": 0.6, "profile": {"type": "rectangle", "half_size": [0.4, 0.2]}})");
    const SdfProgram box = compileJson(R"({"shape": "box", "half_extents": [0.4, 0.2, 0.3]})");
    for (const glm::vec3& p : randomPoints(200, {-1, -1, -1}, {1, 1, 1}, 11))
        EXPECT_NEAR(sdfDistance(extrusion, p), sdfDistance(box, p), 1e-5f);
}

TEST(SdfProfiles, RevolvedCircleIsATorus) {
    const SdfProgram revolution = compileJson(
        R"({"shape": "revolution", "offset": 0.5, "profile": {"type": "circle", "radius": 0.15}})");
    const SdfProgram torus =
        compileJson(R"({"shape": "torus", "major_radius": 0.5, "minor_radius": 0.15})");
    for (const glm::vec3& p : randomPoints(200, {-1, -1, -1}, {1, 1, 1}, 12))
        EXPECT_NEAR(sdfDistance(revolution, p), sdfDistance(torus, p), 1e-5f);
}

TEST(SdfProfiles, PolygonMatchesTheRectangleAndRoundedRectangleIsARoundedBox) {
    // A square written as a polygon (clockwise) equals the rectangle profile.
    const SdfProgram polygon = compileJson(
        R"({"shape": "extrusion", "depth": 0.4, "profile": {"type": "polygon",
            "points": [[-0.3, -0.3], [-0.3, 0.3], [0.3, 0.3], [0.3, -0.3]]}})");
    const SdfProgram rectangle = compileJson(
        R"({"shape": "extrusion", "depth": 0.4, "profile": {"type": "rectangle", "half_size": [0.3, 0.3]}})");
    for (const glm::vec3& p : randomPoints(200, {-1, -1, -1}, {1, 1, 1}, 13))
        EXPECT_NEAR(sdfDistance(polygon, p), sdfDistance(rectangle, p), 1e-5f);
    // A concave polygon: an L. (0.75, 0.75) is in the notch, outside.
    const SdfProgram l = compileJson(
        R"({"shape": "extrusion", "depth": 2, "profile": {"type": "polygon",
            "points": [[0, 0], [1, 0], [1, 0.5], [0.5, 0.5], [0.5, 1], [0, 1]]}})");
    EXPECT_NEAR(sdfDistance(l, {0.75f, 0.75f, 0}), 0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(l, {0.25f, 0.25f, 0}), -0.25f, 1e-6f);
    EXPECT_NEAR(sdfDistance(l, {0.25f, 0.75f, 0}), -0.25f, 1e-6f);
    // The rounded rectangle extruded is the catalogue's round box only in 2D; check the profile:
    // at the corner direction the distance is |q - (h - r)| - r.
    const SdfProgram rounded = compileJson(
        R"({"shape": "revolution", "profile": {"type": "rounded_rectangle", "half_size": [0.3, 0.2], "radius": 0.1}})");
    EXPECT_NEAR(sdfDistance(rounded, {0.5f, 0.3f, 0}),
                glm::length(glm::vec2(0.5f, 0.3f) - glm::vec2(0.2f, 0.1f)) - 0.1f, 1e-6f);
}

TEST(SdfCompilerModifiers, EmitsPointFramesOnlyWhereThePointIsNeeded) {
    const SdfProgram rounded =
        compileJson(R"({"shape": "sphere", "modifiers": [{"type": "round", "radius": 0.1}]})");
    ASSERT_EQ(rounded.instructions.size(), 2u);
    EXPECT_EQ(rounded.instructions[0].opcode, std::uint32_t(SdfOpcode::Shape));
    EXPECT_EQ(rounded.instructions[1].opcode, std::uint32_t(SdfOpcode::DistanceModifier));
    EXPECT_EQ(rounded.pointStackDepth, 0);

    const SdfProgram twisted = compileJson(
        R"({"shape": "sphere", "position": [1, 2, 3],
            "modifiers": [{"type": "round", "radius": 0.1}, {"type": "twist", "amount": 30}]})");
    const std::vector<SdfOpcode> expected = {SdfOpcode::PushPoint, SdfOpcode::PointModifier,
                                             SdfOpcode::Shape, SdfOpcode::DistanceModifier,
                                             SdfOpcode::PopPoint};
    ASSERT_EQ(twisted.instructions.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_EQ(twisted.instructions[i].opcode, std::uint32_t(expected[i])) << i;
    EXPECT_EQ(twisted.instructions[1].kind, modifierKind(SdfModifierType::Twist));
    EXPECT_NEAR(twisted.instructions[1].params[0].x, radians(30), 1e-6);
    // The push carries the node's world-to-local; the shape then reads the point as it is.
    EXPECT_EQ(twisted.instructions[0].worldToLocal[1], glm::vec4(0, 1, 0, -2));
    EXPECT_EQ(twisted.instructions[2].worldToLocal[0], glm::vec4(1, 0, 0, 0));
    EXPECT_EQ(twisted.pointStackDepth, 1);
}

TEST(SdfCompilerModifiers, NeighbourCheckEvaluatesEachCellCombination) {
    // Two repeated axes: 4 cells, each PushPoint, Repeat, shape, PopPoint; 3 unions.
    const SdfProgram program = compileJson(
        R"({"shape": "sphere", "modifiers": [{"type": "repeat", "period": [1, 0, 1], "neighbours": true}]})");
    int pushes = 0, repeats = 0, shapes = 0, pops = 0, combines = 0;
    std::set<std::pair<float, float>> selectors;
    for (const GpuSdfInstruction& i : program.instructions) {
        pushes += i.opcode == std::uint32_t(SdfOpcode::PushPoint);
        pops += i.opcode == std::uint32_t(SdfOpcode::PopPoint);
        shapes += i.opcode == std::uint32_t(SdfOpcode::Shape);
        combines += i.opcode == std::uint32_t(SdfOpcode::Combine);
        if (i.opcode == std::uint32_t(SdfOpcode::PointModifier)) {
            ++repeats;
            EXPECT_EQ(i.params[2].w, 1.0f);
            EXPECT_EQ(i.params[2].y, 0.0f); // y is not repeated
            selectors.insert({i.params[2].x, i.params[2].z});
        }
    }
    EXPECT_EQ(pushes, 5); // the node's frame and one per cell
    EXPECT_EQ(pops, 5);
    EXPECT_EQ(repeats, 4);
    EXPECT_EQ(shapes, 4);
    EXPECT_EQ(combines, 3);
    EXPECT_EQ(selectors.size(), 4u);
    EXPECT_EQ(program.stackDepth, 2);
    EXPECT_EQ(program.pointStackDepth, 2);
    EXPECT_EQ(program.instructions.size(), std::size_t(2 + 4 * 4 + 3));
}

TEST(SdfCompilerModifiers, PolygonPointsGoToTheDataBuffer) {
    const SdfProgram program = compileJson(
        R"({"children": [
             {"shape": "extrusion", "profile": {"type": "polygon", "points": [[0, 0], [1, 0], [0, 1]]}},
             {"shape": "revolution", "profile": {"type": "polygon", "points": [[0, 0], [1, 0], [1, 1], [0, 1]]}}]})");
    ASSERT_EQ(program.data.size(), 7u);
    EXPECT_EQ(program.data[4], glm::vec4(1, 0, 0, 0));
    ASSERT_EQ(program.instructions.size(), 3u);
    EXPECT_EQ(program.instructions[0].opcode, std::uint32_t(SdfOpcode::Profile));
    EXPECT_EQ(program.instructions[0].params[2], glm::vec4(0, 3, 0, 0));
    EXPECT_EQ(program.instructions[1].params[2], glm::vec4(3, 4, 0, 0));
    EXPECT_EQ(program.instructions[1].params[1].x, 1.0f); // revolution
}

TEST(SdfCompilerModifiers, PointStackLimitNamesTheLimitAndTheExcess) {
    // Each mirrored group nests one point frame: 18 levels need 18 entries.
    auto nested = [](int levels) {
        std::string text = R"({"shape": "sphere"})";
        for (int i = 0; i < levels; ++i)
            text =
                R"({"modifiers": [{"type": "mirror", "axes": "x"}], "position": [0.1, 0, 0], "children": [)" +
                text + "]}";
        return text;
    };
    const SdfProgram fits = compileJson(nested(kSdfMaxPointStack));
    EXPECT_EQ(fits.pointStackDepth, kSdfMaxPointStack);
    expectError(nested(kSdfMaxPointStack + 2), "/sdf",
                "needs a point stack of 18 entries, the shader supports 16 (2 over)");
}

TEST(SdfCompilerModifiers, CutNeedsSiblingsToCutFrom) {
    expectError(R"({"children": [{"shape": "sphere", "cut": true}]})", "/sdf",
                "every child of the group is marked \"cut\"");
    expectError(R"({"shape": "sphere", "cut": true})", "/sdf", "root node cannot be \"cut\"");
}

TEST(SdfModifierErrors, UnknownModifierListsTheKnownOnes) {
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "twirl"}]})", "/sdf/modifiers/0/type",
                "unknown modifier \"twirl\"; known modifiers: \"twist\"");
    expectError(R"({"shape": "sphere", "modifiers": [{"amount": 3}]})", "/sdf/modifiers/0",
                "missing \"type\"");
    expectError(R"({"shape": "sphere", "modifiers": {"type": "round"}})", "/sdf/modifiers",
                "expected an array of modifiers");
}

TEST(SdfModifierErrors, RepetitionPeriodsAndCounts) {
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "repeat", "period": [0, 0, 0]}]})",
                "/sdf/modifiers/0/period", "period is 0 on every axis");
    expectError(
        R"({"shape": "sphere", "modifiers": [{"type": "repeat", "period": [1, -2, 0], "count": [2, 2, 0]}]})",
        "/sdf/modifiers/0/period/1", "expected a period in [0, 10000]");
    expectError(
        R"({"shape": "sphere", "modifiers": [{"type": "repeat", "period": [1, 0, 0], "count": [2, 3, 0]}]})",
        "/sdf/modifiers/0/count/1", "count 3 along y needs a period > 0");
    expectError(
        R"({"shape": "sphere", "modifiers": [{"type": "repeat", "period": [1, 0, 0], "count": [2.5, 0, 0]}]})",
        "/sdf/modifiers/0/count/0", "integer");
    expectError(
        R"({"shape": "sphere", "modifiers": [{"type": "repeat", "period": [1, 0, 0], "count": [-1, 0, 0]}]})",
        "/sdf/modifiers/0/count/0", "");
    expectError(
        R"({"shape": "sphere", "modifiers": [{"type": "repeat", "period": [1, 0, 0], "count": [2, 0]}]})",
        "/sdf/modifiers/0/count", "expected 3 integers");
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "repeat"}]})", "/sdf/modifiers/0",
                "missing \"period\"");
}

TEST(SdfModifierErrors, OtherModifierParameters) {
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "polar", "count": 0}]})",
                "/sdf/modifiers/0/count", "");
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "polar", "count": 4, "axis": "w"}]})",
                "/sdf/modifiers/0/axis", "expected an axis");
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "mirror", "axes": "xx"}]})",
                "/sdf/modifiers/0/axes", "different axes");
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "onion", "thickness": 0}]})",
                "/sdf/modifiers/0/thickness", "");
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "twist"}]})", "/sdf/modifiers/0",
                "missing \"amount\"");
    expectError(R"({"shape": "sphere", "cut": 1})", "/sdf/cut", "expected true or false");
    expectError(
        R"({"shape": "sphere", "modifiers": [{"type": "taper", "amount": 2, "radius": 0.5}]})",
        "/sdf/modifiers/0/amount",
        "the taper 2 reaches a scale of 0 within the radius 0.5; |amount| x radius must be "
        "below 1");
    expectError(R"({"shape": "sphere", "modifiers": [{"type": "taper"}]})", "/sdf/modifiers/0",
                "missing \"amount\"");
}

TEST(SdfModifierErrors, ProfileErrors) {
    expectError(
        R"({"shape": "extrusion", "profile": {"type": "polygon", "points": [[0, 0], [1, 0]]}})",
        "/sdf/profile/points", "a polygon needs 3 to 256 points, got 2");
    expectError(
        R"({"shape": "extrusion", "profile": {"type": "polygon", "points": [[0, 0], [1, 1], [2, 2]]}})",
        "/sdf/profile/points", "enclose no area");
    expectError(
        R"({"shape": "extrusion", "profile": {"type": "polygon", "points": [[0, 0], [1, "a"], [2, 0]]}})",
        "/sdf/profile/points/1/1", "");
    expectError(R"({"shape": "revolution", "profile": {"type": "hexagon"}})", "/sdf/profile/type",
                "unknown profile type \"hexagon\"");
    expectError(R"({"shape": "extrusion"})", "/sdf", "missing \"profile\"");
    expectError(
        R"({"shape": "extrusion", "profile": {"type": "rounded_rectangle", "half_size": [0.2, 0.1], "radius": 0.3}})",
        "/sdf/profile/radius", "larger than the smaller half size");
}

TEST(SdfModifierErrors, RoundTripKeepsModifiersCutAndProfiles) {
    const std::string sdf = R"({"children": [
        {"shape": "box", "modifiers": [{"type": "repeat", "period": [1, 0, 2], "count": [3, 0, 0], "neighbours": true},
                                       {"type": "mirror", "axes": "xz"}, {"type": "polar", "count": 5, "axis": "z"},
                                       {"type": "elongate", "half_extents": [0.1, 0, 0.2]},
                                       {"type": "twist", "amount": 20, "radius": 2}, {"type": "bend", "amount": -5, "radius": 1},
                                       {"type": "taper", "amount": 0.3, "radius": 2},
                                       {"type": "round", "radius": 0.05}, {"type": "onion", "thickness": 0.01},
                                       {"type": "displace", "amplitude": 0.02, "frequency": 3}]},
        {"shape": "sphere", "cut": true},
        {"shape": "extrusion", "depth": 0.3, "profile": {"type": "polygon", "points": [[0, 0], [1, 0], [0, 1]]}},
        {"shape": "revolution", "offset": 0.4, "profile": {"type": "rounded_rectangle", "half_size": [0.2, 0.3], "radius": 0.05}}]})";
    Diagnostics d;
    const std::optional<Scene> scene = parseScene(sceneWithSdf(sdf), "a.json", d);
    ASSERT_TRUE(scene) << d.format();
    const std::string written = sceneToJson(*scene);
    const std::optional<Scene> again = parseScene(written, "b.json", d);
    ASSERT_TRUE(again) << d.format() << written;
    EXPECT_EQ(sceneToJson(*again), written);
    EXPECT_NE(written.find("\"neighbours\": true"), std::string::npos);
    EXPECT_NE(written.find("\"cut\": true"), std::string::npos);
    EXPECT_NE(written.find("\"rounded_rectangle\""), std::string::npos);
    ASSERT_EQ(again->sdf->children[0].modifiers.size(), 10u);
    EXPECT_EQ(again->sdf->children[0].modifiers[6].type, SdfModifierType::Taper);
    EXPECT_EQ(again->sdf->children[0].modifiers[6].amount, 0.3f);
    EXPECT_EQ(again->sdf->children[0].modifiers[2].axis, 2);
    EXPECT_EQ(again->sdf->children[0].modifiers[0].counts, glm::ivec3(3, 0, 0));
}
