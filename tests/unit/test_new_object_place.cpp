// Where new shapes go (editor/new_object_place.hpp): on the surface the view's centre ray
// meets, resting on it, or at the fallback distance along it when it meets nothing (or nothing has
// compiled); and a node put at a world point under translated, rotated and scaled groups.
#include "editor/new_object_place.hpp"
#include "editor/scene_edits.hpp"
#include "sdf/compiler.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

// A sphere of radius 1 at (0, 0, -2), compiled.
PreparedScene sphereScene() {
    PreparedScene prepared;
    SdfNode root;
    root.isGroup = true;
    SdfNode ball = makeShape(PrimitiveId::Sphere);
    ball.params[0] = 1.0f;
    ball.transform.position = glm::vec3(0, 0, -2);
    root.children = {ball};
    prepared.scene.sdf = root;
    Diagnostics diagnostics;
    std::optional<SdfProgram> program = compileSdf(*prepared.scene.sdf, 0, "", diagnostics);
    EXPECT_TRUE(program) << diagnostics.format();
    if (program) prepared.sdf = *program;
    return prepared;
}

PickRay rayFrom(glm::vec3 origin, glm::vec3 direction) {
    PickRay ray;
    ray.origin = origin;
    ray.direction = glm::normalize(direction);
    ray.tMin = 0.05f;
    ray.tMax = 100.0f;
    return ray;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "y " << actual.y << " z " << actual.z;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "x " << actual.x << " z " << actual.z;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "x " << actual.x << " y " << actual.y;
}

} // namespace

TEST(NewObjectPlace, OnTheSurfaceUnderTheViewCentre) {
    const PreparedScene prepared = sphereScene();
    // From z = 5 down -z: the sphere's front at z = -1 (the pick settles on the surface: measured
    // within 1e-7).
    expectNear(newObjectSpot(&prepared, rayFrom({0, 0, 5}, {0, 0, -1}), 4.0f).point, {0, 0, -1},
               1e-6f);
    // From the side, at 45 degrees: where the ray meets the sphere, 1 from its centre.
    const glm::vec3 p = newObjectSpot(&prepared, rayFrom({3, 0, 1}, {-1, 0, -1}), 4.0f).point;
    EXPECT_NEAR(glm::length(p - glm::vec3(0, 0, -2)), 1.0f, 1e-6f);
    EXPECT_GT(p.x, 0.0f);
}

TEST(NewObjectPlace, AtTheFallbackDistanceWhenTheRayMeetsNothing) {
    const PreparedScene prepared = sphereScene();
    expectNear(newObjectSpot(&prepared, rayFrom({0, 5, 5}, {0, 0, -1}), 4.0f).point, {0, 5, 1},
               1e-5f);
    // No scene compiled yet: the same.
    expectNear(newObjectSpot(nullptr, rayFrom({0, 0, 5}, {0, 0, -1}), 4.0f).point, {0, 0, 1},
               1e-5f);
    // Never past the far end of the ray, nor nearer than its start.
    PickRay shortRay = rayFrom({0, 5, 5}, {0, 0, -1});
    shortRay.tMax = 2.0f;
    expectNear(newObjectSpot(&prepared, shortRay, 4.0f).point, {0, 5, 3}, 1e-5f);
    expectNear(newObjectSpot(&prepared, shortRay, 0.0f).point, {0, 5, 4.95f}, 1e-5f);
}

TEST(NewObjectPlace, ANodeUnderTransformedGroupsLandsOnTheWorldPoint) {
    Scene scene;
    SdfNode root;
    root.isGroup = true;
    SdfNode group;
    group.isGroup = true;
    group.transform.position = glm::vec3(1, 2, 3);
    group.transform.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    group.transform.scale = glm::vec3(2.0f);
    root.children = {group};
    scene.sdf = root;
    const std::vector<int> path =
        insertSdfNode(scene, Selection::sdf({0}), makeShape(PrimitiveId::Sphere));
    ASSERT_EQ(path, (std::vector<int>{0, 0}));
    const glm::vec3 world(4, -1, 0.5f);
    ASSERT_TRUE(placeSdfNodeAt(scene, path, world));
    expectNear(glm::vec3(sdfWorldMatrix(scene, path)[3]), world, 1e-5f);
    EXPECT_FALSE(placeSdfNodeAt(scene, {5}, world));
}

// The spot's normal faces the ray's origin (the sphere's, where it was met), none where nothing
// was met; a shape put there rests on the surface: its box touches it from outside, under a
// scaled group as well.
TEST(NewObjectPlace, ANewShapeRestsOnTheSurfaceItIsPutOn) {
    const PreparedScene prepared = sphereScene();
    const NewObjectSpot front = newObjectSpot(&prepared, rayFrom({0, 0, 5}, {0, 0, -1}), 4.0f);
    expectNear(front.normal, {0, 0, 1}, 1e-3f);
    const NewObjectSpot side = newObjectSpot(&prepared, rayFrom({3, 0, 1}, {-1, 0, -1}), 4.0f);
    expectNear(side.normal, glm::normalize(side.point - glm::vec3(0, 0, -2)), 1e-3f);
    EXPECT_EQ(newObjectSpot(&prepared, rayFrom({0, 5, 5}, {0, 0, -1}), 4.0f).normal,
              glm::vec3(0.0f));

    Scene scene;
    SdfNode root;
    root.isGroup = true;
    SdfNode group;
    group.isGroup = true;
    group.transform.scale = glm::vec3(2.0f);
    root.children = {group};
    scene.sdf = root;
    SdfNode ball = makeShape(PrimitiveId::Sphere);
    ball.params[0] = 0.25f;
    const std::vector<int> path = insertSdfNode(scene, Selection::sdf({0}), ball);
    // On a floor at y = 0 seen from above: the ball's centre 2 * 0.25 above it (the group
    // doubles it).
    ASSERT_TRUE(placeSdfNodeOn(scene, path, {{1, 0, 2}, {0, 1, 0}}));
    expectNear(glm::vec3(sdfWorldMatrix(scene, path)[3]), {1, 0.5f, 2}, 1e-5f);
    // No normal (nothing was met): at the point itself.
    ASSERT_TRUE(placeSdfNodeOn(scene, path, {{1, 0, 2}, glm::vec3(0.0f)}));
    expectNear(glm::vec3(sdfWorldMatrix(scene, path)[3]), {1, 0, 2}, 1e-5f);
    // An unbounded node (a plane) goes at the point too.
    const std::vector<int> plane =
        insertSdfNode(scene, Selection::sdf({0}), makeShape(PrimitiveId::Plane));
    ASSERT_TRUE(placeSdfNodeOn(scene, plane, {{0, 3, 0}, {0, 1, 0}}));
    expectNear(glm::vec3(sdfWorldMatrix(scene, plane)[3]), {0, 3, 0}, 1e-5f);
}
