// The light gizmo pass (render/light_gizmo_pass.hpp): a light's marker circle lands around its
// projected position and keeps its size in pixels at any distance; a point light has rays
// around it, a spot light its cone and a directional light its line along the direction; the
// selected light is drawn in the selection colour; a light behind the camera draws nothing.
#include "gpu_test_support.hpp"

#include "render/frame.hpp"
#include "render/light_gizmo_pass.hpp"
#include "render/shader_library.hpp"

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;

namespace {

constexpr int kSize = 96;

const LightGizmoPass& gizmoPass() {
    static const std::optional<LightGizmoPass> pass = [] {
        sharedRenderer(); // the shared context
        std::string error;
        std::optional<LightGizmoPass> built = LightGizmoPass::create(embeddedShaderFiles(), error);
        EXPECT_TRUE(built) << error;
        return built;
    }();
    return *pass;
}

// The gizmos of `lights` seen from `eye` towards the origin, over black; top row first.
Pixels<std::uint8_t> drawGizmos(const std::vector<Light>& lights, int selected, glm::vec3 eye) {
    const LightGizmoPass& pass = gizmoPass(); // first: it makes the shared context
    Camera camera;
    camera.position = eye;
    camera.target = glm::vec3(0.0f);
    camera.fovYDegrees = 45.0f;
    FrameTargets targets = createFrameTargets(kSize, kSize);
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(targets.display.framebuffer.id(), GL_COLOR, 0, black);
    const FrameCamera frame = makeFrameCamera(camera, kSize, kSize);
    pass.draw({targets.display.framebuffer.id(), 0, 0, kSize, kSize}, frame.viewProjection, lights,
              selected);
    expectNoGlErrors();
    return readDisplayColor(targets);
}

int brightness(const Pixels<std::uint8_t>& image, int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return std::max({int(p[0]), int(p[1]), int(p[2])});
}

// The largest brightness of the pixels at distance [r0, r1] from the centre (kSize / 2).
int brightestInRing(const Pixels<std::uint8_t>& image, float r0, float r1) {
    int best = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float r = std::hypot(x + 0.5f - kSize / 2.0f, y + 0.5f - kSize / 2.0f);
            if (r >= r0 && r <= r1) best = std::max(best, brightness(image, x, y));
        }
    return best;
}

Light lightOfType(LightType type) {
    Light light;
    light.type = type;
    light.position = glm::vec3(0.0f);
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    return light;
}

} // namespace

TEST(LightGizmoPass, MarkerCircleKeepsItsSizeOnScreen) {
    const float r = kLightMarkerRadiusPixels;
    for (const float distance : {3.0f, 12.0f}) {
        SCOPED_TRACE(distance);
        const Pixels<std::uint8_t> image =
            drawGizmos({lightOfType(LightType::Point)}, -1, glm::vec3(0, 0, distance));
        EXPECT_GT(brightestInRing(image, r - 1.0f, r + 1.0f), 200); // the circle
        EXPECT_EQ(brightestInRing(image, 0.0f, r - 2.0f), 0);       // hollow
        EXPECT_GT(brightestInRing(image, r + 4.0f, r + 6.0f), 100); // the point light's rays
        EXPECT_EQ(brightestInRing(image, r + 9.0f, 1e9f), 0);       // nothing farther out
    }
}

TEST(LightGizmoPass, SpotConeAndDirectionalLineFollowTheDirection) {
    for (const LightType type : {LightType::Spot, LightType::Directional}) {
        SCOPED_TRACE(int(type));
        const Pixels<std::uint8_t> image = drawGizmos({lightOfType(type)}, -1, glm::vec3(0, 0, 5));
        // Pointing down: lines below the marker (rows below the centre, top row first), none
        // above it past the circle.
        int below = 0, above = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                if (brightness(image, x, y) == 0) continue;
                if (y > kSize / 2 + 12) ++below;
                if (y < kSize / 2 - 12) ++above;
            }
        EXPECT_GT(below, 10);
        EXPECT_EQ(above, 0);
        // A point light (no direction) has nothing that far below.
    }
    const Pixels<std::uint8_t> point =
        drawGizmos({lightOfType(LightType::Point)}, -1, glm::vec3(0, 0, 5));
    for (int y = kSize / 2 + 20; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            ASSERT_EQ(brightness(point, x, y), 0) << x << ", " << y;
}

TEST(LightGizmoPass, SelectedLightInTheSelectionColour) {
    Light warm = lightOfType(LightType::Point);
    warm.color = glm::vec3(0.2f, 0.2f, 1.0f); // blue: tinted, never the selection's orange
    auto ringColour = [](const Pixels<std::uint8_t>& image) {
        const int x = kSize / 2 + int(kLightMarkerRadiusPixels), y = kSize / 2;
        for (int dx = -1; dx <= 1; ++dx)
            if (brightness(image, x + dx, y) > 0)
                return glm::ivec3(image.at(x + dx, y)[0], image.at(x + dx, y)[1],
                                  image.at(x + dx, y)[2]);
        return glm::ivec3(0);
    };
    const glm::ivec3 plain = ringColour(drawGizmos({warm}, -1, glm::vec3(0, 0, 5)));
    const glm::ivec3 selected = ringColour(drawGizmos({warm}, 0, glm::vec3(0, 0, 5)));
    EXPECT_GT(plain.z, plain.x); // the light's own hue
    EXPECT_GT(selected.x, selected.y);
    EXPECT_GT(selected.y, selected.z);
    EXPECT_GT(selected.x, 200);
}

TEST(LightGizmoPass, NothingForALightBehindTheCamera) {
    Light light = lightOfType(LightType::Point);
    light.position = glm::vec3(0, 0, 10); // the camera at z = 5 looks towards -z
    const Pixels<std::uint8_t> image = drawGizmos({light}, -1, glm::vec3(0, 0, 5));
    EXPECT_EQ(brightestInRing(image, 0.0f, 1e9f), 0);
}
