// Where new shapes go (editor/new_object_place.hpp): on the surface the view's centre ray
// meets, or at the fallback distance along it when it meets nothing (or nothing has compiled);
// and a node put at a world point under translated, rotated and scaled groups.
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
    expectNear(newObjectPoint(&prepared, rayFrom({0, 0, 5}, {0, 0, -1}), 4.0f), {0, 0, -1}, 1e-6f);
    // From the side, at 45 degrees: where the ray meets the sphere, 1 from its centre.
    const glm::vec3 p = newObjectPoint(&prepared, rayFrom({3, 0, 1}, {-1, 0, -1}), 4.0f);
    EXPECT_NEAR(glm::length(p - glm::vec3(0, 0, -2)), 1.0f, 1e-6f);
    EXPECT_GT(p.x, 0.0f);
}

TEST(NewObjectPlace, AtTheFallbackDistanceWhenTheRayMeetsNothing) {
    const PreparedScene prepared = sphereScene();
    expectNear(newObjectPoint(&prepared, rayFrom({0, 5, 5}, {0, 0, -1}), 4.0f), {0, 5, 1}, 1e-5f);
    // No scene compiled yet: the same.
    expectNear(newObjectPoint(nullptr, rayFrom({0, 0, 5}, {0, 0, -1}), 4.0f), {0, 0, 1}, 1e-5f);
    // Never past the far end of the ray, nor nearer than its start.
    PickRay shortRay = rayFrom({0, 5, 5}, {0, 0, -1});
    shortRay.tMax = 2.0f;
    expectNear(newObjectPoint(&prepared, shortRay, 4.0f), {0, 5, 3}, 1e-5f);
    expectNear(newObjectPoint(&prepared, shortRay, 0.0f), {0, 5, 4.95f}, 1e-5f);
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
