// The adaptive octree of rmsc export (export/dual_contouring.hpp, DcOptions::tolerance): flat
// regions collapse into few triangles, curved ones only as far as the tolerance lets the surface
// move, sharp corners stay, and the mesh stays a closed 2-manifold without self-intersections.
#include "export/dual_contouring.hpp"

#include "export_checks.hpp"

#include <gtest/gtest.h>

using namespace rmsc;
using test::atResolution;
using test::expectGoodMesh;
using test::exportSceneOf;

namespace {

// The largest |distance| at the triangles' centroids, in voxels.
float maxCentroidError(const test::Exported& e) {
    float worst = 0.0f;
    for (const auto& t : e.mesh.mesh.triangles) {
        const glm::vec3 c = (e.mesh.mesh.positions[t[0]] + e.mesh.mesh.positions[t[1]] +
                             e.mesh.mesh.positions[t[2]]) /
                            3.0f;
        worst = std::max(worst, std::abs(e.field.field.distance(c)));
    }
    return worst / e.mesh.grid.voxel;
}

} // namespace

TEST(ExportOctree, FlatFacesTakeFewTriangles) {
    const Scene scene = exportSceneOf(
        R"({"shape": "box", "half_extents": [0.4, 0.3, 0.25], "rotation": [23, 37, 11]})");
    ExportSettings uniform = atResolution(48);
    uniform.tolerance = 0.0f;
    const std::optional<test::Exported> cells = expectGoodMesh(scene, uniform, "uniform box");
    const std::optional<test::Exported> octree = expectGoodMesh(scene, atResolution(48), "box");
    ASSERT_TRUE(cells && octree);
    EXPECT_EQ(cells->mesh.mesh.triangles.size(), cells->mesh.uniformTriangles);
    EXPECT_EQ(octree->mesh.uniformTriangles, cells->mesh.uniformTriangles);
    const double ratio =
        double(octree->mesh.mesh.triangles.size()) / double(cells->mesh.mesh.triangles.size());
    EXPECT_LT(ratio, 0.19); // 2,578 of 15,042 triangles measured (0.171)
    // The corners stay: each has a vertex within 0.1 voxel.
    const glm::mat4 m = scene.sdf->transform.matrix();
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner =
            glm::vec3(m * glm::vec4((c & 1 ? 1 : -1) * 0.4f, (c & 2 ? 1 : -1) * 0.3f,
                                    (c & 4 ? 1 : -1) * 0.25f, 1.0f));
        float nearest = 1e9f;
        for (glm::vec3 p : octree->mesh.mesh.positions)
            nearest = std::min(nearest, glm::length(p - corner));
        EXPECT_LE(nearest / octree->mesh.grid.voxel, 0.1f) << c;
    }
}

// A sphere 48 cells across: the larger the tolerance, the larger the clusters and the fewer the
// triangles (measured: 24%, 16.5% and 5.2% of the cells' triangles at 0.05, 0.1 and 0.3 voxel),
// and the triangles' centroids stay within the tolerance of the surface (measured 0.042, 0.099
// and 0.282 voxel): the collapse tests the centroids of the triangles it makes.
TEST(ExportOctree, CurvedSurfacesCollapseWithinTheTolerance) {
    const Scene scene = exportSceneOf(R"({"shape": "sphere", "radius": 0.5})");
    const struct {
        float tolerance;
        double ratio; // at most this share of the cells' triangles
    } cases[] = {{0.05f, 0.26}, {0.1f, 0.18}, {0.3f, 0.06}};
    std::size_t previous = ~std::size_t(0);
    for (const auto& c : cases) {
        const float tolerance = c.tolerance;
        ExportSettings settings = atResolution(48);
        settings.tolerance = tolerance;
        const std::optional<test::Exported> e =
            expectGoodMesh(scene, settings, "sphere, tolerance " + std::to_string(tolerance));
        ASSERT_TRUE(e);
        const double ratio =
            double(e->mesh.mesh.triangles.size()) / double(e->mesh.uniformTriangles);
        EXPECT_LE(ratio, c.ratio) << tolerance;
        EXPECT_LT(e->mesh.mesh.triangles.size(), previous) << tolerance;
        previous = e->mesh.mesh.triangles.size();
        EXPECT_LE(maxCentroidError(*e), tolerance);
    }
}
