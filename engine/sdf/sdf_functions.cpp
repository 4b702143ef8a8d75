// The single formulas of the CPU evaluator (sdf/sdf_functions.hpp), each the GLSL function of
// the same name in shaders/common/sdf_functions.glsl written again with GLM, statement for
// statement.
#include "sdf/sdf_functions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rmsc {

// Smooth minimum of a and b over a blend region |a - b| < k, and in h how much of a it takes
// (1 where a is far below b, 0 where b is far below a). blend 0: the quadratic polynomial,
// blend 1: a circular arc; both from Inigo Quilez, "Smooth minimum",
// https://iquilezles.org/articles/smin/ (the circular one without its k normalization, so
// both blend over the same width). h is the polynomial's mix factor for both.
float sdfSmoothMin(float a, float b, float k, float blend, float& h) {
    h = std::clamp(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
    if (blend < 0.5f) return glm::mix(b, a, h) - k * h * (1.0f - h);
    const float g = std::max(k - std::abs(a - b), 0.0f) / k;
    return std::min(a, b) - k * 0.5f * (1.0f + g - std::sqrt(1.0f - g * (g - 2.0f)));
}

// a (below) and b (top of the stack) combined with `op`;
// opParams.x = smoothness k (blend width, chamfer or round radius), opParams.y = SmoothBlend.
// weightA is how much of a's material the result carries: 1 or 0 for the hard, chamfer and
// round operations (the side that dominates; subtractions keep a), the blend factor h for the
// smooth ones. Formulas: Inigo Quilez, "Smooth minimum" (https://iquilezles.org/articles/smin/),
// smooth subtraction and intersection as -smin(b, -a) and -smin(-a, -b); chamfer and round
// operations after Mercury's hg_sdf (fOpUnionChamfer, fOpUnionRound, fOpIntersectionChamfer,
// fOpIntersectionRound; subtraction = intersection with -b), https://mercury.sexy/hg_sdf/.
float sdfCombine(SdfOp op, float a, float b, const glm::vec4& opParams, float& weightA) {
    const float k = opParams.x;
    constexpr float kSqrtHalf = 0.70710678f;
    switch (op) {
    case SdfOp::Union:
        weightA = a <= b ? 1.0f : 0.0f;
        return std::min(a, b);
    case SdfOp::Subtraction:
        weightA = 1.0f;
        return std::max(a, -b);
    case SdfOp::Intersection:
        weightA = a >= b ? 1.0f : 0.0f;
        return std::max(a, b);
    case SdfOp::SmoothUnion:
        return sdfSmoothMin(a, b, k, opParams.y, weightA);
    case SdfOp::SmoothSubtraction: {
        float h = 0.0f;
        weightA = 1.0f;
        return -sdfSmoothMin(b, -a, k, opParams.y, h);
    }
    case SdfOp::SmoothIntersection:
        return -sdfSmoothMin(-a, -b, k, opParams.y, weightA);
    case SdfOp::Xor: {
        const float inner = std::min(a, b);
        const float outer = -std::max(a, b);
        weightA = inner >= outer ? (a <= b ? 1.0f : 0.0f) : (a >= b ? 1.0f : 0.0f);
        return std::max(inner, outer);
    }
    case SdfOp::ChamferUnion:
        weightA = a <= b ? 1.0f : 0.0f;
        return std::min(std::min(a, b), (a - k + b) * kSqrtHalf);
    case SdfOp::ChamferSubtraction:
        weightA = 1.0f;
        return std::max(std::max(a, -b), (a + k - b) * kSqrtHalf);
    case SdfOp::ChamferIntersection:
        weightA = a >= b ? 1.0f : 0.0f;
        return std::max(std::max(a, b), (a + k + b) * kSqrtHalf);
    case SdfOp::RoundUnion: {
        weightA = a <= b ? 1.0f : 0.0f;
        const glm::vec2 u = glm::max(glm::vec2(k - a, k - b), 0.0f);
        return std::max(k, std::min(a, b)) - glm::length(u);
    }
    case SdfOp::RoundSubtraction: {
        weightA = 1.0f;
        const glm::vec2 u = glm::max(glm::vec2(k + a, k - b), 0.0f);
        return std::min(-k, std::max(a, -b)) + glm::length(u);
    }
    case SdfOp::RoundIntersection:
        break;
    }
    weightA = a >= b ? 1.0f : 0.0f;
    const glm::vec2 u = glm::max(glm::vec2(k + a, k + b), 0.0f);
    return std::min(-k, std::max(a, b)) + glm::length(u);
}

// Lattice value of the displacement noise at integer cell c, in [-1, 1]: a spatial hash of the
// cell (the primes of Teschner et al. 2003, "Optimized spatial hashing for collision detection
// of deformable objects") mixed by the "lowbias32" finalizer from C. Wellons' hash prospector
// (https://nullprogram.com/blog/2018/07/31/). Unsigned 32-bit arithmetic, as in GLSL.
namespace {

float latticeValue(glm::ivec3 c) {
    std::uint32_t h = std::uint32_t(c.x) * 0x8da6b343u + std::uint32_t(c.y) * 0xd8163841u +
                      std::uint32_t(c.z) * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h >> 8) * (2.0f / 16777215.0f) - 1.0f;
}

} // namespace

// Value noise: lattice values blended trilinearly with the cubic
// smoothstep weights 3t^2 - 2t^3 (Perlin 1985, "An image synthesizer"; Quilez, "Value noise
// derivatives", https://iquilezles.org/articles/morenoise/). In [-1, 1]; gradient length at
// most 3 sqrt(3) (kNoiseGradientBound).
float sdfValueNoise(glm::vec3 p) {
    const glm::vec3 cell = glm::floor(p);
    const glm::vec3 f = p - cell;
    const glm::vec3 u = f * f * (3.0f - 2.0f * f);
    const glm::ivec3 c(cell);
    const float x00 =
        glm::mix(latticeValue(c + glm::ivec3(0, 0, 0)), latticeValue(c + glm::ivec3(1, 0, 0)), u.x);
    const float x10 =
        glm::mix(latticeValue(c + glm::ivec3(0, 1, 0)), latticeValue(c + glm::ivec3(1, 1, 0)), u.x);
    const float x01 =
        glm::mix(latticeValue(c + glm::ivec3(0, 0, 1)), latticeValue(c + glm::ivec3(1, 0, 1)), u.x);
    const float x11 =
        glm::mix(latticeValue(c + glm::ivec3(0, 1, 1)), latticeValue(c + glm::ivec3(1, 1, 1)), u.x);
    return glm::mix(glm::mix(x00, x10, u.y), glm::mix(x01, x11, u.y), u.z);
}

// A point modifier (sdfPointModifier in the shader), parameters as its catalogue row packs them
// (engine/sdf/modifiers.cpp). Formulas: Inigo Quilez, "Distance functions" (twist, bend,
// elongation) and "Domain repetition" (https://iquilezles.org/articles/sdfrepetition/); polar
// repetition as hg_sdf's pModPolar; the taper after Barr, "Global and local deformations of
// solid primitives" (SIGGRAPH 1984).
glm::vec3 sdfPointModifier(SdfPointModifierKind kind, glm::vec3 p, const glm::vec4* a) {
    switch (kind) {
    case SdfPointModifierKind::Repeat:
        for (int axis = 0; axis < 3; ++axis) {
            const float period = a[0][axis];
            if (!(period > 0.0f)) continue;
            const float copies = a[1][axis];
            // Limited: cells 0 .. copies-1 centred on the origin; infinite: every integer.
            const float first = copies > 0.0f ? 0.5f * (copies - 1.0f) : 0.0f;
            float id = std::floor(p[axis] / period + first + 0.5f);
            if (copies > 0.0f) id = std::clamp(id, 0.0f, copies - 1.0f);
            if (a[2].w > 0.5f && a[2][axis] > 0.5f) {
                // The neighbour on the side of the point within its cell.
                id += p[axis] - (id - first) * period < 0.0f ? -1.0f : 1.0f;
                if (copies > 0.0f) id = std::clamp(id, 0.0f, copies - 1.0f);
            }
            p[axis] -= (id - first) * period;
        }
        return p;
    case SdfPointModifierKind::Mirror:
        return glm::mix(p, glm::abs(p), glm::vec3(a[0]));
    case SdfPointModifierKind::Polar: {
        const float sector = 6.28318530718f / a[0].x;
        const int axis = int(a[0].y);
        const int u = axis == 0 ? 1 : 0;
        const int v = axis == 2 ? 1 : 2;
        const float angle = std::atan2(p[v], p[u]);
        const float turn = std::floor(angle / sector + 0.5f) * sector;
        const float c = std::cos(turn);
        const float s = std::sin(turn);
        const float pu = p[u];
        p[u] = c * pu + s * p[v];
        p[v] = c * p[v] - s * pu;
        return p;
    }
    case SdfPointModifierKind::Elongate:
        return p - glm::clamp(p, -glm::vec3(a[0]), glm::vec3(a[0]));
    case SdfPointModifierKind::Twist: {
        const float c = std::cos(a[0].x * p.y);
        const float s = std::sin(a[0].x * p.y);
        return glm::vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
    }
    case SdfPointModifierKind::Bend: {
        const float c = std::cos(a[0].x * p.x);
        const float s = std::sin(a[0].x * p.x);
        return glm::vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
    }
    case SdfPointModifierKind::Taper: {
        // The content at height y scaled by s = 1 + k clamp(y, -R, R) in x and z ([0].x = k per
        // unit along y, [0].y = the reach R), held constant beyond |y| = R so that s stays above
        // 1 - |k| R > 0 everywhere.
        const float scale = 1.0f + a[0].x * std::clamp(p.y, -a[0].y, a[0].y);
        return glm::vec3(p.x / scale, p.y, p.z / scale);
    }
    }
    return p;
}

float sdfDistanceModifier(SdfDistanceModifierKind kind, float d, glm::vec3 p, const glm::vec4& a) {
    switch (kind) {
    case SdfDistanceModifierKind::Round:
        return d - a.x;
    case SdfDistanceModifierKind::Onion:
        return std::abs(d) - a.x;
    case SdfDistanceModifierKind::Displace:
        return d + a.x * sdfValueNoise(p * a.y);
    }
    return d;
}

// The nearest of the polygon's edges, negative inside by the even-odd crossing rule (a ray
// from q towards +x crosses the boundary an odd number of times; W. R. Franklin, PNPOLY). The
// technique of Quilez, "2D distance functions" (https://iquilezles.org/articles/distfunctions2d/).
float sdfPolygonDistance(glm::vec2 q, std::span<const glm::vec4> data, int first, int count) {
    float nearest = 1e30f;
    bool inside = false;
    for (int i = 0; i < count; ++i) {
        const glm::vec2 a(data[std::size_t(first + i)]);
        const glm::vec2 b(data[std::size_t(first + (i + count - 1) % count)]);
        const glm::vec2 edge = b - a;
        const glm::vec2 w = q - a;
        const float t =
            std::clamp(glm::dot(w, edge) / std::max(glm::dot(edge, edge), 1e-20f), 0.0f, 1.0f);
        const glm::vec2 off = w - edge * t;
        nearest = std::min(nearest, glm::dot(off, off));
        if ((a.y > q.y) != (b.y > q.y)) {
            const float crossX = a.x + (q.y - a.y) * edge.x / edge.y;
            if (q.x < crossX) inside = !inside;
        }
    }
    return (inside ? -1.0f : 1.0f) * std::sqrt(nearest);
}

// Extrusion along z or revolution about y (Quilez, "Distance functions": opExtrusion,
// opRevolution; 2D shapes from "2D distance functions").
float sdfProfile(SdfProfileType kind, glm::vec3 q, const glm::vec4 (&a)[3],
                 std::span<const glm::vec4> data) {
    const bool revolution = a[1].x > 0.5f;
    const glm::vec2 q2 = revolution ? glm::vec2(glm::length(glm::vec2(q.x, q.z)) - a[1].y, q.y)
                                    : glm::vec2(q.x, q.y);
    float d2 = 0.0f;
    switch (kind) {
    case SdfProfileType::Circle:
        d2 = glm::length(q2) - a[0].x;
        break;
    case SdfProfileType::Rectangle:
    case SdfProfileType::RoundedRectangle: {
        const float r = kind == SdfProfileType::Rectangle ? 0.0f : a[0].x;
        const glm::vec2 e = glm::abs(q2) - glm::vec2(a[0].y, a[0].z) + r;
        d2 = glm::length(glm::max(e, 0.0f)) + std::min(std::max(e.x, e.y), 0.0f) - r;
        break;
    }
    case SdfProfileType::Polygon:
        d2 = sdfPolygonDistance(q2, data, int(a[2].x), int(a[2].y));
        break;
    }
    if (revolution) return d2;
    const glm::vec2 w(d2, std::abs(q.z) - a[1].y);
    return std::min(std::max(w.x, w.y), 0.0f) + glm::length(glm::max(w, 0.0f));
}

} // namespace rmsc
