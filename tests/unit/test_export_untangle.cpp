// Dual contouring without self-intersections (export/quad_fans.hpp): where two quads of the
// cells' vertices would pass through each other (near a rotated box's sharp edges, found by
// the exact triangle test of countSelfIntersections), they become fans around their edge's
// crossing, and the mesh that comes out intersects nowhere. Also the test itself on triangles
// whose answer is known.
#include "export/dual_contouring.hpp"

#include "export_checks.hpp"

#include <gtest/gtest.h>

using namespace rmsc;

namespace {

ExportMesh meshOf(std::vector<glm::vec3> positions,
                  std::vector<std::array<std::uint32_t, 3>> triangles) {
    ExportMesh mesh;
    mesh.positions = std::move(positions);
    mesh.triangles = std::move(triangles);
    return mesh;
}

} // namespace

TEST(ExportSelfIntersections, KnownCases) {
    // Two triangles crossing like links of a chain.
    EXPECT_EQ(countSelfIntersections(meshOf({{-1, 0, 0},
                                             {1, 0, 0},
                                             {0, 1, 0}, // z = 0
                                             {0, 0.5f, -1},
                                             {0, 0.5f, 1},
                                             {0, -1, 0}},
                                            {{0, 1, 2}, {3, 4, 5}})),
              1);
    // The same, apart.
    EXPECT_EQ(countSelfIntersections(meshOf(
                  {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0.5f, -1}, {5, 0.5f, 1}, {5, -1, 0}},
                  {{0, 1, 2}, {3, 4, 5}})),
              0);
    // Sharing a vertex: not counted.
    EXPECT_EQ(
        countSelfIntersections(meshOf({{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0.5f, 1}, {0, -1, 0}},
                                      {{0, 1, 2}, {0, 3, 4}})),
        0);
    // Overlapping in one plane.
    EXPECT_EQ(countSelfIntersections(meshOf(
                  {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5f, 0.5f, 0}, {3, 0.5f, 0}, {0.5f, 3, 0}},
                  {{0, 1, 2}, {3, 4, 5}})),
              1);
    // In one plane, side by side.
    EXPECT_EQ(countSelfIntersections(meshOf(
                  {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.1f, 0.1f, 0}, {2, 0.1f, 0}, {1.1f, 1, 0}},
                  {{0, 1, 2}, {3, 4, 5}})),
              0);
}

// The rotated box at 24 cells: some of its quads intersect others as dual contouring first
// splits them (near its sharp edges); made fans, none does.
TEST(ExportSelfIntersections, IntersectingQuadsBecomeFans) {
    const Scene scene = test::exportSceneOf(
        R"({"shape": "box", "rotation": [17, 29, 11], "position": [0.013, 0.021, -0.007]})");
    Diagnostics diagnostics;
    const std::optional<ExportField> field = exportField(scene, "", std::nullopt, diagnostics);
    ASSERT_TRUE(field) << diagnostics.format();
    DcGrid grid;
    grid.voxel = (field->box.max - field->box.min).x / 24.0f;
    grid.origin =
        field->box.min - 2.0f * grid.voxel - grid.voxel * glm::vec3(0.0131f, 0.0173f, 0.0191f);
    grid.cells = glm::ivec3(glm::ceil((field->box.max - field->box.min) / grid.voxel)) + 4;
    const DcResult result = dualContour(field->field, grid);
    EXPECT_GT(result.fannedQuads, 0);
    EXPECT_EQ(result.selfIntersections, 0);
    test::expectSoundMesh(result.mesh, "box");
}
