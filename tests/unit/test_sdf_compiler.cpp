// The SDF compiler, checked through the CPU evaluator: operations against their definitions,
// group transforms, material inheritance and blending, object ids, the stack order and every
// error the compiler reports.
#include "core/object_ids.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace rmsc;

namespace {

SdfNode sphere(glm::vec3 center, float radius, int material = -1, std::string pointer = "") {
    SdfNode node;
    node.pointer = std::move(pointer);
    node.primitive = PrimitiveId::Sphere;
    node.params[0] = radius;
    node.transform.position = center;
    node.material = material;
    return node;
}

SdfNode group(SdfOp op, std::vector<SdfNode> children, float smoothness = 0.0f,
              std::string pointer = "") {
    SdfNode node;
    node.pointer = std::move(pointer);
    node.isGroup = true;
    node.op = op;
    node.smoothness = smoothness;
    node.children = std::move(children);
    return node;
}

// The tree as it is, without the bounding hierarchy (tested in test_sdf_bounds_program.cpp), so
// the tests can check its exact layout.
SdfProgram compileOrFail(const SdfNode& root, std::uint32_t defaultMaterial = 0) {
    Diagnostics diagnostics;
    std::optional<SdfProgram> program =
        compileSdf(root, defaultMaterial, "test.json", diagnostics, {.bounds = false});
    EXPECT_TRUE(program.has_value()) << diagnostics.format();
    return program ? *program : SdfProgram{};
}

float sphereDistance(glm::vec3 p, glm::vec3 center, float radius) {
    return glm::length(p - center) - radius;
}

std::vector<glm::vec3> samplePoints(int count, float extent, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> coordinate(-extent, extent);
    std::vector<glm::vec3> points;
    for (int i = 0; i < count; ++i)
        points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    return points;
}

const glm::vec3 kCenterA(-0.6f, 0.0f, 0.0f);
const glm::vec3 kCenterB(0.6f, 0.2f, 0.0f);
constexpr float kRadiusA = 0.8f;
constexpr float kRadiusB = 0.5f;

SdfNode twoSpheres(SdfOp op, float smoothness = 0.0f) {
    return group(op, {sphere(kCenterA, kRadiusA), sphere(kCenterB, kRadiusB)}, smoothness);
}

constexpr float kTol = 1e-5f;

} // namespace

TEST(SdfCompiler, UnionIsMinimum) {
    const SdfProgram program = compileOrFail(twoSpheres(SdfOp::Union));
    EXPECT_EQ(program.instructions.size(), 3u);
    EXPECT_EQ(program.stackDepth, 2);
    for (glm::vec3 p : samplePoints(200, 2.0f, 1)) {
        const float a = sphereDistance(p, kCenterA, kRadiusA);
        const float b = sphereDistance(p, kCenterB, kRadiusB);
        EXPECT_NEAR(sdfDistance(program, p), std::min(a, b), kTol);
    }
}

TEST(SdfCompiler, SubtractionIsMaxOfFirstAndNegatedSecond) {
    const SdfProgram program = compileOrFail(twoSpheres(SdfOp::Subtraction));
    for (glm::vec3 p : samplePoints(200, 2.0f, 2)) {
        const float a = sphereDistance(p, kCenterA, kRadiusA);
        const float b = sphereDistance(p, kCenterB, kRadiusB);
        EXPECT_NEAR(sdfDistance(program, p), std::max(a, -b), kTol);
    }
    // Three children: a minus b minus c.
    const glm::vec3 centerC(-1.2f, 0.0f, 0.0f);
    const SdfProgram three = compileOrFail(
        group(SdfOp::Subtraction,
              {sphere(kCenterA, kRadiusA), sphere(kCenterB, kRadiusB), sphere(centerC, 0.3f)}));
    for (glm::vec3 p : samplePoints(200, 2.0f, 3)) {
        const float a = sphereDistance(p, kCenterA, kRadiusA);
        const float b = sphereDistance(p, kCenterB, kRadiusB);
        const float c = sphereDistance(p, centerC, 0.3f);
        EXPECT_NEAR(sdfDistance(three, p), std::max(std::max(a, -b), -c), kTol);
    }
}

TEST(SdfCompiler, IntersectionIsMaximum) {
    const SdfProgram program = compileOrFail(twoSpheres(SdfOp::Intersection));
    for (glm::vec3 p : samplePoints(200, 2.0f, 4)) {
        const float a = sphereDistance(p, kCenterA, kRadiusA);
        const float b = sphereDistance(p, kCenterB, kRadiusB);
        EXPECT_NEAR(sdfDistance(program, p), std::max(a, b), kTol);
    }
}

// The polynomial smooth minimum lies at most k/4 below the minimum and equals it wherever the
// two distances differ by k or more (h is then clamped to 0 or 1).
TEST(SdfCompiler, SmoothUnionIsBelowMinAndEqualWhenApart) {
    const float k = 0.4f;
    const SdfProgram program = compileOrFail(twoSpheres(SdfOp::SmoothUnion, k));
    int apart = 0, blended = 0;
    for (glm::vec3 p : samplePoints(500, 2.0f, 5)) {
        const float a = sphereDistance(p, kCenterA, kRadiusA);
        const float b = sphereDistance(p, kCenterB, kRadiusB);
        const float d = sdfDistance(program, p);
        EXPECT_LE(d, std::min(a, b) + kTol);
        EXPECT_GE(d, std::min(a, b) - k / 4.0f - kTol);
        if (std::abs(a - b) >= k) {
            EXPECT_NEAR(d, std::min(a, b), kTol);
            ++apart;
        } else if (std::abs(a - b) < 0.5f * k) {
            EXPECT_LT(d, std::min(a, b) - 1e-3f); // strictly below where they blend
            ++blended;
        }
    }
    EXPECT_GT(apart, 50);
    EXPECT_GT(blended, 10);
    // Where a = b the blend is halfway: min - k/4.
    const SdfProgram equal = compileOrFail(
        group(SdfOp::SmoothUnion, {sphere({-1, 0, 0}, 0.5f), sphere({1, 0, 0}, 0.5f)}, k));
    EXPECT_NEAR(sdfDistance(equal, {0, 0, 0}), 0.5f - k / 4.0f, kTol);
}

TEST(SdfCompiler, SmoothIntersectionAndSubtractionBoundTheHardOnes) {
    const float k = 0.3f;
    const SdfProgram intersection = compileOrFail(twoSpheres(SdfOp::SmoothIntersection, k));
    const SdfProgram subtraction = compileOrFail(twoSpheres(SdfOp::SmoothSubtraction, k));
    for (glm::vec3 p : samplePoints(300, 2.0f, 6)) {
        const float a = sphereDistance(p, kCenterA, kRadiusA);
        const float b = sphereDistance(p, kCenterB, kRadiusB);
        // smax(a, b) = -smin(-a, -b) >= max(a, b); smooth a - b = smax(a, -b).
        const float dI = sdfDistance(intersection, p);
        const float dS = sdfDistance(subtraction, p);
        EXPECT_GE(dI, std::max(a, b) - kTol);
        EXPECT_GE(dS, std::max(a, -b) - kTol);
        if (std::abs(a - b) >= k) {
            EXPECT_NEAR(dI, std::max(a, b), kTol);
        }
        if (std::abs(a + b) >= k) {
            EXPECT_NEAR(dS, std::max(a, -b), kTol);
        }
    }
}

TEST(SdfCompiler, GroupTransformMovesChildren) {
    SdfNode moved = group(SdfOp::Union, {sphere({0, 1, 0}, 0.5f), sphere({0, -1, 0}, 0.5f)});
    moved.transform.position = {3, 0, 0};
    const SdfProgram program = compileOrFail(moved);
    // The first sphere's centre is (3, 1, 0) now.
    EXPECT_NEAR(sdfDistance(program, {3, 1, 0}), -0.5f, kTol);
    EXPECT_NEAR(sdfDistance(program, {3, 2, 0}), 0.5f, kTol);
    EXPECT_NEAR(sdfDistance(program, {0, 1, 0}), 2.5f, kTol);

    // Rotation by 90 degrees about z takes local +x to world +y; a uniform scale 2 doubles the
    // child's offset and radius, and the distance stays exact.
    SdfNode turned = group(SdfOp::Union, {sphere({1, 0, 0}, 0.5f)});
    turned.transform.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    turned.transform.scale = glm::vec3(2.0f);
    turned.transform.position = {0, 0, 1};
    const SdfProgram turnedProgram = compileOrFail(turned);
    for (glm::vec3 p : samplePoints(100, 4.0f, 7))
        EXPECT_NEAR(sdfDistance(turnedProgram, p), sphereDistance(p, {0, 2, 1}, 1.0f), 1e-4f);

    // Nested groups compose: parent * child.
    SdfNode inner = group(SdfOp::Union, {sphere({0, 0, 1}, 0.25f)});
    inner.transform.position = {0, 1, 0};
    SdfNode outer = group(SdfOp::Union, {inner, sphere({5, 5, 5}, 0.1f)});
    outer.transform.position = {1, 0, 0};
    const SdfProgram nested = compileOrFail(outer);
    EXPECT_NEAR(sdfDistance(nested, {1, 1, 1}), -0.25f, kTol);
}

// A non-uniformly scaled sphere is an ellipsoid; the compiled distance (local distance times the
// smallest scale factor) must never exceed the distance to its surface, sampled densely.
TEST(SdfCompiler, NonUniformScaleNeverOverestimates) {
    SdfNode child = sphere({0.3f, 0, 0}, 0.5f);
    child.transform.rotation =
        glm::angleAxis(glm::radians(40.0f), glm::normalize(glm::vec3(1, 2, 0)));
    child.transform.scale = {2.0f, 1.0f, 0.7f};
    SdfNode parent = group(SdfOp::Union, {child});
    parent.transform.scale = {1.0f, 2.5f, 1.2f};
    parent.transform.rotation = glm::angleAxis(glm::radians(25.0f), glm::vec3(0, 0, 1));
    const SdfProgram program = compileOrFail(parent);
    ASSERT_EQ(program.instructions.size(), 1u);

    const glm::mat4 world = parent.transform.matrix() * child.transform.matrix();
    std::vector<glm::vec3> surface;
    const int rings = 200, segments = 400;
    for (int i = 0; i <= rings; ++i) {
        const float theta = float(M_PI) * float(i) / float(rings);
        for (int j = 0; j < segments; ++j) {
            const float phi = 2.0f * float(M_PI) * float(j) / float(segments);
            const glm::vec3 local =
                0.5f * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                 std::sin(theta) * std::sin(phi));
            surface.push_back(glm::vec3(world * glm::vec4(local, 1.0f)));
        }
    }
    int outside = 0;
    for (glm::vec3 p : samplePoints(150, 3.0f, 8)) {
        const float d = sdfDistance(program, p);
        if (d <= 0.0f) continue;
        ++outside;
        float nearest = 1e30f;
        for (const glm::vec3& s : surface)
            nearest = std::min(nearest, glm::length(p - s));
        EXPECT_LE(d, nearest + 1e-4f) << "at " << p.x << ", " << p.y << ", " << p.z;
    }
    EXPECT_GT(outside, 100);

    // Axis-aligned scales: the factor is the smallest one.
    SdfNode scaled = sphere({0, 0, 0}, 1.0f);
    scaled.transform.scale = {0.5f, 2.0f, -3.0f};
    EXPECT_NEAR(compileOrFail(scaled).instructions[0].misc.x, 0.5f, 1e-6f);
    // Along the x axis the surface is 0.5 away from the centre, so (2, 0, 0) is 1.5 away; the
    // bound gives (2 / 0.5 - 1) * 0.5 = 1.5, exact there.
    EXPECT_NEAR(sdfDistance(compileOrFail(scaled), {2, 0, 0}), 1.5f, kTol);
}

TEST(SdfCompiler, MaterialsInheritFromTheNearestGroup) {
    SdfNode inner = group(SdfOp::Union, {sphere({0, 0, 0}, 0.1f), sphere({1, 0, 0}, 0.1f, 1)});
    inner.material = 3;
    SdfNode root = group(SdfOp::Union, {sphere({2, 0, 0}, 0.1f), inner});
    root.material = 2;
    SdfProgram program = compileOrFail(root, 7);
    std::vector<std::uint32_t> materialByX(3, 99);
    for (const GpuSdfInstruction& i : program.instructions)
        if (i.opcode == std::uint32_t(SdfOpcode::Shape))
            materialByX[std::size_t(std::lround(-i.worldToLocal[0].w))] = i.material;
    EXPECT_EQ(materialByX[0], 3u); // inherits the inner group's
    EXPECT_EQ(materialByX[1], 1u); // its own
    EXPECT_EQ(materialByX[2], 2u); // inherits the root's

    root.material = -1; // now the root falls back to the default material
    program = compileOrFail(root, 7);
    int checked = 0;
    for (const GpuSdfInstruction& i : program.instructions) {
        if (i.opcode == std::uint32_t(SdfOpcode::Shape) && std::lround(-i.worldToLocal[0].w) == 2) {
            EXPECT_EQ(i.material, 7u);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 1);
}

TEST(SdfCompiler, SmoothUnionBlendsMaterials) {
    std::vector<Material> materials(2);
    materials[0].baseColor = {1, 0, 0};
    materials[0].roughness = 0.2f;
    materials[1].baseColor = {0, 0, 1};
    materials[1].roughness = 0.8f;
    materials[1].metallic = 1.0f;
    materials[1].emissive = {0, 0, 2};
    const SdfNode root = group(SdfOp::SmoothUnion,
                               {sphere({-1, 0, 0}, 0.5f, 0, "/sdf/children/0"),
                                sphere({1, 0, 0}, 0.5f, 1, "/sdf/children/1")},
                               1.0f, "/sdf");
    const SdfProgram program = compileOrFail(root);

    // Halfway both distances are 0.5: h = 0.5, an even mix.
    const SdfSurface middle = sdfSurface(program, materials, {0, 0, 0});
    EXPECT_NEAR(middle.distance, 0.5f - 1.0f / 4.0f, kTol);
    EXPECT_NEAR(middle.baseColor.x, 0.5f, kTol);
    EXPECT_NEAR(middle.baseColor.y, 0.0f, kTol);
    EXPECT_NEAR(middle.baseColor.z, 0.5f, kTol);
    EXPECT_NEAR(middle.roughness, 0.5f, kTol);
    EXPECT_NEAR(middle.metallic, 0.5f, kTol);
    EXPECT_NEAR(middle.emissive.z, 1.0f, kTol);

    // At x = -0.25: a = 0.25, b = 0.75, h = 0.5 + 0.5 * 0.5 / 1 = 0.75 of red.
    const SdfSurface redSide = sdfSurface(program, materials, {-0.25f, 0, 0});
    EXPECT_NEAR(redSide.baseColor.x, 0.75f, kTol);
    EXPECT_NEAR(redSide.baseColor.z, 0.25f, kTol);
    EXPECT_EQ(redSide.objectId, kSdfIdBase + 1); // the red sphere dominates
    EXPECT_NEAR(redSide.distance, sdfDistance(program, {-0.25f, 0, 0}), kTol);

    // Farther apart than k: pure colours and ids.
    const SdfSurface red = sdfSurface(program, materials, {-1.6f, 0, 0});
    EXPECT_EQ(red.baseColor, glm::vec3(1, 0, 0));
    EXPECT_EQ(red.objectId, kSdfIdBase + 1);
    const SdfSurface blue = sdfSurface(program, materials, {1.4f, 0.3f, 0});
    EXPECT_EQ(blue.baseColor, glm::vec3(0, 0, 1));
    EXPECT_EQ(blue.objectId, kSdfIdBase + 2);
}

TEST(SdfCompiler, HardOperationsTakeTheWinningMaterial) {
    std::vector<Material> materials(2);
    materials[0].baseColor = {1, 0, 0};
    materials[1].baseColor = {0, 0, 1};
    const SdfNode a = sphere({-0.5f, 0, 0}, 1.0f, 0);
    const SdfNode b = sphere({0.5f, 0, 0}, 1.0f, 1);
    const SdfProgram unionProgram = compileOrFail(group(SdfOp::Union, {a, b}));
    EXPECT_EQ(sdfSurface(unionProgram, materials, {-2, 0, 0}).baseColor, glm::vec3(1, 0, 0));
    EXPECT_EQ(sdfSurface(unionProgram, materials, {2, 0, 0}).baseColor, glm::vec3(0, 0, 1));
    // Subtraction keeps the first child's material, also on the carved wall: (-0.5, 0, 0) is
    // inside a (-1) and on b's surface (0), so the result 0 comes from b.
    const SdfProgram cut = compileOrFail(group(SdfOp::Subtraction, {a, b}));
    const SdfSurface wall = sdfSurface(cut, materials, {-0.5f, 0, 0});
    EXPECT_NEAR(wall.distance, 0.0f, kTol);
    EXPECT_EQ(wall.baseColor, glm::vec3(1, 0, 0));
    EXPECT_EQ(wall.objectId, kSdfIdBase + 1);
    // Intersection: the larger distance's side. At (-2, 0, 0), b (2.5 - 1) beats a (1.5 - 1).
    const SdfProgram both = compileOrFail(group(SdfOp::Intersection, {a, b}));
    EXPECT_EQ(sdfSurface(both, materials, {-2, 0, 0}).baseColor, glm::vec3(0, 0, 1));
    // An index past the table gives Material's defaults.
    const SdfProgram lone = compileOrFail(sphere({0, 0, 0}, 1.0f), 5);
    EXPECT_EQ(sdfSurface(lone, materials, {0, 0, 0}).baseColor, Material{}.baseColor);
}

TEST(SdfCompiler, ObjectIdsAndPointersFollowPreOrder) {
    //  /sdf (0) -> a (1), g (2) -> [b (3), c (4)], d (5)
    SdfNode g = group(SdfOp::Union,
                      {sphere({0, 3, 0}, 0.5f, -1, "/sdf/children/1/children/0"),
                       sphere({0, 6, 0}, 0.5f, -1, "/sdf/children/1/children/1")},
                      0.0f, "/sdf/children/1");
    const SdfNode root = group(SdfOp::Union,
                               {sphere({0, 0, 0}, 0.5f, -1, "/sdf/children/0"), g,
                                sphere({0, 9, 0}, 0.5f, -1, "/sdf/children/2")},
                               0.0f, "/sdf");
    const SdfProgram program = compileOrFail(root);
    const std::vector<std::string> expected = {"/sdf",
                                               "/sdf/children/0",
                                               "/sdf/children/1",
                                               "/sdf/children/1/children/0",
                                               "/sdf/children/1/children/1",
                                               "/sdf/children/2"};
    EXPECT_EQ(program.nodePointers, expected);
    const std::vector<Material> none;
    EXPECT_EQ(sdfSurface(program, none, {0, 0, 0}).objectId, kSdfIdBase + 1);
    EXPECT_EQ(sdfSurface(program, none, {0, 3, 0}).objectId, kSdfIdBase + 3);
    EXPECT_EQ(sdfSurface(program, none, {0, 6, 0}).objectId, kSdfIdBase + 4);
    EXPECT_EQ(sdfSurface(program, none, {0, 9, 0}).objectId, kSdfIdBase + 5);
    // The group (stack 2) is emitted before the lone spheres; the program still needs only 2.
    EXPECT_EQ(program.stackDepth, 2);
    EXPECT_EQ(program.instructions[0].objectId, kSdfIdBase + 3);
}

TEST(SdfCompiler, OneChildGroupCompilesToTheChildWithTheGroupsTransformAndMaterial) {
    SdfNode wrapper = group(SdfOp::Union, {sphere({0, 0, 0}, 1.0f)});
    wrapper.transform.position = {2, 0, 0};
    wrapper.material = 4;
    const SdfProgram program = compileOrFail(wrapper);
    ASSERT_EQ(program.instructions.size(), 1u);
    EXPECT_EQ(program.instructions[0].material, 4u);
    EXPECT_EQ(program.instructions[0].objectId, kSdfIdBase + 1);
    EXPECT_EQ(program.stackDepth, 1);
    EXPECT_NEAR(sdfDistance(program, {2, 0, 0}), -1.0f, kTol);
}

// Each level of a right-deep tree, compiled in file order, would hold one more entry; putting
// the nested group first keeps both shapes of a tree of any size at stack 2.
TEST(SdfCompiler, ReorderingKeepsUnionTreesAtStackTwo) {
    const int levels = 30; // more than kSdfMaxStack
    SdfNode rightDeep = sphere({0, 0, 0}, 0.1f);
    SdfNode leftDeep = sphere({0, 0, 0}, 0.1f);
    for (int i = 1; i <= levels; ++i) {
        rightDeep = group(SdfOp::Union, {sphere({float(i), 0, 0}, 0.1f), rightDeep});
        leftDeep = group(SdfOp::Union, {leftDeep, sphere({float(i), 0, 0}, 0.1f)});
    }
    const SdfProgram right = compileOrFail(rightDeep);
    const SdfProgram left = compileOrFail(leftDeep);
    EXPECT_EQ(right.stackDepth, 2);
    EXPECT_EQ(left.stackDepth, 2);
    EXPECT_EQ(right.instructions.size(), std::size_t(2 * levels + 1));
    for (int i = 0; i <= levels; ++i) {
        EXPECT_NEAR(sdfDistance(right, {float(i), 0.5f, 0}), 0.4f, kTol);
        EXPECT_NEAR(sdfDistance(left, {float(i), 0.5f, 0}), 0.4f, kTol);
    }
    // Intersection is reordered too.
    SdfNode intersection = sphere({0, 0, 0}, 100.0f);
    for (int i = 1; i <= levels; ++i)
        intersection = group(SdfOp::Intersection, {sphere({0, 0, 0}, 100.0f + i), intersection});
    EXPECT_EQ(compileOrFail(intersection).stackDepth, 2);
    EXPECT_NEAR(sdfDistance(compileOrFail(intersection), {0, 0, 0}), -100.0f, kTol);
}

// Smooth operations keep file order, and a subtraction keeps its first child: a nested group in
// the second place costs one entry per level.
TEST(SdfCompiler, SmoothOperationsAndSubtractionsAreNotReordered) {
    SdfNode chain =
        group(SdfOp::SmoothUnion, {sphere({0, 0, 0}, 0.1f), sphere({1, 0, 0}, 0.1f)}, 0.1f);
    for (int i = 0; i < 4; ++i)
        chain = group(SdfOp::SmoothUnion, {sphere({-1.0f - i, 0, 0}, 0.1f), chain}, 0.1f);
    EXPECT_EQ(compileOrFail(chain).stackDepth, 6); // 2 for the innermost, +1 per level

    const SdfNode cut =
        group(SdfOp::Subtraction, {sphere({0, 0, 0}, 1.0f), twoSpheres(SdfOp::Union)});
    EXPECT_EQ(compileOrFail(cut).stackDepth, 3);
    // Subtraction with the group first needs only 2.
    const SdfNode cutFirst =
        group(SdfOp::Subtraction, {twoSpheres(SdfOp::Union), sphere({0, 0, 0}, 0.2f)});
    EXPECT_EQ(compileOrFail(cutFirst).stackDepth, 2);
}

TEST(SdfCompilerErrors, EmptyGroup) {
    const SdfNode root = group(
        SdfOp::Union, {sphere({0, 0, 0}, 1.0f), group(SdfOp::Union, {}, 0.0f, "/sdf/children/1")},
        0.0f, "/sdf");
    Diagnostics diagnostics;
    EXPECT_FALSE(compileSdf(root, 0, "scene.json", diagnostics));
    ASSERT_EQ(diagnostics.errorCount(), 1);
    EXPECT_EQ(diagnostics.items[0].file, "scene.json");
    EXPECT_EQ(diagnostics.items[0].location, "/sdf/children/1");
    EXPECT_NE(diagnostics.items[0].message.find("no children"), std::string::npos);
}

TEST(SdfCompilerErrors, SubtractionWithOneChild) {
    for (SdfOp op : {SdfOp::Subtraction, SdfOp::SmoothSubtraction}) {
        const SdfNode root = group(op, {sphere({0, 0, 0}, 1.0f)}, 0.5f, "/sdf");
        Diagnostics diagnostics;
        EXPECT_FALSE(compileSdf(root, 0, "scene.json", diagnostics));
        ASSERT_EQ(diagnostics.errorCount(), 1);
        EXPECT_EQ(diagnostics.items[0].location, "/sdf");
        EXPECT_NE(diagnostics.items[0].message.find("at least two children"), std::string::npos);
    }
}

TEST(SdfCompilerErrors, BadSmoothness) {
    for (float k : {0.0f, -0.5f, std::numeric_limits<float>::quiet_NaN(),
                    std::numeric_limits<float>::infinity()}) {
        for (SdfOp op : {SdfOp::SmoothUnion, SdfOp::SmoothSubtraction, SdfOp::SmoothIntersection}) {
            Diagnostics diagnostics;
            SdfNode root = twoSpheres(op, k);
            root.pointer = "/sdf/children/2";
            EXPECT_FALSE(compileSdf(root, 0, "scene.json", diagnostics));
            ASSERT_EQ(diagnostics.errorCount(), 1);
            EXPECT_EQ(diagnostics.items[0].location, "/sdf/children/2");
            EXPECT_NE(diagnostics.items[0].message.find("smoothness"), std::string::npos);
        }
    }
    // The hard operations ignore the smoothness.
    Diagnostics diagnostics;
    EXPECT_TRUE(compileSdf(twoSpheres(SdfOp::Union, 0.0f), 0, "scene.json", diagnostics));
}

TEST(SdfCompilerErrors, ZeroScale) {
    SdfNode root = twoSpheres(SdfOp::Union);
    root.children[1].transform.scale = {1.0f, 0.0f, 1.0f};
    root.children[1].pointer = "/sdf/children/1";
    Diagnostics diagnostics;
    EXPECT_FALSE(compileSdf(root, 0, "scene.json", diagnostics));
    ASSERT_EQ(diagnostics.errorCount(), 1);
    EXPECT_EQ(diagnostics.items[0].location, "/sdf/children/1");
}

// A right-nested chain of smooth unions: each group is (sphere, nested group), so every level
// holds its sphere's distance while the nested group runs. The innermost group of two spheres
// needs 2, each level one more: `levels` groups need levels + 1 entries.
TEST(SdfCompilerErrors, StackOverflow) {
    auto chain = [](int levels) {
        SdfNode node =
            group(SdfOp::SmoothUnion, {sphere({0, 0, 0}, 0.1f), sphere({0.1f, 0, 0}, 0.1f)}, 0.05f);
        std::string pointer = "/sdf";
        for (int i = 1; i < levels; ++i)
            pointer += "/children/1";
        node.pointer = pointer;
        for (int i = levels - 1; i >= 1; --i) {
            pointer.resize(pointer.size() - std::string("/children/1").size());
            node =
                group(SdfOp::SmoothUnion, {sphere({-0.1f * i, 0, 0}, 0.1f), node}, 0.05f, pointer);
        }
        return node;
    };
    // 23 levels need 24: exactly the limit.
    Diagnostics fits;
    const std::optional<SdfProgram> atLimit = compileSdf(chain(23), 0, "scene.json", fits);
    ASSERT_TRUE(atLimit) << fits.format();
    EXPECT_EQ(atLimit->stackDepth, kSdfMaxStack);

    Diagnostics diagnostics;
    EXPECT_FALSE(compileSdf(chain(26), 0, "scene.json", diagnostics));
    ASSERT_EQ(diagnostics.errorCount(), 1);
    const Diagnostic& error = diagnostics.items[0];
    EXPECT_EQ(error.location, "/sdf");
    EXPECT_NE(error.message.find("needs a stack of 27 entries, the shader supports 24 (3 over)"),
              std::string::npos)
        << error.message;
    // The group where the need first passes 24: the one with 24 levels inside (depth 2 from
    // the root), needing 25.
    EXPECT_NE(error.message.find("/sdf/children/1/children/1 "), std::string::npos)
        << error.message;
}

TEST(SdfCompilerErrors, TooManyInstructions) {
    // n spheres in one union compile to n shapes and n - 1 combines.
    const int spheres = kSdfMaxInstructions / 2 + 1; // 2n - 1 = kSdfMaxInstructions + 1
    SdfNode root = group(SdfOp::Union, {}, 0.0f, "/sdf");
    root.children.assign(std::size_t(spheres), sphere({0, 0, 0}, 1.0f));
    Diagnostics diagnostics;
    EXPECT_FALSE(compileSdf(root, 0, "scene.json", diagnostics));
    ASSERT_EQ(diagnostics.errorCount(), 1);
    EXPECT_EQ(diagnostics.items[0].location, "/sdf");
    EXPECT_NE(diagnostics.items[0].message.find(std::to_string(kSdfMaxInstructions + 1) +
                                                " instructions"),
              std::string::npos)
        << diagnostics.items[0].message;
    EXPECT_NE(diagnostics.items[0].message.find("(1 over)"), std::string::npos);

    root.children.pop_back(); // exactly the limit minus one
    Diagnostics fits;
    const std::optional<SdfProgram> program = compileSdf(root, 0, "scene.json", fits);
    ASSERT_TRUE(program);
    EXPECT_EQ(program->instructions.size(), std::size_t(kSdfMaxInstructions - 1));
}

TEST(SdfCompilerErrors, ReportsEveryProblem) {
    const SdfNode root =
        group(SdfOp::Union,
              {group(SdfOp::Union, {}, 0.0f, "/sdf/children/0"),
               group(SdfOp::Subtraction, {sphere({0, 0, 0}, 1.0f)}, 0.0f, "/sdf/children/1"),
               group(SdfOp::SmoothUnion, {sphere({0, 0, 0}, 1.0f), sphere({1, 0, 0}, 1.0f)}, -1.0f,
                     "/sdf/children/2")},
              0.0f, "/sdf");
    Diagnostics diagnostics;
    EXPECT_FALSE(compileSdf(root, 0, "scene.json", diagnostics));
    ASSERT_EQ(diagnostics.errorCount(), 3);
    EXPECT_EQ(diagnostics.items[0].location, "/sdf/children/0");
    EXPECT_EQ(diagnostics.items[1].location, "/sdf/children/1");
    EXPECT_EQ(diagnostics.items[2].location, "/sdf/children/2");
}
