// Test helper for rmsc export's meshes: a scene from SDF JSON text, an export with the field it
// was sampled from, and the checks every exported mesh must pass (a closed, consistently
// oriented 2-manifold facing outwards, free of self-intersections, every vertex on the SDF
// surface). A failed check fails the calling test, naming the case.
#pragma once

#include "export/export_mesh.hpp"
#include "export/sdf_export.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

namespace rmsc::test {

inline Scene exportSceneOf(const std::string& sdfJson, const std::string& extra = "") {
    Diagnostics diagnostics;
    std::optional<Scene> scene = parseScene(
        R"({"version": 1, )" + extra + R"("sdf": )" + sdfJson + "}", "t.json", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.format();
    return scene ? std::move(*scene) : Scene{};
}

struct Exported {
    SdfExport mesh;
    ExportField field;
};

inline std::optional<Exported> exportOf(const Scene& scene, ExportSettings settings,
                                        Diagnostics* errors = nullptr) {
    Diagnostics diagnostics;
    std::optional<SdfExport> mesh = exportSdf(scene, settings, diagnostics);
    if (errors) *errors = diagnostics;
    if (!mesh) return std::nullopt;
    std::optional<ExportField> field =
        exportField(scene, settings.node, settings.bounds, diagnostics);
    if (!field) return std::nullopt;
    return Exported{std::move(*mesh), std::move(*field)};
}

// The largest |distance| at a vertex, in voxels.
inline float maxVertexError(const Exported& e) {
    float worst = 0.0f;
    for (glm::vec3 p : e.mesh.mesh.positions)
        worst = std::max(worst, std::abs(e.field.field.distance(p)));
    return worst / e.mesh.grid.voxel;
}

// The volume the triangles enclose (the divergence theorem: 1/6 sum a . (b x c)), positive
// when they face outwards.
inline double enclosedVolume(const ExportMesh& mesh) {
    double volume = 0.0;
    for (const auto& t : mesh.triangles)
        volume += glm::dot(glm::dvec3(mesh.positions[t[0]]),
                           glm::cross(glm::dvec3(mesh.positions[t[1]]),
                                      glm::dvec3(mesh.positions[t[2]]))) /
                  6.0;
    return volume;
}

// Closed 2-manifold, no self-intersections.
inline void expectSoundMesh(const ExportMesh& mesh, const std::string& what) {
    const MeshTopology topology = meshTopology(mesh);
    EXPECT_TRUE(topology.closedManifold())
        << what << ": " << topology.boundaryEdges << " boundary, " << topology.overSharedEdges
        << " over-shared, " << topology.misorientedEdges << " misoriented edges, "
        << topology.pinchedVertices << " pinched vertices, " << topology.degenerateTriangles
        << " degenerate triangles";
    std::vector<std::array<std::uint32_t, 2>> pairs;
    const std::int64_t crossings = countSelfIntersections(mesh, &pairs, 1);
    EXPECT_EQ(crossings, 0) << what << ": triangles " << (pairs.empty() ? 0 : pairs[0][0])
                            << " and " << (pairs.empty() ? 0 : pairs[0][1])
                            << " (sharing no vertex) intersect";
}

// Exported, closed, outward, without self-intersections, every vertex within `maxError`
// voxels of the surface. Returns the export for further checks.
inline std::optional<Exported> expectGoodMesh(const Scene& scene, ExportSettings settings,
                                              const std::string& what, float maxError = 0.1f) {
    Diagnostics errors;
    std::optional<Exported> e = exportOf(scene, settings, &errors);
    EXPECT_TRUE(e) << what << ": " << errors.format();
    if (!e) return e;
    const ExportMesh& mesh = e->mesh.mesh;
    EXPECT_GT(mesh.triangles.size(), 20u) << what;
    expectSoundMesh(mesh, what);
    EXPECT_GT(enclosedVolume(mesh), 0.0) << what;
    EXPECT_LE(maxVertexError(*e), maxError) << what;
    return e;
}

inline ExportSettings atResolution(int n) {
    ExportSettings settings;
    settings.resolution = n;
    return settings;
}

} // namespace rmsc::test
