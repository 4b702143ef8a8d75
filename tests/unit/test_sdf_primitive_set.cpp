// The full primitive set (Quilez's 3D distance functions and the fractals): distances at points
// whose answer is worked out by hand from the geometry, the "between two points" variants
// against their vertical twins, every bound never above a brute-force distance to its surface,
// and the fractals' known inside / outside points and bounding spheres.
#include "sdf/primitives.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace rmsc;

namespace {

float distanceOf(PrimitiveId id, std::initializer_list<float> params, glm::vec3 p) {
    PrimitiveParams packed{};
    std::copy(params.begin(), params.end(), packed.begin());
    return primitiveSpec(id).distance(p, packed.data());
}

constexpr float kTol = 1e-4f;
const float kSqrt2 = std::sqrt(2.0f);

} // namespace

TEST(SdfPrimitiveSet, BoxFrame) {
    const auto d = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::BoxFrame, {1, 1, 1, 0.1f}, p);
    };
    EXPECT_NEAR(d({2, 1, 0}), 1.0f, kTol); // beside the bar along z at x = y = 1
    // Bars of half thickness 0.1 fill [0.8, 1] across. The centre: the nearest bar (x, y in
    // [0.8, 1]) is sqrt(0.8^2 + 0.8^2) away.
    EXPECT_NEAR(d({0, 0, 0}), std::sqrt(1.28f), kTol);
    // Above the middle of the z = 1 face: the bars there lie 0.8 to the side and 1 below.
    EXPECT_NEAR(d({0, 0, 2}), std::sqrt(0.64f + 1.0f), kTol);
    EXPECT_NEAR(d({0.9f, 0.9f, 0.5f}), -0.1f, kTol); // the middle of a bar
    EXPECT_LT(d({0.95f, 0.95f, 0}), 0.0f);
}

TEST(SdfPrimitiveSet, CappedTorus) {
    // 90 degrees either side of +y: the upper half ring of radius 1, tube 0.25.
    const auto d = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::CappedTorus, {90, 1, 0.25f}, p);
    };
    EXPECT_NEAR(d({0, 1, 0}), -0.25f, kTol);
    EXPECT_NEAR(d({0, 3, 0}), 1.75f, kTol);
    EXPECT_NEAR(d({1, -1, 0}), 0.75f, kTol);                   // nearest the arc's end (1, 0, 0)
    EXPECT_NEAR(d({0, -1, 0}), std::sqrt(2.0f) - 0.25f, kTol); // both ends are sqrt 2 away
}

TEST(SdfPrimitiveSet, Link) {
    const auto d = [](glm::vec3 p) { return distanceOf(PrimitiveId::Link, {0.5f, 1, 0.2f}, p); };
    EXPECT_NEAR(d({1, 0.3f, 0}), -0.2f, kTol); // on a straight side's centre line
    EXPECT_NEAR(d({0, 1.5f, 0}), -0.2f, kTol); // on the top arc's centre line
    EXPECT_NEAR(d({0, 0, 0}), 0.8f, kTol);
    EXPECT_NEAR(d({1, 0, 1}), 0.8f, kTol);
}

TEST(SdfPrimitiveSet, InfiniteCylinderAndCones) {
    EXPECT_NEAR(distanceOf(PrimitiveId::InfiniteCylinder, {0.5f}, {3, 100, 4}), 4.5f, kTol);
    // Cone of 45 degrees, height 1: apex (0, 0.5, 0), base of radius 1 at y = -0.5.
    const auto cone = [](glm::vec3 p) { return distanceOf(PrimitiveId::Cone, {45, 1}, p); };
    EXPECT_NEAR(cone({0, 2, 0}), 1.5f, kTol);
    EXPECT_NEAR(cone({0, -1.5f, 0}), 1.0f, kTol);
    EXPECT_NEAR(cone({0, 0, 0}), -0.5f * std::sin(glm::radians(45.0f)), kTol); // side nearer
    EXPECT_NEAR(cone({2, -0.5f, 0}), 1.0f, kTol); // beside the base rim
    // Infinite cone of 45 degrees opening towards -y.
    const auto infinite = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::InfiniteCone, {45}, p);
    };
    EXPECT_NEAR(infinite({0, -1, 0}), -std::sqrt(0.5f), kTol);
    EXPECT_NEAR(infinite({1, 0, 0}), std::sqrt(0.5f), kTol);
    EXPECT_NEAR(infinite({0, 2, 0}), 2.0f, kTol); // above the apex
}

TEST(SdfPrimitiveSet, Prisms) {
    const auto hex = [](glm::vec3 p) { return distanceOf(PrimitiveId::HexPrism, {0.5f, 1}, p); };
    EXPECT_NEAR(hex({0, 2, 0}), 1.5f, kTol); // a flat side at y = 0.5
    EXPECT_NEAR(hex({0, 0, 3}), 2.0f, kTol);
    EXPECT_NEAR(hex({0, 0, 0}), -0.5f, kTol);
    // The corners lie at radius 0.5 / cos 30 on the x axis.
    EXPECT_NEAR(hex({2, 0, 0}), 2.0f - 0.5f / std::cos(glm::radians(30.0f)), kTol);
    const auto tri = [](glm::vec3 p) { return distanceOf(PrimitiveId::TriPrism, {0.5f, 1}, p); };
    EXPECT_NEAR(tri({0, -2, 0}), 1.5f, kTol); // the bottom side at y = -0.5
    EXPECT_NEAR(tri({0, 0, 0}), -0.5f, kTol);
    EXPECT_NEAR(tri({0, 0, 2}), 1.0f, kTol);
    // Above the apex (0, 1): a bound, between 0 and the true distance 2.
    EXPECT_GT(tri({0, 3, 0}), 0.0f);
    EXPECT_LE(tri({0, 3, 0}), 2.0f);
}

TEST(SdfPrimitiveSet, CapsuleAndCylinderBetweenPoints) {
    const auto capsule = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::CapsuleBetween, {0, 0, 0, 2, 0, 0, 0.5f}, p);
    };
    EXPECT_NEAR(capsule({1, 1, 0}), 0.5f, kTol);
    EXPECT_NEAR(capsule({-1, 0, 0}), 0.5f, kTol);
    EXPECT_NEAR(capsule({3, 0, 1}), kSqrt2 - 0.5f, kTol);
    const auto cylinder = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::CappedCylinderBetween, {0, 0, 0, 0, 0, 2, 1}, p);
    };
    EXPECT_NEAR(cylinder({0, 0, 3}), 1.0f, kTol);
    EXPECT_NEAR(cylinder({2, 0, 1}), 1.0f, kTol);
    EXPECT_NEAR(cylinder({0, 0, 1}), -1.0f, kTol);
    EXPECT_NEAR(cylinder({0, 2, 3}), kSqrt2, kTol); // nearest the rim
    EXPECT_NEAR(cylinder({0, 0, 0.25f}), -0.25f, kTol);
}

// A vertical shape and its "between two points" twin with a = (0, -h, 0), b = (0, h, 0) agree.
TEST(SdfPrimitiveSet, BetweenPointsVariantsMatchTheVerticalOnes) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
    for (int n = 0; n < 200; ++n) {
        const glm::vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        EXPECT_NEAR(
            distanceOf(PrimitiveId::CappedCylinderBetween, {0, -0.7f, 0, 0, 0.7f, 0, 0.4f}, p),
            distanceOf(PrimitiveId::CappedCylinder, {0.4f, 0.7f}, p), 1e-4f);
        EXPECT_NEAR(distanceOf(PrimitiveId::CapsuleBetween, {0, -0.7f, 0, 0, 0.7f, 0, 0.4f}, p),
                    distanceOf(PrimitiveId::Capsule, {0.7f, 0.4f}, p), 1e-4f);
        EXPECT_NEAR(
            distanceOf(PrimitiveId::CappedConeBetween, {0, -0.6f, 0, 0, 0.6f, 0, 0.5f, 0.2f}, p),
            distanceOf(PrimitiveId::CappedCone, {0.6f, 0.5f, 0.2f}, p), 1e-4f);
        EXPECT_NEAR(
            distanceOf(PrimitiveId::RoundConeBetween, {0, -0.4f, 0, 0, 0.4f, 0, 0.4f, 0.15f}, p),
            distanceOf(PrimitiveId::RoundCone, {0.4f, 0.15f, 0.8f}, p), 1e-4f);
    }
}

TEST(SdfPrimitiveSet, RoundedCylinderAndCappedCone) {
    const auto rounded = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::RoundedCylinder, {1, 0.2f, 1}, p);
    };
    EXPECT_NEAR(rounded({2, 0, 0}), 1.0f, kTol); // the outer size stays 1 x 1
    EXPECT_NEAR(rounded({0, 2, 0}), 1.0f, kTol);
    EXPECT_NEAR(rounded({2, 2, 0}), glm::length(glm::vec2(1.2f)) - 0.2f, kTol); // rim torus
    const auto cone = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::CappedCone, {1, 1, 0.5f}, p);
    };
    EXPECT_NEAR(cone({0, 2, 0}), 1.0f, kTol);
    EXPECT_NEAR(cone({0, -3, 0}), 2.0f, kTol);
    // The side runs from (1, -1) to (0.5, 1); (2, 0) projects inside it.
    EXPECT_NEAR(cone({2, 0, 0}), 2.5f / std::sqrt(4.25f), kTol);
}

TEST(SdfPrimitiveSet, SphereCuts) {
    // Solid angle of 90 degrees, radius 1: the upper half ball.
    const auto solid = [](glm::vec3 p) { return distanceOf(PrimitiveId::SolidAngle, {90, 1}, p); };
    EXPECT_NEAR(solid({0, 2, 0}), 1.0f, kTol);
    EXPECT_NEAR(solid({0, -1, 0}), 1.0f, kTol);
    EXPECT_NEAR(solid({2, -1, 0}), kSqrt2, kTol);
    // Cut sphere: radius 1 above y = 0, the same half ball.
    const auto cut = [](glm::vec3 p) { return distanceOf(PrimitiveId::CutSphere, {1, 0}, p); };
    EXPECT_NEAR(cut({0, -1, 0}), 1.0f, kTol);
    EXPECT_NEAR(cut({0, 2, 0}), 1.0f, kTol);
    EXPECT_NEAR(cut({2, -1, 0}), kSqrt2, kTol);
    EXPECT_NEAR(cut({0, 0.3f, 0}), -0.3f, kTol);
    // Hollow: the lower half of a shell of radius 1, half thickness 0.1.
    const auto bowl = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::CutHollowSphere, {1, 0, 0.1f}, p);
    };
    EXPECT_NEAR(bowl({0, 0, 0}), 0.9f, kTol);
    EXPECT_NEAR(bowl({0, -1, 0}), -0.1f, kTol);
    EXPECT_NEAR(bowl({0, 1, 0}), kSqrt2 - 0.1f, kTol); // nearest the rim circle
    // Death star: unit sphere minus a unit sphere at (1, 0, 0).
    const auto star = [](glm::vec3 p) { return distanceOf(PrimitiveId::DeathStar, {1, 1, 1}, p); };
    EXPECT_NEAR(star({-2, 0, 0}), 1.0f, kTol);
    EXPECT_NEAR(star({0.5f, 0, 0}), 0.5f, kTol); // in the dent, 0.5 from its surface
    EXPECT_NEAR(star({-0.5f, 0, 0}), -0.5f, kTol);
}

TEST(SdfPrimitiveSet, RoundConeAndVesica) {
    // Spheres of radius 0.5 at y = -0.5 and 0.25 at y = 0.5.
    const auto cone = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::RoundCone, {0.5f, 0.25f, 1}, p);
    };
    EXPECT_NEAR(cone({0, -2, 0}), 1.0f, kTol);
    EXPECT_NEAR(cone({0, 2, 0}), 1.25f, kTol);
    // Tips (0, +-1, 0), widest radius 0.5: the arcs have radius 1.25 about (-+0.75, 0).
    const auto vesica = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::RevolvedVesica, {0, -1, 0, 0, 1, 0, 0.5f}, p);
    };
    EXPECT_NEAR(vesica({0, 2, 0}), 1.0f, kTol);
    EXPECT_NEAR(vesica({2, 0, 0}), 1.5f, kTol);
    EXPECT_NEAR(vesica({0, 0, 0}), -0.5f, kTol);
}

TEST(SdfPrimitiveSet, RhombusOctahedronPyramid) {
    // A square of half diagonals 1 turned 45 degrees in xz, half thickness 0.1.
    const auto rhombus = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::Rhombus, {1, 1, 0.1f, 0}, p);
    };
    EXPECT_NEAR(rhombus({0, 1, 0}), 0.9f, kTol);
    EXPECT_NEAR(rhombus({1, 0, 1}), std::sqrt(0.5f), kTol); // off the edge x + z = 1
    EXPECT_NEAR(rhombus({0, 0, 0}), -0.1f, kTol);
    const auto octa = [](glm::vec3 p) { return distanceOf(PrimitiveId::Octahedron, {1}, p); };
    EXPECT_NEAR(octa({2, 0, 0}), 1.0f, kTol);
    EXPECT_NEAR(octa({1, 1, 1}), 2.0f / std::sqrt(3.0f), kTol); // off the face x + y + z = 1
    EXPECT_NEAR(octa({0, 0, 0}), -1.0f / std::sqrt(3.0f), kTol);
    EXPECT_NEAR(octa({1, 1, 0}), std::sqrt(0.5f), kTol); // off the edge from (1,0,0) to (0,1,0)
    // Pyramid: base 1 x 1 at y = -0.5, apex at y = 0.5.
    const auto pyramid = [](glm::vec3 p) { return distanceOf(PrimitiveId::Pyramid, {1, 1}, p); };
    EXPECT_NEAR(pyramid({0, 1.5f, 0}), 1.0f, kTol);
    EXPECT_NEAR(pyramid({0, -1.5f, 0}), 1.0f, kTol);
    EXPECT_NEAR(pyramid({2, -0.5f, 0}), 1.5f, kTol);
    EXPECT_NEAR(pyramid({2, -1.5f, 2}), std::sqrt(1.5f * 1.5f * 2.0f + 1.0f), kTol); // a corner
    EXPECT_NEAR(pyramid({0, -0.45f, 0}), -0.05f, kTol); // inside, just above the base
    // Scaling base and height by 2 scales the distances by 2.
    EXPECT_NEAR(distanceOf(PrimitiveId::Pyramid, {2, 2}, {0.6f, 1.4f, -0.4f}),
                2.0f * pyramid({0.3f, 0.7f, -0.2f}), kTol);
}

TEST(SdfPrimitiveSet, TriangleAndQuad) {
    const auto tri = [](glm::vec3 p, float t) {
        return distanceOf(PrimitiveId::Triangle, {0, 0, 0, 1, 0, 0, 0, 1, 0, t}, p);
    };
    EXPECT_NEAR(tri({0.25f, 0.25f, 2}, 0), 2.0f, kTol);
    EXPECT_NEAR(tri({0.25f, 0.25f, -2}, 0), 2.0f, kTol); // unsigned
    EXPECT_NEAR(tri({2, 0, 0}, 0), 1.0f, kTol);
    EXPECT_NEAR(tri({-1, -1, 0}, 0), kSqrt2, kTol);
    EXPECT_NEAR(tri({1, 1, 0}, 0), std::sqrt(0.5f), kTol); // off the hypotenuse
    EXPECT_NEAR(tri({0.25f, 0.25f, 2}, 0.1f), 1.9f, kTol);
    const auto quad = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::Quad, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, p);
    };
    EXPECT_NEAR(quad({0.5f, 0.5f, 3}), 3.0f, kTol);
    EXPECT_NEAR(quad({2, 0.5f, 0}), 1.0f, kTol);
    EXPECT_NEAR(quad({2, 2, 0}), kSqrt2, kTol);
    EXPECT_NEAR(quad({2, 2, 1}), std::sqrt(3.0f), kTol);
}

TEST(SdfPrimitiveSet, Mandelbulb) {
    const auto bulb = [](glm::vec3 p) { return distanceOf(PrimitiveId::Mandelbulb, {8, 8, 2}, p); };
    // Power 8: |c| > 2^(1/7) escapes; beyond the bounding sphere the distance to it.
    const float bound = std::pow(2.0f, 1.0f / 7.0f);
    EXPECT_NEAR(bulb({0, 0, 3}), 3.0f - bound, kTol);
    EXPECT_NEAR(bulb({-2, 2, 1}), 3.0f - bound, kTol);
    // |z| <= 0.7 and |c| <= 0.64 give |z^8 + c| <= 0.7^8 + 0.64 < 0.7: never escapes, inside.
    EXPECT_LT(bulb({0, 0, 0}), 0.0f);
    EXPECT_LT(bulb({0.6f, 0, 0}), 0.0f);
    EXPECT_LT(bulb({0.2f, -0.4f, 0.3f}), 0.0f);
    // Power 2: the bound is 2.
    EXPECT_NEAR(distanceOf(PrimitiveId::Mandelbulb, {2, 8, 4}, {0, 5, 0}), 3.0f, kTol);
}

TEST(SdfPrimitiveSet, MengerSponge) {
    const auto sponge = [](float iterations, glm::vec3 p) {
        return distanceOf(PrimitiveId::MengerSponge, {iterations, 0.5f}, p);
    };
    // Outside the circumscribed sphere (radius sqrt 3 / 2): the distance to it.
    EXPECT_NEAR(sponge(4, {0, 3, 0}), 3.0f - 0.5f * std::sqrt(3.0f), kTol);
    // No iteration: the cube of half edge 0.5.
    EXPECT_NEAR(sponge(0, {0, 0.7f, 0}), 0.2f, kTol);
    EXPECT_NEAR(sponge(0, {0, 0, 0}), -0.5f, kTol);
    // One level: the centre lies in the crossing of the holes of half width 1/3 (in units of
    // the half edge); the estimate is the distance to the nearest hole wall, 1/3 * 0.5.
    EXPECT_NEAR(sponge(1, {0, 0, 0}), 0.5f / 3.0f, kTol);
    EXPECT_GT(sponge(4, {0, 0, 0.49f}), 0.0f); // a face's central hole
    // Points by the corners stay solid at every level.
    EXPECT_LT(sponge(4, glm::vec3(0.495f)), 0.0f);
}

TEST(SdfPrimitiveSet, SierpinskiTetrahedron) {
    const auto tetra = [](float iterations, glm::vec3 p) {
        return distanceOf(PrimitiveId::SierpinskiTetrahedron, {iterations, 0.5f}, p);
    };
    // The corner (1, 1, 1) * size is a fixed point of the fold and scale: on the surface.
    EXPECT_NEAR(tetra(6, glm::vec3(0.5f)), 0.0f, kTol);
    EXPECT_NEAR(tetra(6, glm::vec3(-0.5f, -0.5f, 0.5f)), 0.0f, kTol);
    // The centre is hollow from level 1 on: the nearest sub-tetrahedron's face (x + y + z = 1
    // in the unit frame) is 1 / sqrt 3 away.
    EXPECT_NEAR(tetra(1, {0, 0, 0}), 0.5f / std::sqrt(3.0f), kTol);
    EXPECT_NEAR(tetra(5, {0, 0, 0}), 0.5f / std::sqrt(3.0f), kTol);
    EXPECT_LT(tetra(0, {0, 0, 0}), 0.0f); // level 0: the solid tetrahedron
    EXPECT_NEAR(tetra(6, {0, 4, 0}), 4.0f - 0.5f * std::sqrt(3.0f), kTol);
}

TEST(SdfPrimitiveSet, QuaternionJulia) {
    // c = 0: the set is the unit ball, z_n = z^(2^n), and the estimate |z| log|z| / (2 |z'|)
    // works out to 0.5 |p| log|p| at any iteration count.
    const auto ball = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::QuaternionJulia, {0, 0, 0, 0, 10}, p);
    };
    EXPECT_NEAR(ball({1.05f, 0, 0}), 0.5f * 1.05f * std::log(1.05f), 1e-5f);
    EXPECT_NEAR(ball({0, 1.05f, 0}), 0.5f * 1.05f * std::log(1.05f), 1e-5f);
    EXPECT_LT(ball({0.5f, 0.3f, 0}), 0.0f);
    // Bounding sphere of radius (1 + sqrt(1 + 4 |c|)) / 2.
    EXPECT_NEAR(ball({0, 0, 3}), 2.0f, kTol);
    const float c = glm::length(glm::vec4(-0.45f, -0.45f, 0.18f, 0.31f));
    const float bound = 0.5f * (1.0f + std::sqrt(1.0f + 4.0f * c));
    EXPECT_NEAR(
        distanceOf(PrimitiveId::QuaternionJulia, {-0.45f, -0.45f, 0.18f, 0.31f, 10}, {3, 0, 0}),
        3.0f - bound, kTol);
}

TEST(SdfPrimitiveSet, Gyroid) {
    // period 2 (s = pi), half thickness 0.05.
    const auto d = [](glm::vec3 p) { return distanceOf(PrimitiveId::Gyroid, {2, 0.05f}, p); };
    const float s = std::acos(-1.0f);
    EXPECT_NEAR(d({0, 0, 0}), -0.05f, kTol); // g(0) = 0: the middle of the sheet
    // q = (pi/2, 0, 0): g = sin(pi/2) cos 0 = 1.
    EXPECT_NEAR(d({0.5f, 0, 0}), 1.0f / (std::sqrt(3.0f) * s) - 0.05f, kTol);
    EXPECT_NEAR(d({2.5f, 2, -4}), d({0.5f, 0, 0}), kTol); // periodic along every axis
    // 1-Lipschitz (what makes it a safe step): |d(a) - d(b)| <= |a - b| for close pairs, where
    // the bound is tightest, and far ones.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f), offset(-0.05f, 0.05f);
    float steepest = 0.0f;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 a(coordinate(rng), coordinate(rng), coordinate(rng));
        const glm::vec3 b = a + (i % 2 ? glm::vec3(offset(rng), offset(rng), offset(rng))
                                       : glm::vec3(coordinate(rng), coordinate(rng), 0.0f));
        const float length = glm::length(a - b);
        if (length < 1e-3f) continue;
        const float slope = std::abs(d(a) - d(b)) / length;
        steepest = std::max(steepest, slope);
        ASSERT_LE(slope, 1.0f + 1e-3f) << "between " << a.x << ", " << a.y << ", " << a.z;
    }
    // And not needlessly loose: the steepest slope found comes near 1.
    EXPECT_GT(steepest, 0.8f);
}

// Every bound, times the step scale the march applies, stays at or below the distance to the
// nearest of many surface points, found as sign changes of the function along the edges of a
// fine grid (refined by bisection). Surface points are on the surface, so the nearest one is
// at least the true distance.
TEST(SdfPrimitiveSet, BoundsNeverOverestimate) {
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        if (spec.exact) continue;
        SCOPED_TRACE(std::string(spec.name));
        const PrimitiveParams params = defaultParams(spec);
        const auto f = [&](glm::vec3 p) { return spec.distance(p, params.data()); };
        const int n = 72;
        const float lo = -1.3f, step = 2.6f / float(n);
        std::vector<float> grid(std::size_t(n + 1) * (n + 1) * (n + 1));
        const auto at = [&](int i, int j, int k) -> float& {
            return grid[(std::size_t(i) * (n + 1) + j) * (n + 1) + k];
        };
        const auto point = [&](int i, int j, int k) {
            return glm::vec3(lo + step * float(i), lo + step * float(j), lo + step * float(k));
        };
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                for (int k = 0; k <= n; ++k)
                    at(i, j, k) = f(point(i, j, k));
        std::vector<glm::vec3> surface;
        const auto refine = [&](glm::vec3 a, glm::vec3 b) {
            float fa = f(a);
            for (int it = 0; it < 20; ++it) {
                const glm::vec3 m = 0.5f * (a + b);
                const float fm = f(m);
                if ((fm < 0.0f) == (fa < 0.0f)) {
                    a = m;
                    fa = fm;
                } else {
                    b = m;
                }
            }
            surface.push_back(0.5f * (a + b));
        };
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                for (int k = 0; k <= n; ++k) {
                    const bool inside = at(i, j, k) < 0.0f;
                    if (i < n && (at(i + 1, j, k) < 0.0f) != inside)
                        refine(point(i, j, k), point(i + 1, j, k));
                    if (j < n && (at(i, j + 1, k) < 0.0f) != inside)
                        refine(point(i, j, k), point(i, j + 1, k));
                    if (k < n && (at(i, j, k + 1) < 0.0f) != inside)
                        refine(point(i, j, k), point(i, j, k + 1));
                }
        ASSERT_GT(surface.size(), 500u);
        std::mt19937 rng(31);
        std::uniform_real_distribution<float> coordinate(-1.6f, 1.6f);
        int tested = 0;
        for (int attempt = 0; attempt < 4000 && tested < 150; ++attempt) {
            const glm::vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
            const float d = f(p);
            if (d <= 0.0f) continue;
            float nearest = 1e30f;
            for (const glm::vec3& s : surface)
                nearest = std::min(nearest, glm::length(p - s));
            EXPECT_LE(d * spec.stepScale, nearest + 1e-4f)
                << "at " << p.x << ", " << p.y << ", " << p.z;
            ++tested;
        }
        EXPECT_EQ(tested, 150);
    }
}
