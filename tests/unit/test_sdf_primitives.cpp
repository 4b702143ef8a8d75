// The primitive catalogue: every distance function against values worked out by hand, the
// gradient length of the exact ones, the ellipsoid bound against a brute-force distance, the
// parameter defaults, and that the GLSL side (generated dispatch, sdf_primitives.glsl) names
// every row.
#include "sdf/primitives.hpp"
#include "sdf/program.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

using namespace rmsc;

namespace {

float distanceOf(PrimitiveId id, std::initializer_list<float> params, glm::vec3 p) {
    PrimitiveParams packed{};
    std::copy(params.begin(), params.end(), packed.begin());
    return primitiveSpec(id).distance(p, packed.data());
}

std::string readSourceFile(const std::string& relative) {
    std::ifstream in(std::string(RMSC_TEST_SOURCE_DIR) + "/" + relative);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

constexpr float kTol = 1e-5f;

} // namespace

TEST(SdfPrimitives, Sphere) {
    // |p| - r.
    EXPECT_NEAR(distanceOf(PrimitiveId::Sphere, {0.5f}, {2, 0, 0}), 1.5f, kTol);
    EXPECT_NEAR(distanceOf(PrimitiveId::Sphere, {0.5f}, {0, 0.5f, 0}), 0.0f, kTol);
    EXPECT_NEAR(distanceOf(PrimitiveId::Sphere, {0.5f}, {0, 0, 0}), -0.5f, kTol);
    EXPECT_NEAR(distanceOf(PrimitiveId::Sphere, {1.0f}, {3, 4, 0}), 4.0f, kTol);
}

TEST(SdfPrimitives, Box) {
    const auto d = [](glm::vec3 p) { return distanceOf(PrimitiveId::Box, {1, 2, 3}, p); };
    EXPECT_NEAR(d({3, 0, 0}), 2.0f, kTol);            // facing the +x face at x = 1
    EXPECT_NEAR(d({0, -5, 0}), 3.0f, kTol);           // facing the -y face at y = -2
    EXPECT_NEAR(d({2, 3, 1}), std::sqrt(2.0f), kTol); // nearest the edge (1, 2, z)
    EXPECT_NEAR(d({2, 3, 4}), std::sqrt(3.0f), kTol); // nearest the corner (1, 2, 3)
    EXPECT_NEAR(d({0, 0, 0}), -1.0f, kTol);           // inside: nearest face is x = +-1
    EXPECT_NEAR(d({0, 0, 2.5f}), -0.5f, kTol);        // inside, 0.5 below the z face
}

TEST(SdfPrimitives, RoundBox) {
    const auto d = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::RoundBox, {1, 1, 1, 0.25f}, p);
    };
    // The faces stay at +-1; the corners become spheres of radius 0.25 around (0.75, 0.75, 0.75).
    EXPECT_NEAR(d({3, 0, 0}), 2.0f, kTol);
    EXPECT_NEAR(d({2, 2, 2}), glm::length(glm::vec3(2.0f - 0.75f)) - 0.25f, kTol);
    EXPECT_NEAR(d({0, 0, 0}), -1.0f, kTol);
    // Corner of the unrounded box lies outside the rounded one by |(0.25,0.25,0.25)| - 0.25.
    EXPECT_NEAR(d({1, 1, 1}), std::sqrt(3.0f) * 0.25f - 0.25f, kTol);
}

TEST(SdfPrimitives, Torus) {
    const auto d = [](glm::vec3 p) { return distanceOf(PrimitiveId::Torus, {1.0f, 0.25f}, p); };
    EXPECT_NEAR(d({1, 0, 0}), -0.25f, kTol); // on the ring: the tube's centre
    EXPECT_NEAR(d({0, 0, 0}), 0.75f, kTol);  // centre of the hole
    EXPECT_NEAR(d({3, 0, 0}), 1.75f, kTol);
    EXPECT_NEAR(d({0, 1, -1}), 0.75f, kTol);   // above the ring point (0, 0, -1)
    EXPECT_NEAR(d({0, 0.25f, 1}), 0.0f, kTol); // top of the tube
}

TEST(SdfPrimitives, CappedCylinder) {
    const auto d = [](glm::vec3 p) {
        return distanceOf(PrimitiveId::CappedCylinder, {1.0f, 2.0f}, p);
    };
    EXPECT_NEAR(d({3, 0, 0}), 2.0f, kTol);            // side
    EXPECT_NEAR(d({0, 5, 0}), 3.0f, kTol);            // cap
    EXPECT_NEAR(d({0, 3, 2}), std::sqrt(2.0f), kTol); // nearest the rim at radius 1, y = 2
    EXPECT_NEAR(d({0, 0, 0}), -1.0f, kTol);           // the side (1 away) is nearer than a cap
    EXPECT_NEAR(d({0, 1.5f, 0}), -0.5f, kTol);        // the cap is 0.5 away
}

TEST(SdfPrimitives, PlaneNormalizesItsNormal) {
    EXPECT_NEAR(distanceOf(PrimitiveId::Plane, {0, 2, 0, 1}, {5, 4, 7}), 3.0f, kTol);
    EXPECT_NEAR(distanceOf(PrimitiveId::Plane, {0, 2, 0, 1}, {5, -1, 7}), -2.0f, kTol);
    EXPECT_NEAR(distanceOf(PrimitiveId::Plane, {1, 1, 0, 0}, {1, 1, 0}), std::sqrt(2.0f), kTol);
}

TEST(SdfPrimitives, Capsule) {
    const auto d = [](glm::vec3 p) { return distanceOf(PrimitiveId::Capsule, {1.0f, 0.5f}, p); };
    EXPECT_NEAR(d({2, 0, 0}), 1.5f, kTol);
    EXPECT_NEAR(d({0, 3, 0}), 1.5f, kTol); // beyond the top end (0, 1, 0)
    EXPECT_NEAR(d({0, -1.5f, 0}), 0.0f, kTol);
    EXPECT_NEAR(d({3, 5, 0}), 5.0f - 0.5f, kTol); // (3, 4) from the top end
    EXPECT_NEAR(d({0, 0, 0}), -0.5f, kTol);
}

TEST(SdfPrimitives, EllipsoidIsExactOnItsAxesAndZeroOnItsSurface) {
    const auto d = [](glm::vec3 p) { return distanceOf(PrimitiveId::Ellipsoid, {3, 2, 1}, p); };
    // On the x axis, k0 = x/a and k1 = x/a^2, so k0 (k0 - 1) / k1 = x - a: the true distance.
    EXPECT_NEAR(d({5, 0, 0}), 2.0f, kTol);
    EXPECT_NEAR(d({0, -3, 0}), 1.0f, kTol);
    EXPECT_NEAR(d({0, 0, 4}), 3.0f, kTol);
    // Points with (x/a)^2 + (y/b)^2 + (z/c)^2 = 1 give k0 = 1.
    const float s = std::sqrt(1.0f / 3.0f);
    EXPECT_NEAR(d({3 * s, 2 * s, 1 * s}), 0.0f, kTol);
    EXPECT_NEAR(d({0, 0, 0}), -1.0f, kTol); // the centre: minus the smallest radius
}

// Exact distances have a gradient of length 1 wherever they are differentiable; outside the
// convex primitives that is everywhere, outside the others everywhere off their creases.
TEST(SdfPrimitives, ExactPrimitivesHaveUnitGradientOutside) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
    const float h = 1e-3f;
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        if (!spec.exact) continue;
        SCOPED_TRACE(std::string(spec.name));
        PrimitiveParams params = defaultParams(spec);
        if (spec.id == PrimitiveId::Plane) { // a tilted, unnormalized normal
            params[0] = 0.3f;
            params[1] = 1.0f;
            params[2] = -0.5f;
            params[3] = 0.2f;
        }
        const auto f = [&](glm::vec3 p) { return spec.distance(p, params.data()); };
        int tested = 0;
        while (tested < 200) {
            const glm::vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
            if (f(p) < 0.05f) continue;
            if (spec.id == PrimitiveId::Torus && glm::length(glm::vec2(p.x, p.z)) < 0.1f) continue;
            // Skip points on a crease of the field (where the nearest surface point jumps, as
            // on a medial surface of a non-convex shape): there the one-sided differences
            // disagree and no gradient exists.
            const float f0 = f(p);
            bool crease = false;
            for (int axis = 0; axis < 3; ++axis) {
                glm::vec3 e(0.0f);
                e[axis] = h;
                crease = crease || std::abs((f(p + e) - f0) - (f0 - f(p - e))) > 0.1f * h;
            }
            if (crease) continue;
            const glm::vec3 gradient((f(p + glm::vec3(h, 0, 0)) - f(p - glm::vec3(h, 0, 0))),
                                     (f(p + glm::vec3(0, h, 0)) - f(p - glm::vec3(0, h, 0))),
                                     (f(p + glm::vec3(0, 0, h)) - f(p - glm::vec3(0, 0, h))));
            EXPECT_NEAR(glm::length(gradient / (2.0f * h)), 1.0f, 1e-2f)
                << "at " << p.x << ", " << p.y << ", " << p.z;
            ++tested;
        }
    }
}

// The ellipsoid distance is a bound: never more than the distance to the nearest point of a
// dense sampling of the surface (which itself is >= the true distance).
TEST(SdfPrimitives, EllipsoidNeverOverestimates) {
    const glm::vec3 radii(0.9f, 0.4f, 0.2f);
    std::vector<glm::vec3> surface;
    const int rings = 300, segments = 600;
    for (int i = 0; i <= rings; ++i) {
        const float theta = float(M_PI) * float(i) / float(rings);
        for (int j = 0; j < segments; ++j) {
            const float phi = 2.0f * float(M_PI) * float(j) / float(segments);
            surface.push_back(radii * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                std::sin(theta) * std::sin(phi)));
        }
    }
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> coordinate(-1.5f, 1.5f);
    int outside = 0;
    for (int n = 0; n < 300; ++n) {
        const glm::vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        const float bound = distanceOf(PrimitiveId::Ellipsoid, {radii.x, radii.y, radii.z}, p);
        float nearest = 1e30f;
        for (const glm::vec3& s : surface)
            nearest = std::min(nearest, glm::length(p - s));
        const glm::vec3 unit = p / radii;
        const bool inside = glm::dot(unit, unit) < 1.0f;
        if (inside) {
            EXPECT_LE(bound, 0.0f);
        } else {
            ++outside;
            EXPECT_GE(bound, 0.0f);
            EXPECT_LE(bound, nearest + 1e-5f) << "at " << p.x << ", " << p.y << ", " << p.z;
        }
    }
    EXPECT_GT(outside, 200);
}

TEST(SdfPrimitives, DefaultsAreWithinRangesAndParamsFit) {
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        SCOPED_TRACE(std::string(spec.name));
        int floats = 0;
        for (const ParamSpec& param : spec.params) {
            EXPECT_TRUE(param.components == 1 || param.components == 3);
            EXPECT_LE(param.minValue, param.maxValue);
            for (int c = 0; c < param.components; ++c) {
                EXPECT_GE(param.value[c], param.minValue) << param.name;
                EXPECT_LE(param.value[c], param.maxValue) << param.name;
            }
            floats += param.components;
        }
        EXPECT_LE(floats, kMaxPrimitiveFloats);
        const PrimitiveParams defaults = defaultParams(spec);
        for (std::size_t i = 0; i < spec.params.size(); ++i)
            EXPECT_EQ(defaults[paramOffset(spec, int(i))], spec.params[i].value[0]);
        EXPECT_EQ(findPrimitive(spec.name), &spec);
        EXPECT_EQ(&primitiveSpec(spec.id), &spec);
    }
    EXPECT_EQ(findPrimitive("no_such_shape"), nullptr);
}

TEST(SdfPrimitives, GlslDispatchCallsEveryFunction) {
    const std::string glsl = generateGlslDispatch();
    EXPECT_NE(glsl.find("float sdfPrimitive(uint id, vec3 p, vec4 a, vec4 b, vec4 c)"),
              std::string::npos);
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        const std::string call = "case " + std::to_string(std::uint32_t(spec.id)) + "u: return " +
                                 std::string(spec.glslFunction) + "(p";
        EXPECT_NE(glsl.find(call), std::string::npos) << call;
    }
}

// The hand-written GLSL defines each catalogue function with as many arguments as the dispatch
// passes (p plus one per parameter).
TEST(SdfPrimitives, GlslFileDefinesEveryFunction) {
    const std::string glsl = readSourceFile("shaders/common/sdf_primitives.glsl");
    ASSERT_FALSE(glsl.empty());
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        const std::string head = "float " + std::string(spec.glslFunction) + "(vec3 p";
        const std::size_t at = glsl.find(head);
        ASSERT_NE(at, std::string::npos) << head;
        const std::string signature = glsl.substr(at, glsl.find(')', at) - at);
        std::string expected = head;
        for (const ParamSpec& param : spec.params)
            expected += param.components == 1 ? ", float" : ", vec3";
        std::string types = head; // the signature with the argument names dropped
        std::istringstream words(signature.substr(head.size()));
        std::string word;
        while (words >> word)
            if (word == "float" || word == "vec3") types += ", " + word;
        EXPECT_EQ(types, expected);
    }
    // The stack sizes, opcodes and kinds come from the generated header, not from a copy.
    const std::string scene = readSourceFile("shaders/common/sdf_functions.glsl");
    EXPECT_NE(scene.find("#include \"generated/constants.glsl\""), std::string::npos);
    EXPECT_EQ(scene.find("#define SDF_MAX_STACK"), std::string::npos);
}
