// The quads made fans, and their vertices moved into their cells, where they intersect (see
// quad_fans.hpp).
#include "quad_fans.hpp"

#include "field_steps.hpp"
#include "triangle_grid.hpp"

#include <algorithm>
#include <iterator>
#include <limits>

namespace rmsc::exporter {
namespace {

// How far out of its cell (in cells; negative: inside) a vertex of an intersecting fan may stay,
// in the rounds that move such vertices: as little as it takes, since the nearer the cell's
// middle a vertex is kept, the farther from the surface it may be (where the surface clips the
// cell's corner). The last of them keeps it strictly inside: vertices of two cells on their
// common face would make triangles in one plane that overlap. After them, a vertex still in the
// way goes to the mean of its crossings (massPoints).
constexpr float kMargins[] = {0.15f, 0.05f, -0.01f, -0.1f, -0.25f};
// How far (in cells) a vertex moved back towards its place may step onto the surface.
constexpr float kReach = 0.15f;

// The vertices moved into their cells, each moved back towards where it was (on the surface) as
// far as its triangles then intersect nothing (the whole way, or seven eighths, ... one
// eighth), in two passes (a vertex blocked by one moved back later may pass the second time).
void relaxBack(const SdfField& field, const DcGrid& grid, ExportMesh& mesh,
               std::vector<std::pair<std::uint32_t, glm::vec3>>& original, UntangleStats& stats) {
    // The first place each vertex had (a vertex may have been moved in several rounds).
    std::stable_sort(original.begin(), original.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    original.erase(std::unique(original.begin(), original.end(),
                               [](const auto& a, const auto& b) { return a.first == b.first; }),
                   original.end());
    // The farthest from the surface first: where two block each other, the worse one goes.
    std::vector<float> off(mesh.positions.size(), 0.0f);
    for (const auto& [v, from] : original) {
        off[v] = std::abs(field.distance(mesh.positions[v]));
        ++stats.evaluations;
    }
    std::stable_sort(original.begin(), original.end(),
                     [&](const auto& a, const auto& b) { return off[a.first] > off[b.first]; });
    std::vector<std::vector<std::uint32_t>> around(mesh.positions.size());
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t v : mesh.triangles[t])
            around[v].push_back(t);
    TriangleGrid triangles = gridOfTriangles(mesh, grid.origin, grid.voxel);
    glm::vec3 lo(mesh.positions.empty() ? glm::vec3(0.0f) : mesh.positions[0]), hi = lo;
    for (glm::vec3 p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 extent = hi - lo;
    const double epsilon =
        1e-9 * std::max(double(std::max(extent.x, std::max(extent.y, extent.z))), 1e-6);
    std::vector<float> shares(original.size(), 0.0f); // how far each has gone back
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i < original.size(); ++i) {
            const auto& [v, from] = original[i];
            if (shares[i] >= 1.0f) continue;
            const glm::vec3 safe = mesh.positions[v];
            for (int eighths = 8; eighths >= 1; --eighths) {
                // From where it is now: share s of the way from the safe place it had first.
                const float share = float(eighths) / 8.0f;
                if (share <= shares[i]) break;
                const float step = (share - shares[i]) / (1.0f - shares[i]);
                mesh.positions[v] = glm::mix(safe, from, step);
                // On the way back the vertex is off the surface by up to what the move cost; steps
                // onto it (by at most kReach cells) are tried first.
                const glm::vec3 onto = stepOntoSurface(
                    field, mesh.positions[v], mesh.positions[v] - kReach * grid.voxel,
                    mesh.positions[v] + kReach * grid.voxel, 0.01f * grid.voxel, 1e-4f * grid.voxel,
                    stats.evaluations);
                bool clear = true;
                for (const glm::vec3 place : {onto, mesh.positions[v]}) {
                    mesh.positions[v] = place;
                    clear = true;
                    for (std::uint32_t t : around[v]) {
                        const TrianglePoints p = pointsOf(mesh, t);
                        if (intersectsNearby(mesh, triangles, p, mesh.triangles[t], epsilon,
                                             [](std::uint32_t) { return false; })) {
                            clear = false;
                            break;
                        }
                    }
                    if (clear) break;
                }
                if (clear) {
                    for (std::uint32_t t : around[v]) {
                        const TrianglePoints p = pointsOf(mesh, t);
                        triangles.insert(t, glm::vec3(glm::min(p[0], glm::min(p[1], p[2]))),
                                         glm::vec3(glm::max(p[0], glm::max(p[1], p[2]))));
                    }
                    mesh.normals[v] = unitGradient(field, mesh.positions[v], 0.01f * grid.voxel,
                                                   stats.evaluations);
                    shares[i] = share;
                    break;
                }
                mesh.positions[v] = safe;
            }
        }
}

} // namespace

UntangleStats untangleQuads(const SdfField& field, const DcGrid& grid, ExportMesh& mesh,
                            const std::vector<DcQuad>& quads, std::vector<glm::ivec3>& cells,
                            const std::vector<glm::vec3>& massPoints, std::vector<Qef>* qefs,
                            int rounds, const std::atomic<bool>* cancel) {
    UntangleStats stats;
    std::vector<std::uint8_t> isFan(quads.size(), 0);
    std::vector<std::array<std::uint32_t, 2>> pairs;
    const std::size_t all = std::numeric_limits<std::size_t>::max();
    stats.left = countSelfIntersections(mesh, &pairs, all);
    // The quad of each triangle (a fan's four triangles keep their quad's number).
    std::vector<std::uint32_t> quadOf(mesh.triangles.size());
    for (std::size_t t = 0; t < quadOf.size(); ++t)
        quadOf[t] = std::uint32_t(t / 2);
    const std::size_t firstCentre = mesh.positions.size(); // fans' centres from here on
    std::size_t moveRound = 0;
    std::vector<std::pair<std::uint32_t, glm::vec3>> original; // moved vertices, where they were
    for (int round = 0; round < rounds && stats.left > 0; ++round) {
        if (cancel && cancel->load()) return stats;
        std::vector<std::uint32_t> chosen, inFans;
        for (const auto& pair : pairs)
            for (std::uint32_t t : pair) {
                const std::uint32_t q = quadOf[t];
                if (q >= quads.size()) continue;
                if (!isFan[q]) {
                    isFan[q] = 1;
                    chosen.push_back(q);
                } else {
                    inFans.push_back(t);
                }
            }
        for (std::uint32_t q : chosen) {
            const DcQuad& quad = quads[q];
            const std::uint32_t centre = std::uint32_t(mesh.positions.size());
            std::uint32_t material = 0;
            glm::vec3 color(0.8f);
            field.surface(quad.point, material, color);
            ++stats.evaluations;
            mesh.positions.push_back(quad.point);
            mesh.normals.push_back(quad.normal);
            mesh.colors.push_back(color);
            mesh.vertexMaterial.push_back(material);
            cells.push_back(quad.cell);
            if (qefs) {
                Qef plane;
                plane.add(quad.point, quad.normal);
                qefs->push_back(plane);
            }
            const auto& c = quad.corners;
            mesh.triangles[2 * q] = {c[0], c[1], centre};
            mesh.triangles[2 * q + 1] = {c[1], c[2], centre};
            for (const std::array<std::uint32_t, 3> tri :
                 {std::array<std::uint32_t, 3>{c[2], c[3], centre},
                  std::array<std::uint32_t, 3>{c[3], c[0], centre}}) {
                mesh.triangles.push_back(tri);
                quadOf.push_back(q);
            }
            ++stats.fannedQuads;
        }
        // Fans that intersect although they were fans already: their vertices back towards their
        // cells, where a fan's triangles stay within the two cells they join.
        std::int64_t moved = 0;
        const float margin = kMargins[std::min<std::size_t>(moveRound, std::size(kMargins) - 1)];
        const bool massRound = moveRound >= std::size(kMargins);
        const bool lastMargin = moveRound >= std::size(kMargins);
        if (!inFans.empty()) ++moveRound;
        for (std::uint32_t t : inFans)
            for (std::uint32_t v : mesh.triangles[t]) {
                if (v >= firstCentre) continue; // a centre is on its edge, in its cells
                // Strictly inside: vertices of two cells on their common face would make
                // triangles in one plane that overlap.
                const glm::vec3 lo = grid.origin + grid.voxel * (glm::vec3(cells[v]) - margin);
                const glm::vec3 hi = lo + grid.voxel * (1.0f + 2.0f * margin);
                const glm::vec3 p = mesh.positions[v];
                if (massRound) {
                    // Last: the mean of its crossings, inside the cell, off the surface where
                    // it is curved (the vertex of surface nets).
                    if (p == massPoints[v]) continue;
                    original.push_back({v, p});
                    mesh.positions[v] = massPoints[v];
                    ++moved;
                    continue;
                }
                if (glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi)))
                    continue;
                original.push_back({v, p});
                mesh.positions[v] =
                    stepOntoSurface(field, glm::clamp(p, lo, hi), lo, hi, 0.01f * grid.voxel,
                                    1e-4f * grid.voxel, stats.evaluations);
                mesh.normals[v] =
                    unitGradient(field, mesh.positions[v], 0.01f * grid.voxel, stats.evaluations);
                ++moved;
            }
        stats.verticesMovedIn += moved;
        // Nothing changed: a smaller margin next round, unless this was the smallest.
        if (chosen.empty() && moved == 0) {
            if (lastMargin) break;
            continue;
        }
        pairs.clear();
        stats.left = countSelfIntersections(mesh, &pairs, all);
    }
    if (!original.empty()) relaxBack(field, grid, mesh, original, stats);
    // The triangles' materials: the one most of their vertices have (the first on a tie).
    mesh.triangleMaterial.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const std::uint32_t a = mesh.vertexMaterial[tri[0]], b = mesh.vertexMaterial[tri[1]],
                            c = mesh.vertexMaterial[tri[2]];
        mesh.triangleMaterial[t] = b == c ? b : a;
    }
    return stats;
}

} // namespace rmsc::exporter
