// The C++ formulas of the modifier catalogue, mirroring shaders/common/sdf_functions.glsl
// (sdfPointModifier, sdfDistanceModifier, sdfValueNoise) statement for statement. Formulas:
// Inigo Quilez, "Distance functions" (twist, bend, elongation, rounding, onion;
// https://iquilezles.org/articles/distfunctions/) and "Domain repetition"
// (https://iquilezles.org/articles/sdfrepetition/); polar repetition as hg_sdf's pModPolar
// (https://mercury.sexy/hg_sdf/); the taper after Barr 1984 (see taper).
#include "modifier_formulas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rmsc::formulas {
namespace {

// Lattice value of the displacement noise at integer cell c, in [-1, 1]: a spatial hash of the
// cell (the primes of Teschner et al. 2003, "Optimized spatial hashing for collision detection
// of deformable objects") mixed by the "lowbias32" finalizer from C. Wellons' hash prospector
// (https://nullprogram.com/blog/2018/07/31/). Unsigned 32-bit arithmetic, as in GLSL.
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

// Lattice values blended trilinearly with the cubic smoothstep weights 3t^2 - 2t^3 (Perlin
// 1985, "An image synthesizer"; Quilez, "Value noise derivatives",
// https://iquilezles.org/articles/morenoise/).
float valueNoise(glm::vec3 p) {

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

// Params: [0].xyz period (0: axis not repeated), [1].xyz copies (0: infinite), [2].xyz neighbour
// cell selector (0 own cell, 1 nearest neighbour), [2].w 1 when the selector is used.
glm::vec3 repeat(glm::vec3 p, const glm::vec4* a) {
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
}

// Params: [0].xyz 1 where the axis is folded.
glm::vec3 mirror(glm::vec3 p, const glm::vec4* a) {
    return glm::mix(p, glm::abs(p), glm::vec3(a[0]));
}

// Params: [0].x copies, [0].y axis (0 x, 1 y, 2 z).
glm::vec3 polar(glm::vec3 p, const glm::vec4* a) {
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

// Params: [0].xyz half extents.
glm::vec3 elongate(glm::vec3 p, const glm::vec4* a) {
    return p - glm::clamp(p, -glm::vec3(a[0]), glm::vec3(a[0]));
}

// Params: [0].x radians per unit along y.
glm::vec3 twist(glm::vec3 p, const glm::vec4* a) {
    const float c = std::cos(a[0].x * p.y);
    const float s = std::sin(a[0].x * p.y);
    return glm::vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}

// Params: [0].x radians per unit along x.
glm::vec3 bend(glm::vec3 p, const glm::vec4* a) {
    const float c = std::cos(a[0].x * p.x);
    const float s = std::sin(a[0].x * p.x);
    return glm::vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
}

// Params: [0].x the scale change k per unit along y, [0].y the reach R. The content at height y
// is scaled by s = 1 + k clamp(y, -R, R) in x and z: a linear taper (Barr, "Global and local
// deformations of solid primitives", SIGGRAPH 1984), held constant beyond |y| = R so that s
// stays above 1 - |k| R > 0 everywhere.
glm::vec3 taper(glm::vec3 p, const glm::vec4* a) {
    const float scale = 1.0f + a[0].x * std::clamp(p.y, -a[0].y, a[0].y);
    return glm::vec3(p.x / scale, p.y, p.z / scale);
}

// Params: [0].x radius.
float round(float d, glm::vec3, const glm::vec4* a) {
    return d - a[0].x;
}

// Params: [0].x thickness.
float onion(float d, glm::vec3, const glm::vec4* a) {
    return std::abs(d) - a[0].x;
}

// Params: [0].x amplitude, [0].y frequency (in the point's units).
float displace(float d, glm::vec3 p, const glm::vec4* a) {
    return d + a[0].x * valueNoise(p * a[0].y);
}

} // namespace rmsc::formulas
