// The primitive catalogue rows and their C++ distance functions. Formulas follow Inigo Quilez,
// "Distance functions" (https://iquilezles.org/articles/distfunctions/); the GLSL versions in
// shaders/common/sdf_primitives.glsl must stay identical.
#include "sdf/primitives.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

namespace rmsc {
namespace {

using glm::vec2;
using glm::vec3;

constexpr float kBig = 1.0e4f; // upper bound of lengths in the scene format

vec3 v3(const float* p) { return vec3(p[0], p[1], p[2]); }

float sdSphere(vec3 p, const float* a) { return glm::length(p) - a[0]; }

float sdBox(vec3 p, const float* a) {
    const vec3 q = glm::abs(p) - v3(a);
    return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

float sdRoundBox(vec3 p, const float* a) {
    const float r = a[3];
    const vec3 q = glm::abs(p) - v3(a) + r;
    return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f) - r;
}

float sdTorus(vec3 p, const float* a) {
    const vec2 q(glm::length(vec2(p.x, p.z)) - a[0], p.y);
    return glm::length(q) - a[1];
}

float sdCappedCylinder(vec3 p, const float* a) {
    const vec2 d = glm::abs(vec2(glm::length(vec2(p.x, p.z)), p.y)) - vec2(a[0], a[1]);
    return std::min(std::max(d.x, d.y), 0.0f) + glm::length(glm::max(d, 0.0f));
}

float sdPlane(vec3 p, const float* a) {
    const vec3 n = v3(a);
    return glm::dot(p, n) / std::max(glm::length(n), 1e-6f) - a[3];
}

float sdCapsule(vec3 p, const float* a) {
    p.y -= std::clamp(p.y, -a[0], a[0]);
    return glm::length(p) - a[1];
}

float sdEllipsoid(vec3 p, const float* a) {
    const vec3 r = v3(a);
    const float k0 = glm::length(p / r);
    const float k1 = glm::length(p / (r * r));
    return k1 > 0.0f ? k0 * (k0 - 1.0f) / k1 : -std::min(r.x, std::min(r.y, r.z));
}

constexpr ParamSpec kSphere[] = {{"radius", 1, {0.5f}, 0.0f, kBig, "radius"}};
constexpr ParamSpec kBox[] = {
    {"half_extents", 3, {0.5f, 0.5f, 0.5f}, 0.0f, kBig, "half the size along x, y, z"}};
constexpr ParamSpec kRoundBox[] = {
    {"half_extents", 3, {0.5f, 0.5f, 0.5f}, 0.0f, kBig, "half the size along x, y, z"},
    {"radius", 1, {0.1f}, 0.0f, kBig, "edge rounding, taken from inside the box"}};
constexpr ParamSpec kTorus[] = {
    {"major_radius", 1, {0.5f}, 0.0f, kBig, "radius of the ring (in the xz plane)"},
    {"minor_radius", 1, {0.15f}, 0.0f, kBig, "radius of the tube"}};
constexpr ParamSpec kCappedCylinder[] = {
    {"radius", 1, {0.5f}, 0.0f, kBig, "radius"},
    {"half_height", 1, {0.5f}, 0.0f, kBig, "half the height along y"}};
constexpr ParamSpec kPlane[] = {
    {"normal", 3, {0.0f, 1.0f, 0.0f}, -1.0f, 1.0f, "normal (normalized on use), solid below"},
    {"offset", 1, {0.0f}, -kBig, kBig, "distance of the plane from the origin along the normal"}};
constexpr ParamSpec kCapsule[] = {
    {"half_height", 1, {0.5f}, 0.0f, kBig, "half the length of the axis segment along y"},
    {"radius", 1, {0.25f}, 0.0f, kBig, "radius"}};
constexpr ParamSpec kEllipsoid[] = {
    {"radii", 3, {0.6f, 0.4f, 0.3f}, 1e-4f, kBig, "semi-axes along x, y, z"}};

constexpr const char* kIq = "Quilez, Distance functions";

const PrimitiveSpec kCatalogue[] = {
    {PrimitiveId::Sphere, "sphere", "sdSphere", true, kSphere, sdSphere, "a sphere at the origin",
     kIq},
    {PrimitiveId::Box, "box", "sdBox", true, kBox, sdBox, "an axis-aligned box", kIq},
    {PrimitiveId::RoundBox, "round_box", "sdRoundBox", true, kRoundBox, sdRoundBox,
     "a box with rounded edges", kIq},
    {PrimitiveId::Torus, "torus", "sdTorus", true, kTorus, sdTorus, "a ring in the xz plane", kIq},
    {PrimitiveId::CappedCylinder, "capped_cylinder", "sdCappedCylinder", true, kCappedCylinder,
     sdCappedCylinder, "a cylinder along y with flat caps", kIq},
    {PrimitiveId::Plane, "plane", "sdPlane", true, kPlane, sdPlane,
     "an infinite plane; the solid is the half-space below it", kIq},
    {PrimitiveId::Capsule, "capsule", "sdVerticalCapsule", true, kCapsule, sdCapsule,
     "a segment along y swept by a sphere", kIq},
    {PrimitiveId::Ellipsoid, "ellipsoid", "sdEllipsoid", false, kEllipsoid, sdEllipsoid,
     "an ellipsoid (a bound, improved by the gradient-length correction)", kIq},
};
static_assert(std::size(kCatalogue) == std::size_t(PrimitiveId::Count));

} // namespace

std::span<const PrimitiveSpec> primitiveCatalogue() { return kCatalogue; }

const PrimitiveSpec& primitiveSpec(PrimitiveId id) {
    assert(std::size_t(id) < std::size(kCatalogue));
    return kCatalogue[std::size_t(id)];
}

const PrimitiveSpec* findPrimitive(std::string_view name) {
    for (const PrimitiveSpec& spec : kCatalogue)
        if (spec.name == name) return &spec;
    return nullptr;
}

int paramOffset(const PrimitiveSpec& spec, int paramIndex) {
    int offset = 0;
    for (int i = 0; i < paramIndex; ++i) offset += spec.params[i].components;
    return offset;
}

PrimitiveParams defaultParams(const PrimitiveSpec& spec) {
    PrimitiveParams params{};
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
        const int offset = paramOffset(spec, int(i));
        for (int c = 0; c < spec.params[i].components; ++c)
            params[offset + c] = spec.params[i].value[c];
    }
    return params;
}

std::string generateGlslDispatch() {
    // Float k of the packed parameters lives in a[k], b[k - 4] or c[k - 8].
    auto component = [](int k) {
        return std::string(1, char('a' + k / 4)) + "[" + std::to_string(k % 4) + "]";
    };
    std::ostringstream out;
    out << "// Generated from the primitive catalogue (engine/sdf/primitives.cpp).\n"
        << "float sdfPrimitive(uint id, vec3 p, vec4 a, vec4 b, vec4 c) {\n    switch (id) {\n";
    for (const PrimitiveSpec& spec : kCatalogue) {
        out << "    case " << std::uint32_t(spec.id) << "u: return " << spec.glslFunction << "(p";
        for (std::size_t i = 0; i < spec.params.size(); ++i) {
            const int offset = paramOffset(spec, int(i));
            if (spec.params[i].components == 1) {
                out << ", " << component(offset);
            } else {
                out << ", vec3(" << component(offset) << ", " << component(offset + 1) << ", "
                    << component(offset + 2) << ")";
            }
        }
        out << ");\n";
    }
    out << "    }\n    return 1e10;\n}\n";
    return out.str();
}

} // namespace rmsc
