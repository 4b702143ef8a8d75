// Dual contouring in five passes over the blocks near the surface, each on every core: find the
// blocks, sample their corners, find where the surface crosses their edges (Hermite data: point
// and normal), place one vertex per cell component (QEF, clamped to the cell, then moved onto
// the surface along the gradient), and join the four cells around each crossed edge by a quad;
// then the quads that intersect others untangled, and the adaptive octree's collapse.
#include "export/dual_contouring.hpp"

#include "adaptive_octree.hpp"
#include "export/cell_components.hpp"
#include "field_steps.hpp"
#include "parallel_for.hpp"
#include "qef.hpp"
#include "quad_fans.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace rmsc {
namespace {

using exporter::cellComponents;
using exporter::CellComponents;
using exporter::cellEdge;
using exporter::kEdgeAxis;
using exporter::kEdgeCorners;
using exporter::parallelFor;
using exporter::Qef;
using exporter::unitGradient;

constexpr int B = kDcBlock;
// How far (in cells) the steps onto the surface may take a vertex out of its cell.
constexpr float kNewtonMargin = 0.25f;
constexpr int kCornersPerSide = B + 1;
// The share of the progress the uniform passes report when the adaptive octree follows.
constexpr double kUniformShare = 0.8;
// Rounds of making intersecting quads fans and moving their vertices into their cells.
constexpr int kUntangleRounds = 12;

struct Hermite {
    glm::vec3 point;
    glm::vec3 normal;
};

struct Checkerboard {
    glm::ivec3 cell; // the cell whose low face across `axis` it is
    int axis;
};

struct Block {
    glm::ivec3 cell{0};                  // first cell
    std::vector<float> corners;          // (B+1)^3
    std::vector<std::int32_t> edgeIndex; // B^3 * 3: owned edges (start corner in the block)
    std::vector<Hermite> hermite;
    std::vector<std::uint32_t> cellVertex;   // B^3: first vertex (local), ~0 without surface
    std::vector<std::uint8_t> cellConfig;    // B^3
    std::vector<std::uint8_t> faceFlip;      // B^3 * 3: the low face of each cell, per axis
    std::vector<std::uint8_t> cellFlips;     // B^3: bit f set when face f's rule is flipped
    std::vector<Checkerboard> checkerboards; // the low faces with four crossed edges
    std::vector<glm::vec3> positions, normals, colors;
    std::vector<std::uint32_t> materials;
    std::vector<Qef> qefs;               // each vertex's planes (for the adaptive octree)
    std::vector<glm::ivec3> vertexCells; // each vertex's cell
    std::vector<glm::vec3> massPoints;   // each vertex's crossings' mean
    std::uint32_t vertexBase = 0;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<exporter::DcQuad> quads; // each the source of two triangles, in order
    std::int64_t evaluations = 0;
};

int cornerIndex(glm::ivec3 l) {
    return l.x + kCornersPerSide * (l.y + kCornersPerSide * l.z);
}
int cellIndex(glm::ivec3 l) {
    return l.x + B * (l.y + B * l.z);
}
glm::ivec3 cornerOffset(int corner) {
    return {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
}
glm::ivec3 axisVector(int axis) {
    glm::ivec3 v(0);
    v[axis] = 1;
    return v;
}

} // namespace

std::uint64_t estimateDcTriangles(std::int64_t activeBlocks) {
    return std::uint64_t(activeBlocks) * std::uint64_t(B * B) * 2;
}

DcResult dualContour(const SdfField& field, DcGrid grid, const DcOptions& options) {
    DcResult result;
    const int threads = options.threads > 0
                            ? options.threads
                            : int(std::max(1u, std::thread::hardware_concurrency()));
    const glm::ivec3 blocks = (grid.cells + glm::ivec3(B - 1)) / B;
    grid.cells = blocks * B;
    const float voxel = grid.voxel;
    const std::int64_t blockCount = std::int64_t(blocks.x) * blocks.y * blocks.z;
    // The uniform passes' share of the progress; the adaptive octree takes the rest.
    const double share = options.tolerance > 0.0f ? kUniformShare : 1.0;
    std::function<void(double)> progress;
    if (options.progress) progress = [&](double f) { options.progress(share * f); };
    auto blockCoord = [&](std::int64_t i) {
        return glm::ivec3(int(i % blocks.x), int((i / blocks.x) % blocks.y),
                          int(i / (std::int64_t(blocks.x) * blocks.y)));
    };
    auto cornerPosition = [&](glm::ivec3 c) { return grid.origin + voxel * glm::vec3(c); };

    const auto samplingStart = std::chrono::steady_clock::now();
    // Pass 1: which blocks may hold surface.
    std::vector<std::uint8_t> near(std::size_t(blockCount), 0);
    const float halfDiagonal = 0.5f * voxel * float(B) * std::sqrt(3.0f);
    // Chamfer operations make the field up to sqrt(2) steep ((a + b) / sqrt(2) where both
    // sides fall), so the half diagonal is scaled by that, plus half a cell for rounding.
    const float reach = std::sqrt(2.0f) * halfDiagonal + 0.5f * voxel;
    // The block centres as a lattice of spacing B cells, from the first block's centre.
    const glm::vec3 firstCentre = grid.origin + 0.5f * voxel * float(B);
    // With a lattice sampler, the centres in one call: a lattice of one point per block, its
    // spacing a block, from the first block's centre.
    const bool latticeCentres = field.lattice && [&] {
        std::vector<glm::ivec3> starts(static_cast<std::size_t>(blockCount));
        for (std::int64_t i = 0; i < blockCount; ++i)
            starts[std::size_t(i)] = blockCoord(i);
        std::vector<float> centres(static_cast<std::size_t>(blockCount));
        if (!field.lattice(firstCentre, voxel * float(B), starts.data(), starts.size(), 1,
                           centres.data()))
            return false;
        for (std::int64_t i = 0; i < blockCount; ++i)
            near[std::size_t(i)] = std::abs(centres[std::size_t(i)]) <= reach ? 1 : 0;
        return true;
    }();
    if (!latticeCentres &&
        !parallelFor(blockCount, threads, options.cancel, progress, 0.0, 0.05, [&](std::int64_t i) {
            const glm::vec3 centre = cornerPosition(blockCoord(i) * B) + 0.5f * voxel * float(B);
            near[std::size_t(i)] = std::abs(field.distance(centre)) <= reach ? 1 : 0;
        })) {
        result.cancelled = true;
        return result;
    }
    result.evaluations += blockCount;
    std::vector<std::int32_t> blockOf(std::size_t(blockCount), -1);
    std::vector<Block> active;
    for (std::int64_t i = 0; i < blockCount; ++i)
        if (near[std::size_t(i)]) {
            blockOf[std::size_t(i)] = std::int32_t(active.size());
            active.emplace_back().cell = blockCoord(i) * B;
        }
    result.activeBlocks = std::int64_t(active.size());
    result.estimatedTriangles = estimateDcTriangles(result.activeBlocks);
    if (result.estimatedTriangles > options.maxTriangles) {
        result.overLimit = true;
        return result;
    }
    const std::int64_t activeCount = std::int64_t(active.size());
    auto blockAt = [&](glm::ivec3 cell) -> Block* {
        if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
            glm::any(glm::greaterThanEqual(cell, grid.cells)))
            return nullptr;
        const glm::ivec3 b = cell / B;
        const std::int32_t index = blockOf[std::size_t(
            b.x + std::int64_t(blocks.x) * (b.y + std::int64_t(blocks.y) * b.z))];
        return index < 0 ? nullptr : &active[std::size_t(index)];
    };
    // The Hermite data of the edge from global corner `c` along `axis` (nullptr: not crossed).
    auto hermiteAt = [&](glm::ivec3 c, int axis) -> const Hermite* {
        const Block* block = blockAt(c);
        if (!block) return nullptr;
        const glm::ivec3 local = c - block->cell;
        const std::int32_t index = block->edgeIndex[std::size_t(cellIndex(local) * 3 + axis)];
        return index < 0 ? nullptr : &block->hermite[std::size_t(index)];
    };

    // Pass 2: the corners of the blocks near the surface. With a lattice sampler, the blocks'
    // corners are sampled in chunks of kLatticeChunk blocks, each chunk in one call.
    constexpr std::int64_t kCornersPerBlock = kCornersPerSide * kCornersPerSide * kCornersPerSide;
    constexpr std::int64_t kLatticeChunk = 4096;
    bool latticeCorners = latticeCentres;
    for (std::int64_t first = 0; latticeCorners && first < activeCount; first += kLatticeChunk) {
        if (options.cancel && options.cancel->load()) {
            result.cancelled = true;
            return result;
        }
        const std::int64_t count = std::min(kLatticeChunk, activeCount - first);
        std::vector<glm::ivec3> starts(static_cast<std::size_t>(count));
        for (std::int64_t i = 0; i < count; ++i)
            starts[std::size_t(i)] = active[std::size_t(first + i)].cell;
        std::vector<float> corners(std::size_t(count * kCornersPerBlock));
        latticeCorners = field.lattice(grid.origin, voxel, starts.data(), starts.size(),
                                       kCornersPerSide, corners.data());
        for (std::int64_t i = 0; latticeCorners && i < count; ++i) {
            const float* c = corners.data() + i * kCornersPerBlock;
            active[std::size_t(first + i)].corners.assign(c, c + kCornersPerBlock);
        }
        if (progress) progress(0.05 + 0.3 * double(first + count) / double(activeCount));
    }
    result.latticeSampled = latticeCorners;
    if (!parallelFor(
            activeCount, threads, options.cancel, progress, 0.05, 0.35, [&](std::int64_t i) {
                Block& block = active[std::size_t(i)];
                if (!latticeCorners) {
                    block.corners.resize(std::size_t(kCornersPerBlock));
                    for (int z = 0; z <= B; ++z)
                        for (int y = 0; y <= B; ++y)
                            for (int x = 0; x <= B; ++x)
                                block.corners[std::size_t(cornerIndex({x, y, z}))] = field.distance(
                                    cornerPosition(block.cell + glm::ivec3(x, y, z)));
                }
                block.evaluations += kCornersPerBlock;
                block.cellConfig.assign(std::size_t(B * B * B), 0);
                block.faceFlip.assign(std::size_t(B * B * B * 3), 0);
                for (int z = 0; z < B; ++z)
                    for (int y = 0; y < B; ++y)
                        for (int x = 0; x < B; ++x) {
                            const glm::ivec3 l(x, y, z);
                            int config = 0;
                            for (int c = 0; c < 8; ++c)
                                if (block.corners[std::size_t(cornerIndex(l + cornerOffset(c)))] <
                                    0.0f)
                                    config |= 1 << c;
                            block.cellConfig[std::size_t(cellIndex(l))] = std::uint8_t(config);
                            // Checkerboard faces on the cell's low sides: candidates for a flip.
                            if (config != 0 && config != 255)
                                for (int axis = 0; axis < 3; ++axis)
                                    if (exporter::checkerboardFace(std::uint8_t(config), 2 * axis))
                                        block.checkerboards.push_back({block.cell + l, axis});
                        }
            })) {
        result.cancelled = true;
        return result;
    }
    result.samplingSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - samplingStart).count();

    // The flips of the checkerboard faces. A face whose two patch edges belong to one component
    // in both cells beside it would join the two cells' vertices by four triangles. Both patch
    // edges lie on one component of a cell only when the corners the face's rule separates are
    // joined through the rest of the cell's surface (the component is then the one region's
    // boundary), and at most one of the face's two diagonals can be (two paths between
    // alternating corners of the face, one inside and one outside, would cross on the rest of
    // the cube's surface). So the other rule is good for both cells: flipping such a face mends
    // it. A flip changes the components of the two cells, which may make another of their faces
    // bad; rounds repeat until none is (or a round cap; what is left is counted by
    // meshTopology's over-shared edges).
    auto cellAt = [&](glm::ivec3 cell, std::uint8_t& config, std::uint8_t& flips) {
        const Block* block = blockAt(cell);
        if (!block) return false;
        config = block->cellConfig[std::size_t(cellIndex(cell - block->cell))];
        flips = 0;
        for (int f = 0; f < 6; ++f) {
            const glm::ivec3 face = cell + (f & 1) * axisVector(f / 2);
            const Block* owner = blockAt(face);
            if (owner && owner->faceFlip[std::size_t(cellIndex(face - owner->cell) * 3 + f / 2)])
                flips |= std::uint8_t(1 << f);
        }
        return true;
    };
    auto oneComponent = [&](glm::ivec3 cell, int face) {
        std::uint8_t config = 0, flips = 0;
        if (!cellAt(cell, config, flips)) return false;
        const CellComponents& parts = cellComponents(config, flips);
        const int first = parts.edge[std::size_t(exporter::faceEdge(face, 0))];
        for (int k = 1; k < 4; ++k)
            if (parts.edge[std::size_t(exporter::faceEdge(face, k))] != first) return false;
        return true;
    };
    for (int round = 0; round < 16; ++round) {
        int flipped = 0;
        for (Block& block : active)
            for (const Checkerboard& face : block.checkerboards) {
                const glm::ivec3 below = face.cell - axisVector(face.axis);
                if (oneComponent(face.cell, 2 * face.axis) &&
                    oneComponent(below, 2 * face.axis + 1)) {
                    std::uint8_t& flip = block.faceFlip[std::size_t(
                        cellIndex(face.cell - block.cell) * 3 + face.axis)];
                    flip ^= 1;
                    ++flipped;
                }
            }
        result.faceFlips += flipped;
        if (flipped == 0) break;
    }

    auto configAt = [&](glm::ivec3 cell) -> std::uint8_t {
        const Block* block = blockAt(cell);
        return block ? block->cellConfig[std::size_t(cellIndex(cell - block->cell))] : 0;
    };
    auto inCell = [](glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
        return glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi));
    };
    // Whether `cell` places the vertex of a corner that lies in an empty neighbour: the
    // neighbour's non-empty neighbour nearest the corner does (ties: the lowest in z, y, x), so
    // one vertex takes it.
    auto takesOutsideCorner = [&](glm::ivec3 cell, glm::vec3 corner) {
        const glm::ivec3 e(glm::floor((corner - grid.origin) / voxel));
        if (glm::any(glm::greaterThan(glm::abs(e - cell), glm::ivec3(1)))) return false;
        const std::uint8_t config = configAt(e);
        if (config != 0 && config != 255) return false;
        float best = std::numeric_limits<float>::max();
        glm::ivec3 bestCell(0);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 n = e + glm::ivec3(dx, dy, dz);
                    const std::uint8_t c = configAt(n);
                    if (c == 0 || c == 255) continue;
                    const float d = glm::length(cornerPosition(n) + 0.5f * voxel - corner);
                    if (d < best) {
                        best = d;
                        bestCell = n;
                    }
                }
        return best < std::numeric_limits<float>::max() && bestCell == cell;
    };

    // Pass 3: where the surface crosses the edges each block owns (start corner inside it).
    const float gradientStep = 0.01f * voxel;
    if (!parallelFor(
            activeCount, threads, options.cancel, progress, 0.35, 0.55, [&](std::int64_t i) {
                Block& block = active[std::size_t(i)];
                block.edgeIndex.assign(std::size_t(B * B * B * 3), -1);
                for (int z = 0; z < B; ++z)
                    for (int y = 0; y < B; ++y)
                        for (int x = 0; x < B; ++x)
                            for (int axis = 0; axis < 3; ++axis) {
                                const glm::ivec3 l(x, y, z);
                                const float d0 = block.corners[std::size_t(cornerIndex(l))];
                                const float d1 =
                                    block.corners[std::size_t(cornerIndex(l + axisVector(axis)))];
                                if ((d0 < 0.0f) == (d1 < 0.0f)) continue;
                                const glm::vec3 a = cornerPosition(block.cell + l);
                                const glm::vec3 b = a + voxel * glm::vec3(axisVector(axis));
                                // The root by false position with the Illinois correction.
                                float lo = 0.0f, hi = 1.0f, flo = d0, fhi = d1;
                                float t = flo / (flo - fhi);
                                int side = 0;
                                for (int it = 0; it < 10; ++it) {
                                    t = lo + (hi - lo) * flo / (flo - fhi);
                                    const float f = field.distance(a + t * (b - a));
                                    ++block.evaluations;
                                    if (std::abs(f) < 1e-5f * voxel) break;
                                    if ((f < 0.0f) == (flo < 0.0f)) {
                                        lo = t;
                                        flo = f;
                                        if (side == -1) fhi *= 0.5f;
                                        side = -1;
                                    } else {
                                        hi = t;
                                        fhi = f;
                                        if (side == 1) flo *= 0.5f;
                                        side = 1;
                                    }
                                }
                                const glm::vec3 p = a + t * (b - a);
                                block.edgeIndex[std::size_t(cellIndex(l) * 3 + axis)] =
                                    std::int32_t(block.hermite.size());
                                block.hermite.push_back(
                                    {p, unitGradient(field, p, gradientStep, block.evaluations)});
                            }
            })) {
        result.cancelled = true;
        return result;
    }

    // Pass 4: a vertex per component of each cell the surface crosses.
    if (!parallelFor(
            activeCount, threads, options.cancel, progress, 0.55, 0.9, [&](std::int64_t i) {
                Block& block = active[std::size_t(i)];
                block.cellVertex.assign(std::size_t(B * B * B), ~0u);
                block.cellFlips.assign(std::size_t(B * B * B), 0);
                for (int z = 0; z < B; ++z)
                    for (int y = 0; y < B; ++y)
                        for (int x = 0; x < B; ++x) {
                            const glm::ivec3 l(x, y, z);
                            const glm::ivec3 cell = block.cell + l;
                            std::uint8_t config = 0, flips = 0;
                            cellAt(cell, config, flips);
                            if (config == 0 || config == 255) continue;
                            const CellComponents& parts = cellComponents(config, flips);
                            block.cellFlips[std::size_t(cellIndex(l))] = flips;
                            block.cellVertex[std::size_t(cellIndex(l))] =
                                std::uint32_t(block.positions.size());
                            const glm::vec3 lo = cornerPosition(cell);
                            const glm::vec3 hi = lo + voxel;
                            for (int k = 0; k < parts.count; ++k) {
                                Qef qef;
                                for (int s = parts.start[k]; s < parts.start[k + 1]; ++s) {
                                    const int e = parts.cycle[std::size_t(s)];
                                    const Hermite* h = hermiteAt(
                                        cell + cornerOffset(kEdgeCorners[e][0]), kEdgeAxis[e]);
                                    if (h) qef.add(h->point, h->normal);
                                }
                                int rank = 0;
                                const glm::vec3 solution = qef.solve(0.01, &rank);
                                glm::vec3 p = glm::clamp(solution, lo, hi);
                                // Where the planes meet in a point (rank 3), that point is a
                                // corner of the surface. A corner in this cell whose faces do not
                                // all cross the cell's edges leaves fewer planes: those of the
                                // crossings around the cell (its 26 neighbours' edges) may meet
                                // there.
                                glm::vec3 corner = solution;
                                bool haveCorner = rank == 3;
                                if (rank < 3) {
                                    Qef wide;
                                    for (int dz = -1; dz <= 1; ++dz)
                                        for (int dy = -1; dy <= 1; ++dy)
                                            for (int dx = -1; dx <= 1; ++dx)
                                                for (int e = 0; e < 12; ++e) {
                                                    const Hermite* h = hermiteAt(
                                                        cell + glm::ivec3(dx, dy, dz) +
                                                            cornerOffset(kEdgeCorners[e][0]),
                                                        kEdgeAxis[e]);
                                                    if (h) wide.add(h->point, h->normal);
                                                }
                                    int wideRank = 0;
                                    corner = wide.solve(0.01, &wideRank);
                                    haveCorner = wideRank == 3;
                                }
                                // The corner is taken when it lies on the surface, in this cell,
                                // or in an empty neighbour (a tip that crosses none of its edges)
                                // whose nearest non-empty neighbour this cell is.
                                bool cornerTaken = false;
                                if (haveCorner &&
                                    (inCell(corner, lo, hi) || takesOutsideCorner(cell, corner))) {
                                    ++block.evaluations;
                                    if (std::abs(field.distance(corner)) < 0.01f * voxel) {
                                        p = corner;
                                        cornerTaken = true;
                                    }
                                }
                                // Onto the surface along the gradient, near the cell.
                                if (!cornerTaken)
                                    p = exporter::stepOntoSurface(
                                        field, p, lo - kNewtonMargin * voxel,
                                        hi + kNewtonMargin * voxel, gradientStep, 1e-4f * voxel,
                                        block.evaluations);
                                std::uint32_t material = 0;
                                glm::vec3 color(0.8f);
                                field.surface(p, material, color);
                                ++block.evaluations;
                                block.positions.push_back(p);
                                block.normals.push_back(
                                    unitGradient(field, p, gradientStep, block.evaluations));
                                block.colors.push_back(color);
                                block.materials.push_back(material);
                                block.vertexCells.push_back(cell);
                                block.massPoints.push_back(qef.massPoint());
                                if (options.tolerance > 0.0f) block.qefs.push_back(qef);
                            }
                        }
            })) {
        result.cancelled = true;
        return result;
    }
    std::uint64_t vertexCount = 0;
    for (Block& block : active) {
        block.vertexBase = std::uint32_t(vertexCount);
        vertexCount += block.positions.size();
    }
    // The vertex of the component of `cell` that `edge` (local to the cell) belongs to.
    auto vertexOf = [&](glm::ivec3 cell, int edge) -> std::int64_t {
        const Block* block = blockAt(cell);
        if (!block) return -1;
        const int index = cellIndex(cell - block->cell);
        const std::uint32_t first = block->cellVertex[std::size_t(index)];
        if (first == ~0u) return -1;
        const int component = cellComponents(block->cellConfig[std::size_t(index)],
                                             block->cellFlips[std::size_t(index)])
                                  .edge[std::size_t(edge)];
        if (component < 0) return -1;
        return std::int64_t(block->vertexBase) + first + std::uint32_t(component);
    };
    auto positionOf = [&](std::int64_t v) {
        // Vertices are numbered block by block; find the block by binary search.
        auto it = std::upper_bound(
            active.begin(), active.end(), std::uint32_t(v),
            [](std::uint32_t value, const Block& b) { return value < b.vertexBase; });
        const Block& block = *(it - 1);
        return block.positions[std::size_t(v - block.vertexBase)];
    };

    // Pass 5: a quad (two triangles) around every crossed edge, facing the outside.
    std::atomic<bool> broken{false};
    if (!parallelFor(activeCount, threads, options.cancel, progress, 0.9, 1.0, [&](std::int64_t i) {
            Block& block = active[std::size_t(i)];
            for (int z = 0; z < B; ++z)
                for (int y = 0; y < B; ++y)
                    for (int x = 0; x < B; ++x)
                        for (int axis = 0; axis < 3; ++axis) {
                            const glm::ivec3 l(x, y, z);
                            if (block.edgeIndex[std::size_t(cellIndex(l) * 3 + axis)] < 0) continue;
                            const int u = axis == 0 ? 1 : 0;
                            const int v = axis == 2 ? 1 : 2;
                            const glm::ivec3 corner = block.cell + l;
                            std::int64_t quad[4];
                            const int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                            for (int k = 0; k < 4; ++k) {
                                const int du = offsets[k][0], dv = offsets[k][1];
                                const glm::ivec3 cell =
                                    corner - du * axisVector(u) - dv * axisVector(v);
                                quad[k] = vertexOf(cell, cellEdge(axis, du, dv));
                            }
                            if (quad[0] < 0 || quad[1] < 0 || quad[2] < 0 || quad[3] < 0) {
                                broken = true; // the grid's border: the field was not outside
                                continue;
                            }
                            // (0,0), (-1,0), (-1,-1), (0,-1) in (u, v) run counter-clockwise
                            // seen from +axis when (u, v, axis) is right-handed (not for y).
                            const bool insideFirst =
                                block.corners[std::size_t(cornerIndex(l))] < 0.0f;
                            const bool facesPlus = insideFirst; // outward normal along +axis
                            if (facesPlus == (axis == 1)) std::swap(quad[1], quad[3]);
                            // Split along the diagonal whose midpoint is nearer the surface.
                            const glm::vec3 p0 = positionOf(quad[0]), p1 = positionOf(quad[1]),
                                            p2 = positionOf(quad[2]), p3 = positionOf(quad[3]);
                            const float d02 = std::abs(field.distance(0.5f * (p0 + p2)));
                            const float d13 = std::abs(field.distance(0.5f * (p1 + p3)));
                            block.evaluations += 2;
                            auto id = [](std::int64_t value) { return std::uint32_t(value); };
                            const Hermite& crossing = block.hermite[std::size_t(
                                block.edgeIndex[std::size_t(cellIndex(l) * 3 + axis)])];
                            block.quads.push_back(
                                {{id(quad[0]), id(quad[1]), id(quad[2]), id(quad[3])},
                                 crossing.point,
                                 crossing.normal,
                                 corner});
                            if (d02 <= d13) {
                                block.triangles.push_back({id(quad[0]), id(quad[1]), id(quad[2])});
                                block.triangles.push_back({id(quad[0]), id(quad[2]), id(quad[3])});
                            } else {
                                block.triangles.push_back({id(quad[0]), id(quad[1]), id(quad[3])});
                                block.triangles.push_back({id(quad[1]), id(quad[2]), id(quad[3])});
                            }
                        }
        })) {
        result.cancelled = true;
        return result;
    }

    std::uint64_t triangleCount = 0;
    for (const Block& block : active) {
        triangleCount += block.triangles.size();
        result.evaluations += block.evaluations;
    }
    if (triangleCount > options.maxTriangles) {
        result.overLimit = true;
        result.estimatedTriangles = triangleCount;
        return result;
    }
    ExportMesh& mesh = result.mesh;
    mesh.positions.reserve(vertexCount);
    for (Block& block : active) {
        mesh.positions.insert(mesh.positions.end(), block.positions.begin(), block.positions.end());
        mesh.normals.insert(mesh.normals.end(), block.normals.begin(), block.normals.end());
        mesh.colors.insert(mesh.colors.end(), block.colors.begin(), block.colors.end());
        mesh.vertexMaterial.insert(mesh.vertexMaterial.end(), block.materials.begin(),
                                   block.materials.end());
    }
    mesh.triangles.reserve(triangleCount);
    for (Block& block : active)
        mesh.triangles.insert(mesh.triangles.end(), block.triangles.begin(), block.triangles.end());
    // A triangle's material: the one most of its vertices have (the first on a tie).
    mesh.triangleMaterial.reserve(triangleCount);
    for (const auto& tri : mesh.triangles) {
        const std::uint32_t a = mesh.vertexMaterial[tri[0]], b = mesh.vertexMaterial[tri[1]],
                            c = mesh.vertexMaterial[tri[2]];
        mesh.triangleMaterial.push_back(b == c ? b : a);
    }
    (void)broken;
    std::vector<Qef> qefs;
    std::vector<glm::ivec3> cells;
    std::vector<glm::vec3> masses;
    std::vector<exporter::DcQuad> quads;
    quads.reserve(triangleCount / 2);
    const bool adaptive = options.tolerance > 0.0f;
    cells.reserve(vertexCount);
    if (adaptive) qefs.reserve(vertexCount);
    for (Block& block : active) {
        quads.insert(quads.end(), block.quads.begin(), block.quads.end());
        cells.insert(cells.end(), block.vertexCells.begin(), block.vertexCells.end());
        masses.insert(masses.end(), block.massPoints.begin(), block.massPoints.end());
        if (adaptive) qefs.insert(qefs.end(), block.qefs.begin(), block.qefs.end());
        block = Block{}; // its memory, for what follows
    }
    // Quads that pass through others become fans around their edge's crossing.
    const exporter::UntangleStats untangled =
        exporter::untangleQuads(field, grid, mesh, quads, cells, masses, adaptive ? &qefs : nullptr,
                                kUntangleRounds, options.cancel);
    if (options.cancel && options.cancel->load()) {
        result.cancelled = true;
        result.mesh = ExportMesh{};
        return result;
    }
    result.fannedQuads = untangled.fannedQuads;
    result.verticesMovedIn = untangled.verticesMovedIn;
    result.selfIntersections = untangled.left;
    result.evaluations += untangled.evaluations;
    quads = {};
    result.uniformTriangles = mesh.triangles.size();
    if (adaptive) {
        exporter::OctreeSettings octree;
        octree.origin = grid.origin;
        octree.voxel = voxel;
        octree.tolerance = options.tolerance;
        octree.maxLevel = options.octreeLevels;
        octree.threads = threads;
        octree.cancel = options.cancel;
        if (options.progress)
            octree.progress = [&](double f) {
                options.progress(kUniformShare + (1.0 - kUniformShare) * f);
            };
        exporter::OctreeStats stats;
        if (!exporter::collapseOctree(field, mesh, std::move(cells), std::move(qefs), octree,
                                      stats)) {
            result.cancelled = true;
            result.mesh = ExportMesh{};
            return result;
        }
        result.collapsedClusters = stats.collapsed;
        result.evaluations += stats.evaluations;
    }
    return result;
}

} // namespace rmsc
