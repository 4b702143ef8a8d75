// The adaptive octree's bottom-up collapse (see adaptive_octree.hpp): per level, the candidate
// clusters of every node; per parity class of the nodes, the candidates tested on worker threads
// (read only), then the collapses applied in order; at the end the mesh compacted.
#include "adaptive_octree.hpp"

#include "field_steps.hpp"
#include "parallel_for.hpp"
#include "triangle_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace rmsc::exporter {
namespace {

// How far (in cells) the steps onto the surface may take a cluster's vertex out of its node (as
// dual contouring lets a cell's vertex leave its cell).
constexpr float kNodeMargin = 0.25f;
// The cells of the grid the triangles are filed in, in voxels.
constexpr float kGridCells = 2.0f;

enum class Verdict { Untested, Collapse, Error, Topology, Folding, Intersection };

struct Candidate {
    std::vector<std::uint32_t> members; // sorted
    glm::ivec3 node{0};                 // at `level`: 2^level cells a side
    int level = 0;
    Verdict verdict = Verdict::Untested;
    std::vector<std::uint32_t> star;                  // the triangles around the cluster, sorted
    std::vector<std::array<std::uint32_t, 2>> border; // the loop the new vertex is joined to
    Qef qef;
    glm::vec3 position{0.0f}, normal{0.0f}, color{0.0f};
    std::uint32_t material = 0;
    std::int64_t evaluations = 0;
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

class Collapser {
  public:
    Collapser(const SdfField& field, ExportMesh& mesh, std::vector<glm::ivec3> cells,
              std::vector<Qef> qefs, const OctreeSettings& settings)
        : field_(field), mesh_(mesh), cells_(std::move(cells)), qefs_(std::move(qefs)),
          settings_(settings), voxel_(settings.voxel), limit_(settings.tolerance * settings.voxel),
          grid_(gridOfTriangles(mesh, settings.origin, kGridCells * settings.voxel)) {
        glm::vec3 lo(mesh.positions.empty() ? glm::vec3(0.0f) : mesh.positions[0]), hi = lo;
        for (glm::vec3 p : mesh.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const glm::vec3 extent = hi - lo;
        epsilon_ = 1e-9 * std::max(double(std::max(extent.x, std::max(extent.y, extent.z))), 1e-6);
    }

    bool run(OctreeStats& stats) {
        const std::size_t vertexCount = mesh_.positions.size();
        around_.assign(vertexCount, {});
        standing_.assign(vertexCount, 1);
        dead_.assign(vertexCount, 0);
        triangleDead_.assign(mesh_.triangles.size(), 0);
        for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t)
            for (std::uint32_t v : mesh_.triangles[t])
                around_[v].push_back(t);
        const int levels = std::max(settings_.maxLevel, 0);
        for (int level = 1; level <= levels; ++level) {
            std::vector<Candidate> candidates = candidatesAt(level);
            if (candidates.empty()) break;
            for (int parity = 0; parity < 8; ++parity) {
                std::vector<Candidate*> group;
                for (Candidate& c : candidates)
                    if ((c.node.x & 1) + 2 * (c.node.y & 1) + 4 * (c.node.z & 1) == parity)
                        group.push_back(&c);
                const double from = double((level - 1) * 8 + parity) / double(levels * 8);
                const double to = double((level - 1) * 8 + parity + 1) / double(levels * 8);
                if (!parallelFor(std::int64_t(group.size()), settings_.threads, settings_.cancel,
                                 settings_.progress, from, to,
                                 [&](std::int64_t i) { test(*group[std::size_t(i)]); }))
                    return false;
                // Same-parity candidates were tested against the mesh before any of them was
                // applied; their new triangles are tested again against those applied since.
                TriangleGrid changed(settings_.origin, kGridCells * voxel_);
                for (Candidate* c : group) {
                    if (c->verdict == Verdict::Collapse && crossesChanged(*c, changed))
                        c->verdict = Verdict::Intersection;
                    stats.evaluations += c->evaluations;
                    switch (c->verdict) {
                    case Verdict::Collapse:
                        apply(*c, changed);
                        ++stats.collapsed;
                        break;
                    case Verdict::Intersection:
                        ++stats.refusedIntersection;
                        break;
                    case Verdict::Error:
                        ++stats.refusedError;
                        break;
                    case Verdict::Topology:
                        ++stats.refusedTopology;
                        break;
                    case Verdict::Folding:
                    case Verdict::Untested:
                        ++stats.refusedFolding;
                        break;
                    }
                    if (c->verdict != Verdict::Collapse)
                        for (std::uint32_t v : c->members)
                            standing_[v] = 0;
                }
            }
        }
        compact();
        return true;
    }

  private:
    // The clusters of `level`: in each node, the vertices joined by edges inside the node. Those
    // with a vertex that an earlier level refused are refused too (they stay as they are).
    std::vector<Candidate> candidatesAt(int level) {
        std::vector<std::uint32_t> order;
        for (std::uint32_t v = 0; v < mesh_.positions.size(); ++v)
            if (!dead_[v] && !around_[v].empty()) order.push_back(v);
        auto nodeOf = [&](std::uint32_t v) { return cells_[v] >> level; };
        auto less = [](glm::ivec3 a, glm::ivec3 b) {
            return a.z != b.z ? a.z < b.z : a.y != b.y ? a.y < b.y : a.x < b.x;
        };
        std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return less(nodeOf(a), nodeOf(b));
        });
        std::vector<std::uint32_t> parent(mesh_.positions.size());
        auto find = [&](std::uint32_t x) {
            while (parent[x] != x)
                x = parent[x] = parent[parent[x]];
            return x;
        };
        std::vector<Candidate> out;
        for (std::size_t begin = 0; begin < order.size();) {
            const glm::ivec3 node = nodeOf(order[begin]);
            std::size_t end = begin;
            while (end < order.size() && nodeOf(order[end]) == node)
                ++end;
            for (std::size_t i = begin; i < end; ++i)
                parent[order[i]] = order[i];
            for (std::size_t i = begin; i < end; ++i) {
                const std::uint32_t v = order[i];
                for (std::uint32_t t : around_[v])
                    for (std::uint32_t u : mesh_.triangles[t])
                        if (u != v && nodeOf(u) == node) parent[find(u)] = find(v);
            }
            // Group the node's vertices by their root.
            std::vector<std::pair<std::uint32_t, std::uint32_t>> byRoot;
            for (std::size_t i = begin; i < end; ++i)
                byRoot.push_back({find(order[i]), order[i]});
            std::sort(byRoot.begin(), byRoot.end());
            for (std::size_t i = 0; i < byRoot.size();) {
                std::size_t j = i;
                bool standing = true;
                for (; j < byRoot.size() && byRoot[j].first == byRoot[i].first; ++j)
                    if (!standing_[byRoot[j].second]) standing = false;
                if (!standing) {
                    for (std::size_t k = i; k < j; ++k)
                        standing_[byRoot[k].second] = 0;
                } else if (j - i > 1) {
                    Candidate& c = out.emplace_back();
                    c.node = node;
                    c.level = level;
                    for (std::size_t k = i; k < j; ++k)
                        c.members.push_back(byRoot[k].second);
                    std::sort(c.members.begin(), c.members.end());
                }
                i = j;
            }
            begin = end;
        }
        return out;
    }

    bool member(const Candidate& c, std::uint32_t v) const {
        return std::binary_search(c.members.begin(), c.members.end(), v);
    }

    // The cluster's triangles form a disk whose border is one simple loop, and replacing the
    // cluster by one vertex joined to that loop keeps a closed 2-manifold. `border` gets the
    // loop's directed edges (each from a triangle with one cluster vertex, in its order).
    bool topologyAllows(Candidate& c, std::vector<std::array<std::uint32_t, 2>>& border) const {
        for (std::uint32_t v : c.members)
            c.star.insert(c.star.end(), around_[v].begin(), around_[v].end());
        std::sort(c.star.begin(), c.star.end());
        c.star.erase(std::unique(c.star.begin(), c.star.end()), c.star.end());
        std::vector<std::uint64_t> edges;
        std::vector<std::uint32_t> vertices;
        for (std::uint32_t t : c.star) {
            const auto& tri = mesh_.triangles[t];
            int inside = 0, at = -1;
            for (int k = 0; k < 3; ++k) {
                vertices.push_back(tri[k]);
                edges.push_back(edgeKey(tri[k], tri[(k + 1) % 3]));
                if (member(c, tri[k])) {
                    ++inside;
                    at = k;
                }
            }
            if (inside == 1) border.push_back({tri[(at + 1) % 3], tri[(at + 2) % 3]});
        }
        std::sort(vertices.begin(), vertices.end());
        const std::int64_t V = std::unique(vertices.begin(), vertices.end()) - vertices.begin();
        std::sort(edges.begin(), edges.end());
        std::int64_t E = 0;
        for (std::size_t i = 0; i < edges.size();) {
            std::size_t j = i;
            while (j < edges.size() && edges[j] == edges[i])
                ++j;
            ++E;
            const bool touches = member(c, std::uint32_t(edges[i] >> 32)) ||
                                 member(c, std::uint32_t(edges[i] & 0xffffffffu));
            // Edges at the cluster are inside the disk (two triangles), the others on its border
            // (one): a triangle with one cluster vertex then has its opposite edge on the border.
            if (j - i != (touches ? 2u : 1u)) return false;
            i = j;
        }
        if (V - E + std::int64_t(c.star.size()) != 1) return false;
        // One simple loop: each border vertex starts one border edge and ends one, and walking
        // from any returns after all of them.
        const std::size_t n = border.size();
        if (n < 3) return false;
        std::vector<std::array<std::uint32_t, 2>> sorted = border;
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i = 1; i < n; ++i)
            if (sorted[i][0] == sorted[i - 1][0]) return false;
        auto next = [&](std::uint32_t from) -> std::int64_t {
            auto it = std::lower_bound(sorted.begin(), sorted.end(),
                                       std::array<std::uint32_t, 2>{from, 0});
            return it != sorted.end() && (*it)[0] == from ? std::int64_t((*it)[1]) : -1;
        };
        std::uint32_t at = border[0][0];
        for (std::size_t steps = 0; steps < n; ++steps) {
            const std::int64_t to = next(at);
            if (to < 0) return false;
            at = std::uint32_t(to);
            if (at == border[0][0] && steps + 1 < n) return false; // a shorter loop
        }
        if (at != border[0][0]) return false;
        // A loop of three that is already a triangle elsewhere would close a tetrahedron's
        // worth of surface onto it.
        if (n == 3) {
            const std::uint32_t a = border[0][0], b = border[0][1];
            const std::uint32_t d = border[1][0] == b ? border[1][1] : border[2][1];
            for (std::uint32_t t : around_[a]) {
                if (std::binary_search(c.star.begin(), c.star.end(), t)) continue;
                const auto& tri = mesh_.triangles[t];
                const bool hasB = tri[0] == b || tri[1] == b || tri[2] == b;
                const bool hasD = tri[0] == d || tri[1] == d || tri[2] == d;
                if (hasB && hasD) return false;
            }
        }
        return true;
    }

    // Whether the cluster may become one vertex, and where (read only: runs on worker threads).
    void test(Candidate& c) const {
        std::vector<std::array<std::uint32_t, 2>> border;
        if (!topologyAllows(c, border)) {
            c.verdict = Verdict::Topology;
            return;
        }
        for (std::uint32_t v : c.members)
            c.qef += qefs_[v];
        const int cells = 1 << c.level;
        const glm::vec3 lo = settings_.origin + voxel_ * glm::vec3(c.node * cells);
        const glm::vec3 hi = lo + voxel_ * float(cells);
        const float step = 0.01f * voxel_;
        glm::vec3 x = glm::clamp(c.qef.solve(0.01), lo, hi);
        x = stepOntoSurface(field_, x, lo - kNodeMargin * voxel_, hi + kNodeMargin * voxel_, step,
                            1e-4f * voxel_, c.evaluations);
        if (!(std::sqrt(c.qef.error(x) / double(std::max(c.qef.count, 1))) <= double(limit_))) {
            c.verdict = Verdict::Error;
            return;
        }
        for (const auto& [a, b] : border) {
            const glm::vec3 pa = mesh_.positions[a], pb = mesh_.positions[b];
            const glm::vec3 n = glm::cross(pa - x, pb - x);
            const float length = glm::length(n);
            if (!(length > 1e-6f * voxel_ * voxel_)) {
                c.verdict = Verdict::Folding;
                return;
            }
            const glm::vec3 centroid = (x + pa + pb) / 3.0f;
            ++c.evaluations;
            if (!(std::abs(field_.distance(centroid)) <= limit_) ||
                !(std::abs(field_.distance(0.5f * (x + pa))) <= limit_)) {
                ++c.evaluations;
                c.verdict = Verdict::Error;
                return;
            }
            ++c.evaluations;
            const glm::vec3 g = unitGradient(field_, centroid, step, c.evaluations);
            if (glm::dot(n / length, g) < kMinFacing) {
                c.verdict = Verdict::Folding;
                return;
            }
        }
        for (const auto& [a, b] : border)
            if (intersectsNearby(mesh_, grid_, fanTriangle(x, a, b), {~0u, a, b}, epsilon_,
                                 [&](std::uint32_t t) { return replaced(c, t); })) {
                c.verdict = Verdict::Intersection;
                return;
            }
        c.border = std::move(border);
        c.position = x;
        c.normal = unitGradient(field_, x, step, c.evaluations);
        field_.surface(x, c.material, c.color);
        ++c.evaluations;
        c.verdict = Verdict::Collapse;
    }

    TrianglePoints fanTriangle(glm::vec3 x, std::uint32_t a, std::uint32_t b) const {
        return {glm::dvec3(x), glm::dvec3(mesh_.positions[a]), glm::dvec3(mesh_.positions[b])};
    }
    // A triangle the collapse of `c` removes or replaces (or one gone already).
    bool replaced(const Candidate& c, std::uint32_t t) const {
        return triangleDead_[t] || std::binary_search(c.star.begin(), c.star.end(), t);
    }
    bool crossesChanged(const Candidate& c, const TriangleGrid& changed) const {
        for (const auto& [a, b] : c.border)
            if (intersectsNearby(mesh_, changed, fanTriangle(c.position, a, b), {~0u, a, b},
                                 epsilon_, [&](std::uint32_t t) { return replaced(c, t); }))
                return true;
        return false;
    }

    void apply(const Candidate& c, TriangleGrid& changed) {
        const std::uint32_t keep = c.members[0];
        std::vector<std::uint32_t> kept;
        for (std::uint32_t t : c.star) {
            auto& tri = mesh_.triangles[t];
            int inside = 0;
            for (std::uint32_t v : tri)
                inside += member(c, v) ? 1 : 0;
            if (inside >= 2) {
                triangleDead_[t] = 1;
                for (std::uint32_t u : tri) {
                    if (member(c, u)) continue;
                    auto& list = around_[u];
                    auto it = std::find(list.begin(), list.end(), t);
                    if (it != list.end()) {
                        *it = list.back();
                        list.pop_back();
                    }
                }
            } else {
                for (std::uint32_t& v : tri)
                    if (member(c, v)) v = keep;
                kept.push_back(t);
            }
        }
        for (std::uint32_t v : c.members) {
            around_[v].clear();
            if (v != keep) dead_[v] = 1;
        }
        for (std::uint32_t t : kept) {
            const TrianglePoints p = pointsOf(mesh_, t);
            const glm::vec3 lo(glm::min(p[0], glm::min(p[1], p[2])));
            const glm::vec3 hi(glm::max(p[0], glm::max(p[1], p[2])));
            grid_.insert(t, lo, hi);
            changed.insert(t, lo, hi);
        }
        around_[keep] = std::move(kept);
        mesh_.positions[keep] = c.position;
        mesh_.normals[keep] = c.normal;
        mesh_.colors[keep] = c.color;
        mesh_.vertexMaterial[keep] = c.material;
        qefs_[keep] = c.qef;
    }

    // Drops the collapsed vertices and triangles; the triangles' materials from their vertices
    // again (the one most of them have; the first on a tie).
    void compact() {
        std::vector<std::uint32_t> index(mesh_.positions.size(), ~0u);
        ExportMesh out;
        std::vector<std::array<std::uint32_t, 3>> triangles;
        for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
            if (triangleDead_[t]) continue;
            std::array<std::uint32_t, 3> tri = mesh_.triangles[t];
            for (std::uint32_t& v : tri) {
                if (index[v] == ~0u) {
                    index[v] = std::uint32_t(out.positions.size());
                    out.positions.push_back(mesh_.positions[v]);
                    out.normals.push_back(mesh_.normals[v]);
                    out.colors.push_back(mesh_.colors[v]);
                    out.vertexMaterial.push_back(mesh_.vertexMaterial[v]);
                }
                v = index[v];
            }
            out.triangles.push_back(tri);
            const std::uint32_t a = out.vertexMaterial[tri[0]], b = out.vertexMaterial[tri[1]],
                                c = out.vertexMaterial[tri[2]];
            out.triangleMaterial.push_back(b == c ? b : a);
        }
        mesh_ = std::move(out);
    }

    const SdfField& field_;
    ExportMesh& mesh_;
    std::vector<glm::ivec3> cells_;
    std::vector<Qef> qefs_;
    const OctreeSettings& settings_;
    const float voxel_;
    const float limit_; // the tolerance in world units
    TriangleGrid grid_; // every triangle, filed again where a collapse moved it
    double epsilon_ = 0.0;
    std::vector<std::vector<std::uint32_t>> around_; // the live triangles around each vertex
    std::vector<std::uint8_t> standing_;             // may still join a larger cluster
    std::vector<std::uint8_t> dead_;                 // collapsed into another vertex
    std::vector<std::uint8_t> triangleDead_;
};

} // namespace

bool collapseOctree(const SdfField& field, ExportMesh& mesh, std::vector<glm::ivec3> cells,
                    std::vector<Qef> qefs, const OctreeSettings& settings, OctreeStats& stats) {
    Collapser collapser(field, mesh, std::move(cells), std::move(qefs), settings);
    return collapser.run(stats);
}

} // namespace rmsc::exporter
