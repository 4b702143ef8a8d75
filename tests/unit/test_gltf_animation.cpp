// glTF animation, morph targets and skins: the sampler's value at t = 0, at a key and between
// keys for LINEAR (slerp for rotations), STEP and CUBICSPLINE, worked out by hand from glTF 2.0
// Appendix C; a node animation moving a triangle; a morph at weight 0.5 putting vertices
// halfway; a strip skinned to two joints and bent 90 degrees putting its tip where the joint
// matrices say; the refusals; and the Khronos samples AnimatedMorphCube, BoxAnimated and
// RiggedSimple.
#include "gltf_builder.hpp"
#include "scene/gltf_animation.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/mesh_pose.hpp"
#include "scene/mesh_rig.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;
using nlohmann::json;

namespace {

AnimationSampler sampler(AnimationInterpolation interpolation, std::vector<float> times,
                         std::vector<float> values, int width) {
    AnimationSampler s;
    s.interpolation = interpolation;
    s.times = std::move(times);
    s.values = std::move(values);
    s.width = width;
    return s;
}

glm::vec3 sample3(const AnimationSampler& s, double t) {
    glm::vec3 v(-99.0f);
    sampleAnimation(s, t, false, &v.x);
    return v;
}

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance = 1e-6f) {
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
    EXPECT_NEAR(got.z, want.z, tolerance);
}

} // namespace

TEST(GltfAnimationSampling, LinearAtStartAtKeysBetweenAndOutside) {
    const auto s =
        sampler(AnimationInterpolation::Linear, {0, 1, 2}, {0, 0, 0, 2, 0, 0, 2, 4, 0}, 3);
    expectNear(sample3(s, 0.0), {0, 0, 0});
    expectNear(sample3(s, 1.0), {2, 0, 0});
    expectNear(sample3(s, 0.25), {0.5f, 0, 0});
    expectNear(sample3(s, 1.5), {2, 2, 0});
    expectNear(sample3(s, -1.0), {0, 0, 0}); // before the first key: its value
    expectNear(sample3(s, 7.0), {2, 4, 0});  // after the last: its value
}

TEST(GltfAnimationSampling, StepHoldsEachKeyUntilTheNext) {
    const auto s = sampler(AnimationInterpolation::Step, {0, 1, 2}, {0, 0, 0, 2, 0, 0, 2, 4, 0}, 3);
    expectNear(sample3(s, 0.0), {0, 0, 0});
    expectNear(sample3(s, 0.99), {0, 0, 0});
    expectNear(sample3(s, 1.0), {2, 0, 0});
    expectNear(sample3(s, 1.75), {2, 0, 0});
    expectNear(sample3(s, 2.0), {2, 4, 0});
}

TEST(GltfAnimationSampling, CubicSplineFollowsTheHermiteFormula) {
    // Keys at 0 and 2 (t_d = 2); x: v0 = 0, out-tangent b0 = 0.5, in-tangent a1 = 0.25, v1 = 1.
    // Halfway (s = 0.5): (2s^3 - 3s^2 + 1) 0 + 2 (s^3 - 2s^2 + s) 0.5 + (-2s^3 + 3s^2) 1
    // + 2 (s^3 - s^2) 0.25 = 0.125 + 0.5 - 0.0625 = 0.5625. y: flat tangents from 1 to 3, 2.
    const auto s = sampler(AnimationInterpolation::CubicSpline, {0, 2},
                           {/*a0*/ 9, 0, 0, /*v0*/ 0, 1, 0, /*b0*/ 0.5f, 0, 0,
                            /*a1*/ 0.25f, 0, 0, /*v1*/ 1, 3, 0, /*b1*/ 9, 0, 0},
                           3);
    expectNear(sample3(s, 0.0), {0, 1, 0});
    expectNear(sample3(s, 2.0), {1, 3, 0});
    expectNear(sample3(s, 1.0), {0.5625f, 2, 0});
    // s = 0.25: 2 (1/64 - 1/8 + 1/4) 0.5 + (-1/32 + 3/16) + 2 (1/64 - 1/16) 0.25
    const double x = 2 * (1.0 / 64 - 1.0 / 8 + 0.25) * 0.5 + (-1.0 / 32 + 3.0 / 16) +
                     2 * (1.0 / 64 - 1.0 / 16) * 0.25;
    const double y = 1 + 2 * (3 * 0.0625 - 2 * 0.015625); // 1 + 2 (3s^2 - 2s^3)
    expectNear(sample3(s, 0.5), {float(x), float(y), 0});
}

TEST(GltfAnimationSampling, LinearRotationSlerpsAlongTheShorterArc) {
    const float h = std::sqrt(0.5f);
    // Identity to 90 degrees about +y; the second key stored negated (the same rotation).
    for (const float sign : {1.0f, -1.0f}) {
        const auto s = sampler(AnimationInterpolation::Linear, {0, 1},
                               {0, 0, 0, 1, 0, sign * h, 0, sign * h}, 4);
        float q[4];
        sampleAnimation(s, 0.5, true, q);
        const float angle = glm::radians(22.5f); // half of 45 degrees
        EXPECT_NEAR(q[0], 0.0f, 1e-6f);
        EXPECT_NEAR(q[1], std::sin(angle), 1e-6f) << "sign " << sign;
        EXPECT_NEAR(q[2], 0.0f, 1e-6f);
        EXPECT_NEAR(q[3], std::cos(angle), 1e-6f);
        sampleAnimation(s, 0.0, true, q);
        EXPECT_NEAR(q[3], 1.0f, 1e-6f);
    }
}

namespace {

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

glm::vec3 vertex(const MeshAsset& asset, std::size_t primitive, std::size_t i) {
    return asset.primitives.at(primitive).vertices.at(i).position;
}

// A triangle on node 0, animated by `animation` (its accessors in `b`).
std::string animatedTriangle(GltfBuilder& b, const json& animation, const json& node = {}) {
    const int p = b.accessor(kTriangle, kFloatType, "VEC3", 3);
    json n = {{"mesh", 0}};
    if (!node.is_null()) n.merge_patch(node);
    return b.text({{"scenes", {{{"nodes", {0}}}}},
                   {"nodes", {n}},
                   {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", p}}}}}}}}},
                   {"animations", {animation}}});
}

} // namespace

TEST(GltfAnimation, NodeTranslationMovesTheMeshAtEachTime) {
    GltfBuilder b;
    const int times = b.accessor(std::vector<float>{0, 1, 2}, kFloatType, "SCALAR", 3);
    const int values =
        b.accessor(std::vector<float>{0, 0, 0, 4, 0, 0, 4, 0, 8}, kFloatType, "VEC3", 3);
    const std::string text = animatedTriangle(
        b, {{"name", "slide"},
            {"samplers", {{{"input", times}, {"output", values}}}},
            {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}});
    Diagnostics d;
    auto asset = loadGltfText(text, d);
    ASSERT_TRUE(asset) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    ASSERT_TRUE(asset->rig);
    ASSERT_EQ(asset->rig->animations.size(), 1u);
    EXPECT_EQ(asset->rig->animations[0].name, "slide");
    EXPECT_FLOAT_EQ(asset->rig->animations[0].duration, 2.0f);
    expectNear(vertex(*asset, 0, 1), {1, 0, 0}); // the rest pose: no translation
    for (const auto& [t, offset] : std::vector<std::pair<double, glm::vec3>>{
             {0.0, {0, 0, 0}}, {1.0, {4, 0, 0}}, {0.5, {2, 0, 0}}, {1.25, {4, 0, 2}}}) {
        ASSERT_TRUE(poseMeshAsset(*asset, {0, t}, d)) << d.format();
        expectNear(vertex(*asset, 0, 1), glm::vec3(1, 0, 0) + offset);
        EXPECT_NEAR(asset->boundsMin.x, offset.x, 1e-6f) << "t " << t;
    }
    std::string why;
    EXPECT_EQ(findAnimation(*asset->rig, "slide", why), 0);
    EXPECT_EQ(findAnimation(*asset->rig, "0", why), 0);
    EXPECT_FALSE(findAnimation(*asset->rig, "walk", why));
    EXPECT_EQ(why, "there is no animation \"walk\"; the file has animations 0 \"slide\"");
    EXPECT_FALSE(poseMeshAsset(*asset, {3, 0.0}, d));
}

TEST(GltfAnimation, RefusesBadSamplersNamingThePlace) {
    const auto load = [](const json& output, const char* interpolation, std::vector<float> keys) {
        GltfBuilder b;
        const int times = b.accessor(keys, kFloatType, "SCALAR", keys.size());
        const int values =
            b.accessor(output.get<std::vector<float>>(), kFloatType, "VEC3", output.size() / 3);
        const std::string text = animatedTriangle(
            b,
            {{"samplers",
              {{{"input", times}, {"output", values}, {"interpolation", interpolation}}}},
             {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}});
        Diagnostics d;
        EXPECT_FALSE(loadGltfText(text, d));
        return d.format();
    };
    EXPECT_NE(
        load({0, 0, 0, 1, 1, 1}, "LINEAR", {0, 1, 2})
            .find(
                "/animations/0/samplers/0/output: accessor has 2 elements for 3 keys, expected 3"),
        std::string::npos);
    EXPECT_NE(load({0, 0, 0, 1, 1, 1}, "CUBICSPLINE", {0, 1})
                  .find("/animations/0/samplers/0/output: accessor has 2 elements for 2 keys, "
                        "expected 6"),
              std::string::npos);
    EXPECT_NE(load({0, 0, 0, 1, 1, 1}, "SMOOTH", {0, 1})
                  .find("/animations/0/samplers/0/interpolation: expected LINEAR, STEP or "
                        "CUBICSPLINE, got \"SMOOTH\""),
              std::string::npos);
    EXPECT_NE(load({0, 0, 0, 1, 1, 1}, "LINEAR", {1, 0}).find("expected increasing times"),
              std::string::npos);
}

namespace {

// A triangle with one morph target moving every vertex by (0, 2, 0).
std::string morphTriangle(GltfBuilder& b, const json& mesh, const json& node = {},
                          const json& animations = nullptr) {
    const int p = b.accessor(kTriangle, kFloatType, "VEC3", 3);
    const int delta =
        b.accessor(std::vector<float>{0, 2, 0, 0, 2, 0, 0, 2, 0}, kFloatType, "VEC3", 3);
    json m = {{"primitives",
               {{{"attributes", {{"POSITION", p}}}, {"targets", {{{"POSITION", delta}}}}}}}};
    m.merge_patch(mesh);
    json n = {{"mesh", 0}};
    if (!node.is_null()) n.merge_patch(node);
    json gltf = {{"scenes", {{{"nodes", {0}}}}}, {"nodes", {n}}, {"meshes", {m}}};
    if (!animations.is_null()) gltf["animations"] = animations;
    return b.text(gltf);
}

} // namespace

TEST(GltfMorphTargets, MeshWeightHalfPutsVerticesHalfway) {
    GltfBuilder b;
    Diagnostics d;
    const auto asset = loadGltfText(morphTriangle(b, {{"weights", {0.5}}}), d);
    ASSERT_TRUE(asset) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    for (std::size_t i = 0; i < 3; ++i)
        expectNear(vertex(*asset, 0, i),
                   glm::vec3(kTriangle[3 * i], kTriangle[3 * i + 1] + 1.0f, kTriangle[3 * i + 2]));
}

TEST(GltfMorphTargets, NodeWeightsOverrideTheMeshAndAnimationOverridesBoth) {
    GltfBuilder b;
    const int times = b.accessor(std::vector<float>{0, 1}, kFloatType, "SCALAR", 2);
    const int values = b.accessor(std::vector<float>{0, 1}, kFloatType, "SCALAR", 2);
    const json animation = {
        {"samplers", {{{"input", times}, {"output", values}}}},
        {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}}};
    Diagnostics d;
    auto asset = loadGltfText(
        morphTriangle(b, {{"weights", {0.5}}}, {{"weights", {0.25}}}, json::array({animation})), d);
    ASSERT_TRUE(asset) << d.format();
    expectNear(vertex(*asset, 0, 0), {0, 0.5f, 0}); // node weight 0.25 of the 2-unit delta
    ASSERT_TRUE(poseMeshAsset(*asset, {0, 0.75}, d));
    expectNear(vertex(*asset, 0, 0), {0, 1.5f, 0}); // animated weight 0.75
    ASSERT_TRUE(poseMeshAsset(*asset, {0, 0.0}, d));
    expectNear(vertex(*asset, 0, 0), {0, 0, 0});
}

TEST(GltfMorphTargets, RefusesWeightsThatDoNotMatchTheTargets) {
    GltfBuilder b;
    Diagnostics d;
    EXPECT_FALSE(loadGltfText(morphTriangle(b, {{"weights", {0.5, 0.5}}}), d));
    EXPECT_NE(d.format().find("/meshes/0/weights: has 2 weights for 1 morph targets, expected one "
                              "per target"),
              std::string::npos)
        << d.format();
}

namespace {

// A strip along +y from 0 to 2, x = 0 or 0.1 (vertices 0-1 at y 0, 2-3 at 1, 4-5 at 2), on
// node 0 (translated by (5, 0, 0), which skinning ignores) with skin 0: joint node 1 at the
// origin, its child joint node 2 at (0, 1, 0) with `jointRotation`. Rows 0 and 1 follow joint 0,
// row 2 joint 1, except vertex 5, half joint 0 and half joint 1.
std::string skinnedStrip(GltfBuilder& b, const std::vector<double>& jointRotation) {
    const int p = b.accessor(
        std::vector<float>{0, 0, 0, 0.1f, 0, 0, 0, 1, 0, 0.1f, 1, 0, 0, 2, 0, 0.1f, 2, 0},
        kFloatType, "VEC3", 6);
    const int joints = b.accessor(std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                                            0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0},
                                  kUnsignedByte, "VEC4", 6);
    const int weights = b.accessor(std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1,    0,    0, 0,
                                                      1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0},
                                   kFloatType, "VEC4", 6);
    const int indices = b.accessor(std::vector<std::uint16_t>{0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4},
                                   kUnsignedShort, "SCALAR", 12);
    // Inverse bind matrices: joint 0 at the origin (identity), joint 1 at (0, 1, 0).
    const int inverseBind =
        b.accessor(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                      1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
                   kFloatType, "MAT4", 2);
    return b.text(
        {{"scenes", {{{"nodes", {0, 1}}}}},
         {"nodes",
          {{{"mesh", 0}, {"skin", 0}, {"translation", {5, 0, 0}}},
           {{"children", {2}}},
           {{"translation", {0, 1, 0}}, {"rotation", jointRotation}}}},
         {"skins", {{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBind}}}},
         {"meshes",
          {{{"primitives",
             {{{"attributes", {{"POSITION", p}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}},
               {"indices", indices}}}}}}}});
}

} // namespace

TEST(GltfSkins, StripAtBindPoseIsUnchanged) {
    GltfBuilder b;
    Diagnostics d;
    const auto asset = loadGltfText(skinnedStrip(b, {0, 0, 0, 1}), d);
    ASSERT_TRUE(asset) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    expectNear(vertex(*asset, 0, 4), {0, 2, 0}, 1e-6f); // the node's (5, 0, 0) is not applied
    expectNear(vertex(*asset, 0, 5), {0.1f, 2, 0}, 1e-6f);
}

TEST(GltfSkins, StripBentNinetyDegreesPutsItsTipWhereTheJointMathsSays) {
    // Joint 1 turned 90 degrees about +z: jointMatrix1 = T(0,1,0) Rz(90) T(0,-1,0) takes
    // (x, 2, 0) to (-1, 1 + x, 0); the lower rows stay. Vertex 5 (x = 0.1) is half and half:
    // 0.5 (0.1, 2, 0) + 0.5 (-1, 1.1, 0) = (-0.45, 1.55, 0).
    GltfBuilder b;
    Diagnostics d;
    const double h = std::sqrt(0.5);
    const auto asset = loadGltfText(skinnedStrip(b, {0, 0, h, h}), d);
    ASSERT_TRUE(asset) << d.format();
    expectNear(vertex(*asset, 0, 2), {0, 1, 0}, 1e-6f);
    expectNear(vertex(*asset, 0, 3), {0.1f, 1, 0}, 1e-6f);
    expectNear(vertex(*asset, 0, 4), {-1, 1, 0}, 1e-6f);
    expectNear(vertex(*asset, 0, 5), {-0.45f, 1.55f, 0}, 1e-6f);
}

TEST(GltfSkins, RefusesJointsOutsideTheSkin) {
    GltfBuilder b;
    std::string text = skinnedStrip(b, {0, 0, 0, 1});
    json gltf = json::parse(text);
    gltf["skins"][0]["joints"] = {1}; // one joint; vertex 4 names joint 1
    Diagnostics d;
    EXPECT_FALSE(loadGltfText(gltf.dump(), d));
    EXPECT_NE(d.format().find("/meshes/0/primitives/0/attributes/JOINTS_0: vertex 4 uses joint 1 "
                              "but the node's skin has 1 joints"),
              std::string::npos)
        << d.format();
}

TEST(GltfAnimationSamples, AnimatedMorphCubeIsACubeAtRestAndMorphsWhenAnimated) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    Diagnostics d;
    auto asset = loadGltf(gltfSamples() / "AnimatedMorphCube.gltf", diskFileSource(), d);
    ASSERT_TRUE(asset) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    const glm::vec3 rest = asset->boundsMax - asset->boundsMin;
    // A cube at rest (weights 0, 0) and at frame 0 of the animation.
    EXPECT_NEAR(rest.x, rest.y, 1e-3f * rest.x);
    EXPECT_NEAR(rest.y, rest.z, 1e-3f * rest.x);
    ASSERT_TRUE(poseMeshAsset(*asset, {0, 0.0}, d));
    EXPECT_NEAR((asset->boundsMax - asset->boundsMin).y, rest.y, 1e-3f * rest.y);
    // Animated it becomes a thin slab, then a ramp: at some time its size differs by far.
    float largestChange = 0.0f;
    for (double t = 0.0; t <= 4.2; t += 0.3) {
        ASSERT_TRUE(poseMeshAsset(*asset, {0, t}, d));
        const glm::vec3 size = asset->boundsMax - asset->boundsMin;
        largestChange = std::max(largestChange, glm::length(size - rest) / glm::length(rest));
    }
    EXPECT_GT(largestChange, 0.25f);
}

TEST(GltfAnimationSamples, BoxAnimatedInnerBoxRisesWhenAnimated) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    Diagnostics d;
    auto asset = loadGltf(gltfSamples() / "BoxAnimated.gltf", diskFileSource(), d);
    ASSERT_TRUE(asset) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    ASSERT_EQ(asset->primitives.size(), 2u);
    const auto top = [](const MeshPrimitive& p) {
        float y = -1e30f;
        for (const MeshVertex& v : p.vertices)
            y = std::max(y, v.position.y);
        return y;
    };
    // The scene lists the outer box's node first.
    ASSERT_TRUE(poseMeshAsset(*asset, {0, 0.0}, d));
    const float outer0 = top(asset->primitives[0]), inner0 = top(asset->primitives[1]);
    float highest = inner0;
    for (double t = 0.0; t <= 3.8; t += 0.2) {
        ASSERT_TRUE(poseMeshAsset(*asset, {0, t}, d));
        highest = std::max(highest, top(asset->primitives[1]));
        EXPECT_FLOAT_EQ(top(asset->primitives[0]), outer0); // the outer box stays
    }
    EXPECT_GT(highest, inner0 + 0.5f); // the inner box rose
}

TEST(GltfAnimationSamples, RiggedSimpleIsStraightAtRestAndBendsWhenAnimated) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    Diagnostics d;
    auto asset = loadGltf(gltfSamples() / "RiggedSimple.gltf", diskFileSource(), d);
    ASSERT_TRUE(asset) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    // Upright: taller than wide, centred on its axis.
    const glm::vec3 rest = asset->boundsMax - asset->boundsMin;
    const glm::vec3 restCentre = 0.5f * (asset->boundsMax + asset->boundsMin);
    ASSERT_GT(rest.y, 2.0f * rest.x);
    // Bending moves the top half sideways: the bounds' centre leaves the axis.
    float largestShift = 0.0f;
    for (double t = 0.0; t <= 2.1; t += 0.25) {
        ASSERT_TRUE(poseMeshAsset(*asset, {0, t}, d));
        const glm::vec3 centre = 0.5f * (asset->boundsMax + asset->boundsMin);
        largestShift = std::max(largestShift, std::abs(centre.z - restCentre.z) +
                                                  std::abs(centre.x - restCentre.x));
    }
    EXPECT_GT(largestShift, 0.1f * rest.y);
}
