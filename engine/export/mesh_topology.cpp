// Counting a mesh's edges by their triangles, and each vertex's fans by union-find over the
// triangles around it.
#include "export/export_mesh.hpp"

#include <algorithm>
#include <numeric>

namespace rmsc {

MeshTopology meshTopology(const ExportMesh& mesh) {
    MeshTopology out;
    // Directed edges (from, to, triangle), sorted by their undirected key.
    struct HalfEdge {
        std::uint64_t key;
        bool forward; // from < to
        std::uint32_t triangle;
    };
    std::vector<HalfEdge> halves;
    halves.reserve(mesh.triangles.size() * 3);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
            ++out.degenerateTriangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[k];
            const std::uint32_t b = tri[(k + 1) % 3];
            halves.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), a < b, t});
        }
    }
    std::sort(halves.begin(), halves.end(),
              [](const HalfEdge& x, const HalfEdge& y) { return x.key < y.key; });
    for (std::size_t i = 0; i < halves.size();) {
        std::size_t j = i;
        while (j < halves.size() && halves[j].key == halves[i].key)
            ++j;
        ++out.edges;
        const std::size_t uses = j - i;
        if (uses == 1) ++out.boundaryEdges;
        if (uses > 2) ++out.overSharedEdges;
        if (uses == 2 && halves[i].forward == halves[i + 1].forward) ++out.misorientedEdges;
        i = j;
    }
    // Fans: around each vertex, triangles that share an edge at the vertex are one fan.
    std::vector<std::vector<std::uint32_t>> around(mesh.positions.size());
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t v : mesh.triangles[t])
            if (v < around.size()) around[v].push_back(t);
    for (std::uint32_t v = 0; v < around.size(); ++v) {
        const auto& tris = around[v];
        if (tris.empty()) continue;
        std::vector<int> parent(tris.size());
        std::iota(parent.begin(), parent.end(), 0);
        auto find = [&](int x) {
            while (parent[x] != x)
                x = parent[x] = parent[parent[x]];
            return x;
        };
        for (std::size_t a = 0; a < tris.size(); ++a)
            for (std::size_t b = a + 1; b < tris.size(); ++b) {
                // Do the two triangles share a vertex other than v (an edge at v)?
                int shared = 0;
                for (std::uint32_t x : mesh.triangles[tris[a]])
                    for (std::uint32_t y : mesh.triangles[tris[b]])
                        shared += (x == y && x != v) ? 1 : 0;
                if (shared > 0) parent[find(int(a))] = find(int(b));
            }
        int fans = 0;
        for (std::size_t a = 0; a < tris.size(); ++a)
            fans += find(int(a)) == int(a) ? 1 : 0;
        if (fans > 1) ++out.pinchedVertices;
    }
    return out;
}

} // namespace rmsc
