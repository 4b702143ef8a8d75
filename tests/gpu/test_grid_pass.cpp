// The grid pass (render/grid_pass.hpp): lines land where the plane y = 0 has them, the axes in
// their colours; objects in front hide it; it changes the colour only, never depth, normals or
// ids.
#include "gpu_test_support.hpp"

#include "render/frame.hpp"

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// An SDF ball of radius 0.5 at (0, 1, 0), seen straight down from (0, 5, 0) with -z up the image.
PreparedScene ballAboveTheGround(Camera& camera) {
    Scene scene;
    scene.file = std::filesystem::path(RMSC_TEST_SOURCE_DIR) / "tests" / "scene.json";
    camera.position = {0.0f, 5.0f, 0.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 0.0f, -1.0f};
    camera.fovYDegrees = 50.0f;
    scene.camera = camera;
    SdfNode ball;
    ball.pointer = "/sdf";
    ball.primitive = PrimitiveId::Sphere;
    ball.params = defaultParams(primitiveSpec(PrimitiveId::Sphere));
    ball.params[0] = 0.5f;
    ball.transform.position = {0.0f, 1.0f, 0.0f};
    scene.sdf = ball;
    Diagnostics diagnostics;
    std::optional<PreparedScene> prepared =
        prepareScene(std::move(scene), diskFileSource(), diagnostics);
    EXPECT_TRUE(prepared) << diagnostics.format();
    return std::move(*prepared);
}

// Turns the shared renderer's grid on for one scope.
struct GridOn {
    GridOn() { sharedRenderer().setGroundGrid(true); }
    ~GridOn() { sharedRenderer().setGroundGrid(false); }
};

} // namespace

TEST(GridPass, LinesAxesAndOcclusionWhereThePlaneHasThem) {
    const int size = 160;
    Camera camera;
    const PreparedScene prepared = ballAboveTheGround(camera);
    const FrameTargets plain = renderPrepared(prepared, size, size);
    const Pixels<float> plainColor = readHdrColor(plain);
    const Pixels<std::uint32_t> plainIds = readObjectIds(plain);
    const Pixels<float> plainDepth = readViewDepth(plain);
    const Pixels<float> plainNormals = readNormals(plain);

    Pixels<float> gridColor;
    {
        GridOn on;
        const FrameTargets withGrid = renderPrepared(prepared, size, size);
        gridColor = readHdrColor(withGrid);
        // Colour only: every other attachment is exactly the scene's.
        EXPECT_EQ(readObjectIds(withGrid).data, plainIds.data);
        EXPECT_EQ(readViewDepth(withGrid).data, plainDepth.data);
        EXPECT_EQ(readNormals(withGrid).data, plainNormals.data);
    }
    expectNoGlErrors();

    const FrameCamera frame = makeFrameCamera(camera, size, size);
    auto planePoint = [&](int x, int yFromBottom) {
        const glm::vec3 d = pixelRayDirection(frame, float(x), float(yFromBottom), size, size);
        const float t = -camera.position.y / d.y;
        return glm::vec2(camera.position.x + t * d.x, camera.position.z + t * d.z);
    };
    // The bounds below sit just under what llvmpipe gives (the axes, half a pixel off their
    // centres at half coverage: 0.222 added, 0.144 over the other colour; unit lines at least
    // 0.066; between lines exactly nothing); the shader's own numbers give the same.
    const float pixel =
        glm::length(planePoint(size / 2 + 1, size / 2) - planePoint(size / 2, size / 2));
    int onBall = 0, red = 0, blue = 0, unitLines = 0, clear = 0;
    for (int row = 0; row < size; ++row) {
        for (int x = 0; x < size; ++x) {
            const glm::vec2 p = planePoint(x, size - 1 - row);
            const float* before = plainColor.at(x, row);
            const float* after = gridColor.at(x, row);
            const glm::vec3 added(after[0] - before[0], after[1] - before[1], after[2] - before[2]);
            if (*plainIds.at(x, row) != 0) { // the ball hides the grid
                ++onBall;
                EXPECT_EQ(added, glm::vec3(0.0f)) << x << "," << row;
                continue;
            }
            const glm::vec2 toLine =
                glm::abs(glm::fract(p - 0.5f) - 0.5f); // to the nearest unit line
            if (std::abs(p.y) < 0.55f * pixel && std::abs(p.x) > 3.0f * pixel) {
                ++red; // on the x axis (z = 0)
                EXPECT_GT(added.x, 0.2f) << x << "," << row;
                EXPECT_GT(added.x, added.z + 0.12f) << x << "," << row;
            } else if (std::abs(p.x) < 0.55f * pixel && std::abs(p.y) > 3.0f * pixel) {
                ++blue; // on the z axis (x = 0)
                EXPECT_GT(added.z, 0.2f) << x << "," << row;
                EXPECT_GT(added.z, added.x + 0.12f) << x << "," << row;
            } else if (toLine.x < 0.25f * pixel && toLine.y > 3.0f * pixel &&
                       std::abs(p.x) > 0.5f) {
                ++unitLines; // on a line x = +-1, +-2
                EXPECT_GT(added.y, 0.05f) << x << "," << row;
            } else if (toLine.x > 3.0f * pixel && toLine.y > 3.0f * pixel) {
                ++clear; // between lines: untouched
                EXPECT_EQ(added, glm::vec3(0.0f)) << x << "," << row;
            }
        }
    }
    EXPECT_GT(onBall, 500);
    EXPECT_GT(red, 20);
    EXPECT_GT(blue, 20);
    EXPECT_GT(unitLines, 20);
    EXPECT_GT(clear, 10000);
}

TEST(GridPass, OffByDefault) {
    Camera camera;
    const PreparedScene prepared = ballAboveTheGround(camera);
    const FrameTargets a = renderPrepared(prepared, 64, 64);
    const Pixels<float> first = readHdrColor(a);
    { GridOn on; }
    const Pixels<float> second = readHdrColor(renderPrepared(prepared, 64, 64));
    EXPECT_EQ(first.data, second.data);
    // And on, the same frame differs (the axes cross the view).
    GridOn on;
    EXPECT_NE(readHdrColor(renderPrepared(prepared, 64, 64)).data, first.data);
}
