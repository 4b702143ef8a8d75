// Conservative bounds of SDF content (see bounds.hpp). Everything is bounded at a "level": the
// box of the points where a field is <= level. The level starts at 0 and grows where the tree
// can push its surface outwards: smooth, chamfer and round unions, the distance modifiers, and
// the conversion of field units into the lengths of a frame whose field is only a lower bound of
// the distance (non-uniform scale, step corrections). Each rule below states why it is safe.
#include "sdf/bounds.hpp"

#include "sdf/compiler.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rmsc {
namespace {

using glm::vec3;

constexpr float kSqrtHalf = 0.70710678f;
constexpr float kSqrt3 = 1.7320508f;

vec3 v3(const PrimitiveParams& a, int offset) {
    return vec3(a[std::size_t(offset)], a[std::size_t(offset) + 1], a[std::size_t(offset) + 2]);
}

SdfBounds boundedBy(const Aabb& box) {
    SdfBounds bounds;
    bounds.box = box;
    return bounds;
}

SdfBounds unbounded(std::string by) {
    SdfBounds bounds;
    bounds.bounded = false;
    bounds.unboundedBy = std::move(by);
    return bounds;
}

Aabb symmetric(vec3 half) {
    return aabbAround(vec3(0.0f), half);
}

Aabb ballBox(vec3 center, float radius) {
    return aabbAround(center, vec3(radius));
}

// The box of a disc of `radius` centred at `center` in the plane perpendicular to the unit
// vector `axis`: along axis i it reaches radius * sqrt(1 - axis_i^2). A zero axis gives the
// ball's box (what the formulas degenerate to when both ends coincide).
Aabb discBox(vec3 center, vec3 axis, float radius) {
    const float length = glm::length(axis);
    if (!(length > 0.0f)) return ballBox(center, radius);
    const vec3 n = axis / length;
    return aabbAround(center, radius * glm::sqrt(glm::max(1.0f - n * n, 0.0f)));
}

// Degrees to (sin, cos) in double precision; angles of the catalogue are in [0, 180].
double sinDegrees(double degrees) {
    return std::sin(degrees * std::numbers::pi / 180.0);
}
double cosDegrees(double degrees) {
    return std::cos(degrees * std::numbers::pi / 180.0);
}

// The level-0 box of a primitive whose distance is exact, so that {d <= level} lies within
// `level` of {d <= 0} and the caller grows the box by the level. primitiveBounds handles the
// other rows: the unbounded ones, the formulas that are bounds rather than distances, and those
// whose level set needs its own derivation (round box, death star, quad).
Aabb exactPrimitiveBox(PrimitiveId id, const PrimitiveParams& a) {
    switch (id) {
    case PrimitiveId::Sphere:
        return symmetric(vec3(a[0]));
    case PrimitiveId::Box:
    case PrimitiveId::BoxFrame: // every bar part is >= |p_i| - h_i on every axis
        return symmetric(v3(a, 0));
    case PrimitiveId::Torus:
        return symmetric(vec3(a[0] + a[1], a[1], a[0] + a[1]));
    case PrimitiveId::CappedCylinder:
        return symmetric(vec3(a[0], a[1], a[0]));
    case PrimitiveId::Capsule:
        return symmetric(vec3(a[1], a[0] + a[1], a[1]));
    case PrimitiveId::CappedTorus: {
        // The tube of radius rb around the arc of radius ra in the xy plane spanning `angle`
        // either side of +y: x reaches ra sin(angle) (ra once the arc passes the x axis), y runs
        // from ra cos(angle) to ra.
        const double angle = std::clamp(double(a[0]), 0.0, 180.0);
        const float ra = a[1], rb = a[2];
        const float halfX = angle >= 90.0 ? ra : ra * float(sinDegrees(angle));
        Aabb arc;
        arc.add(vec3(-halfX, ra * float(cosDegrees(angle)), 0.0f));
        arc.add(vec3(halfX, ra, 0.0f));
        return inflateAabb(arc, rb);
    }
    case PrimitiveId::Link: // a torus (r1, r2) in the xy plane stretched by le along y
        return symmetric(vec3(a[1] + a[2], a[0] + a[1] + a[2], a[2]));
    case PrimitiveId::Cone: {
        // Base radius h tan(angle) at y = -h/2, apex at y = h/2 (q = h (tan, -1) in sdCone).
        const double angle = double(a[0]);
        const float baseRadius = a[1] * float(sinDegrees(angle) / cosDegrees(angle));
        return symmetric(vec3(baseRadius, 0.5f * a[1], baseRadius));
    }
    case PrimitiveId::HexPrism:
        // Flat sides at distance h from the axis: |y| <= h and 0.866 |x| + 0.5 |y| <= h, so the
        // corners on the x axis lie at h / 0.866 (the constant of sdHexPrism).
        return symmetric(vec3(a[0] / 0.8660254f, a[0], a[1]));
    case PrimitiveId::CapsuleBetween: {
        Aabb box;
        box.add(v3(a, 0));
        box.add(v3(a, 3));
        return inflateAabb(box, a[6]);
    }
    case PrimitiveId::CappedCylinderBetween: {
        const vec3 pa = v3(a, 0), pb = v3(a, 3);
        Aabb box = discBox(pa, pb - pa, a[6]);
        box.add(discBox(pb, pb - pa, a[6]));
        return box;
    }
    case PrimitiveId::RoundedCylinder: // box-like in (|xz| - r + e, |y| - h + e), minus e
        return symmetric(vec3(a[0], a[2], a[0]));
    case PrimitiveId::CappedCone: {
        const float radius = std::max(a[1], a[2]);
        return symmetric(vec3(radius, a[0], radius));
    }
    case PrimitiveId::CappedConeBetween: {
        // The convex hull of the two cap discs lies in the box of both.
        const vec3 pa = v3(a, 0), pb = v3(a, 3);
        Aabb box = discBox(pa, pb - pa, a[6]);
        box.add(discBox(pb, pb - pa, a[7]));
        return box;
    }
    case PrimitiveId::SolidAngle: {
        // The ball of radius ra (apex at the origin) within `angle` of +y: up to ra along y;
        // down to 0 (the apex) or, past 90 degrees, ra cos(angle); sideways ra sin(angle) or ra.
        const double angle = std::clamp(double(a[0]), 0.0, 180.0);
        const float ra = a[1];
        const float side = angle >= 90.0 ? ra : ra * float(sinDegrees(angle));
        const float bottom = angle <= 90.0 ? 0.0f : ra * float(cosDegrees(angle));
        Aabb box;
        box.add(vec3(-side, bottom, -side));
        box.add(vec3(side, ra, side));
        return box;
    }
    case PrimitiveId::CutSphere: {
        // The part of the ball above y = h: the widest circle is the equator, or the cut circle
        // of radius sqrt(r^2 - h^2) when the cut is above it.
        const float r = a[0];
        const float h = std::min(std::max(a[1], -r), r);
        const float side = h <= 0.0f ? r : std::sqrt(std::max(r * r - h * h, 0.0f));
        Aabb box;
        box.add(vec3(-side, h, -side));
        box.add(vec3(side, r, side));
        return box;
    }
    case PrimitiveId::CutHollowSphere: {
        // The shell (half thickness t) around the part of the sphere below y = h.
        const float r = a[0];
        const float h = std::min(std::max(a[1], -r), r);
        const float side = h >= 0.0f ? r : std::sqrt(std::max(r * r - h * h, 0.0f));
        Aabb curve;
        curve.add(vec3(-side, -r, -side));
        curve.add(vec3(side, h, side));
        return inflateAabb(curve, a[2]);
    }
    case PrimitiveId::RoundCone: {
        // The hull of the spheres r1 at y = -h/2 and r2 at y = h/2 (when h is below the
        // difference of the radii, the larger sphere alone, which may reach past the other).
        Aabb box = ballBox(vec3(0.0f, -0.5f * a[2], 0.0f), a[0]);
        box.add(ballBox(vec3(0.0f, 0.5f * a[2], 0.0f), a[1]));
        return box;
    }
    case PrimitiveId::RoundConeBetween: {
        Aabb box = ballBox(v3(a, 0), a[6]);
        box.add(ballBox(v3(a, 3), a[7]));
        return box;
    }
    case PrimitiveId::RevolvedVesica: {
        // A spindle from tip a to tip b whose radius (at most the width, clamped to half the
        // length as sdRevolvedVesica does) peaks in the middle: within the cylinder of that
        // radius around the segment, whose box is the box of its two end discs.
        const vec3 pa = v3(a, 0), pb = v3(a, 3);
        const float width = std::min(a[6], 0.5f * std::max(glm::length(pb - pa), 1e-6f));
        Aabb box = discBox(pa, pb - pa, width);
        box.add(discBox(pb, pb - pa, width));
        return box;
    }
    case PrimitiveId::Rhombus: // the rhombus (la, lb) in xz grown by ra, |y| <= h
        return symmetric(vec3(a[0] + a[3], a[2], a[1] + a[3]));
    case PrimitiveId::Octahedron:
        return symmetric(vec3(a[0]));
    case PrimitiveId::Pyramid:
        return symmetric(vec3(0.5f * a[0], 0.5f * a[1], 0.5f * a[0]));
    case PrimitiveId::Triangle: {
        Aabb box;
        box.add(v3(a, 0));
        box.add(v3(a, 3));
        box.add(v3(a, 6));
        return inflateAabb(box, a[9]);
    }
    default:
        return {};
    }
}

// sdQuad: where the point is outside an edge (by the formula's sign tests), the distance to the
// nearest edge, which d <= t keeps within t of the corners' box; elsewhere the distance to the
// plane through a with normal nor = (b - a) x (a - d). That second region is the polytope of the
// four side half-spaces (edge x nor) . (p - corner) >= 0 and the slab |n . (p - a)| <= t: the
// quad's prism for a planar convex quad, but for corners out of one plane (the catalogue asks
// for one plane and does not check it) the side planes bound a different prism, wider or open.
// So the box also takes the polytope's vertices (every triple of its 6 planes that meets inside
// the others), and the quad is unbounded when the side normals leave the prism open (all of them
// within a half-plane of directions).
SdfBounds quadBounds(const PrimitiveParams& a, float t) {
    using glm::dvec3;
    dvec3 corner[4];
    Aabb box;
    for (int i = 0; i < 4; ++i) {
        corner[i] = dvec3(v3(a, 3 * i));
        box.add(v3(a, 3 * i));
    }
    box = inflateAabb(box, t);
    const dvec3 nor = glm::cross(corner[1] - corner[0], corner[0] - corner[3]);
    if (!(glm::length(nor) > 0.0)) return boundedBy(box); // every sign test is 0: edges only
    const dvec3 n = glm::normalize(nor);

    // Half-spaces normal . p <= offset.
    dvec3 normals[6];
    double offsets[6];
    for (int i = 0; i < 4; ++i) {
        const dvec3 side = glm::cross(corner[(i + 1) % 4] - corner[i], nor);
        normals[i] = -side;
        offsets[i] = -glm::dot(side, corner[i]);
    }
    normals[4] = n;
    offsets[4] = glm::dot(n, corner[0]) + double(t);
    normals[5] = -n;
    offsets[5] = -glm::dot(n, corner[0]) + double(t);

    // Open prism: the directions of the side normals (in the plane across n) leave a gap of at
    // least half a turn.
    const dvec3 u = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, dvec3(1.0, 0.0, 0.0))
                                                       : glm::cross(n, dvec3(0.0, 1.0, 0.0)));
    const dvec3 w = glm::cross(n, u);
    std::vector<double> angles;
    for (int i = 0; i < 4; ++i)
        if (glm::length(normals[i]) > 1e-12 * glm::length(nor) * glm::length(nor))
            angles.push_back(std::atan2(glm::dot(normals[i], w), glm::dot(normals[i], u)));
    std::sort(angles.begin(), angles.end());
    double widestGap = angles.empty() ? 2.0 * std::numbers::pi : 0.0;
    for (std::size_t i = 0; i < angles.size(); ++i) {
        const double next =
            i + 1 < angles.size() ? angles[i + 1] : angles.front() + 2.0 * std::numbers::pi;
        widestGap = std::max(widestGap, next - angles[i]);
    }
    if (widestGap >= std::numbers::pi - 1e-9) return unbounded("");

    double scale = 1.0;
    for (const dvec3& c : corner)
        scale = std::max(scale, glm::length(c));
    for (int i = 0; i < 6; ++i)
        for (int j = i + 1; j < 6; ++j)
            for (int k = j + 1; k < 6; ++k) {
                const glm::dmat3 m = glm::transpose(glm::dmat3(normals[i], normals[j], normals[k]));
                const double det = glm::determinant(m);
                if (!(std::abs(det) > 1e-14)) continue;
                const dvec3 p = glm::inverse(m) * dvec3(offsets[i], offsets[j], offsets[k]);
                bool inside = true;
                for (int c = 0; c < 6 && inside; ++c)
                    inside = glm::dot(normals[c], p) <=
                             offsets[c] + 1e-9 * scale * (1.0 + glm::length(normals[c]));
                if (inside) box.add(vec3(p));
            }
    return boundedBy(box);
}

// How far past their bounding spheres the fractal formulas of fractal_formulas.cpp keep
// evaluating the fractal before they return the distance to the sphere (MengerSponge and
// SierpinskiTetrahedron: this times their size).
constexpr float kFractalMargin = 0.1f;

} // namespace

Aabb aabbAround(vec3 center, vec3 half) {
    Aabb box;
    box.min = center - half;
    box.max = center + half;
    return box;
}

Aabb intersectAabb(const Aabb& a, const Aabb& b) {
    Aabb box;
    box.min = glm::max(a.min, b.min);
    box.max = glm::min(a.max, b.max);
    return box.empty() ? Aabb{} : box;
}

Aabb inflateAabb(const Aabb& box, float amount) {
    if (box.empty()) return box;
    Aabb grown;
    grown.min = box.min - amount;
    grown.max = box.max + amount;
    return grown.empty() ? Aabb{} : grown;
}

Aabb transformAabb(const Aabb& box, const glm::mat4& m) {
    Aabb out;
    if (box.empty()) return out;
    for (int corner = 0; corner < 8; ++corner) {
        const vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                     (corner & 4) ? box.max.z : box.min.z);
        out.add(vec3(m * glm::vec4(p, 1.0f)));
    }
    return out;
}

SdfBounds primitiveBounds(PrimitiveId id, const PrimitiveParams& a, float level) {
    const float t = std::max(level, 0.0f);
    switch (id) {
    case PrimitiveId::Plane:
        // A half-space, unless the normal is 0: then sdPlane is the constant -offset (inside
        // everywhere or nowhere).
        if (v3(a, 0) == vec3(0.0f) && -a[3] > t) return boundedBy(Aabb{});
        return unbounded("");
    case PrimitiveId::InfiniteCylinder:
    case PrimitiveId::InfiniteCone:
    case PrimitiveId::Gyroid:
        return unbounded("");
    case PrimitiveId::Quad:
        return quadBounds(a, t);
    case PrimitiveId::Ellipsoid: {
        // sdEllipsoid is k0 (k0 - 1) / k1 with k0 = |p / r|, k1 = |p / r^2| <= k0 / min(r), so
        // outside (k0 >= 1) it is >= (k0 - 1) min(r): d <= t gives k0 <= 1 + t / min(r), and
        // |p_i| <= r_i k0.
        const vec3 r = v3(a, 0);
        const float smallest = std::min(r.x, std::min(r.y, r.z));
        if (!(smallest > 0.0f)) return boundedBy(symmetric(glm::abs(r) + t));
        return boundedBy(symmetric(r * (1.0f + t / smallest)));
    }
    case PrimitiveId::TriPrism: {
        // sdTriPrism is max(|z| - l, max(0.866025 |x| + 0.5 y, -y) - r) (a bound, not the
        // distance): d <= t is exactly the prism with r + t, whose triangle has y in
        // [-(r + t), 2 (r + t)] and |x| <= 1.5 (r + t) / 0.866025.
        const float r = a[0] + t;
        Aabb box;
        box.min = vec3(-1.5f * r / 0.866025f, -r, -(a[1] + t));
        box.max = vec3(1.5f * r / 0.866025f, 2.0f * r, a[1] + t);
        return boundedBy(box.empty() ? Aabb{} : box);
    }
    case PrimitiveId::RoundBox: {
        // sdRoundBox is the box of half extents c = h - r grown by r: with q = |p| - c,
        // length(max(q, 0)) + min(max_i q_i, 0) - r <= t. Inside the inner box |p_i| <= c_i;
        // else |max(q, 0)| <= r + t, where max(q_j, 0) >= e_j = max(-c_j, 0) (a rounding
        // larger than the box shrinks it), so |p_i| <= c_i + sqrt((r + t)^2 - sum_j!=i e_j^2).
        const vec3 c = v3(a, 0) - a[3];
        const vec3 e = glm::max(-c, 0.0f);
        const float reach = a[3] + t;
        if (glm::dot(e, e) > reach * reach) return boundedBy(Aabb{});
        vec3 half;
        for (int i = 0; i < 3; ++i)
            half[i] =
                c[i] + std::sqrt(std::max(reach * reach - glm::dot(e, e) + e[i] * e[i], 0.0f));
        return boundedBy(symmetric(half));
    }
    case PrimitiveId::DeathStar: {
        // The ball ra minus the ball rb at (d, 0, 0). sdDeathStar returns the distance to the
        // rim circle (x = ca, radius cb in yz) in the rim's cone, else max(|p| - ra,
        // rb - |p - (d, 0, 0)|): <= t keeps |p| <= R = ra + t and |p - (d, 0, 0)| >= r = rb - t,
        // and on the sphere |p| = R that second condition is x <= (R^2 - r^2 + d^2) / (2d) (as
        // for ca), so no point of that set passes that x. The rim lies on the sphere, except when
        // the carved ball swallows the whole one (ca < -ra, cb = 0): then the "rim" is the point
        // (ca, 0, 0), which d <= t > 0 reaches.
        const float ra = a[0], rb = a[1], d = a[2];
        const float outer = ra + t, carved = rb - t;
        if (!(d > 0.0f)) return boundedBy(symmetric(vec3(outer)));
        const float farX =
            carved <= 0.0f
                ? outer
                : std::min(outer, (outer * outer - carved * carved + d * d) / (2.0f * d));
        Aabb box;
        if (farX >= -outer) {
            const float side =
                farX >= 0.0f ? outer : std::sqrt(std::max(outer * outer - farX * farX, 0.0f));
            box.add(vec3(-outer, -side, -side));
            box.add(vec3(farX, side, side));
        }
        const float ca = (ra * ra - rb * rb + d * d) / (2.0f * d);
        const float cb = std::sqrt(std::max(ra * ra - ca * ca, 0.0f));
        if (std::isfinite(ca) && (t > 0.0f || ca * ca <= ra * ra))
            box.add(aabbAround(vec3(ca, 0.0f, 0.0f), vec3(t, cb + t, cb + t)));
        return boundedBy(box);
    }
    case PrimitiveId::Mandelbulb: {
        // Bound 2^(1/(n-1)) (sdMandelbulb): beyond it |z^n + p| >= |z|^n - |p| > |z| (|z|^(n-1)
        // > 2 and |z| >= |p|), so |z| only grows from |p| > 1, log|z| > 0 and the estimate
        // 0.5 |z| log|z| / dr is > 0: nothing outside the ball is inside. Points within the
        // margin (0.1) beyond it may have any small positive estimate; past the margin the
        // formula is the distance to the ball.
        const float n = a[0];
        const float bound = std::pow(2.0f, 1.0f / (n - 1.0f));
        if (!(n > 1.0f) || !std::isfinite(bound)) return unbounded("");
        return boundedBy(symmetric(vec3(t > 0.0f ? bound + std::max(t, kFractalMargin) : bound)));
    }
    case PrimitiveId::MengerSponge: {
        // Within the bounding sphere (radius sqrt(3) s, margin 0.1 s) sdMengerSponge is
        // max(box, crosses) >= the exact distance to the cube of half edge s; past the margin
        // it is |p| - sqrt(3) s.
        const float s = a[1];
        const float half = t <= kFractalMargin * s ? s + t : kSqrt3 * s + t;
        return boundedBy(symmetric(vec3(half)));
    }
    case PrimitiveId::SierpinskiTetrahedron: {
        // The estimate is (P(z_n) - 1) 0.57735 2^-n s with P(z) the largest of the tetrahedron
        // T's four plane functions (-x-y-z, x+y-z, -x+y+z, x-y+z; T has corners (+-1,+-1,+-1)
        // with an even number of minus signs). The three folds permute those functions, so P
        // is unchanged by them; z' = 2 z - (1, 1, 1) gives P(z') <= 1 + e => P(z) <= 1 + e/2
        // since each plane function is linear and at most 1 at (1, 1, 1). So d <= t gives
        // P(p / s) <= 1 + t / (0.57735 s): p lies in the tetrahedron scaled by that, whose box
        // is [-(s + t / 0.57735), s + t / 0.57735]^3. Past the margin of the bounding sphere
        // (radius sqrt(3) s, margin 0.1 s) the formula is |p| - sqrt(3) s.
        const float s = a[1];
        float half = s + t / 0.57735027f;
        if (t > kFractalMargin * s) half = std::max(half, kSqrt3 * s + t);
        return boundedBy(symmetric(vec3(half)));
    }
    case PrimitiveId::QuaternionJulia: {
        // Bound R = (1 + sqrt(1 + 4 |c|)) / 2 (sdQuaternionJulia): beyond it |z^2 + c| >=
        // |z|^2 - |c| > |z| >= 1, so |z| only grows, log|z| > 0 and the estimate is > 0. Within
        // the margin (0.1) beyond R any small positive estimate is possible; past it the
        // formula is |p| - R.
        const glm::vec4 c(a[0], a[1], a[2], a[3]);
        const float bound = 0.5f * (1.0f + std::sqrt(1.0f + 4.0f * glm::length(c)));
        return boundedBy(symmetric(vec3(t > 0.0f ? bound + std::max(t, kFractalMargin) : bound)));
    }
    default:
        // Exact distances: {d <= t} is the level-0 solid grown by t, whose box is the solid's
        // box grown by t.
        return boundedBy(inflateAabb(exactPrimitiveBox(id, a), t));
    }
}

SdfBounds profileBounds(const SdfProfile& profile, float level) {
    const float t = std::max(level, 0.0f);
    // The 2D profile's box in its plane. Rectangles (rounded or not) are box-like: e = |q| - h +
    // r and d = box(e) - r >= |q_i| - h_i. The 2D distances are exact (the polygon's is the
    // nearest edge with an even-odd sign), so d2 <= t grows the box by t.
    glm::vec2 lo(0.0f), hi(0.0f);
    switch (profile.type) {
    case SdfProfileType::Circle:
        lo = glm::vec2(-profile.radius);
        hi = glm::vec2(profile.radius);
        break;
    case SdfProfileType::Rectangle:
    case SdfProfileType::RoundedRectangle:
        lo = -profile.halfSize;
        hi = profile.halfSize;
        break;
    case SdfProfileType::Polygon:
        if (profile.points.empty()) return boundedBy(Aabb{});
        lo = hi = profile.points.front();
        for (const glm::vec2& point : profile.points) {
            lo = glm::min(lo, point);
            hi = glm::max(hi, point);
        }
        break;
    }
    lo -= t;
    hi += t;
    if (lo.x > hi.x || lo.y > hi.y) return boundedBy(Aabb{});
    Aabb box;
    if (profile.solid == SdfProfileSolid::Extrusion) {
        // max-like combination of d2 and |z| - depth / 2: each is <= t.
        const float halfDepth = 0.5f * profile.depth + t;
        if (halfDepth < 0.0f) return boundedBy(Aabb{});
        box.min = vec3(lo, -halfDepth);
        box.max = vec3(hi, halfDepth);
    } else {
        // Revolution about y: the profile's x is the distance from the y axis minus the offset.
        const float radius = profile.offset + hi.x;
        if (radius < 0.0f) return boundedBy(Aabb{});
        box.min = vec3(-radius, lo.y, -radius);
        box.max = vec3(radius, hi.y, radius);
    }
    return boundedBy(box);
}

namespace {

// The smallest scale factor of a transform (scale, then rotation, then translation): the least
// a length of the node's frame can shrink to in the parent's frame. For a chain of transforms
// the product of these is at most the chain's smallest singular value, which the compiler uses.
float smallestScale(const Transform& transform) {
    const vec3 s = glm::abs(transform.scale);
    return std::min(s.x, std::min(s.y, s.z));
}

// Box of the points whose image under the point modifier `m` lies in `box` (the modifier maps
// the node's local point to the point its content is evaluated at, as its C++ formula does).
SdfBounds modifierPreimage(const SdfModifier& m, const Aabb& box) {
    if (box.empty()) return boundedBy(box);
    return modifierSpec(m.type).preimage(m, box);
}

SdfBounds localBoundsAt(const SdfNode& node, float level, float fieldScale);

// The node's bounds in its parent's frame at `level` (a length of the parent's frame).
// `fieldScale`: field units per unit of length of the parent's frame, at most what the compiler
// uses. A length L of the parent's frame is at most L / smallestScale in the node's frame.
SdfBounds parentBoundsAt(const SdfNode& node, float level, float fieldScale) {
    const float scale = smallestScale(node.transform);
    if (!(scale > 0.0f) || !std::isfinite(scale)) return unbounded(node.pointer); // not invertible
    const SdfBounds local = localBoundsAt(node, level / scale, fieldScale * scale);
    if (!local.bounded) return local;
    return boundedBy(transformAabb(local.box, node.transform.matrix()));
}

// Unions and xor (xor = max(min(a, b), -max(a, b)) <= min(a, b) is bounded like a union).
bool isUnionLike(SdfOp op) {
    const SdfOpCombination combination = operationSpec(op).combination;
    return combination == SdfOpCombination::Union || combination == SdfOpCombination::Xor;
}

bool isIntersectionLike(SdfOp op) {
    return operationSpec(op).combination == SdfOpCombination::Intersection;
}

// For a union-like op(a, b) <= t: the level u with min(a, b) <= u. `k` is the smoothness as a
// length of the group's frame (smoothness / field scale). Every rule is monotonic and of degree 1
// in (t, k), so it holds for lengths as for field units.
float unionGrowth(SdfOp op, SmoothBlend blend, float t, float k) {
    switch (op) {
    case SdfOp::SmoothUnion:
        // Polynomial smin (Quilez, "Smooth minimum", https://iquilezles.org/articles/smin/):
        // mix(b, a, h) - k h (1 - h) >= min(a, b) - k / 4. The circular variant subtracts
        // k/2 (1 + g - sqrt(1 + 2g - g^2)) with g in [0, 1], increasing in g, so at most
        // k/2 (2 - sqrt(2)) = (1 - 1/sqrt(2)) k at g = 1 (a = b).
        return t + (blend == SmoothBlend::Polynomial ? 0.25f : 1.0f - kSqrtHalf) * k;
    case SdfOp::ChamferUnion:
        // hg_sdf fOpUnionChamfer (https://mercury.sexy/hg_sdf/): min(a, b, (a + b - k) / sqrt 2)
        // <= t means min(a, b) <= t or a + b <= sqrt(2) t + k, and then min(a, b) <= (a + b) / 2.
        return std::max(t, 0.5f * (std::numbers::sqrt2_v<float> * t + k));
    case SdfOp::RoundUnion:
        // hg_sdf fOpUnionRound: max(k, min(a, b)) - |max((k - a, k - b), 0)|. For t < k it is
        // <= t when min(a, b) <= t or (k - a)^2 + (k - b)^2 >= (k - t)^2 with a, b < k, whose
        // largest min(a, b) is at a = b: k - (k - t) / sqrt 2. For t >= k: min(a, b) <= t.
        return t < k ? (1.0f - kSqrtHalf) * k + kSqrtHalf * t : t;
    case SdfOp::Union:
    case SdfOp::Xor: // min(a, b) <= t (xor = max(min(a, b), -max(a, b)))
        return t;
    // Not unions: groupBoundsAt bounds them by their first child or their intersection. Listed
    // rather than left to a default, so a new operation does not compile without its rule.
    case SdfOp::Subtraction:
    case SdfOp::Intersection:
    case SdfOp::SmoothSubtraction:
    case SdfOp::SmoothIntersection:
    case SdfOp::ChamferSubtraction:
    case SdfOp::ChamferIntersection:
    case SdfOp::RoundSubtraction:
    case SdfOp::RoundIntersection:
        return t;
    }
    return t;
}

// The children of a group at level t (a length of the group's frame).
SdfBounds groupBoundsAt(const SdfNode& node, float t, float fieldScale) {
    std::vector<const SdfNode*> kept;
    for (const SdfNode& child : node.children)
        if (!child.cut) kept.push_back(&child);
    // Cut children are subtracted from the rest with a subtraction of the group's family, and
    // every subtraction keeps its first operand's bound (max(a, -b), the smooth one
    // -smin(b, -a) >= max(a, -b) since smin <= min, the chamfer and round ones: see below), so
    // they are left out. A group of cut children only is refused by the compiler.
    if (kept.empty()) return boundedBy(Aabb{});
    const SdfOp op = node.op;
    const float k = std::max(node.smoothness, 0.0f) / fieldScale;
    if (!std::isfinite(k) && isUnionLike(op) && takesSmoothness(op))
        return unbounded(node.pointer); // refused by the compiler anyway

    if (isUnionLike(op)) {
        // The fold c0 c1 OP c2 OP ... : the last operand and everything before it at growth(t),
        // the one before that at growth(growth(t)), and so on; c0 at the same level as c1.
        const std::size_t n = kept.size();
        std::vector<float> levels(n, t);
        float level = t;
        for (std::size_t i = n; i-- > 1;) {
            level = unionGrowth(op, node.blend, level, k);
            levels[i] = level;
        }
        levels[0] = level;
        // A fold of polynomial smooth minima with one k never dips more than k below the least
        // of its operands, however many there are: with P = smin(Q, o) and Q >= m - k (m the
        // least operand so far, Q <= m), where Q <= o the dip is (k - d)^2 / 4k with
        // d = o - Q >= k - e for e = Q - (m - k) in [0, k], at most e^2 / 4k <= e; where o < Q,
        // o - k/4 >= min(m, o) - k. So past four operands, where the fold's own growth would
        // reach k, every operand is bounded at t + k.
        if (op == SdfOp::SmoothUnion && node.blend == SmoothBlend::Polynomial && n > 4)
            std::fill(levels.begin(), levels.end(), t + k);
        Aabb box;
        for (std::size_t i = 0; i < n; ++i) {
            const SdfBounds child = parentBoundsAt(*kept[i], levels[i], fieldScale);
            if (!child.bounded) return child;
            box.add(child.box);
        }
        return boundedBy(box);
    }
    if (isIntersectionLike(op)) {
        // max(a, b) <= t needs both <= t. The smooth one, -smin(-a, -b), is >= max(a, b)
        // (smin <= min); hg_sdf's chamfer one is max(max(a, b), ...) and its round one,
        // min(-k, max(a, b)) + |max((k + a, k + b), 0)|, is >= max(a, b) (if max(a, b) >= -k
        // it is -k + |u| >= -k + k + max(a, b); else it is max(a, b) + |u|). So no growth, and
        // unbounded children (planes) are cut by the bounded ones.
        Aabb box;
        bool anyBounded = false;
        std::string firstUnbounded;
        for (const SdfNode* child : kept) {
            const SdfBounds b = parentBoundsAt(*child, t, fieldScale);
            if (!b.bounded) {
                if (firstUnbounded.empty()) firstUnbounded = b.unboundedBy;
                continue;
            }
            box = anyBounded ? intersectAabb(box, b.box) : b.box;
            anyBounded = true;
        }
        if (!anyBounded) return unbounded(firstUnbounded.empty() ? node.pointer : firstUnbounded);
        return boundedBy(box);
    }
    // Subtractions: max(a, -b) <= t needs a <= t. Smooth: -smin(b, -a) >= -min(b, -a) >= a.
    // Chamfer (hg_sdf fOpDifferenceChamfer): max(max(a, -b), ...) >= a. Round
    // (fOpDifferenceRound): min(-k, max(a, -b)) + |max((k + a, k - b), 0)| >= a (as for the
    // round intersection).
    return parentBoundsAt(*kept.front(), t, fieldScale);
}

// The node's bounds in its own frame at `level` (a length of that frame); `fieldScale`: field
// units per unit of length of the node's frame (at most the compiler's).
SdfBounds localBoundsAt(const SdfNode& node, float level, float fieldScale) {
    // Twist, bend and displacement divide the node's field by `shrink` (the compiler's step
    // corrections), so a field level is `shrink` times longer in the modified frame, where the
    // children and the distance modifiers' lengths live.
    const float shrink = float(sdfFieldShrink(node.modifiers));
    float bodyLevel = level * shrink;
    const float bodyFieldScale = fieldScale / shrink;
    // Distance modifiers, applied to the body's field in list order, each turn "result <= t"
    // into "body <= t + growth" (ModifierSpec::growth).
    for (const SdfModifier& m : node.modifiers) {
        const ModifierSpec& spec = modifierSpec(m.type);
        if (spec.growth) bodyLevel += spec.growth(m);
    }
    bodyLevel = std::max(bodyLevel, 0.0f);

    SdfBounds body;
    if (node.isGroup) {
        body = groupBoundsAt(node, bodyLevel, bodyFieldScale);
    } else {
        body = node.profile ? profileBounds(*node.profile, bodyLevel)
                            : primitiveBounds(node.primitive, node.params, bodyLevel);
        if (!body.bounded) body.unboundedBy = node.pointer;
    }
    if (!body.bounded) return body;
    // The point modifiers map the local point to the content's, first to last; undo them from
    // the last.
    for (auto m = node.modifiers.rbegin(); m != node.modifiers.rend(); ++m) {
        if (!isPointModifier(m->type)) continue;
        body = modifierPreimage(*m, body.box);
        if (!body.bounded) return body;
    }
    return body;
}

} // namespace

SdfBounds sdfNodeLocalBounds(const SdfNode& node, float parentFieldScale) {
    const float scale = smallestScale(node.transform);
    if (!(scale > 0.0f) || !std::isfinite(scale)) return unbounded(node.pointer);
    return localBoundsAt(node, 0.0f, parentFieldScale * scale);
}

SdfBounds sdfNodeBounds(const SdfNode& node, float parentFieldScale) {
    return parentBoundsAt(node, 0.0f, parentFieldScale);
}

SdfBounds sdfNodeBoundsAtLevel(const SdfNode& node, float level, float parentFieldScale) {
    // A length L of the parent's frame is a field value of L * parentFieldScale.
    return parentBoundsAt(node, std::max(level, 0.0f) / parentFieldScale, parentFieldScale);
}

} // namespace rmsc
