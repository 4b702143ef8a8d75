// The combine operations of the CPU evaluator (the GLSL interpreter's twin): xor, the
// polynomial and circular smooth operations, the chamfer and round operations. Each is run on
// two planes, so the operands at point (a, b, 0) are exactly a and b, and compared with
// properties worked out from the definitions. Also the materials they carry, and the "blend"
// key and the new op names in scene files.
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rmsc;

namespace {

// A plane whose signed distance at p is dot(p, normal) (unit normal), material `material`.
GpuSdfInstruction planeShape(glm::vec3 normal, std::uint32_t material) {
    GpuSdfInstruction i;
    i.opcode = std::uint32_t(SdfOpcode::Shape);
    i.kind = std::uint32_t(PrimitiveId::Plane);
    i.material = material;
    i.objectId = kSdfIdBase + material;
    i.params[0] = glm::vec4(normal, 0.0f);
    i.worldToLocal[0] = {1, 0, 0, 0};
    i.worldToLocal[1] = {0, 1, 0, 0};
    i.worldToLocal[2] = {0, 0, 1, 0};
    i.misc.x = 1.0f;
    return i;
}

// The program "a OP b" with a = x and b = y.
SdfProgram twoPlanes(SdfOp op, float k = 0.0f, float blend = 0.0f) {
    SdfProgram program;
    GpuSdfInstruction combine;
    combine.opcode = std::uint32_t(SdfOpcode::Combine);
    combine.kind = std::uint32_t(op);
    combine.params[0] = {k, blend, 0, 0};
    program.instructions = {planeShape({1, 0, 0}, 0), planeShape({0, 1, 0}, 1), combine};
    program.stackDepth = 2;
    return program;
}

float run(const SdfProgram& program, float a, float b) {
    return sdfDistance(program, {a, b, 0});
}

// Operand values on a grid over [-2, 2]^2.
template <typename F> void forGrid(F&& check) {
    for (int i = -20; i <= 20; ++i)
        for (int j = -20; j <= 20; ++j)
            check(0.1f * float(i) + 0.013f, 0.1f * float(j) - 0.007f);
}

std::vector<Material> redAndBlue() {
    Material red, blue;
    red.baseColor = {1, 0, 0};
    blue.baseColor = {0, 0, 1};
    return {red, blue};
}

constexpr float kTol = 1e-5f;

} // namespace

TEST(SdfOperations, XorIsInsideExactlyOne) {
    const SdfProgram program = twoPlanes(SdfOp::Xor);
    forGrid([&](float a, float b) {
        const float d = run(program, a, b);
        EXPECT_NEAR(d, std::max(std::min(a, b), -std::max(a, b)), kTol);
        // Negative exactly where one operand is negative and the other positive.
        EXPECT_EQ(d < 0.0f, (a < 0.0f) != (b < 0.0f)) << a << ", " << b;
        // For exact operands: +-min(|a|, |b|), the distance to the nearer boundary.
        EXPECT_NEAR(std::abs(d), std::min(std::abs(a), std::abs(b)), kTol);
    });
}

TEST(SdfOperations, PolynomialSmoothUnionIsQuilezQuadratic) {
    const float k = 0.5f;
    const SdfProgram program = twoPlanes(SdfOp::SmoothUnion, k, 0.0f);
    forGrid([&](float a, float b) {
        const float h = std::clamp(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
        EXPECT_NEAR(run(program, a, b), b + (a - b) * h - k * h * (1.0f - h), kTol);
    });
    EXPECT_NEAR(run(program, 0.3f, 0.3f), 0.3f - k / 4.0f, kTol); // the deepest point of the blend
}

TEST(SdfOperations, CircularSmoothUnionBlendsOverTheSameWidth) {
    const float k = 0.5f;
    const SdfProgram program = twoPlanes(SdfOp::SmoothUnion, k, 1.0f);
    forGrid([&](float a, float b) {
        const float d = run(program, a, b);
        EXPECT_LE(d, std::min(a, b) + kTol);
        if (std::abs(a - b) >= k) {
            EXPECT_NEAR(d, std::min(a, b), kTol);
        }
    });
    // On the diagonal a = b the circular arc dips by k (1 - sqrt(1/2)), more than the
    // polynomial's k / 4: the arc is tangent to both lines |a - b| = k.
    EXPECT_NEAR(run(program, 0.2f, 0.2f), 0.2f - k * (1.0f - std::sqrt(0.5f)), kTol);
    // Inside the blend, the result is the circle of radius k centred at min + k along both
    // axes' tangent points: at |a - b| = k / 2 the dip is k/2 (1 + g - sqrt(2 - (1 - g)^2)).
    const float g = 0.5f;
    EXPECT_NEAR(run(program, 0.0f, 0.25f),
                0.0f - 0.5f * k * (1.0f + g - std::sqrt(2.0f - (1.0f - g) * (1.0f - g))), kTol);
    // Different from the polynomial curve inside the blend region.
    EXPECT_GT(std::abs(run(program, 0.1f, 0.2f) -
                       run(twoPlanes(SdfOp::SmoothUnion, k, 0.0f), 0.1f, 0.2f)),
              1e-3f);
}

TEST(SdfOperations, SmoothSubtractionAndIntersectionMirrorTheUnion) {
    const float k = 0.4f;
    for (float blend : {0.0f, 1.0f}) {
        const SdfProgram uni = twoPlanes(SdfOp::SmoothUnion, k, blend);
        const SdfProgram sub = twoPlanes(SdfOp::SmoothSubtraction, k, blend);
        const SdfProgram inter = twoPlanes(SdfOp::SmoothIntersection, k, blend);
        forGrid([&](float a, float b) {
            // smax(a, -b) = -smin(-a, b) and smax(a, b) = -smin(-a, -b).
            EXPECT_NEAR(run(sub, a, b), -run(uni, b, -a), kTol);
            EXPECT_NEAR(run(inter, a, b), -run(uni, -a, -b), kTol);
            EXPECT_GE(run(inter, a, b), std::max(a, b) - kTol);
            EXPECT_GE(run(sub, a, b), std::max(a, -b) - kTol);
        });
    }
}

TEST(SdfOperations, ChamferOperations) {
    const float r = 0.3f;
    const SdfProgram uni = twoPlanes(SdfOp::ChamferUnion, r);
    const SdfProgram sub = twoPlanes(SdfOp::ChamferSubtraction, r);
    const SdfProgram inter = twoPlanes(SdfOp::ChamferIntersection, r);
    forGrid([&](float a, float b) {
        EXPECT_LE(run(uni, a, b), std::min(a, b) + kTol);
        EXPECT_GE(run(inter, a, b), std::max(a, b) - kTol);
        EXPECT_NEAR(run(sub, a, b), run(inter, a, -b), kTol); // subtraction: intersect with -b
        // Far from the seam (the 45-degree cut lies above the surfaces) nothing changes.
        if (std::abs(a - b) > r * 1.5f + 1e-3f || (a > r && b > r)) {
            if ((a + b - r) * std::sqrt(0.5f) >= std::min(a, b)) {
                EXPECT_NEAR(run(uni, a, b), std::min(a, b), kTol);
            }
        }
    });
    // The corner of two perpendicular planes is cut by the plane (a + b - r) / sqrt 2 = 0: the
    // chamfer meets each face r from the edge.
    EXPECT_NEAR(run(uni, 0.0f, r), 0.0f, kTol);
    EXPECT_NEAR(run(uni, 0.0f, 0.0f), -r * std::sqrt(0.5f), kTol);
    EXPECT_NEAR(run(uni, 1.0f, 2.0f), 1.0f, kTol);
}

TEST(SdfOperations, RoundOperations) {
    const float r = 0.3f;
    const SdfProgram uni = twoPlanes(SdfOp::RoundUnion, r);
    const SdfProgram sub = twoPlanes(SdfOp::RoundSubtraction, r);
    const SdfProgram inter = twoPlanes(SdfOp::RoundIntersection, r);
    forGrid([&](float a, float b) {
        EXPECT_LE(run(uni, a, b), std::min(a, b) + kTol);
        EXPECT_GE(run(inter, a, b), std::max(a, b) - kTol);
        EXPECT_NEAR(run(sub, a, b), run(inter, a, -b), kTol);
        // Once the other operand is r or more away, the union is the plain minimum.
        if (a >= r && b >= r) {
            EXPECT_NEAR(run(uni, a, b), std::min(a, b), kTol);
        }
        if (a <= 0.0f && b >= r) {
            EXPECT_NEAR(run(uni, a, b), a, kTol);
        }
    });
    // The inside corner is filled by a quarter circle of radius r centred at (r, r): the
    // surface passes through (r - r / sqrt 2, r - r / sqrt 2).
    const float s = r - r * std::sqrt(0.5f);
    EXPECT_NEAR(run(uni, s, s), 0.0f, kTol);
    EXPECT_NEAR(run(uni, 0.0f, 0.0f), r - std::sqrt(2.0f) * r, kTol);
    // Round intersection: the outside corner is rounded with radius r.
    EXPECT_NEAR(run(inter, -r + r * std::sqrt(0.5f), -r + r * std::sqrt(0.5f)), 0.0f, kTol);
}

TEST(SdfOperations, MaterialsFollowTheBlendOrTheDominantSide) {
    const std::vector<Material> materials = redAndBlue();
    // Smooth union (both curves): on the diagonal half red, half blue; far away one colour.
    for (float blend : {0.0f, 1.0f}) {
        const SdfProgram program = twoPlanes(SdfOp::SmoothUnion, 0.5f, blend);
        const SdfSurface middle = sdfSurface(program, materials, {0.1f, 0.1f, 0});
        EXPECT_NEAR(middle.baseColor.x, 0.5f, kTol);
        EXPECT_NEAR(middle.baseColor.z, 0.5f, kTol);
        const SdfSurface nearA = sdfSurface(program, materials, {0.0f, 0.2f, 0});
        EXPECT_GT(nearA.baseColor.x, nearA.baseColor.z); // a is nearer: more of a's red
        EXPECT_EQ(sdfSurface(program, materials, {0.0f, 1.0f, 0}).baseColor, glm::vec3(1, 0, 0));
    }
    // Chamfer, round and xor take the side that dominates, no blend.
    for (SdfOp op : {SdfOp::ChamferUnion, SdfOp::RoundUnion, SdfOp::Xor}) {
        const SdfProgram program = twoPlanes(op, 0.3f);
        EXPECT_EQ(sdfSurface(program, materials, {0.05f, 0.1f, 0}).baseColor, glm::vec3(1, 0, 0));
        EXPECT_EQ(sdfSurface(program, materials, {0.1f, 0.05f, 0}).baseColor, glm::vec3(0, 0, 1));
    }
    for (SdfOp op : {SdfOp::ChamferIntersection, SdfOp::RoundIntersection}) {
        const SdfProgram program = twoPlanes(op, 0.3f);
        EXPECT_EQ(sdfSurface(program, materials, {0.1f, 0.05f, 0}).objectId, kSdfIdBase + 0);
        EXPECT_EQ(sdfSurface(program, materials, {0.05f, 0.1f, 0}).objectId, kSdfIdBase + 1);
    }
    // Subtractions keep the first child's material on the cut surface too.
    for (SdfOp op : {SdfOp::ChamferSubtraction, SdfOp::RoundSubtraction}) {
        const SdfProgram program = twoPlanes(op, 0.3f);
        EXPECT_EQ(sdfSurface(program, materials, {-0.5f, -0.05f, 0}).baseColor, glm::vec3(1, 0, 0));
    }
}

TEST(SdfOperations, SceneFilesNameTheNewOpsAndTheBlend) {
    const std::string text = R"({"version": 1, "sdf": {"op": "union", "children": [
        {"op": "smooth_union", "smoothness": 0.2, "blend": "circular", "children": [
            {"shape": "sphere"}, {"shape": "box"}]},
        {"op": "xor", "children": [{"shape": "sphere"}, {"shape": "box"}]},
        {"op": "chamfer_union", "smoothness": 0.1, "children": [{"shape": "sphere"}, {"shape": "box"}]},
        {"op": "round_subtraction", "smoothness": 0.1, "children": [{"shape": "sphere"}, {"shape": "box"}]},
        {"op": "round_intersection", "smoothness": 0.1, "children": [{"shape": "sphere"}, {"shape": "box"}]}
    ]}})";
    Diagnostics d;
    const std::optional<Scene> scene = parseScene(text, "ops.json", d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_FALSE(d.hasErrors());
    const std::vector<SdfNode>& groups = scene->sdf->children;
    ASSERT_EQ(groups.size(), 5u);
    EXPECT_EQ(groups[0].op, SdfOp::SmoothUnion);
    EXPECT_EQ(groups[0].blend, SmoothBlend::Circular);
    EXPECT_EQ(groups[1].op, SdfOp::Xor);
    EXPECT_EQ(groups[2].op, SdfOp::ChamferUnion);
    EXPECT_EQ(groups[3].op, SdfOp::RoundSubtraction);
    EXPECT_EQ(groups[4].op, SdfOp::RoundIntersection);
    EXPECT_FLOAT_EQ(groups[2].smoothness, 0.1f);

    // The blend reaches the combine instruction as params[0].y.
    Diagnostics cd;
    const std::optional<SdfProgram> program = compileSdf(groups[0], 0, "ops.json", cd);
    ASSERT_TRUE(program) << cd.format();
    EXPECT_EQ(program->instructions.back().params[0].y, 1.0f);

    // Written and read back, the same ops and blend.
    Diagnostics again;
    const std::optional<Scene> reread = parseScene(sceneToJson(*scene), "again.json", again);
    ASSERT_TRUE(reread) << again.format();
    for (std::size_t i = 0; i < groups.size(); ++i) {
        EXPECT_EQ(reread->sdf->children[i].op, groups[i].op);
        EXPECT_EQ(reread->sdf->children[i].blend, groups[i].blend);
        EXPECT_EQ(reread->sdf->children[i].smoothness, groups[i].smoothness);
    }
}

TEST(SdfOperations, BadBlendsAndRadiiAreReported) {
    Diagnostics d;
    EXPECT_FALSE(parseScene(R"({"version": 1, "sdf": {"op": "union", "children": [
        {"op": "smooth_union", "smoothness": 0.2, "blend": "cubic", "children": [{"shape": "sphere"}, {"shape": "box"}]},
        {"op": "chamfer_union", "children": [{"shape": "sphere"}, {"shape": "box"}]}
    ]}})",
                            "bad.json", d));
    const std::string all = d.format();
    EXPECT_NE(all.find("/sdf/children/0/blend"), std::string::npos) << all;
    EXPECT_NE(all.find("\"polynomial\""), std::string::npos) << all;
    EXPECT_NE(all.find("/sdf/children/1"), std::string::npos) << all;
    EXPECT_NE(all.find("smoothness"), std::string::npos) << all;
    EXPECT_EQ(d.errorCount(), 2) << all;

    // A round subtraction with one child: the compiler refuses it at the group's pointer.
    Diagnostics parsed;
    const std::optional<Scene> one = parseScene(R"({"version": 1, "sdf": {"op": "round_subtraction",
        "smoothness": 0.1, "children": [{"shape": "sphere"}]}})",
                                                "one.json", parsed);
    ASSERT_TRUE(one) << parsed.format();
    Diagnostics compiled;
    EXPECT_FALSE(compileSdf(*one->sdf, 0, "one.json", compiled));
    EXPECT_NE(compiled.format().find("round subtraction needs at least two children"),
              std::string::npos)
        << compiled.format();

    // "blend" on an op that does not blend: a warning, the scene still loads.
    Diagnostics w;
    EXPECT_TRUE(parseScene(R"({"version": 1, "sdf": {"op": "round_union", "smoothness": 0.1,
        "blend": "circular", "children": [{"shape": "sphere"}, {"shape": "box"}]}})",
                           "w.json", w));
    EXPECT_FALSE(w.hasErrors());
    EXPECT_NE(w.format().find("/sdf/blend"), std::string::npos) << w.format();
}
