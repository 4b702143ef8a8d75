// The surface components of a grid cell for each of the 256 sign configurations of its corners:
// which of the cell's 12 edges belong to which component. Manifold dual contouring places one
// vertex per component (Schaefer, Ju and Warren, "Manifold Dual Contouring", IEEE TVCG 2007),
// so a cell the surface passes through twice gets two vertices instead of one that would pinch
// the mesh. A component is the cycle of crossed edges that bounds one marching-cubes patch.
//
// Corner i of a cell is at offset (i & 1, (i >> 1) & 1, (i >> 2) & 1); bit i of a configuration
// is set when corner i is inside (distance < 0). Edge e joins kEdgeCorners[e][0] (the lower
// end) to kEdgeCorners[e][1] along axis kEdgeAxis[e].
//
// Faces with four crossed edges (a "checkerboard" face) are resolved by a rule that depends on
// the face's four signs and one bit the two cells sharing the face both read (dual_contouring
// keeps it per face): by default the inside corners are kept apart; flipped, they are joined.
// The two cells always agree, so every patch edge on a face is seen the same way from both
// sides and the patches form a closed surface.
//
// Face f of a cell is the one across axis f / 2, on its low (f even) or high (f odd) side.
#pragma once

#include <array>
#include <cstdint>

namespace rmsc::exporter {

inline constexpr int kEdgeCorners[12][2] = {
    {0, 1}, {2, 3}, {4, 5}, {6, 7}, // along x
    {0, 2}, {1, 3}, {4, 6}, {5, 7}, // along y
    {0, 4}, {1, 5}, {2, 6}, {3, 7}, // along z
};
inline constexpr int kEdgeAxis[12] = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2};

struct CellComponents {
    std::uint8_t count = 0;             // components (0 for a cell with all corners alike)
    std::array<std::int8_t, 12> edge{}; // component of each edge, -1 where not crossed
    // Each component's crossed edges in order around its patch (marching-cubes polygon),
    // concatenated; `start[c]` to `start[c + 1]` are component c's.
    std::array<std::int8_t, 12> cycle{};
    std::array<std::uint8_t, 7> start{};
};

// The table, built once. Bit f of `flips` flips the rule of face f.
const CellComponents& cellComponents(std::uint8_t configuration, std::uint8_t flips = 0);

// Whether face f of a cell in `configuration` has four crossed edges.
bool checkerboardFace(std::uint8_t configuration, int face);

// The cell's crossed edges on face f, in order around the face (the edges joining its corners
// kFaceCorners[f][k] and kFaceCorners[f][k + 1]).
inline constexpr int kFaceCorners[6][4] = {
    {0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6},
};
int faceEdge(int face, int k);

// The local edge (0..11) of a cell that lies along `axis` at the cell's offsets (u, v) in the
// other two axes (in increasing axis order), e.g. axis 0, (1, 0): the x edge at y + 1, z.
int cellEdge(int axis, int u, int v);

} // namespace rmsc::exporter
