// rmsc export on the shapes and modifiers test_export_mesh.cpp leaves out: the four fractals
// (cut to bounds), the triangle and the quad, the profile solids (extrusion and revolution of
// each profile) and the polar, bend, taper and displace modifiers. Each mesh is checked as
// every export is (export_checks.hpp): a closed, outward 2-manifold without self-intersections,
// every vertex within 0.1 voxel of the SDF surface.
#include "export_checks.hpp"

#include <gtest/gtest.h>

using namespace rmsc;
using test::atResolution;
using test::expectGoodMesh;
using test::exportSceneOf;

// The fractals are distance bounds, not distances, with detail at every scale: the mesh is that
// of the surface at the voxel size, cut to a box through their middle (so the cut faces are
// checked too) and closed there. Their vertices are not all within 0.1 voxel of d = 0: the steps
// onto the surface follow the estimate's gradient, which near these surfaces is far from unit
// length and, for the Mandelbulb and the Julia set, jumps where the escape iteration changes.
// Each bound is the largest |d| measured at a vertex (in voxels), rounded up.
TEST(ExportCoverage, FractalsCutToBounds) {
    const struct {
        const char* json;
        float maxError;
    } cases[] = {
        {R"({"shape": "mandelbulb", "iterations": 6})", 1.65f},             // 1.644
        {R"({"shape": "menger_sponge", "iterations": 2})", 0.1f},           // 0.011
        {R"({"shape": "sierpinski_tetrahedron", "iterations": 3})", 0.38f}, // 0.370
        {R"({"shape": "quaternion_julia", "iterations": 8})", 0.35f},       // 0.340
    };
    for (const auto& c : cases) {
        ExportSettings settings = atResolution(40);
        settings.bounds = Aabb{glm::vec3(-1.3f, -1.3f, -1.3f), glm::vec3(1.3f, 0.11f, 1.3f)};
        expectGoodMesh(exportSceneOf(c.json), settings, c.json, c.maxError);
    }
}

// The triangle is thickened (its own `thickness`); the quad has no inside (an unsigned
// distance): it is exported once a modifier gives it one, and refused on its own.
TEST(ExportCoverage, TriangleAndQuad) {
    expectGoodMesh(
        exportSceneOf(R"({"shape": "triangle", "thickness": 0.06, "rotation": [20, 30, 10]})"),
        atResolution(40), "triangle");
    expectGoodMesh(exportSceneOf(R"({"shape": "quad", "rotation": [20, 30, 10],
                          "modifiers": [{"type": "round", "radius": 0.06}]})"),
                   atResolution(40), "rounded quad");
    Diagnostics errors;
    EXPECT_FALSE(test::exportOf(exportSceneOf(R"({"shape": "quad"})"), atResolution(16), &errors));
    ASSERT_FALSE(errors.items.empty());
    EXPECT_NE(errors.items[0].message.find("no surface"), std::string::npos)
        << errors.items[0].message;
}

TEST(ExportCoverage, ProfileSolids) {
    const char* profiles[] = {
        R"({"type": "circle", "radius": 0.3})",
        R"({"type": "rectangle", "half_size": [0.3, 0.2]})",
        R"({"type": "rounded_rectangle", "half_size": [0.3, 0.2], "radius": 0.08})",
        R"({"type": "polygon", "points": [[0, -0.3], [0.3, -0.1], [0.15, 0.3], [-0.2, 0.25], [-0.3, -0.2]]})",
    };
    for (const char* profile : profiles) {
        expectGoodMesh(
            exportSceneOf(
                R"({"shape": "extrusion", "depth": 0.4, "rotation": [15, 25, 5], "profile": )" +
                std::string(profile) + "}"),
            atResolution(32), std::string("extrusion of ") + profile);
        expectGoodMesh(
            exportSceneOf(
                R"({"shape": "revolution", "offset": 0.45, "rotation": [15, 25, 5], "profile": )" +
                std::string(profile) + "}"),
            atResolution(32), std::string("revolution of ") + profile);
    }
}

TEST(ExportCoverage, PolarBendTaperDisplace) {
    const char* cases[] = {
        R"({"shape": "sphere", "radius": 0.15, "position": [0.4, 0, 0],
            "modifiers": [{"type": "polar", "count": 6}]})",
        R"({"shape": "box", "half_extents": [0.6, 0.08, 0.15],
            "modifiers": [{"type": "bend", "amount": 60, "radius": 0.7}]})",
        R"({"shape": "capped_cylinder", "radius": 0.3, "half_height": 0.4,
            "modifiers": [{"type": "taper", "amount": -0.8, "radius": 0.5}]})",
        R"({"shape": "sphere", "radius": 0.4,
            "modifiers": [{"type": "displace", "amplitude": 0.04, "frequency": 4}]})",
    };
    for (const char* json : cases)
        expectGoodMesh(exportSceneOf(json), atResolution(40), json);
}
