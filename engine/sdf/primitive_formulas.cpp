// The C++ distance functions of Inigo Quilez's 3D primitives beyond the basic shapes, after
// "Distance functions", https://iquilezles.org/articles/distfunctions/ (written anew from the
// article's math, with guards against division by zero for degenerate parameters). Each mirrors,
// statement for statement, the GLSL function of the same name (sd + Name) in
// shaders/common/sdf_primitives.glsl. Angles arrive in degrees and are converted here.
#include "primitive_formulas.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::formulas {
namespace {

using glm::vec2;
using glm::vec3;

vec3 v3(const float* p) {
    return vec3(p[0], p[1], p[2]);
}
float dot2(vec2 v) {
    return glm::dot(v, v);
}
float dot2(vec3 v) {
    return glm::dot(v, v);
}
float ndot(vec2 a, vec2 b) {
    return a.x * b.x - a.y * b.y;
}
float sign(float x) {
    return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f);
}
float lengthXz(vec3 p) {
    return glm::length(vec2(p.x, p.z));
}

// Distance to a box corner region, the building block of the box frame.
float boxPart(vec3 q) {
    return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

} // namespace

float boxFrame(vec3 p, const float* a) {
    const float e = a[3];
    p = glm::abs(p) - v3(a);
    const vec3 q = glm::abs(p + e) - e;
    return std::min(std::min(boxPart(vec3(p.x, q.y, q.z)), boxPart(vec3(q.x, p.y, q.z))),
                    boxPart(vec3(q.x, q.y, p.z)));
}

float cappedTorus(vec3 p, const float* a) {
    const float angle = glm::radians(a[0]);
    const float ra = a[1], rb = a[2];
    const vec2 sc(std::sin(angle), std::cos(angle));
    p.x = std::abs(p.x);
    const vec2 pxy(p.x, p.y);
    const float k = sc.y * p.x > sc.x * p.y ? glm::dot(pxy, sc) : glm::length(pxy);
    return std::sqrt(std::max(glm::dot(p, p) + ra * ra - 2.0f * ra * k, 0.0f)) - rb;
}

float link(vec3 p, const float* a) {
    const float le = a[0], r1 = a[1], r2 = a[2];
    const vec3 q(p.x, std::max(std::abs(p.y) - le, 0.0f), p.z);
    return glm::length(vec2(glm::length(vec2(q.x, q.y)) - r1, q.z)) - r2;
}

float infiniteCylinder(vec3 p, const float* a) {
    return lengthXz(p) - a[0];
}

float cone(vec3 p, const float* a) {
    const float angle = glm::radians(a[0]);
    const float h = a[1];
    const vec2 c(std::sin(angle), std::cos(angle));
    p.y -= 0.5f * h;
    const vec2 q = h * vec2(c.x / c.y, -1.0f);
    const vec2 w(lengthXz(p), p.y);
    const vec2 pa = w - q * std::clamp(glm::dot(w, q) / glm::dot(q, q), 0.0f, 1.0f);
    const vec2 pb = w - q * vec2(std::clamp(w.x / q.x, 0.0f, 1.0f), 1.0f);
    const float k = sign(q.y);
    const float d = std::min(glm::dot(pa, pa), glm::dot(pb, pb));
    const float s = std::max(k * (w.x * q.y - w.y * q.x), k * (w.y - q.y));
    return std::sqrt(d) * sign(s);
}

float infiniteCone(vec3 p, const float* a) {
    const float angle = glm::radians(a[0]);
    const vec2 c(std::sin(angle), std::cos(angle));
    const vec2 q(lengthXz(p), -p.y);
    const float d = glm::length(q - c * std::max(glm::dot(q, c), 0.0f));
    return d * (q.x * c.y - q.y * c.x < 0.0f ? -1.0f : 1.0f);
}

float hexPrism(vec3 p, const float* a) {
    const vec3 k(-0.8660254f, 0.5f, 0.57735f);
    const vec2 h(a[0], a[1]);
    p = glm::abs(p);
    const vec2 kxy(k.x, k.y);
    vec2 pxy(p.x, p.y);
    pxy -= 2.0f * std::min(glm::dot(kxy, pxy), 0.0f) * kxy;
    const vec2 d(glm::length(pxy - vec2(std::clamp(pxy.x, -k.z * h.x, k.z * h.x), h.x)) *
                     sign(pxy.y - h.x),
                 p.z - h.y);
    return std::min(std::max(d.x, d.y), 0.0f) + glm::length(glm::max(d, 0.0f));
}

float triPrism(vec3 p, const float* a) {
    const float r = a[0], halfLength = a[1];
    const vec3 q = glm::abs(p);
    return std::max(q.z - halfLength, std::max(q.x * 0.866025f + p.y * 0.5f, -p.y) - r);
}

float capsuleBetween(vec3 p, const float* a) {
    const vec3 pa = p - v3(a), ba = v3(a + 3) - v3(a);
    const float h = std::clamp(glm::dot(pa, ba) / std::max(glm::dot(ba, ba), 1e-12f), 0.0f, 1.0f);
    return glm::length(pa - ba * h) - a[6];
}

float cappedCylinderBetween(vec3 p, const float* a) {
    const vec3 ba = v3(a + 3) - v3(a);
    const vec3 pa = p - v3(a);
    const float r = a[6];
    const float baba = std::max(glm::dot(ba, ba), 1e-12f);
    const float paba = glm::dot(pa, ba);
    const float x = glm::length(pa * baba - ba * paba) - r * baba;
    const float y = std::abs(paba - baba * 0.5f) - baba * 0.5f;
    const float x2 = x * x;
    const float y2 = y * y * baba;
    const float d =
        std::max(x, y) < 0.0f ? -std::min(x2, y2) : (x > 0.0f ? x2 : 0.0f) + (y > 0.0f ? y2 : 0.0f);
    return sign(d) * std::sqrt(std::abs(d)) / baba;
}

float roundedCylinder(vec3 p, const float* a) {
    const float radius = a[0], halfHeight = a[2];
    const float e = std::min(a[1], std::min(radius, halfHeight));
    const vec2 d(lengthXz(p) - radius + e, std::abs(p.y) - halfHeight + e);
    return std::min(std::max(d.x, d.y), 0.0f) + glm::length(glm::max(d, 0.0f)) - e;
}

float cappedCone(vec3 p, const float* a) {
    const float h = a[0], r1 = a[1], r2 = a[2];
    const vec2 q(lengthXz(p), p.y);
    const vec2 k1(r2, h);
    const vec2 k2(r2 - r1, 2.0f * h);
    const vec2 ca(q.x - std::min(q.x, q.y < 0.0f ? r1 : r2), std::abs(q.y) - h);
    const vec2 cb = q - k1 + k2 * std::clamp(glm::dot(k1 - q, k2) / dot2(k2), 0.0f, 1.0f);
    const float s = cb.x < 0.0f && ca.y < 0.0f ? -1.0f : 1.0f;
    return s * std::sqrt(std::min(dot2(ca), dot2(cb)));
}

float cappedConeBetween(vec3 p, const float* a) {
    const vec3 pa = v3(a), pb = v3(a + 3);
    const float ra = a[6], rb = a[7];
    const float rba = rb - ra;
    const float baba = std::max(dot2(pb - pa), 1e-12f);
    const float papa = dot2(p - pa);
    const float paba = glm::dot(p - pa, pb - pa) / baba;
    const float x = std::sqrt(std::max(papa - paba * paba * baba, 0.0f));
    const float cax = std::max(0.0f, x - (paba < 0.5f ? ra : rb));
    const float cay = std::abs(paba - 0.5f) - 0.5f;
    const float k = rba * rba + baba;
    const float f = std::clamp((rba * (x - ra) + paba * baba) / k, 0.0f, 1.0f);
    const float cbx = x - ra - f * rba;
    const float cby = paba - f;
    const float s = cbx < 0.0f && cay < 0.0f ? -1.0f : 1.0f;
    return s * std::sqrt(std::min(cax * cax + cay * cay * baba, cbx * cbx + cby * cby * baba));
}

float solidAngle(vec3 p, const float* a) {
    const float angle = glm::radians(a[0]);
    const float ra = a[1];
    const vec2 c(std::sin(angle), std::cos(angle));
    const vec2 q(lengthXz(p), p.y);
    const float l = glm::length(q) - ra;
    const float m = glm::length(q - c * std::clamp(glm::dot(q, c), 0.0f, ra));
    return std::max(l, m * sign(c.y * q.x - c.x * q.y));
}

float cutSphere(vec3 p, const float* a) {
    const float r = a[0];
    const float h = std::clamp(a[1], -r, r);
    const float w = std::sqrt(std::max(r * r - h * h, 0.0f));
    const vec2 q(lengthXz(p), p.y);
    const float s = std::max((h - r) * q.x * q.x + w * w * (h + r - 2.0f * q.y), h * q.x - w * q.y);
    return s < 0.0f ? glm::length(q) - r : (q.x < w ? h - q.y : glm::length(q - vec2(w, h)));
}

float cutHollowSphere(vec3 p, const float* a) {
    const float r = a[0];
    const float h = std::clamp(a[1], -r, r);
    const float t = a[2];
    const float w = std::sqrt(std::max(r * r - h * h, 0.0f));
    const vec2 q(lengthXz(p), p.y);
    return (h * q.x < w * q.y ? glm::length(q - vec2(w, h)) : std::abs(glm::length(q) - r)) - t;
}

float deathStar(vec3 p, const float* a) {
    const float ra = a[0], rb = a[1], d = a[2];
    const float ca = (ra * ra - rb * rb + d * d) / (2.0f * d);
    const float cb = std::sqrt(std::max(ra * ra - ca * ca, 0.0f));
    const vec2 q(p.x, glm::length(vec2(p.y, p.z)));
    if (q.x * cb - q.y * ca > d * std::max(cb - q.y, 0.0f)) return glm::length(q - vec2(ca, cb));
    return std::max(glm::length(q) - ra, -(glm::length(q - vec2(d, 0.0f)) - rb));
}

float roundCone(vec3 p, const float* a) {
    const float r1 = a[0], r2 = a[1], h = a[2];
    p.y += 0.5f * h;
    const float b = (r1 - r2) / h;
    const float c = std::sqrt(std::max(1.0f - b * b, 0.0f));
    const vec2 q(lengthXz(p), p.y);
    const float k = glm::dot(q, vec2(-b, c));
    if (k < 0.0f) return glm::length(q) - r1;
    if (k > c * h) return glm::length(q - vec2(0.0f, h)) - r2;
    return glm::dot(q, vec2(c, b)) - r1;
}

float roundConeBetween(vec3 p, const float* a) {
    const vec3 pa0 = v3(a), pb0 = v3(a + 3);
    const float r1 = a[6], r2 = a[7];
    const vec3 ba = pb0 - pa0;
    const float l2 = std::max(glm::dot(ba, ba), 1e-12f);
    const float rr = r1 - r2;
    const float a2 = l2 - rr * rr;
    const float il2 = 1.0f / l2;
    const vec3 pa = p - pa0;
    const float y = glm::dot(pa, ba);
    const float z = y - l2;
    const float x2 = dot2(pa * l2 - ba * y);
    const float y2 = y * y * l2;
    const float z2 = z * z * l2;
    const float k = sign(rr) * rr * rr * x2;
    if (sign(z) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - r2;
    if (sign(y) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - r1;
    return (std::sqrt(std::max(x2 * a2 * il2, 0.0f)) + y * rr) * il2 - r1;
}

float revolvedVesica(vec3 p, const float* a) {
    const vec3 pa = v3(a), pb = v3(a + 3);
    const vec3 c = (pa + pb) * 0.5f;
    const float l = std::max(glm::length(pb - pa), 1e-6f);
    const vec3 v = (pb - pa) / l;
    const float y = glm::dot(p - c, v);
    const vec2 q(glm::length(p - c - y * v), std::abs(y));
    const float r = 0.5f * l;
    const float w = std::min(a[6], r);
    const float d = 0.5f * (r * r - w * w) / w;
    if (r * q.x < d * (q.y - r)) return glm::length(q - vec2(0.0f, r));
    // length(q + (d, 0)) - (d + w) as a difference of squares over their roots' sum: d grows
    // as 1 / w, and the plain difference of two numbers near d keeps none of the distance's
    // digits for a thin or a far vesica.
    return (glm::dot(q, q) + 2.0f * d * (q.x - w) - w * w) /
           (glm::length(q + vec2(d, 0.0f)) + d + w);
}

float rhombus(vec3 p, const float* a) {
    const float la = a[0], lb = a[1], h = a[2], ra = a[3];
    p = glm::abs(p);
    const vec2 b(la, lb);
    const vec2 pxz(p.x, p.z);
    const float f = std::clamp(ndot(b, b - 2.0f * pxz) / glm::dot(b, b), -1.0f, 1.0f);
    const vec2 q(glm::length(pxz - 0.5f * b * vec2(1.0f - f, 1.0f + f)) *
                         sign(p.x * b.y + p.z * b.x - b.x * b.y) -
                     ra,
                 p.y - h);
    return std::min(std::max(q.x, q.y), 0.0f) + glm::length(glm::max(q, 0.0f));
}

float octahedron(vec3 p, const float* a) {
    const float s = a[0];
    p = glm::abs(p);
    const float m = p.x + p.y + p.z - s;
    vec3 q;
    if (3.0f * p.x < m)
        q = p;
    else if (3.0f * p.y < m)
        q = vec3(p.y, p.z, p.x);
    else if (3.0f * p.z < m)
        q = vec3(p.z, p.x, p.y);
    else
        return m * 0.57735027f;
    const float k = std::clamp(0.5f * (q.z - q.y + s), 0.0f, s);
    return glm::length(vec3(q.x, q.y - s + k, q.z - k));
}

float pyramid(vec3 p, const float* a) {
    const float base = a[0], height = a[1];
    p.y += 0.5f * height;
    p /= base;
    const float h = height / base;
    const float m2 = h * h + 0.25f;
    vec2 xz(std::abs(p.x), std::abs(p.z));
    if (xz.y > xz.x) xz = vec2(xz.y, xz.x);
    xz -= 0.5f;
    const vec3 q(xz.y, h * p.y - 0.5f * xz.x, h * xz.x + 0.5f * p.y);
    const float s = std::max(-q.x, 0.0f);
    const float t = std::clamp((q.y - 0.5f * xz.y) / (m2 + 0.25f), 0.0f, 1.0f);
    const float da = m2 * (q.x + s) * (q.x + s) + q.y * q.y;
    const float db = m2 * (q.x + 0.5f * t) * (q.x + 0.5f * t) + (q.y - m2 * t) * (q.y - m2 * t);
    const float d2 = std::min(q.y, -q.x * m2 - q.y * 0.5f) > 0.0f ? 0.0f : std::min(da, db);
    const float d = std::sqrt((d2 + q.z * q.z) / m2) * sign(std::max(q.z, -p.y));
    // Quilez's formula measures the slanted faces only. Below the base plane the nearest point
    // is on the base square (every point of the pyramid lies above it); inside, the base is one
    // more half-space of the intersection.
    if (p.y < 0.0f) {
        const vec3 e(std::max(std::abs(p.x) - 0.5f, 0.0f), p.y,
                     std::max(std::abs(p.z) - 0.5f, 0.0f));
        return base * glm::length(e);
    }
    return base * (d < 0.0f ? std::max(d, -p.y) : d);
}

float triangle(vec3 p, const float* a) {
    const vec3 va = v3(a), vb = v3(a + 3), vc = v3(a + 6);
    const vec3 ba = vb - va, pa = p - va;
    const vec3 cb = vc - vb, pb = p - vb;
    const vec3 ac = va - vc, pc = p - vc;
    const vec3 nor = glm::cross(ba, ac);
    const bool outsideAnEdge = sign(glm::dot(glm::cross(ba, nor), pa)) +
                                   sign(glm::dot(glm::cross(cb, nor), pb)) +
                                   sign(glm::dot(glm::cross(ac, nor), pc)) <
                               2.0f;
    const float d2 =
        outsideAnEdge
            ? std::min(
                  std::min(dot2(ba * std::clamp(glm::dot(ba, pa) / dot2(ba), 0.0f, 1.0f) - pa),
                           dot2(cb * std::clamp(glm::dot(cb, pb) / dot2(cb), 0.0f, 1.0f) - pb)),
                  dot2(ac * std::clamp(glm::dot(ac, pc) / dot2(ac), 0.0f, 1.0f) - pc))
            : glm::dot(nor, pa) * glm::dot(nor, pa) / dot2(nor);
    return std::sqrt(d2) - a[9];
}

float quad(vec3 p, const float* a) {
    const vec3 va = v3(a), vb = v3(a + 3), vc = v3(a + 6), vd = v3(a + 9);
    const vec3 ba = vb - va, pa = p - va;
    const vec3 cb = vc - vb, pb = p - vb;
    const vec3 dc = vd - vc, pc = p - vc;
    const vec3 ad = va - vd, pd = p - vd;
    const vec3 nor = glm::cross(ba, ad);
    const bool outsideAnEdge =
        sign(glm::dot(glm::cross(ba, nor), pa)) + sign(glm::dot(glm::cross(cb, nor), pb)) +
            sign(glm::dot(glm::cross(dc, nor), pc)) + sign(glm::dot(glm::cross(ad, nor), pd)) <
        3.0f;
    const float d2 =
        outsideAnEdge
            ? std::min(
                  std::min(dot2(ba * std::clamp(glm::dot(ba, pa) / dot2(ba), 0.0f, 1.0f) - pa),
                           dot2(cb * std::clamp(glm::dot(cb, pb) / dot2(cb), 0.0f, 1.0f) - pb)),
                  std::min(dot2(dc * std::clamp(glm::dot(dc, pc) / dot2(dc), 0.0f, 1.0f) - pc),
                           dot2(ad * std::clamp(glm::dot(ad, pd) / dot2(ad), 0.0f, 1.0f) - pd)))
            : glm::dot(nor, pa) * glm::dot(nor, pa) / dot2(nor);
    return std::sqrt(d2);
}

} // namespace rmsc::formulas
