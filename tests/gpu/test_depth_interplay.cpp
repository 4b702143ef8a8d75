// Meshes and SDF objects share one depth: checked where the answer is known analytically.
#include "gpu_test_support.hpp"

#include "render/frame.hpp"

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// A glTF quad (plane.gltf, 2x2, scaled by `quadScale`) at height `quadY` cutting an SDF sphere
// of radius `radius` at the origin, seen straight from above.
PreparedScene quadCuttingSphere(float quadY, float quadScale, float radius, Camera camera) {
    Scene scene;
    scene.file = std::filesystem::path(RMSC_TEST_SOURCE_DIR) / "tests" / "scene.json";
    scene.camera = camera;
    MeshInstance quad;
    quad.name = "quad";
    quad.file = "plane.gltf";
    quad.path = std::filesystem::path(RMSC_TEST_SOURCE_DIR) / "samples/assets/plane.gltf";
    quad.transform.position = {0.0f, quadY, 0.0f};
    quad.transform.scale = glm::vec3(quadScale);
    quad.pointer = "/meshes/0";
    scene.meshes.push_back(quad);
    SdfNode sphere;
    sphere.pointer = "/sdf";
    sphere.primitive = PrimitiveId::Sphere;
    sphere.params = defaultParams(primitiveSpec(PrimitiveId::Sphere));
    sphere.params[0] = radius;
    scene.sdf = sphere;
    Diagnostics diagnostics;
    std::optional<PreparedScene> prepared =
        prepareScene(std::move(scene), diskFileSource(), diagnostics);
    EXPECT_TRUE(prepared) << diagnostics.format();
    return std::move(*prepared);
}

Camera lookingDown(float height) {
    Camera camera;
    camera.position = {0.0f, height, 0.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 0.0f, -1.0f};
    camera.fovYDegrees = 50.0f;
    return camera;
}

} // namespace

// From straight above, the sphere's cap over the quad ends exactly on the circle where the
// sphere meets the quad's plane: radius sqrt(r^2 - y^2). Every pixel whose centre ray crosses the
// plane inside that circle must show the sphere, outside it the quad; only pixels within one
// pixel of the analytic circle may go either way.
TEST(DepthInterplay, QuadCuttingSphereShowsTheAnalyticCircle) {
    const float quadY = 0.3f, radius = 0.8f;
    const int size = 160;
    const Camera camera = lookingDown(3.0f);
    const PreparedScene prepared = quadCuttingSphere(quadY, 1.5f, radius, camera);
    const FrameTargets targets = renderPrepared(prepared, size, size);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);

    const FrameCamera frame = makeFrameCamera(camera, size, size);
    const float circle = std::sqrt(radius * radius - quadY * quadY);
    // Expected distance (in plane units) of a pixel centre's plane point from the circle.
    auto planePoint = [&](float x, float y) {
        const glm::vec3 d = pixelRayDirection(frame, x, y, size, size);
        const float t = (quadY - camera.position.y) / d.y;
        return glm::vec2(camera.position.x + t * d.x, camera.position.z + t * d.z);
    };
    // One pixel's footprint on the plane.
    const float pixelSize = glm::length(planePoint(size / 2.0f + 1.0f, size / 2.0f) -
                                        planePoint(size / 2.0f, size / 2.0f));
    int sphere = 0, quad = 0, boundary = 0, wrong = 0;
    for (int row = 0; row < size; ++row) {
        for (int x = 0; x < size; ++x) {
            const int yFromBottom = size - 1 - row;
            const glm::vec2 p = planePoint(float(x), float(yFromBottom));
            if (std::abs(p.x) > 1.5f - pixelSize || std::abs(p.y) > 1.5f - pixelSize) continue;
            const float signedDistance = glm::length(p) - circle;
            const std::uint32_t id = *ids.at(x, row);
            const std::uint32_t expected = signedDistance < 0.0f ? kSdfIdBase : kMeshIdBase;
            if (std::abs(signedDistance) <= pixelSize) {
                ++boundary;
                EXPECT_TRUE(id == kSdfIdBase || id == kMeshIdBase) << x << "," << row;
                continue;
            }
            (expected == kSdfIdBase ? sphere : quad) += 1;
            if (id != expected) {
                ++wrong;
                ADD_FAILURE() << "pixel " << x << "," << row << " shows object " << id
                              << ", expected " << expected << " (" << signedDistance / pixelSize
                              << " pixels from the circle)";
                if (wrong > 10) return;
            }
        }
    }
    EXPECT_GT(sphere, 1000);
    EXPECT_GT(quad, 1000);
    EXPECT_GT(boundary, 100);
}

// The same scene from the side: where the quad is in front of the sphere's lower half the quad
// wins; where the cap rises above the quad the sphere wins. Checked through both orders along
// one ray each, with depths compared to the analytic intersections.
TEST(DepthInterplay, NearerObjectWinsInBothOrders) {
    Camera camera;
    camera.position = {0.0f, 0.0f, 4.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.fovYDegrees = 40.0f;
    const int size = 101; // odd, so the centre pixel's ray is the view axis

    // Mesh in front: a quad standing at z = 1.5 (rotated to face the camera) hides the sphere.
    for (const float quadZ : {1.5f, -1.5f}) {
        PreparedScene prepared = quadCuttingSphere(0.0f, 0.5f, 0.8f, camera);
        prepared.scene.meshes[0].transform.position = {0.0f, 0.0f, quadZ};
        prepared.scene.meshes[0].transform.rotation =
            glm::angleAxis(glm::radians(90.0f), glm::vec3(1, 0, 0));
        const FrameTargets targets = renderPrepared(prepared, size, size);
        const std::uint32_t id = *readObjectIds(targets).at(size / 2, size / 2);
        const float depth = *readViewDepth(targets).at(size / 2, size / 2);
        if (quadZ > 0.0f) {
            EXPECT_EQ(id, kMeshIdBase) << "the mesh in front must hide the SDF sphere";
            EXPECT_NEAR(depth, 4.0f - quadZ, 1e-3f);
        } else {
            EXPECT_EQ(id, kSdfIdBase) << "the SDF sphere in front must hide the mesh";
            EXPECT_NEAR(depth, 4.0f - 0.8f, 2e-3f);
        }
    }
}
