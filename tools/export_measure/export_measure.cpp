// rmsc_export_measure: the numbers of docs/export.md for one scene. Exports a node as
// `rmsc export` does and measures the mesh against the SDF: triangles, the largest and mean
// |distance| at the vertices and at points spread over the triangles (in voxels), the distance
// of given sharp corners to the nearest vertex, and the time. With --marching-cubes it measures
// plain marching cubes on the same grid instead (vertices linearly interpolated on the crossed
// edges, one polygon per cell component): a baseline for the table, not a feature of rmsc.
//
//   rmsc_export_measure SCENE [--node P] [--resolution N | --voxel S] [--tolerance T]
//                       [--marching-cubes] [--corner X,Y,Z]... [--threads N]
// Prints one JSON object.
#include "export/cell_components.hpp"
#include "export/dual_contouring.hpp"
#include "export/sdf_export.hpp"
#include "scene/scene_json.hpp"
#include "sdf/primitives.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

using namespace rmsc;

namespace {

// Plain marching cubes on the grid dualContour samples (same blocks near the surface).
ExportMesh marchingCubes(const SdfField& field, DcGrid grid, int threads) {
    const int B = kDcBlock;
    grid.cells = ((grid.cells + glm::ivec3(B - 1)) / B) * B;
    const glm::ivec3 n = grid.cells + 1;
    const std::int64_t count = std::int64_t(n.x) * n.y * n.z;
    std::vector<float> corner(std::size_t(count), NAN);
    auto at = [&](glm::ivec3 c) -> float& {
        return corner[std::size_t(c.x + std::int64_t(n.x) * (c.y + std::int64_t(n.y) * c.z))];
    };
    auto position = [&](glm::ivec3 c) { return grid.origin + grid.voxel * glm::vec3(c); };
    const glm::ivec3 blocks = grid.cells / B;
    // The same blocks as dualContour's (export/dual_contouring.cpp).
    const float reach =
        std::sqrt(2.0f) * 0.5f * grid.voxel * float(B) * std::sqrt(3.0f) + 0.5f * grid.voxel;
    std::vector<glm::ivec3> nearBlocks;
    for (int z = 0; z < blocks.z; ++z)
        for (int y = 0; y < blocks.y; ++y)
            for (int x = 0; x < blocks.x; ++x) {
                const glm::vec3 centre =
                    position(glm::ivec3(x, y, z) * B) + 0.5f * grid.voxel * float(B);
                if (std::abs(field.distance(centre)) <= reach) nearBlocks.push_back({x, y, z});
            }
    std::atomic<std::size_t> next{0};
    auto sample = [&] {
        for (std::size_t i; (i = next++) < nearBlocks.size();)
            for (int z = 0; z <= B; ++z)
                for (int y = 0; y <= B; ++y)
                    for (int x = 0; x <= B; ++x) {
                        const glm::ivec3 c = nearBlocks[i] * B + glm::ivec3(x, y, z);
                        at(c) = field.distance(position(c)); // shared faces: same value twice
                    }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(sample);
    sample();
    for (auto& t : pool)
        t.join();
    ExportMesh mesh;
    std::unordered_map<std::uint64_t, std::uint32_t> vertexOfEdge;
    for (const glm::ivec3 b : nearBlocks)
        for (int z = 0; z < B; ++z)
            for (int y = 0; y < B; ++y)
                for (int x = 0; x < B; ++x) {
                    const glm::ivec3 cell = b * B + glm::ivec3(x, y, z);
                    float d[8];
                    int config = 0;
                    for (int k = 0; k < 8; ++k) {
                        d[k] = at(cell + glm::ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
                        if (d[k] < 0.0f) config |= 1 << k;
                    }
                    if (config == 0 || config == 255) continue;
                    const auto& parts = exporter::cellComponents(std::uint8_t(config));
                    for (int c = 0; c < parts.count; ++c) {
                        std::vector<glm::vec3> polygon;
                        std::vector<std::uint64_t> edgeKeys;
                        for (int s = parts.start[c]; s < parts.start[c + 1]; ++s) {
                            const int e = parts.cycle[std::size_t(s)];
                            const int c0 = exporter::kEdgeCorners[e][0],
                                      c1 = exporter::kEdgeCorners[e][1];
                            const glm::vec3 p0 =
                                position(cell + glm::ivec3(c0 & 1, (c0 >> 1) & 1, (c0 >> 2) & 1));
                            const glm::vec3 p1 =
                                position(cell + glm::ivec3(c1 & 1, (c1 >> 1) & 1, (c1 >> 2) & 1));
                            const float t = d[c0] / (d[c0] - d[c1]);
                            polygon.push_back(p0 + t * (p1 - p0));
                            const glm::ivec3 start =
                                cell + glm::ivec3(c0 & 1, (c0 >> 1) & 1, (c0 >> 2) & 1);
                            edgeKeys.push_back((std::uint64_t(start.x) |
                                                std::uint64_t(start.y) << 20 |
                                                std::uint64_t(start.z) << 40) *
                                                   3 +
                                               std::uint64_t(exporter::kEdgeAxis[e]));
                        }
                        // Orientation from the first patch edge, on the face f the cycle's
                        // first two edges share: seen from outside, the patch lies to the left
                        // of its boundary, so (m x t) . n_f > 0 with t the boundary's direction,
                        // m pointing from its start to the inside corner of that edge and n_f
                        // the face's outward normal.
                        {
                            const int e0 = parts.cycle[std::size_t(parts.start[c])];
                            const int e1 = parts.cycle[std::size_t(parts.start[c] + 1)];
                            int face = -1;
                            for (int f = 0; f < 6 && face < 0; ++f) {
                                bool has0 = false, has1 = false;
                                for (int k = 0; k < 4; ++k) {
                                    has0 |= exporter::faceEdge(f, k) == e0;
                                    has1 |= exporter::faceEdge(f, k) == e1;
                                }
                                if (has0 && has1) face = f;
                            }
                            const int c0 = exporter::kEdgeCorners[e0][0],
                                      c1 = exporter::kEdgeCorners[e0][1];
                            const int in = d[c0] < 0.0f ? c0 : c1;
                            const glm::vec3 inside =
                                position(cell + glm::ivec3(in & 1, (in >> 1) & 1, (in >> 2) & 1));
                            glm::vec3 nf(0.0f);
                            nf[face / 2] = face & 1 ? 1.0f : -1.0f;
                            // Edge midpoints stand in for the vertices (which coincide where a
                            // corner's value is 0): the sign depends only on the topology.
                            auto midpoint = [&](int e) {
                                const int lo = exporter::kEdgeCorners[e][0],
                                          hi = exporter::kEdgeCorners[e][1];
                                return 0.5f * (position(cell + glm::ivec3(lo & 1, (lo >> 1) & 1,
                                                                          (lo >> 2) & 1)) +
                                               position(cell + glm::ivec3(hi & 1, (hi >> 1) & 1,
                                                                          (hi >> 2) & 1)));
                            };
                            const glm::vec3 t = midpoint(e1) - midpoint(e0);
                            const glm::vec3 m = inside - midpoint(e0);
                            if (glm::dot(glm::cross(m, t), nf) < 0.0f) {
                                std::reverse(polygon.begin(), polygon.end());
                                std::reverse(edgeKeys.begin(), edgeKeys.end());
                            }
                        }
                        // One vertex per crossed grid edge, shared by the cells around it.
                        std::vector<std::uint32_t> ids;
                        for (std::size_t k = 0; k < polygon.size(); ++k) {
                            auto [it, added] = vertexOfEdge.try_emplace(
                                edgeKeys[k], std::uint32_t(mesh.positions.size()));
                            if (added) mesh.positions.push_back(polygon[k]);
                            ids.push_back(it->second);
                        }
                        for (std::size_t k = 1; k + 1 < ids.size(); ++k)
                            mesh.triangles.push_back({ids[0], ids[k], ids[k + 1]});
                    }
                }
    return mesh;
}

bool parseVec(const std::string& text, glm::vec3& v) {
    std::stringstream in(text);
    char comma1 = 0, comma2 = 0;
    return bool(in >> v.x >> comma1 >> v.y >> comma2 >> v.z) && comma1 == ',' && comma2 == ',';
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr,
                     "usage: rmsc_export_measure SCENE [--node P] [--resolution N | --voxel S] "
                     "[--marching-cubes] [--corner X,Y,Z]... [--threads N]\n");
        return 2;
    }
    // --box-corners SCENE: the world corners of the scene's root box, for --corner.
    if (std::string(argv[1]) == "--box-corners" && argc == 3) {
        Diagnostics diagnostics;
        const std::optional<Scene> scene = loadScene(argv[2], diskFileSource(), diagnostics);
        if (!scene || !scene->sdf || scene->sdf->isGroup ||
            scene->sdf->primitive != PrimitiveId::Box) {
            std::fprintf(stderr, "%s: expected a scene whose sdf is one box\n", argv[2]);
            return 1;
        }
        const PrimitiveSpec& spec = primitiveSpec(PrimitiveId::Box);
        const float* half = scene->sdf->params.data() + paramOffset(spec, 0);
        const glm::mat4 m = scene->sdf->transform.matrix();
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 local((c & 1 ? 1 : -1) * half[0], (c & 2 ? 1 : -1) * half[1],
                                  (c & 4 ? 1 : -1) * half[2]);
            const glm::vec3 p = glm::vec3(m * glm::vec4(local, 1.0f));
            std::printf("%.6f,%.6f,%.6f\n", p.x, p.y, p.z);
        }
        return 0;
    }
    ExportSettings settings;
    bool marching = false;
    std::vector<glm::vec3> corners;
    int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        const std::string value = i + 1 < argc ? argv[i + 1] : "";
        if (arg == "--node")
            settings.node = value, ++i;
        else if (arg == "--resolution")
            settings.resolution = std::stoi(value), ++i;
        else if (arg == "--voxel")
            settings.voxel = std::stof(value), ++i;
        else if (arg == "--tolerance")
            settings.tolerance = std::stof(value), ++i;
        else if (arg == "--threads")
            threads = std::stoi(value), ++i;
        else if (arg == "--marching-cubes")
            marching = true;
        else if (arg == "--corner") {
            glm::vec3 c;
            if (!parseVec(value, c)) return 2;
            corners.push_back(c);
            ++i;
        } else {
            std::fprintf(stderr, "unknown argument %s\n", arg.c_str());
            return 2;
        }
    }
    settings.threads = threads;
    Diagnostics diagnostics;
    const std::optional<Scene> scene = loadScene(argv[1], diskFileSource(), diagnostics);
    if (!scene) {
        std::fputs(diagnostics.format().c_str(), stderr);
        return 1;
    }
    const std::optional<ExportField> field =
        exportField(*scene, settings.node, settings.bounds, diagnostics);
    if (!field) {
        std::fputs(diagnostics.format().c_str(), stderr);
        return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock(); // the process's CPU time, every thread's
    std::clock_t mcCpuStart = 0;
    ExportMesh mesh;
    DcGrid grid;
    std::uint64_t estimate = 0;
    std::int64_t flips = 0;
    std::uint64_t uniform = 0; // dual contouring's triangles before the adaptive octree
    double mcSeconds = 0.0;    // marching cubes alone (its grid comes from a dual contouring run)
    if (marching) {
        // The grid exportSdf would use, from a tiny export's settings.
        std::optional<SdfExport> probe = exportSdf(*scene, settings, diagnostics);
        if (!probe) {
            std::fputs(diagnostics.format().c_str(), stderr);
            return 1;
        }
        grid = probe->grid;
        mcSeconds = -1.0;
        const auto mcStart = std::chrono::steady_clock::now();
        mcCpuStart = std::clock();
        mesh = marchingCubes(field->field, grid, threads);
        mcSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - mcStart).count();
    } else {
        std::optional<SdfExport> exported = exportSdf(*scene, settings, diagnostics);
        if (!exported) {
            std::fputs(diagnostics.format().c_str(), stderr);
            return 1;
        }
        mesh = std::move(exported->mesh);
        grid = exported->grid;
        estimate = exported->estimatedTriangles;
        flips = exported->faceFlips;
        uniform = exported->uniformTriangles;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double elapsed = marching ? mcSeconds : seconds;
    const double cpuSeconds =
        double(std::clock() - (marching ? mcCpuStart : cpuStart)) / double(CLOCKS_PER_SEC);
    const float voxel = grid.voxel;
    double maxVertex = 0.0, sumVertex = 0.0;
    for (glm::vec3 p : mesh.positions) {
        const double e = std::abs(field->field.distance(p)) / voxel;
        maxVertex = std::max(maxVertex, e);
        sumVertex += e;
    }
    // Points spread over the triangles by area (a fixed seed): their |distance|.
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    double area = 0.0;
    for (const auto& t : mesh.triangles)
        area += 0.5 * glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                             mesh.positions[t[2]] - mesh.positions[t[0]]));
    const int samples = 200000;
    double sumSurface = 0.0, maxSurface = 0.0;
    int taken = 0;
    for (const auto& t : mesh.triangles) {
        const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]],
                        c = mesh.positions[t[2]];
        const double share = 0.5 * glm::length(glm::cross(b - a, c - a)) / area * samples;
        int k = int(share);
        if (unit(random) < share - k) ++k;
        for (int s = 0; s < k; ++s) {
            float u = unit(random), v = unit(random);
            if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
            const double e = std::abs(field->field.distance(a + u * (b - a) + v * (c - a))) / voxel;
            sumSurface += e;
            maxSurface = std::max(maxSurface, e);
            ++taken;
        }
    }
    double cornerError = 0.0;
    for (glm::vec3 c : corners) {
        float nearest = 1e30f;
        for (glm::vec3 p : mesh.positions)
            nearest = std::min(nearest, glm::length(p - c));
        cornerError = std::max(cornerError, double(nearest) / voxel);
    }
    const MeshTopology topology = meshTopology(mesh);
    nlohmann::json out = {
        {"method", marching ? "marching cubes" : "dual contouring"},
        {"voxel", voxel},
        {"grid", {grid.cells.x, grid.cells.y, grid.cells.z}},
        {"triangles", mesh.triangles.size()},
        {"vertices", mesh.positions.size()},
        {"max_vertex_error", maxVertex},
        {"mean_vertex_error",
         mesh.positions.empty() ? 0.0 : sumVertex / double(mesh.positions.size())},
        {"max_surface_error", maxSurface},
        {"mean_surface_error", taken ? sumSurface / taken : 0.0},
        {"corner_error", corners.empty() ? nlohmann::json(nullptr) : nlohmann::json(cornerError)},
        {"closed_manifold", topology.closedManifold()},
        {"over_shared_edges", topology.overSharedEdges},
        {"pinched_vertices", topology.pinchedVertices},
        {"boundary_edges", topology.boundaryEdges},
        {"misoriented_edges", topology.misorientedEdges},
        {"degenerate_triangles", topology.degenerateTriangles},
        {"self_intersections", countSelfIntersections(mesh)},
        {"seconds", elapsed},
        {"cpu_seconds", cpuSeconds},
        {"estimated_triangles", estimate},
        {"face_flips", flips},
        {"uniform_triangles", uniform},
        {"tolerance", marching ? 0.0f : settings.tolerance},
        {"threads", threads},
    };
    std::puts(out.dump().c_str());
    return 0;
}
