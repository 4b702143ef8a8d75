// The 256 cell configurations' components, derived from the faces' rules at first use (no
// table is written out by hand).
#include "export/cell_components.hpp"

#include <vector>

namespace rmsc::exporter {
namespace {

int edgeBetween(int a, int b) {
    for (int e = 0; e < 12; ++e)
        if ((kEdgeCorners[e][0] == a && kEdgeCorners[e][1] == b) ||
            (kEdgeCorners[e][0] == b && kEdgeCorners[e][1] == a))
            return e;
    return -1;
}

CellComponents build(int configuration, int flips) {
    auto inside = [&](int corner) { return (configuration >> corner) & 1; };
    auto crossed = [&](int e) { return inside(kEdgeCorners[e][0]) != inside(kEdgeCorners[e][1]); };
    // The patch edges: on each face, which crossed edges a segment of the surface joins.
    int partner[12][2];
    int partners[12] = {};
    auto link = [&](int a, int b) {
        partner[a][partners[a]++] = b;
        partner[b][partners[b]++] = a;
    };
    for (int f = 0; f < 6; ++f) {
        const auto& face = kFaceCorners[f];
        int edges[4];
        int crossings = 0;
        for (int k = 0; k < 4; ++k) {
            edges[k] = edgeBetween(face[k], face[(k + 1) % 4]);
            crossings += crossed(edges[k]) ? 1 : 0;
        }
        if (crossings == 2) {
            int pair[2];
            int n = 0;
            for (int k = 0; k < 4; ++k)
                if (crossed(edges[k])) pair[n++] = edges[k];
            link(pair[0], pair[1]);
        } else if (crossings == 4) {
            // The inside corners kept apart: a segment cuts off each inside corner (flipped:
            // each outside corner, which joins the inside ones).
            const int cutOff = (flips >> f) & 1 ? 0 : 1;
            for (int k = 0; k < 4; ++k)
                if (inside(face[k]) == cutOff) link(edges[(k + 3) % 4], edges[k]);
        }
    }
    CellComponents out;
    out.edge.fill(-1);
    int written = 0;
    for (int first = 0; first < 12; ++first) {
        if (!crossed(first) || out.edge[first] >= 0) continue;
        const int component = out.count++;
        out.start[component] = std::uint8_t(written);
        // Every crossed edge lies on two faces, so it has two partners: the patch is a cycle.
        int previous = -1;
        int current = first;
        do {
            out.edge[current] = std::int8_t(component);
            out.cycle[written++] = std::int8_t(current);
            const int next =
                partner[current][0] != previous ? partner[current][0] : partner[current][1];
            previous = current;
            current = next;
        } while (current != first);
    }
    out.start[out.count] = std::uint8_t(written);
    return out;
}

struct Table {
    std::vector<CellComponents> entries;
    Table() : entries(256 * 64) {
        for (int c = 0; c < 256; ++c)
            for (int f = 0; f < 64; ++f)
                entries[std::size_t(c * 64 + f)] = build(c, f);
    }
};

} // namespace

const CellComponents& cellComponents(std::uint8_t configuration, std::uint8_t flips) {
    static const Table table;
    return table.entries[std::size_t(configuration) * 64 + (flips & 63)];
}

int faceEdge(int face, int k) {
    return edgeBetween(kFaceCorners[face][k], kFaceCorners[face][(k + 1) % 4]);
}

bool checkerboardFace(std::uint8_t configuration, int face) {
    int crossings = 0;
    for (int k = 0; k < 4; ++k) {
        const int e = faceEdge(face, k);
        crossings += ((configuration >> kEdgeCorners[e][0]) & 1) !=
                     ((configuration >> kEdgeCorners[e][1]) & 1);
    }
    return crossings == 4;
}

int cellEdge(int axis, int u, int v) {
    return 4 * axis + u + 2 * v;
}

} // namespace rmsc::exporter
