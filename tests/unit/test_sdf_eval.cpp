// The CPU evaluator: hand-built programs, normals, and sphere tracing against analytic hits.
#include "core/object_ids.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rmsc;

namespace {

// One shape instruction: `id` at `position`, no rotation or scale.
GpuSdfInstruction shapeAt(PrimitiveId id, const PrimitiveParams& params, glm::vec3 position,
                          std::uint32_t material = 0) {
    GpuSdfInstruction i;
    i.opcode = std::uint32_t(SdfOpcode::Shape);
    i.kind = std::uint32_t(id);
    i.material = material;
    i.objectId = kSdfIdBase;
    i.params[0] = {params[0], params[1], params[2], params[3]};
    i.params[1] = {params[4], params[5], params[6], params[7]};
    i.worldToLocal[0] = {1, 0, 0, -position.x};
    i.worldToLocal[1] = {0, 1, 0, -position.y};
    i.worldToLocal[2] = {0, 0, 1, -position.z};
    i.misc.x = 1.0f;
    return i;
}

GpuSdfInstruction combine(SdfOp op, float k = 0.0f) {
    GpuSdfInstruction i;
    i.opcode = std::uint32_t(SdfOpcode::Combine);
    i.kind = std::uint32_t(op);
    i.params[0].x = k;
    return i;
}

SdfProgram sphereProgram(glm::vec3 center, float radius) {
    SdfProgram program;
    program.instructions.push_back(shapeAt(PrimitiveId::Sphere, {radius}, center));
    program.stackDepth = 1;
    return program;
}

constexpr float kTol = 1e-5f;

} // namespace

TEST(SdfEval, RunsAHandBuiltProgram) {
    // Box of half size 1 at the origin minus a sphere of radius 0.5 at (1, 0, 0).
    SdfProgram program;
    program.instructions = {shapeAt(PrimitiveId::Box, {1, 1, 1}, {0, 0, 0}),
                            shapeAt(PrimitiveId::Sphere, {0.5f}, {1, 0, 0}),
                            combine(SdfOp::Subtraction)};
    program.stackDepth = 2;
    EXPECT_NEAR(sdfDistance(program, {0, 0, 0}), -0.5f, kTol); // the sphere's surface is nearer
    EXPECT_NEAR(sdfDistance(program, {1, 0, 0}), 0.5f, kTol);  // inside the hole
    EXPECT_NEAR(sdfDistance(program, {0, 3, 0}), 2.0f, kTol);  // above the box
    // The distance scale multiplies the primitive's distance.
    program.instructions[0].misc.x = 2.0f;
    EXPECT_NEAR(sdfDistance(program, {0, 3, 0}), 4.0f, kTol);
}

TEST(SdfEval, EmptyProgramIsFarAndNeverHit) {
    const SdfProgram empty;
    EXPECT_GT(sdfDistance(empty, {0, 0, 0}), 1e9f);
    const std::vector<Material> materials(1);
    EXPECT_GT(sdfSurface(empty, materials, {0, 0, 0}).distance, 1e9f);
    EXPECT_FALSE(sdfCastRay(empty, RenderSettings{}, {0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f));
}

TEST(SdfEval, SurfaceDistanceEqualsDistance) {
    SdfProgram program;
    program.instructions = {shapeAt(PrimitiveId::Sphere, {0.5f}, {0, 0, 0}, 0),
                            shapeAt(PrimitiveId::Torus, {1.0f, 0.2f}, {0.5f, 0, 0}, 1),
                            combine(SdfOp::SmoothUnion, 0.3f),
                            shapeAt(PrimitiveId::Box, {0.3f, 0.3f, 0.3f}, {0, 0.4f, 0}, 1),
                            combine(SdfOp::SmoothSubtraction, 0.2f)};
    program.stackDepth = 2;
    const std::vector<Material> materials(2);
    for (float x = -2.0f; x <= 2.0f; x += 0.25f)
        for (float y = -1.0f; y <= 1.0f; y += 0.25f) {
            const glm::vec3 p(x, y, 0.3f * x);
            EXPECT_EQ(sdfSurface(program, materials, p).distance, sdfDistance(program, p));
        }
}

TEST(SdfEval, NormalIsTheGradientDirection) {
    const SdfProgram ball = sphereProgram({1, 2, 3}, 1.5f);
    const glm::vec3 direction = glm::normalize(glm::vec3(1, -2, 0.5f));
    const glm::vec3 n = sdfNormal(ball, glm::vec3(1, 2, 3) + 1.5f * direction, 1e-3f);
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(n, direction), 1.0f - 1e-4f);

    SdfProgram plane;
    plane.instructions = {shapeAt(PrimitiveId::Plane, {0, 0, 3, 0.5f}, {0, 0, 0})};
    const glm::vec3 up = sdfNormal(plane, {0.3f, 7.0f, 0.5f}, 1e-3f);
    EXPECT_NEAR(up.z, 1.0f, 1e-4f);
}

TEST(SdfEval, CastRayHitsSphereAtAnalyticDistance) {
    const SdfProgram ball = sphereProgram({0, 0, 5}, 1.0f);
    RenderSettings settings;
    // The ray from the origin along +z meets the sphere at t = 5 - 1. Sphere tracing on an exact
    // distance never passes the surface and stops within epsilon * max(t, 1) of it.
    const std::optional<SdfHit> hit =
        sdfCastRay(ball, settings, {0, 0, 0}, {0, 0, 2}, 0.0f, 100.0f); // unnormalized direction
    ASSERT_TRUE(hit);
    EXPECT_LE(hit->t, 4.0f + kTol);
    EXPECT_GE(hit->t, 4.0f - settings.surfaceEpsilon * 4.0f);
    EXPECT_NEAR(hit->position.z, hit->t, kTol);
    EXPECT_GE(hit->steps, 1);
    EXPECT_LE(hit->steps, settings.maxSteps);

    // An oblique ray: from (0, 0.6, 0) along +z the sphere is met where x^2 + 0.36 + (z-5)^2 = 1,
    // z = 5 - 0.8.
    const std::optional<SdfHit> oblique =
        sdfCastRay(ball, settings, {0, 0.6f, 0}, {0, 0, 1}, 0.0f, 100.0f);
    ASSERT_TRUE(oblique);
    EXPECT_NEAR(oblique->t, 4.2f, 4.2f * settings.surfaceEpsilon);

    // Starting at tMin changes nothing but the start.
    const std::optional<SdfHit> late =
        sdfCastRay(ball, settings, {0, 0, 0}, {0, 0, 1}, 2.0f, 100.0f);
    ASSERT_TRUE(late);
    EXPECT_NEAR(late->t, 4.0f, 4.0f * settings.surfaceEpsilon);
}

TEST(SdfEval, CastRayEpsilonGrowsWithDistance) {
    const SdfProgram ball = sphereProgram({0, 0, 100}, 1.0f);
    RenderSettings settings;
    settings.surfaceEpsilon = 0.01f;
    const std::optional<SdfHit> hit =
        sdfCastRay(ball, settings, {0, 0, 0}, {0, 0, 1}, 0.0f, 200.0f);
    ASSERT_TRUE(hit);
    EXPECT_LE(hit->t, 99.0f + 1e-3f);
    EXPECT_GE(hit->t, 99.0f - 0.01f * 99.0f);

    // A ray passing 0.05 outside the sphere: near t = 100 the distance (0.05) is below
    // 0.01 * t = 1 though above 0.01 itself, so the scaled test counts it as a hit.
    const std::optional<SdfHit> graze =
        sdfCastRay(ball, settings, {0, 1.05f, 0}, {0, 0, 1}, 0.0f, 200.0f);
    ASSERT_TRUE(graze);
    EXPECT_LT(graze->t, 100.0f);
    settings.surfaceEpsilon = 1e-4f; // 0.05 > 1e-4 * 100: passes by
    EXPECT_FALSE(sdfCastRay(ball, settings, {0, 1.05f, 0}, {0, 0, 1}, 0.0f, 200.0f));
}

TEST(SdfEval, CastRayMisses) {
    const SdfProgram ball = sphereProgram({0, 0, 5}, 1.0f);
    RenderSettings settings;
    EXPECT_FALSE(sdfCastRay(ball, settings, {0, 0, 0}, {0, 0, -1}, 0.0f, 100.0f));   // away
    EXPECT_FALSE(sdfCastRay(ball, settings, {0, 1.5f, 0}, {0, 0, 1}, 0.0f, 100.0f)); // passes by
    EXPECT_FALSE(sdfCastRay(ball, settings, {0, 0, 0}, {0, 0, 1}, 0.0f, 3.5f));      // stops before
    settings.maxSteps = 1; // one step lands at t = 4 but is not yet tested there
    EXPECT_FALSE(sdfCastRay(ball, settings, {0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f));
}

// Plain sphere tracing (relaxation 1) hits a plane head-on in exactly two steps: the first
// evaluation returns the full distance, the second lands on the surface. (The relaxed march
// takes one more: test_sdf_relaxed_march.cpp.)
TEST(SdfEval, CastRayStepsOntoAPlane) {
    SdfProgram plane;
    plane.instructions = {shapeAt(PrimitiveId::Plane, {0, 1, 0, 0}, {0, 0, 0})};
    const std::optional<SdfHit> hit =
        sdfCastRay(plane, RenderSettings{}, {0, 2, 0}, {0, -1, 0}, 0.0f, 100.0f, 1.0f);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0f, kTol);
    EXPECT_EQ(hit->steps, 2);
}

TEST(SdfEval, CompiledSceneCastsLikeTheTree) {
    // A group moved to z = 6 holding a sphere of radius 1 at its local origin, in union with a far
    // sphere: the ray along +z meets the first at t = 5.
    SdfNode near;
    near.primitive = PrimitiveId::Sphere;
    near.params[0] = 1.0f;
    SdfNode far = near;
    far.transform.position = {0, 50, 0};
    SdfNode root;
    root.isGroup = true;
    root.children = {near, far};
    root.transform.position = {0, 0, 6};
    Diagnostics diagnostics;
    const std::optional<SdfProgram> program = compileSdf(root, 0, "", diagnostics);
    ASSERT_TRUE(program) << diagnostics.format();
    const std::optional<SdfHit> hit =
        sdfCastRay(*program, RenderSettings{}, {0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0f, 5.0f * RenderSettings{}.surfaceEpsilon);
}

// The part nearest a point (the lean interpreter's first guess): the leaf with the smallest
// distance there, whatever its place in the program; none in a program without leaves.
TEST(SdfEval, NearestLeafIsTheLeafNearestThePoint) {
    SdfProgram program;
    program.instructions.push_back(shapeAt(PrimitiveId::Sphere, {0.5f}, {-3, 0, 0}));
    program.instructions.push_back(combine(SdfOp::Union));
    program.instructions.push_back(shapeAt(PrimitiveId::Sphere, {0.5f}, {0, 0, 0}));
    program.instructions.push_back(combine(SdfOp::Union));
    program.instructions.push_back(shapeAt(PrimitiveId::Sphere, {2.0f}, {3, 0, 0}));
    EXPECT_EQ(sdfNearestLeaf(program, {-2.9f, 0, 0}), 0u);
    EXPECT_EQ(sdfNearestLeaf(program, {0, 0.2f, 0}), 2u);
    // Nearer the middle sphere's centre, nearer the big one's surface.
    EXPECT_EQ(sdfNearestLeaf(program, {1.4f, 0, 0}), 4u);
    EXPECT_EQ(sdfNearestLeaf(SdfProgram{}, {0, 0, 0}), ~0u);
}
