// Self-intersections of a triangle mesh: the triangles' boxes in a uniform grid, and every pair
// of triangles that share a grid cell and no vertex tested exactly by Moller's interval method
// (T. Moller, "A Fast Triangle-Triangle Intersection Test", Journal of Graphics Tools 2(2),
// 1997), coplanar pairs by their edges and corners in the plane.
#include "export/export_mesh.hpp"
#include "triangle_grid.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc {
namespace {

using Tri = exporter::TrianglePoints;

// The interval where a triangle (projections p, signed distances d to the other's plane)
// crosses the line of the two planes; false when it lies in the plane (coplanar).
bool interval(const double p[3], const double d[3], double& lo, double& hi) {
    auto cut = [](double pa, double pb, double da, double db) {
        return pa + (pb - pa) * da / (da - db);
    };
    double a, b;
    if (d[0] * d[1] > 0.0) { // vertex 2 alone on its side
        a = cut(p[2], p[0], d[2], d[0]);
        b = cut(p[2], p[1], d[2], d[1]);
    } else if (d[0] * d[2] > 0.0) { // vertex 1 alone
        a = cut(p[1], p[0], d[1], d[0]);
        b = cut(p[1], p[2], d[1], d[2]);
    } else if (d[1] * d[2] > 0.0 || d[0] != 0.0) { // vertex 0 alone
        a = cut(p[0], p[1], d[0], d[1]);
        b = cut(p[0], p[2], d[0], d[2]);
    } else if (d[1] != 0.0) {
        a = cut(p[1], p[0], d[1], d[0]);
        b = cut(p[1], p[2], d[1], d[2]);
    } else if (d[2] != 0.0) {
        a = cut(p[2], p[0], d[2], d[0]);
        b = cut(p[2], p[1], d[2], d[1]);
    } else {
        return false;
    }
    lo = std::min(a, b);
    hi = std::max(a, b);
    return true;
}

double cross2(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Strictly inside the triangle abc (either winding).
bool insideTriangle(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const double u = cross2(a, b, p), v = cross2(b, c, p), w = cross2(c, a, p);
    return (u > 0 && v > 0 && w > 0) || (u < 0 && v < 0 && w < 0);
}

// Two triangles in one plane (normal n): an edge of one crosses an edge of the other, or a
// corner of one lies inside the other.
bool coplanarOverlap(const Tri& a, const Tri& b, glm::dvec3 n) {
    const glm::dvec3 m = glm::abs(n);
    const int drop = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2;
    glm::dvec2 p[3], q[3];
    for (int k = 0; k < 3; ++k) {
        p[k] = {a[k][i], a[k][j]};
        q[k] = {b[k][i], b[k][j]};
    }
    for (int e = 0; e < 3; ++e)
        for (int f = 0; f < 3; ++f) {
            const glm::dvec2 p0 = p[e], p1 = p[(e + 1) % 3], q0 = q[f], q1 = q[(f + 1) % 3];
            const double s0 = cross2(p0, p1, q0), s1 = cross2(p0, p1, q1);
            const double t0 = cross2(q0, q1, p0), t1 = cross2(q0, q1, p1);
            if (((s0 > 0 && s1 < 0) || (s0 < 0 && s1 > 0)) &&
                ((t0 > 0 && t1 < 0) || (t0 < 0 && t1 > 0)))
                return true;
        }
    for (int k = 0; k < 3; ++k)
        if (insideTriangle(p[k], q[0], q[1], q[2]) || insideTriangle(q[k], p[0], p[1], p[2]))
            return true;
    return false;
}

} // namespace

namespace exporter {

bool trianglesIntersect(const Tri& a, const Tri& b, double epsilon) {
    const glm::dvec3 nb = glm::cross(b[1] - b[0], b[2] - b[0]);
    const double lb = glm::length(nb);
    if (!(lb > 0.0)) return false; // a degenerate triangle is counted elsewhere
    double da[3];
    for (int k = 0; k < 3; ++k) {
        da[k] = glm::dot(nb / lb, a[k] - b[0]);
        if (std::abs(da[k]) < epsilon) da[k] = 0.0;
    }
    if ((da[0] > 0 && da[1] > 0 && da[2] > 0) || (da[0] < 0 && da[1] < 0 && da[2] < 0))
        return false;
    const glm::dvec3 na = glm::cross(a[1] - a[0], a[2] - a[0]);
    const double la = glm::length(na);
    if (!(la > 0.0)) return false;
    double db[3];
    for (int k = 0; k < 3; ++k) {
        db[k] = glm::dot(na / la, b[k] - a[0]);
        if (std::abs(db[k]) < epsilon) db[k] = 0.0;
    }
    if ((db[0] > 0 && db[1] > 0 && db[2] > 0) || (db[0] < 0 && db[1] < 0 && db[2] < 0))
        return false;
    if (da[0] == 0.0 && da[1] == 0.0 && da[2] == 0.0) return coplanarOverlap(a, b, na);
    // Both cross the line where the planes meet: project on its largest axis.
    const glm::dvec3 line = glm::abs(glm::cross(na, nb));
    const int axis = line.x >= line.y && line.x >= line.z ? 0 : line.y >= line.z ? 1 : 2;
    const double pa[3] = {a[0][axis], a[1][axis], a[2][axis]};
    const double pb[3] = {b[0][axis], b[1][axis], b[2][axis]};
    double a0, a1, b0, b1;
    if (!interval(pa, da, a0, a1) || !interval(pb, db, b0, b1)) return coplanarOverlap(a, b, na);
    return std::min(a1, b1) - std::max(a0, b0) > epsilon;
}

} // namespace exporter

std::int64_t countSelfIntersections(const ExportMesh& mesh,
                                    std::vector<std::array<std::uint32_t, 2>>* pairs,
                                    std::size_t keep) {
    const std::size_t count = mesh.triangles.size();
    if (count < 2) return 0;
    // The grid: cells about twice the median triangle's box, over the mesh's box.
    glm::dvec3 lo(mesh.positions.empty() ? glm::vec3(0.0f) : mesh.positions[0]), hi = lo;
    for (glm::vec3 p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    std::vector<double> sizes;
    sizes.reserve(count);
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        const glm::dvec3 e = glm::max(a, glm::max(b, c)) - glm::min(a, glm::min(b, c));
        sizes.push_back(std::max(e.x, std::max(e.y, e.z)));
    }
    std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(count / 2), sizes.end());
    const glm::dvec3 extent = hi - lo;
    const double longest = std::max(extent.x, std::max(extent.y, extent.z));
    double cell = std::max(2.0 * sizes[count / 2], longest / 1024.0);
    if (!(cell > 0.0)) return 0;
    const glm::ivec3 cells = glm::ivec3(glm::floor(extent / cell)) + 1;
    auto cellOf = [&](glm::dvec3 p) {
        return glm::clamp(glm::ivec3(glm::floor((p - lo) / cell)), glm::ivec3(0), cells - 1);
    };
    // (cell, triangle) for every cell a triangle's box touches, sorted by cell.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
    std::vector<std::array<glm::ivec3, 2>> ranges(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const auto& tri = mesh.triangles[t];
        const glm::dvec3 a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]),
            c(mesh.positions[tri[2]]);
        const glm::ivec3 from = cellOf(glm::min(a, glm::min(b, c)));
        const glm::ivec3 to = cellOf(glm::max(a, glm::max(b, c)));
        ranges[t] = {from, to};
        for (int z = from.z; z <= to.z; ++z)
            for (int y = from.y; y <= to.y; ++y)
                for (int x = from.x; x <= to.x; ++x)
                    entries.push_back(
                        {std::uint64_t(x) + std::uint64_t(cells.x) *
                                                (std::uint64_t(y) + std::uint64_t(cells.y) * z),
                         t});
    }
    std::sort(entries.begin(), entries.end());
    const double epsilon = 1e-9 * std::max(longest, 1e-6);
    std::int64_t found = 0;
    for (std::size_t i = 0; i < entries.size();) {
        std::size_t j = i;
        while (j < entries.size() && entries[j].first == entries[i].first)
            ++j;
        const std::uint64_t key = entries[i].first;
        const glm::ivec3 here(int(key % std::uint64_t(cells.x)),
                              int((key / std::uint64_t(cells.x)) % std::uint64_t(cells.y)),
                              int(key / (std::uint64_t(cells.x) * std::uint64_t(cells.y))));
        for (std::size_t p = i; p < j; ++p)
            for (std::size_t q = p + 1; q < j; ++q) {
                const std::uint32_t s = entries[p].second, t = entries[q].second;
                // Each pair once: in the first cell both boxes touch.
                const glm::ivec3 first = glm::max(ranges[s][0], ranges[t][0]);
                if (first != here) continue;
                if (glm::any(glm::greaterThan(first, glm::min(ranges[s][1], ranges[t][1]))))
                    continue;
                const auto& a = mesh.triangles[s];
                const auto& b = mesh.triangles[t];
                bool shared = false;
                for (std::uint32_t u : a)
                    for (std::uint32_t v : b)
                        shared = shared || u == v;
                if (shared) continue;
                const Tri ta{glm::dvec3(mesh.positions[a[0]]), glm::dvec3(mesh.positions[a[1]]),
                             glm::dvec3(mesh.positions[a[2]])};
                const Tri tb{glm::dvec3(mesh.positions[b[0]]), glm::dvec3(mesh.positions[b[1]]),
                             glm::dvec3(mesh.positions[b[2]])};
                // Boxes first.
                const glm::dvec3 alo = glm::min(ta[0], glm::min(ta[1], ta[2]));
                const glm::dvec3 ahi = glm::max(ta[0], glm::max(ta[1], ta[2]));
                const glm::dvec3 blo = glm::min(tb[0], glm::min(tb[1], tb[2]));
                const glm::dvec3 bhi = glm::max(tb[0], glm::max(tb[1], tb[2]));
                if (glm::any(glm::lessThan(ahi, blo)) || glm::any(glm::lessThan(bhi, alo)))
                    continue;
                if (!exporter::trianglesIntersect(ta, tb, epsilon)) continue;
                ++found;
                if (pairs && pairs->size() < keep) pairs->push_back({s, t});
            }
        i = j;
    }
    return found;
}

} // namespace rmsc
