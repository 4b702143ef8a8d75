// Picking by CPU ray casts (editor/picking.hpp, editor/ray_triangle.hpp): small scenes built in
// code, with a ray whose answer is known: an SDF shape in front of a mesh, a mesh in front of an
// SDF shape, a miss, and rotated / translated nodes and instances.
#include "editor/picking.hpp"
#include "editor/ray_triangle.hpp"
#include "editor/scene_edits.hpp"
#include "sdf/compiler.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

// A square of side 2 in the asset's xy plane, centred on the origin: two triangles.
MeshAsset squareAsset() {
    MeshAsset asset;
    MeshPrimitive square;
    for (glm::vec2 corner :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        MeshVertex v{};
        v.position = glm::vec3(corner, 0.0f);
        v.normal = glm::vec3(0, 0, 1);
        square.vertices.push_back(v);
    }
    square.indices = {0, 1, 2, 0, 2, 3};
    asset.primitives.push_back(square);
    asset.boundsMin = glm::vec3(-1, -1, 0);
    asset.boundsMax = glm::vec3(1, 1, 0);
    return asset;
}

// Scene: root union { ball: sphere r 0.5 at the origin, bar: box half extents (1, 0.1, 0.1) at
// (0, 0, -1), shifted: union at (3, 0, 0) { small: sphere r 0.3 } }, and one square mesh
// instance placed by `square`.
PreparedScene makeScene(const Transform& square) {
    PreparedScene prepared;
    Scene& scene = prepared.scene;
    SdfNode root;
    root.isGroup = true;
    SdfNode ball = makeShape(PrimitiveId::Sphere);
    ball.params[0] = 0.5f;
    SdfNode bar = makeShape(PrimitiveId::Box);
    bar.params[0] = 1.0f;
    bar.params[1] = 0.1f;
    bar.params[2] = 0.1f;
    bar.transform.position = glm::vec3(0, 0, -1);
    SdfNode shifted;
    shifted.isGroup = true;
    shifted.transform.position = glm::vec3(3, 0, 0);
    SdfNode small = makeShape(PrimitiveId::Sphere);
    small.params[0] = 0.3f;
    shifted.children.push_back(small);
    root.children = {ball, bar, shifted};
    scene.sdf = root;
    MeshInstance instance;
    instance.name = "square";
    instance.transform = square;
    scene.meshes.push_back(instance);
    prepared.assets.push_back(squareAsset());
    prepared.instanceAsset.push_back(0);
    return prepared;
}

void compile(PreparedScene& prepared) {
    Diagnostics diagnostics;
    std::optional<SdfProgram> program = compileSdf(*prepared.scene.sdf, 0, "", diagnostics);
    ASSERT_TRUE(program) << diagnostics.format();
    prepared.sdf = *program;
}

Transform at(glm::vec3 position) {
    Transform t;
    t.position = position;
    return t;
}

// Straight down -z from z = 5 through (x, y).
PickRay rayDownZ(float x, float y) {
    PickRay ray;
    ray.origin = glm::vec3(x, y, 5.0f);
    ray.direction = glm::vec3(0, 0, -1);
    ray.tMin = 0.05f;
    ray.tMax = 100.0f;
    return ray;
}

} // namespace

TEST(RayTriangle, HitsInsideFromBothSidesAndMissesOutside) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    const std::optional<float> front = rayTriangle({0.25f, 0.25f, 2}, {0, 0, -1}, a, b, c, 0, 10);
    ASSERT_TRUE(front);
    EXPECT_NEAR(*front, 2.0f, 1e-6f);
    const std::optional<float> back = rayTriangle({0.25f, 0.25f, -3}, {0, 0, 1}, a, b, c, 0, 10);
    ASSERT_TRUE(back);
    EXPECT_NEAR(*back, 3.0f, 1e-6f);
    // Beyond the hypotenuse (u + v > 1), beside an edge, parallel, behind the origin, too far.
    EXPECT_FALSE(rayTriangle({0.6f, 0.6f, 2}, {0, 0, -1}, a, b, c, 0, 10));
    EXPECT_FALSE(rayTriangle({-0.1f, 0.5f, 2}, {0, 0, -1}, a, b, c, 0, 10));
    EXPECT_FALSE(rayTriangle({0.25f, 0.25f, 2}, {1, 0, 0}, a, b, c, 0, 10));
    EXPECT_FALSE(rayTriangle({0.25f, 0.25f, 2}, {0, 0, 1}, a, b, c, 0, 10));
    EXPECT_FALSE(rayTriangle({0.25f, 0.25f, 2}, {0, 0, -1}, a, b, c, 0, 1.5f));
    // An unnormalized direction: t is in its units.
    const std::optional<float> scaled = rayTriangle({0.25f, 0.25f, 2}, {0, 0, -4}, a, b, c, 0, 10);
    ASSERT_TRUE(scaled);
    EXPECT_NEAR(*scaled, 0.5f, 1e-6f);
}

TEST(RayTriangle, BoxSlabs) {
    EXPECT_TRUE(rayHitsBox({0, 0, 5}, {0, 0, -1}, glm::vec3(-1), glm::vec3(1), 0, 10));
    EXPECT_FALSE(rayHitsBox({2, 0, 5}, {0, 0, -1}, glm::vec3(-1), glm::vec3(1), 0, 10));
    EXPECT_FALSE(rayHitsBox({0, 0, 5}, {0, 0, -1}, glm::vec3(-1), glm::vec3(1), 0, 3.5f));
    EXPECT_TRUE(rayHitsBox({5, 5, 5}, {-1, -1, -1}, glm::vec3(-1), glm::vec3(1), 0, 10));
    // A flat box (a square's bounds) is still hit head-on.
    EXPECT_TRUE(rayHitsBox({0, 0, 5}, {0, 0, -1}, {-1, -1, 0}, {1, 1, 0}, 0, 10));
}

TEST(Picking, SdfInFrontOfAMesh) {
    PreparedScene prepared = makeScene(at({0, 0, -3}));
    compile(prepared);
    const std::optional<PickHit> hit = pick(prepared, rayDownZ(0, 0));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->selection, Selection::sdf({0})); // the ball, its front at z = 0.5
    EXPECT_EQ(hit->objectId, kSdfIdBase + 1);
    EXPECT_NEAR(hit->t, 4.5f, 0.01f);
    // The mesh behind it is hit by the mesh test alone.
    const std::optional<PickHit> mesh = pickMesh(prepared, rayDownZ(0, 0));
    ASSERT_TRUE(mesh);
    EXPECT_EQ(mesh->selection, Selection::mesh(0));
    EXPECT_NEAR(mesh->t, 8.0f, 1e-4f);
}

TEST(Picking, MeshInFrontOfSdf) {
    PreparedScene prepared = makeScene(at({0, 0, 2}));
    compile(prepared);
    const std::optional<PickHit> hit = pick(prepared, rayDownZ(0.2f, 0.1f));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->selection, Selection::mesh(0));
    EXPECT_EQ(hit->objectId, kMeshIdBase);
    EXPECT_NEAR(hit->t, 3.0f, 1e-4f);
}

TEST(Picking, MissesWhenNothingIsOnTheRay) {
    PreparedScene prepared = makeScene(at({0, 0, -3}));
    compile(prepared);
    EXPECT_FALSE(pick(prepared, rayDownZ(1.6f, 1.6f))); // outside the square and every shape
    // Looking away from everything.
    PickRay away = rayDownZ(0, 0);
    away.direction = glm::vec3(0, 0, 1);
    EXPECT_FALSE(pick(prepared, away));
    // A far plane before the first surface.
    PickRay shortRay = rayDownZ(0, 0);
    shortRay.tMax = 4.0f;
    EXPECT_FALSE(pick(prepared, shortRay));
}

TEST(Picking, ChildOfATranslatedGroupAndAShapeBehindAnother) {
    PreparedScene prepared = makeScene(at({0, 0, -30}));
    compile(prepared);
    // The small sphere lives in a group moved to x = 3.
    const std::optional<PickHit> small = pick(prepared, rayDownZ(3.0f, 0.0f));
    ASSERT_TRUE(small);
    EXPECT_EQ(small->selection, Selection::sdf({2, 0}));
    EXPECT_NEAR(small->t, 4.7f, 0.01f);
    // The bar (x up to 1, behind the ball) is seen beside the ball.
    const std::optional<PickHit> bar = pick(prepared, rayDownZ(0.8f, 0.0f));
    ASSERT_TRUE(bar);
    EXPECT_EQ(bar->selection, Selection::sdf({1}));
    EXPECT_NEAR(bar->t, 5.9f, 0.01f);
}

TEST(Picking, RotatedNodeAndRotatedInstance) {
    // The bar turned 90 degrees about z stands along y: now hit above the ball, no longer beside.
    PreparedScene prepared = makeScene(at({0, 0, -30}));
    findSdfNode(prepared.scene, {1})->transform.rotation =
        glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    compile(prepared);
    const std::optional<PickHit> above = pick(prepared, rayDownZ(0.0f, 0.8f));
    ASSERT_TRUE(above);
    EXPECT_EQ(above->selection, Selection::sdf({1}));
    EXPECT_FALSE(pickSdf(prepared, rayDownZ(0.8f, 0.0f)));

    // The square turned 90 degrees about y lies in the yz plane: edge-on to a ray along -z,
    // face-on to a ray along -x. Scaled by 2, it reaches y = 2.
    Transform turned = at({0, 0, -3});
    turned.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    turned.scale = glm::vec3(2.0f);
    prepared.scene.meshes[0].transform = turned;
    EXPECT_FALSE(pickMesh(prepared, rayDownZ(0.5f, 1.5f)));
    PickRay sideways;
    sideways.origin = glm::vec3(5, 1.5f, -3.5f);
    sideways.direction = glm::vec3(-1, 0, 0);
    const std::optional<PickHit> side = pick(prepared, sideways);
    ASSERT_TRUE(side);
    EXPECT_EQ(side->selection, Selection::mesh(0));
    EXPECT_NEAR(side->t, 5.0f, 1e-4f);
    sideways.origin.y = 2.5f; // above the scaled square
    EXPECT_FALSE(pickMesh(prepared, sideways));
}

TEST(Picking, SecondInstanceOfTheSameAssetIsNamedByItsIndex) {
    PreparedScene prepared = makeScene(at({0, 0, -3}));
    MeshInstance second = prepared.scene.meshes[0];
    second.transform = at({10, 0, 0});
    prepared.scene.meshes.push_back(second);
    prepared.instanceAsset.push_back(0);
    compile(prepared);
    const std::optional<PickHit> hit = pick(prepared, rayDownZ(10.5f, 0.5f));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->selection, Selection::mesh(1));
    EXPECT_EQ(hit->objectId, kMeshIdBase + 1);
}

// A shell marches on its own: picking finds its nodes through their own program and frame, in
// front of and behind the fullscreen shapes.
TEST(Picking, ShellsArePickedInTheirOwnFrame) {
    PreparedScene prepared = makeScene(at({0, 0, -30}));
    SdfNode& shifted = prepared.scene.sdf->children[2];
    shifted.transform.scale = glm::vec3(2.0f); // the small sphere: radius 0.6 at x = 3
    shifted.shell = SdfShell{};
    Diagnostics diagnostics;
    std::optional<CompiledSdfScene> split =
        compileSdfScene(*prepared.scene.sdf, 0, "", diagnostics);
    ASSERT_TRUE(split) << diagnostics.format();
    ASSERT_EQ(split->shells.size(), 1u);
    prepared.sdf = split->main;
    PreparedShell shell;
    shell.compiled = split->shells[0];
    shell.clipMin = glm::vec3(-1.0f);
    shell.clipMax = glm::vec3(1.0f);
    prepared.shells.push_back(shell);

    const std::optional<PickHit> small = pick(prepared, rayDownZ(3.0f, 0.0f));
    ASSERT_TRUE(small);
    EXPECT_EQ(small->selection, Selection::sdf({2, 0}));
    EXPECT_NEAR(small->t, 4.4f, 0.01f);
    // The ball is still the fullscreen pass's.
    const std::optional<PickHit> ball = pick(prepared, rayDownZ(0.0f, 0.0f));
    ASSERT_TRUE(ball);
    EXPECT_EQ(ball->selection, Selection::sdf({0}));
    // Clipped by the shell's bound: a box that cuts the sphere at y = 0.3 (object 0.15).
    prepared.shells[0].clipMax.y = 0.15f;
    EXPECT_FALSE(pick(prepared, rayDownZ(3.0f, 0.5f)));
}
