// Bounds of SDF content (sdf/bounds.hpp): exact boxes of simple primitives; a containment
// property test for every catalogue row (every point the distance function puts inside, at
// level 0 and at a positive level, lies in the box; the box is not much larger than the inside
// found); the same containment on trees compiled by the real compiler and run by the CPU
// evaluator (transforms, every operation, cut children, every modifier, profiles); and the
// detection of unbounded content with the pointer responsible.
#include "sdf/bounds.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>

using namespace rmsc;

namespace {

using DistanceFn = std::function<float(glm::vec3)>;

std::string describe(const Aabb& box) {
    std::ostringstream out;
    out << "[(" << box.min.x << ", " << box.min.y << ", " << box.min.z << ") .. (" << box.max.x
        << ", " << box.max.y << ", " << box.max.z << ")]";
    return out.str();
}

void expectBox(const SdfBounds& bounds, glm::vec3 min, glm::vec3 max) {
    ASSERT_TRUE(bounds.bounded) << bounds.unboundedBy;
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(bounds.box.min[axis], min[axis], 1e-5f) << describe(bounds.box);
        EXPECT_NEAR(bounds.box.max[axis], max[axis], 1e-5f) << describe(bounds.box);
    }
}

// What sampling found: how many points were inside (distance <= level), their box, and the
// inside points that lie outside the bound (beyond the tolerance).
struct Sampling {
    int inside = 0;
    Aabb found;
    int escaped = 0;
    glm::vec3 firstEscaped{0.0f};
};

// `count` deterministic random points in `region`, checked against `box`.
Sampling sample(const DistanceFn& distance, const Aabb& region, const Aabb& box, float level,
                int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float scale = box.empty() ? 1.0f : std::max(1.0f, glm::length(box.halfSize()));
    const Aabb allowed = inflateAabb(box, 1e-4f * scale);
    Sampling s;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 p =
            region.min + (region.max - region.min) * glm::vec3(u(rng), u(rng), u(rng));
        if (!(distance(p) <= level)) continue;
        ++s.inside;
        s.found.add(p);
        if (!allowed.contains(p)) {
            if (s.escaped == 0) s.firstEscaped = p;
            ++s.escaped;
        }
    }
    return s;
}

// The region sampled around a bound: 2.5 times the box about its centre, plus a margin so that
// flat or tiny boxes get a region too.
Aabb regionAround(const Aabb& box) {
    if (box.empty()) return aabbAround(glm::vec3(0.0f), glm::vec3(2.0f));
    const glm::vec3 half = box.halfSize();
    const float largest = std::max(half.x, std::max(half.y, half.z));
    return aabbAround(box.center(), 2.5f * half + 0.1f * std::max(largest, 0.2f));
}

// Every point the field puts at or below `level` in the region around the box lies in the box.
// With `tightness`, also samples the box itself and, when enough inside points turn up, checks
// that the box is at most about twice the extent of what was found on every axis.
void expectContained(const DistanceFn& distance, const SdfBounds& bounds, float level,
                     const std::string& what, bool tightness, int count = 20000,
                     unsigned seed = 1) {
    ASSERT_TRUE(bounds.bounded) << what << ": unbounded by " << bounds.unboundedBy;
    const Sampling around =
        sample(distance, regionAround(bounds.box), bounds.box, level, count, seed);
    EXPECT_EQ(around.escaped, 0) << what << ": " << around.escaped << " of " << around.inside
                                 << " inside points lie outside the box " << describe(bounds.box)
                                 << ", e.g. (" << around.firstEscaped.x << ", "
                                 << around.firstEscaped.y << ", " << around.firstEscaped.z << ")";
    if (!tightness || bounds.box.empty()) return;
    Sampling within = sample(distance, bounds.box, bounds.box, level, count, seed + 7);
    within.found.add(around.found);
    if (within.inside + around.inside < 200) return; // too thin to judge
    const glm::vec3 boxSize = bounds.box.max - bounds.box.min;
    const glm::vec3 foundSize = within.found.max - within.found.min;
    const float largest = std::max(boxSize.x, std::max(boxSize.y, boxSize.z));
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_LE(boxSize[axis], 2.0f * foundSize[axis] + 0.05f * largest)
            << what << ": axis " << axis << " of " << describe(bounds.box)
            << " is loose; the inside found spans " << describe(within.found);
}

// ---------------------------------------------------------------------------------------------
// Trees.

Transform transform(glm::vec3 position, glm::vec3 degrees = glm::vec3(0.0f),
                    glm::vec3 scale = glm::vec3(1.0f)) {
    Transform t;
    t.position = position;
    t.rotation = glm::quat(glm::radians(degrees));
    t.scale = scale;
    return t;
}

SdfNode shape(PrimitiveId id, const std::vector<float>& params, const std::string& pointer,
              const Transform& t = {}) {
    SdfNode node;
    node.pointer = pointer;
    node.primitive = id;
    node.params = defaultParams(primitiveSpec(id));
    for (std::size_t i = 0; i < params.size(); ++i)
        node.params[i] = params[i];
    node.transform = t;
    return node;
}

SdfNode sphere(float radius, const std::string& pointer, const Transform& t = {}) {
    return shape(PrimitiveId::Sphere, {radius}, pointer, t);
}

SdfNode group(SdfOp op, std::vector<SdfNode> children, const std::string& pointer,
              float smoothness = 0.0f, const Transform& t = {}) {
    SdfNode node;
    node.isGroup = true;
    node.op = op;
    node.smoothness = smoothness;
    node.children = std::move(children);
    node.pointer = pointer;
    node.transform = t;
    return node;
}

SdfModifier modifier(SdfModifierType type, const std::string& pointer) {
    SdfModifier m;
    m.type = type;
    m.pointer = pointer;
    return m;
}

SdfProgram compile(const SdfNode& root) {
    Diagnostics diagnostics;
    const std::optional<SdfProgram> program = compileSdf(root, 0, "test.json", diagnostics);
    EXPECT_TRUE(program) << diagnostics.format();
    return program ? *program : SdfProgram{};
}

// Compiles the tree, bounds it and checks containment with the CPU evaluator.
void expectTreeContained(const SdfNode& root, const std::string& what, bool tightness = false) {
    const SdfProgram program = compile(root);
    ASSERT_FALSE(program.instructions.empty()) << what;
    const SdfBounds bounds = sdfNodeBounds(root);
    expectContained([&](glm::vec3 p) { return sdfDistance(program, p); }, bounds, 0.0f, what,
                    tightness);
    // And at a positive level (where the march's hit threshold reaches: sdfNodeBoundsAtLevel
    // ends rays, render/gpu_scene.cpp).
    const SdfBounds atLevel = sdfNodeBoundsAtLevel(root, 0.1f);
    ASSERT_EQ(atLevel.bounded, bounds.bounded) << what;
    if (atLevel.bounded)
        expectContained([&](glm::vec3 p) { return sdfDistance(program, p); }, atLevel, 0.1f,
                        what + ", level 0.1", false);
}

// A sphere and a box overlapping a little, the box turned and scaled non-uniformly.
std::vector<SdfNode> twoShapes(const std::string& pointer) {
    std::vector<SdfNode> children;
    children.push_back(sphere(0.4f, pointer + "/children/0", transform({-0.3f, 0.1f, 0.0f})));
    children.push_back(
        shape(PrimitiveId::Box, {0.3f, 0.2f, 0.25f}, pointer + "/children/1",
              transform({0.35f, -0.1f, 0.1f}, {20.0f, 35.0f, -10.0f}, {1.5f, 0.6f, 1.0f})));
    return children;
}

// ---------------------------------------------------------------------------------------------
// Random valid parameters: every catalogue range, lengths limited to [-1, 1] (the catalogue
// allows 1e4, which says nothing more about the formulas).
PrimitiveParams randomParams(const PrimitiveSpec& spec, std::mt19937& rng) {
    PrimitiveParams params = defaultParams(spec);
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
        const ParamSpec& p = spec.params[i];
        float lo = p.minValue, hi = p.maxValue;
        if (hi >= 1.0e4f) {
            lo = std::max(lo, -1.0f);
            hi = std::min(hi, 1.0f);
        }
        std::uniform_real_distribution<float> u(lo, hi);
        const int offset = paramOffset(spec, int(i));
        for (int c = 0; c < p.components; ++c)
            params[std::size_t(offset + c)] = u(rng);
    }
    return params;
}

bool infinite(PrimitiveId id) {
    return id == PrimitiveId::Plane || id == PrimitiveId::InfiniteCylinder ||
           id == PrimitiveId::InfiniteCone || id == PrimitiveId::Gyroid;
}

bool fractal(PrimitiveId id) {
    return id == PrimitiveId::Mandelbulb || id == PrimitiveId::MengerSponge ||
           id == PrimitiveId::SierpinskiTetrahedron || id == PrimitiveId::QuaternionJulia;
}

} // namespace

TEST(SdfBounds, AabbHelpers) {
    Aabb box;
    EXPECT_TRUE(box.empty());
    box.add(glm::vec3(1.0f, 2.0f, 3.0f));
    box.add(glm::vec3(-1.0f, 0.0f, 5.0f));
    EXPECT_FALSE(box.empty());
    EXPECT_EQ(box.center(), glm::vec3(0.0f, 1.0f, 4.0f));
    EXPECT_EQ(box.halfSize(), glm::vec3(1.0f, 1.0f, 1.0f));
    EXPECT_TRUE(intersectAabb(box, aabbAround(glm::vec3(5.0f), glm::vec3(1.0f))).empty());
    // A quarter turn about z and a translation: x and y swap.
    const Aabb turned = transformAabb(aabbAround(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f)),
                                      transform({10.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 90.0f}).matrix());
    EXPECT_NEAR(turned.min.x, 8.0f, 1e-5f);
    EXPECT_NEAR(turned.max.x, 12.0f, 1e-5f);
    EXPECT_NEAR(turned.max.y, 1.0f, 1e-5f);
    EXPECT_NEAR(turned.max.z, 3.0f, 1e-5f);
    EXPECT_TRUE(transformAabb(Aabb{}, glm::mat4(1.0f)).empty());
}

TEST(SdfBounds, ExactBoxesOfSimplePrimitives) {
    PrimitiveParams p{};
    p[0] = 0.7f;
    expectBox(primitiveBounds(PrimitiveId::Sphere, p), glm::vec3(-0.7f), glm::vec3(0.7f));
    expectBox(primitiveBounds(PrimitiveId::Sphere, p, 0.1f), glm::vec3(-0.8f), glm::vec3(0.8f));

    p = {0.3f, 0.5f, 0.7f};
    expectBox(primitiveBounds(PrimitiveId::Box, p), {-0.3f, -0.5f, -0.7f}, {0.3f, 0.5f, 0.7f});

    p = {0.5f, 0.15f};
    expectBox(primitiveBounds(PrimitiveId::Torus, p), {-0.65f, -0.15f, -0.65f},
              {0.65f, 0.15f, 0.65f});

    p = {-0.3f, -0.3f, 0.0f, 0.3f, 0.4f, 0.0f, 0.2f};
    expectBox(primitiveBounds(PrimitiveId::CapsuleBetween, p), {-0.5f, -0.5f, -0.2f},
              {0.5f, 0.6f, 0.2f});

    p = {0.5f, 0.25f}; // half height, radius
    expectBox(primitiveBounds(PrimitiveId::Capsule, p), {-0.25f, -0.75f, -0.25f},
              {0.25f, 0.75f, 0.25f});

    p = {0.0f, 1.0f, 0.0f, 0.0f};
    EXPECT_FALSE(primitiveBounds(PrimitiveId::Plane, p).bounded);
    EXPECT_FALSE(primitiveBounds(PrimitiveId::InfiniteCylinder, p).bounded);
    EXPECT_FALSE(primitiveBounds(PrimitiveId::InfiniteCone, p).bounded);

    // In the parent's frame: scale 2 then the offset; a quarter turn about y swaps x and z.
    const SdfNode moved =
        shape(PrimitiveId::Box, {0.5f, 0.25f, 0.1f}, "/sdf",
              transform({1.0f, 2.0f, 3.0f}, {0.0f, 90.0f, 0.0f}, glm::vec3(2.0f)));
    expectBox(sdfNodeBounds(moved), {0.8f, 1.5f, 2.0f}, {1.2f, 2.5f, 4.0f});
    expectBox(sdfNodeLocalBounds(moved), {-0.5f, -0.25f, -0.1f}, {0.5f, 0.25f, 0.1f});
}

// Every catalogue row, its defaults and random valid parameters, at level 0 and at a positive
// level (what rounding and smooth unions rely on).
TEST(SdfBounds, EveryPrimitiveContainsItsInside) {
    std::mt19937 rng(20240611);
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        for (int set = 0; set < 8; ++set) {
            const PrimitiveParams params = set == 0 ? defaultParams(spec) : randomParams(spec, rng);
            for (const float level : {0.0f, 0.15f}) {
                const SdfBounds bounds = primitiveBounds(spec.id, params, level);
                std::ostringstream what;
                what << spec.name << " parameter set " << set << " (";
                for (float v : params)
                    what << v << " ";
                what << ") at level " << level;
                if (infinite(spec.id)) {
                    EXPECT_FALSE(bounds.bounded) << what.str();
                    continue;
                }
                // Tightness at level 0; for the fractals only at their defaults (thin random
                // fractals leave too little inside to sample, and their bounds are spheres
                // that hold every parameter choice).
                const bool tightness = level == 0.0f && (set == 0 || !fractal(spec.id));
                expectContained([&](glm::vec3 p) { return spec.distance(p, params.data()); },
                                bounds, level, what.str(), tightness, 20000,
                                unsigned(set * 31 + int(spec.id)));
            }
        }
    }
}

// The containment check itself fails on a box that is too small (so the tests above can fail).
TEST(SdfBounds, ContainmentCheckCatchesATooSmallBox) {
    PrimitiveParams p{};
    p[0] = 0.5f;
    SdfBounds small = primitiveBounds(PrimitiveId::Sphere, p);
    small.box = inflateAabb(small.box, -0.05f);
    const Sampling s = sample(
        [&](glm::vec3 q) { return primitiveSpec(PrimitiveId::Sphere).distance(q, p.data()); },
        regionAround(small.box), small.box, 0.0f, 20000, 3);
    EXPECT_GT(s.inside, 100);
    EXPECT_GT(s.escaped, 0);
}

TEST(SdfBounds, TransformedShapesAndNestedGroups) {
    SdfNode root = group(SdfOp::Union, {}, "/sdf", 0.0f,
                         transform({0.2f, -0.1f, 0.3f}, {10.0f, 70.0f, 5.0f}, {1.2f, 0.5f, 0.8f}));
    root.children.push_back(
        shape(PrimitiveId::Torus, {0.5f, 0.15f}, "/sdf/children/0",
              transform({0.0f, 0.3f, 0.0f}, {60.0f, 0.0f, 30.0f}, {1.0f, 2.0f, 0.5f})));
    root.children.push_back(
        group(SdfOp::Union, twoShapes("/sdf/children/1"), "/sdf/children/1", 0.0f,
              transform({0.5f, 0.0f, 0.0f}, {0.0f, 45.0f, 0.0f}, {0.7f, 1.3f, 1.0f})));
    expectTreeContained(root, "nested transforms", true);
}

// Every operation, the smooth ones with a blend as large as the shapes, both blends, and a
// three-child fold (where the growth of smooth unions accumulates).
TEST(SdfBounds, EveryOperationContainsItsInside) {
    const SdfOp ops[] = {SdfOp::Union,
                         SdfOp::Subtraction,
                         SdfOp::Intersection,
                         SdfOp::SmoothUnion,
                         SdfOp::SmoothSubtraction,
                         SdfOp::SmoothIntersection,
                         SdfOp::Xor,
                         SdfOp::ChamferUnion,
                         SdfOp::ChamferSubtraction,
                         SdfOp::ChamferIntersection,
                         SdfOp::RoundUnion,
                         SdfOp::RoundSubtraction,
                         SdfOp::RoundIntersection};
    for (const SdfOp op : ops) {
        for (const SmoothBlend blend : {SmoothBlend::Polynomial, SmoothBlend::Circular}) {
            for (const float k : {0.1f, 0.8f}) {
                const std::string what = "op " + std::to_string(int(op)) + " blend " +
                                         std::to_string(int(blend)) + " k " + std::to_string(k);
                SdfNode two = group(op, twoShapes("/sdf"), "/sdf", k,
                                    transform({0.1f, 0.0f, 0.0f}, {0.0f, 20.0f, 0.0f}));
                two.blend = blend;
                expectTreeContained(two, what + " two children");

                // Three children, the group inside a parent scaled down, so the world-unit
                // smoothness is large in the group's frame.
                SdfNode three = group(op, twoShapes("/sdf/children/0"), "/sdf/children/0", k);
                three.blend = blend;
                three.children.push_back(shape(PrimitiveId::Capsule, {0.3f, 0.15f},
                                               "/sdf/children/0/children/2",
                                               transform({0.0f, 0.3f, 0.2f}, {0.0f, 0.0f, 60.0f})));
                SdfNode root =
                    group(SdfOp::Union, {}, "/sdf", 0.0f,
                          transform(glm::vec3(0.0f), glm::vec3(0.0f), {0.5f, 0.3f, 0.4f}));
                root.children.push_back(three);
                expectTreeContained(root, what + " three children, scaled parent");
            }
        }
    }
}

TEST(SdfBounds, SmoothUnionGrowthIsUsedAndTight) {
    // Two spheres of radius 0.3 at x = +-0.2 with k = 1: the polynomial smin is k/4 below the
    // spheres' distance where a = b, so on the plane x = 0 the blend reaches y = sqrt(0.55^2 -
    // 0.2^2) = 0.51, beyond the spheres' own box (0.3); the bound allows 0.3 + k/4.
    SdfNode root = group(SdfOp::SmoothUnion, {}, "/sdf", 1.0f);
    root.children.push_back(sphere(0.3f, "/sdf/children/0", transform({-0.2f, 0.0f, 0.0f})));
    root.children.push_back(sphere(0.3f, "/sdf/children/1", transform({0.2f, 0.0f, 0.0f})));
    const SdfBounds bounds = sdfNodeBounds(root);
    ASSERT_TRUE(bounds.bounded);
    EXPECT_NEAR(bounds.box.max.y, 0.3f + 0.25f, 1e-5f);
    const SdfProgram program = compile(root);
    EXPECT_LT(sdfDistance(program, glm::vec3(0.0f, 0.5f, 0.0f)), 0.0f);
    EXPECT_GT(sdfDistance(program, glm::vec3(0.0f, 0.52f, 0.0f)), 0.0f);
    expectTreeContained(root, "smooth union of two spheres", true);
}

// A fold of many polynomial smooth minima with one k never dips more than k below its least
// operand. Twelve equal spheres at nearly one place are the worst case: each step adds
// (k - d)^2 / 4k to the dip d, which tends to k. The bound is t + k for every operand (the
// fold's own growth, k/4 a step, would reach 11k/4); a bound of t + k/2 leaves inside points
// out. Scattered spheres and a large k as well.
TEST(SdfBounds, AFoldOfSmoothMinimaDipsAtMostKBelowItsLeastOperand) {
    SdfNode stacked = group(SdfOp::SmoothUnion, {}, "/sdf", 1.0f);
    for (int i = 0; i < 12; ++i)
        stacked.children.push_back(sphere(0.3f, "/sdf/children/" + std::to_string(i),
                                          transform({0.001f * float(i), 0.0f, 0.0f})));
    const SdfBounds bounds = sdfNodeBounds(stacked);
    ASSERT_TRUE(bounds.bounded);
    EXPECT_NEAR(bounds.box.max.y, 0.3f + 1.0f, 1e-5f);
    const SdfProgram program = compile(stacked);
    // The recurrence gives a dip of 0.76 k after twelve steps: the surface reaches y = 1.06.
    EXPECT_LT(sdfDistance(program, glm::vec3(0.0f, 1.0f, 0.0f)), 0.0f);
    expectTreeContained(stacked, "twelve stacked spheres", true);

    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    SdfNode scattered = group(SdfOp::SmoothUnion, {}, "/sdf", 0.6f);
    for (int i = 0; i < 30; ++i)
        scattered.children.push_back(sphere(0.1f + 0.1f * std::abs(u(rng)),
                                            "/sdf/children/" + std::to_string(i),
                                            transform({u(rng), u(rng), u(rng)})));
    expectTreeContained(scattered, "thirty scattered spheres", true);
}

TEST(SdfBounds, CutChildrenOnlyRemove) {
    SdfNode root = group(SdfOp::SmoothUnion, twoShapes("/sdf"), "/sdf", 0.3f);
    SdfNode cutter = sphere(2.0f, "/sdf/children/2", transform({0.0f, 2.2f, 0.0f}));
    cutter.cut = true;
    root.children.push_back(cutter);
    SdfNode withoutCut = root;
    withoutCut.children.pop_back();
    const SdfBounds bounds = sdfNodeBounds(root);
    const SdfBounds boundsWithout = sdfNodeBounds(withoutCut);
    ASSERT_TRUE(bounds.bounded);
    EXPECT_EQ(bounds.box.min, boundsWithout.box.min);
    EXPECT_EQ(bounds.box.max, boundsWithout.box.max);
    expectTreeContained(root, "cut child");
    // A cut plane does not make the group unbounded.
    SdfNode plane = shape(PrimitiveId::Plane, {0.0f, -1.0f, 0.0f, 0.1f}, "/sdf/children/2");
    plane.cut = true;
    root.children.back() = plane;
    EXPECT_TRUE(sdfNodeBounds(root).bounded);
    expectTreeContained(root, "cut plane");
}

TEST(SdfBounds, EveryModifierContainsItsInside) {
    struct Case {
        std::string what;
        std::vector<SdfModifier> modifiers;
    };
    std::vector<Case> cases;
    auto m = [](SdfModifierType type) { return modifier(type, "/sdf/modifiers/0"); };

    SdfModifier repeat = m(SdfModifierType::Repeat);
    repeat.vector = {1.1f, 0.0f, 0.9f};
    repeat.counts = {3, 0, 4};
    cases.push_back({"finite repeat", {repeat}});
    repeat.neighbours = true;
    repeat.vector = {0.7f, 0.6f, 0.0f};
    repeat.counts = {2, 5, 0};
    cases.push_back({"finite repeat with neighbours", {repeat}});

    SdfModifier mirror = m(SdfModifierType::Mirror);
    mirror.axes = {true, false, true};
    cases.push_back({"mirror xz", {mirror}});

    for (int axis = 0; axis < 3; ++axis) {
        SdfModifier polar = m(SdfModifierType::Polar);
        polar.count = 5;
        polar.axis = axis;
        cases.push_back({"polar about axis " + std::to_string(axis), {polar}});
    }

    SdfModifier elongate = m(SdfModifierType::Elongate);
    elongate.vector = {0.3f, 0.0f, 0.5f};
    cases.push_back({"elongate", {elongate}});

    SdfModifier twist = m(SdfModifierType::Twist);
    twist.amount = 120.0f;
    twist.radius = 0.8f;
    cases.push_back({"twist", {twist}});

    SdfModifier bend = m(SdfModifierType::Bend);
    bend.amount = 90.0f;
    bend.radius = 0.8f;
    cases.push_back({"bend", {bend}});

    SdfModifier taper = m(SdfModifierType::Taper);
    taper.amount = 1.1f;
    taper.radius = 0.6f;
    cases.push_back({"taper", {taper}});
    SdfModifier narrowing = taper;
    narrowing.amount = -1.5f;
    narrowing.radius = 0.45f;
    cases.push_back({"narrowing taper", {narrowing}});

    SdfModifier round = m(SdfModifierType::Round);
    round.radius = 0.15f;
    cases.push_back({"round", {round}});

    SdfModifier onion = m(SdfModifierType::Onion);
    onion.thickness = 0.1f;
    cases.push_back({"onion", {onion}});

    SdfModifier displace = m(SdfModifierType::Displace);
    displace.amount = 0.1f;
    displace.frequency = 4.0f;
    cases.push_back({"displace", {displace}});

    // Chains: the order matters for the point modifiers; distance modifiers after a twist see
    // the step-corrected field.
    cases.push_back(
        {"mirror, elongate, twist, round, displace", {mirror, elongate, twist, round, displace}});
    cases.push_back(
        {"repeat then polar then bend, onion", {repeat, cases[3].modifiers[0], bend, onion}});
    cases.push_back({"taper, twist, round", {taper, twist, round}});

    for (const Case& c : cases) {
        // On a shape, turned and scaled non-uniformly and off-centre.
        SdfNode box =
            shape(PrimitiveId::Box, {0.3f, 0.2f, 0.15f}, "/sdf",
                  transform({0.2f, 0.1f, -0.1f}, {15.0f, 30.0f, 0.0f}, {1.3f, 0.7f, 1.0f}));
        box.modifiers = c.modifiers;
        expectTreeContained(box, c.what + " on a box");
        // On a smooth union group below a scaled parent.
        SdfNode inner =
            group(SdfOp::SmoothUnion, twoShapes("/sdf/children/0"), "/sdf/children/0", 0.3f,
                  transform({0.1f, 0.0f, 0.2f}, {0.0f, 0.0f, 25.0f}, {0.8f, 1.2f, 0.9f}));
        inner.modifiers = c.modifiers;
        SdfNode root = group(SdfOp::Union, {}, "/sdf", 0.0f,
                             transform(glm::vec3(0.0f), {0.0f, 30.0f, 0.0f}, {0.6f, 0.4f, 0.5f}));
        root.children.push_back(inner);
        expectTreeContained(root, c.what + " on a smooth group");
    }
}

TEST(SdfBounds, RepeatExpandsByTheCopies) {
    SdfNode node = sphere(0.25f, "/sdf");
    SdfModifier repeat = modifier(SdfModifierType::Repeat, "/sdf/modifiers/0");
    repeat.vector = {1.0f, 0.0f, 0.0f};
    repeat.counts = {4, 0, 0}; // centres at -1.5, -0.5, 0.5, 1.5
    node.modifiers.push_back(repeat);
    expectBox(sdfNodeLocalBounds(node), {-1.75f, -0.25f, -0.25f}, {1.75f, 0.25f, 0.25f});
    expectTreeContained(node, "four spheres in a row", true);
}

TEST(SdfBounds, ProfilesContainTheirInside) {
    std::vector<SdfProfile> profiles;
    SdfProfile circle;
    circle.radius = 0.3f;
    profiles.push_back(circle);
    SdfProfile rectangle;
    rectangle.type = SdfProfileType::Rectangle;
    rectangle.halfSize = {0.4f, 0.2f};
    profiles.push_back(rectangle);
    SdfProfile rounded = rectangle;
    rounded.type = SdfProfileType::RoundedRectangle;
    rounded.radius = 0.1f;
    profiles.push_back(rounded);
    SdfProfile polygon;
    polygon.type = SdfProfileType::Polygon;
    polygon.points = {{0.0f, 0.0f}, {0.5f, -0.1f}, {0.4f, 0.3f}, {0.1f, 0.2f}, {-0.2f, 0.5f}};
    profiles.push_back(polygon);

    for (std::size_t i = 0; i < profiles.size(); ++i) {
        for (const SdfProfileSolid solid :
             {SdfProfileSolid::Extrusion, SdfProfileSolid::Revolution}) {
            for (const float offset : {0.0f, 0.6f}) {
                SdfProfile profile = profiles[i];
                profile.solid = solid;
                profile.depth = 0.7f;
                profile.offset = offset;
                SdfNode node;
                node.pointer = "/sdf";
                node.profile = profile;
                node.transform =
                    transform({0.1f, 0.2f, 0.0f}, {30.0f, 0.0f, 40.0f}, {1.0f, 0.6f, 1.4f});
                SdfModifier round = modifier(SdfModifierType::Round, "/sdf/modifiers/0");
                round.radius = 0.05f;
                node.modifiers.push_back(round);
                expectTreeContained(node,
                                    "profile " + std::to_string(i) + " solid " +
                                        std::to_string(int(solid)) + " offset " +
                                        std::to_string(offset),
                                    true);
            }
        }
    }
    // Extrusion: depth is the full length along z; revolution: the offset moves the profile
    // away from the y axis.
    SdfProfile extruded = rectangle;
    extruded.depth = 1.0f;
    const SdfBounds e = profileBounds(extruded);
    EXPECT_NEAR(e.box.max.z, 0.5f, 1e-6f);
    EXPECT_NEAR(e.box.max.x, 0.4f, 1e-6f);
    SdfProfile revolved = circle;
    revolved.solid = SdfProfileSolid::Revolution;
    revolved.offset = 1.0f;
    const SdfBounds r = profileBounds(revolved);
    EXPECT_NEAR(r.box.max.x, 1.3f, 1e-6f);
    EXPECT_NEAR(r.box.min.z, -1.3f, 1e-6f);
    EXPECT_NEAR(r.box.max.y, 0.3f, 1e-6f);
}

TEST(SdfBounds, UnboundedContentNamesThePointerResponsible) {
    const SdfNode plane = shape(PrimitiveId::Plane, {0.0f, 1.0f, 0.0f, 0.0f}, "/sdf/children/1");
    {
        const SdfBounds b = sdfNodeBounds(plane);
        EXPECT_FALSE(b.bounded);
        EXPECT_EQ(b.unboundedBy, "/sdf/children/1");
    }
    {
        SdfNode node = sphere(0.3f, "/sdf");
        SdfModifier finite = modifier(SdfModifierType::Repeat, "/sdf/modifiers/0");
        finite.vector = {1.0f, 0.0f, 0.0f};
        finite.counts = {3, 0, 0};
        SdfModifier infiniteRepeat = modifier(SdfModifierType::Repeat, "/sdf/modifiers/1");
        infiniteRepeat.vector = {0.0f, 0.0f, 2.0f}; // z repeated without end, x and y not at all
        node.modifiers = {finite, infiniteRepeat};
        const SdfBounds b = sdfNodeBounds(node);
        EXPECT_FALSE(b.bounded);
        EXPECT_EQ(b.unboundedBy, "/sdf/modifiers/1");
    }
    {
        SdfNode u = group(SdfOp::Union, {sphere(0.3f, "/sdf/children/0"), plane}, "/sdf");
        const SdfBounds b = sdfNodeBounds(u);
        EXPECT_FALSE(b.bounded);
        EXPECT_EQ(b.unboundedBy, "/sdf/children/1");
        // Under a parent and a modifier, the plane is still named.
        SdfNode mirrored = u;
        mirrored.modifiers.push_back(modifier(SdfModifierType::Mirror, "/sdf/modifiers/0"));
        mirrored.modifiers.back().axes = {true, false, false};
        EXPECT_EQ(sdfNodeBounds(group(SdfOp::SmoothUnion, {mirrored}, "/", 0.1f)).unboundedBy,
                  "/sdf/children/1");
    }
    {
        // Intersection and subtraction: bounded by the bounded operand.
        for (const SdfOp op : {SdfOp::Intersection, SdfOp::SmoothIntersection,
                               SdfOp::ChamferIntersection, SdfOp::RoundIntersection}) {
            SdfNode cap = group(op, {plane, sphere(0.5f, "/sdf/children/1")}, "/sdf", 0.2f);
            const SdfBounds b = sdfNodeBounds(cap);
            expectBox(b, glm::vec3(-0.5f), glm::vec3(0.5f));
            expectTreeContained(cap, "plane and sphere, op " + std::to_string(int(op)));
        }
        SdfNode sub = group(SdfOp::Subtraction, {sphere(0.5f, "/sdf/children/0"), plane}, "/sdf");
        expectBox(sdfNodeBounds(sub), glm::vec3(-0.5f), glm::vec3(0.5f));
        SdfNode firstPlane = plane;
        firstPlane.pointer = "/sdf/children/0";
        SdfNode subPlane =
            group(SdfOp::Subtraction, {firstPlane, sphere(0.5f, "/sdf/children/1")}, "/sdf");
        EXPECT_EQ(sdfNodeBounds(subPlane).unboundedBy, "/sdf/children/0");
        // Two unbounded operands of an intersection: still unbounded.
        SdfNode slab =
            group(SdfOp::Intersection,
                  {plane, shape(PrimitiveId::Plane, {0.0f, -1.0f, 0.0f, 0.5f}, "/sdf/children/1")},
                  "/sdf");
        EXPECT_FALSE(sdfNodeBounds(slab).bounded);
    }
}

// The same tree below ancestors that shrink it: the caller passes the ancestors' scale so the
// world-unit smoothness is converted into the subtree's frame.
TEST(SdfBounds, SubtreeBoundsUseTheAncestorsScale) {
    SdfNode inner = group(SdfOp::SmoothUnion, {}, "/sdf/children/0", 0.2f);
    inner.children.push_back(
        sphere(0.3f, "/sdf/children/0/children/0", transform({-0.5f, 0.0f, 0.0f})));
    inner.children.push_back(
        sphere(0.3f, "/sdf/children/0/children/1", transform({0.5f, 0.0f, 0.0f})));
    const SdfBounds atRoot = sdfNodeBounds(inner);
    const SdfBounds below = sdfNodeBounds(inner, 0.25f); // ancestors scale by 0.25
    ASSERT_TRUE(atRoot.bounded && below.bounded);
    EXPECT_NEAR(atRoot.box.max.y, 0.3f + 0.05f, 1e-5f);
    EXPECT_NEAR(below.box.max.y, 0.3f + 0.2f, 1e-5f); // k = 0.2 world = 0.8 local, k/4
    SdfNode root = group(SdfOp::Union, {inner}, "/sdf", 0.0f,
                         transform(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.25f)));
    expectTreeContained(root, "smooth union below a scale of 0.25", true);
}

// A child whose field the compiler divides by its step correction (twist, bend, displacement)
// reaches further into a smooth union's blend: the blend's level is longer in its frame.
TEST(SdfBounds, StepCorrectedChildrenReachFurtherIntoABlend) {
    std::vector<SdfModifier> corrections;
    SdfModifier twist = modifier(SdfModifierType::Twist, "/sdf/children/0/modifiers/0");
    twist.amount = 300.0f;
    twist.radius = 1.0f;
    corrections.push_back(twist);
    SdfModifier bend = modifier(SdfModifierType::Bend, "/sdf/children/0/modifiers/0");
    bend.amount = 200.0f;
    bend.radius = 1.0f;
    corrections.push_back(bend);
    SdfModifier displace = modifier(SdfModifierType::Displace, "/sdf/children/0/modifiers/0");
    displace.amount = 0.02f;
    displace.frequency = 20.0f;
    corrections.push_back(displace);
    for (const SdfModifier& m : corrections) {
        for (const SdfOp op : {SdfOp::SmoothUnion, SdfOp::ChamferUnion, SdfOp::RoundUnion}) {
            SdfNode corrected = shape(PrimitiveId::Box, {0.3f, 0.3f, 0.3f}, "/sdf/children/0",
                                      transform({-0.35f, 0.0f, 0.0f}));
            corrected.modifiers.push_back(m);
            SdfNode root = group(
                op, {corrected, sphere(0.3f, "/sdf/children/1", transform({0.35f, 0.0f, 0.0f}))},
                "/sdf", 0.6f);
            EXPECT_GT(sdfFieldShrink(corrected.modifiers), 2.0);
            expectTreeContained(root, "modifier " + std::to_string(int(m.type)) + " under op " +
                                          std::to_string(int(op)));
        }
    }
}

// Under a non-uniform scale the field is the local distance times the smallest scale factor, so
// a rounding of the group reaches 1 / that factor further along the other axes.
TEST(SdfBounds, NonUniformScaleStretchesTheLevel) {
    SdfNode root = group(SdfOp::Union,
                         {sphere(0.5f, "/sdf/children/0",
                                 transform(glm::vec3(0.0f), glm::vec3(0.0f), {1.0f, 0.1f, 1.0f}))},
                         "/sdf");
    SdfModifier round = modifier(SdfModifierType::Round, "/sdf/modifiers/0");
    round.radius = 0.1f;
    root.modifiers.push_back(round);
    const SdfProgram program = compile(root);
    // 0.1 (|(x, 10 y, z)| - 0.5) - 0.1 <= 0 out to x = 1.5.
    EXPECT_LT(sdfDistance(program, glm::vec3(1.45f, 0.0f, 0.0f)), 0.0f);
    expectBox(sdfNodeBounds(root), {-1.5f, -0.15f, -1.5f}, {1.5f, 0.15f, 1.5f});
    expectTreeContained(root, "rounded flattened sphere", true);
}
