// Picking glTF lines and points (editor/picking.hpp, editor/ray_segment.hpp): a ray picks a line
// or point it passes within kLinePickPixels pixels of, measured in the world (through the
// instance's transform), with a pixel that grows with distance or not; a nearer triangle hides
// it, and it hides a farther triangle.
#include "editor/picking.hpp"
#include "editor/ray_segment.hpp"

#include <gtest/gtest.h>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

MeshVertex vertex(glm::vec3 p) {
    MeshVertex v{};
    v.position = p;
    v.color = glm::vec4(1.0f);
    return v;
}

// A segment from (-1, 0, 0) to (1, 0, 0), a point at (0, 1, 0) and, when `quadZ` is given, a
// square of side 4 at that z facing +z; placed at (0, 0, -2) with scale 2.
PreparedScene linesScene(std::optional<float> quadZ = std::nullopt) {
    MeshAsset asset;
    MeshPrimitive line;
    line.mode = PrimitiveMode::Lines;
    line.vertices = {vertex({-1, 0, 0}), vertex({1, 0, 0})};
    line.indices = {0, 1};
    asset.primitives.push_back(line);
    MeshPrimitive point;
    point.mode = PrimitiveMode::Points;
    point.vertices = {vertex({0, 1, 0})};
    point.indices = {0};
    asset.primitives.push_back(point);
    if (quadZ) {
        MeshPrimitive quad;
        for (glm::vec2 c : {glm::vec2(-2, -2), glm::vec2(2, -2), glm::vec2(2, 2), glm::vec2(-2, 2)})
            quad.vertices.push_back(vertex(glm::vec3(c, *quadZ)));
        quad.indices = {0, 1, 2, 0, 2, 3};
        asset.primitives.push_back(quad);
    }
    asset.boundsMin = glm::vec3(-2, -2, std::min(0.0f, quadZ.value_or(0.0f)));
    asset.boundsMax = glm::vec3(2, 2, std::max(0.0f, quadZ.value_or(0.0f)));
    PreparedScene prepared;
    MeshInstance instance;
    instance.transform.position = glm::vec3(0, 0, -2);
    instance.transform.scale = glm::vec3(2);
    prepared.scene.meshes.push_back(instance);
    prepared.assets.push_back(asset);
    prepared.instanceAsset.push_back(0);
    return prepared;
}

// A ray down -z from (x, y, 5); a pixel is 0.01 wide per unit of distance (perspective).
PickRay ray(float x, float y, float pixelSpread = 0.01f, float pixelSize = 0.0f) {
    PickRay r;
    r.origin = glm::vec3(x, y, 5);
    r.direction = glm::vec3(0, 0, -1);
    r.tMin = 0.01f;
    r.tMax = 100.0f;
    r.pixelSpread = pixelSpread;
    r.pixelSize = pixelSize;
    return r;
}

} // namespace

TEST(RaySegment, NearestApproachOfASegment) {
    // The ray along -z from (0, 0, 5); the segment from (1, -1, 0) to (1, 1, 0) passes 1 away at
    // its middle, at t = 5.
    const auto a = raySegmentApproach({0, 0, 5}, {0, 0, -1}, {1, -1, 0}, {1, 1, 0}, 0, 100);
    ASSERT_TRUE(a);
    EXPECT_NEAR(a->t, 5.0f, 1e-5f);
    EXPECT_NEAR(a->s, 0.5f, 1e-5f);
    EXPECT_NEAR(a->distance, 1.0f, 1e-5f);
    // A segment beside the ray, ending short of it: its nearest end, (2, 0, 1).
    const auto b = raySegmentApproach({0, 0, 5}, {0, 0, -1}, {2, 0, 1}, {4, 0, -3}, 0, 100);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->s, 0.0f, 1e-6f);
    EXPECT_NEAR(b->t, 4.0f, 1e-5f);
    EXPECT_NEAR(b->distance, 2.0f, 1e-5f);
    // A point (a segment of length zero), and one behind the ray's start.
    const auto c = raySegmentApproach({0, 0, 5}, {0, 0, -1}, {0, 3, 1}, {0, 3, 1}, 0, 100);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->t, 4.0f, 1e-5f);
    EXPECT_NEAR(c->distance, 3.0f, 1e-5f);
    EXPECT_FALSE(raySegmentApproach({0, 0, 5}, {0, 0, -1}, {0, 3, 6}, {0, 3, 6}, 0, 100));
}

TEST(PickingLines, ALineIsPickedWithinTwoPixels) {
    // The placed line runs from (-2, 0, -2) to (2, 0, -2), 7 from the rays' start: two pixels
    // there are 0.14.
    const PreparedScene prepared = linesScene();
    const std::optional<PickHit> hit = pickMesh(prepared, ray(1.0f, 0.1f));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->objectId, kMeshIdBase);
    EXPECT_NEAR(hit->t, 7.0f, 1e-4f);
    EXPECT_FALSE(pickMesh(prepared, ray(1.0f, 0.2f)));    // three pixels off
    EXPECT_FALSE(pickMesh(prepared, ray(2.2f, 0.0f)));    // past its end
    EXPECT_TRUE(pickMesh(prepared, ray(2.1f, 0.0f)));     // within two pixels of its end
    EXPECT_FALSE(pickMesh(prepared, ray(1.0f, 0.0f, 0))); // no pixel size: never
    // An orthographic pixel of 0.05 at any distance.
    EXPECT_TRUE(pickMesh(prepared, ray(1.0f, 0.09f, 0, 0.05f)));
    EXPECT_FALSE(pickMesh(prepared, ray(1.0f, 0.11f, 0, 0.05f)));
}

TEST(PickingLines, APointIsPickedWithinTwoPixels) {
    const PreparedScene prepared = linesScene();
    EXPECT_TRUE(pickMesh(prepared, ray(0.1f, 2.05f)));
    EXPECT_FALSE(pickMesh(prepared, ray(0.1f, 2.2f)));
}

TEST(PickingLines, TheNearestOfLinesAndTrianglesWins) {
    // A square in front of the line (asset z 0.5: world -1) hides it; behind it (asset z -0.5:
    // world -3), the line is picked at its own distance.
    const std::optional<PickHit> front = pickMesh(linesScene(0.5f), ray(1.0f, 0.05f));
    ASSERT_TRUE(front);
    EXPECT_NEAR(front->t, 6.0f, 1e-4f);
    const std::optional<PickHit> behind = pickMesh(linesScene(-0.5f), ray(1.0f, 0.05f));
    ASSERT_TRUE(behind);
    EXPECT_NEAR(behind->t, 7.0f, 1e-4f);
}
