// Orthographic cameras (render/frame.hpp, shaders/common/frame.glsl): a sphere seen through one
// has its analytic silhouette radius in pixels (ortho height over image height, widened by the
// march's hit threshold only) at any distance, with every pixel's view depth that of a parallel
// ray; the cone pass's cylinders
// never start a pixel past its first surface and leave the image as it is without them; and
// the CPU mirror of the cylinders finds the GPU's tiles.
#include "gpu_test_support.hpp"
#include "scene_text.hpp"

#include "core/object_ids.hpp"
#include "render/frame.hpp"
#include "sdf/cpu_eval.hpp"

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;

namespace {

constexpr int kWidth = 96, kHeight = 64;
constexpr float kEpsilon = 0.001f; // render.surface_epsilon's default

// A sphere of radius 1 at (0, 0, z), seen from (0, 0, 5) down -z by an orthographic camera 4
// units high: 16 pixels a unit, so its silhouette is a disc of radius 16 pixels about the
// image's centre whatever z is (and the hit threshold's growth with distance).
std::string sphereScene(float z) {
    return R"({"version": 1,
      "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "far": 100,
                 "projection": "orthographic", "ortho_height": 4},
      "render": {"max_distance": 100},
      "sdf": {"shape": "sphere", "radius": 1, "position": [0, 0, )" +
           std::to_string(z) + "]}}";
}

// The scene's camera made orthographic, showing at its target what it showed there.
Camera orthographic(Camera camera) {
    camera.projection = CameraProjection::Orthographic;
    camera.orthoHeight = 2.0f * glm::length(camera.target - camera.position) *
                         std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    return camera;
}

} // namespace

TEST(Orthographic, ASphereKeepsItsAnalyticSizeAtAnyDistance) {
    for (const float z : {0.0f, -30.0f}) {
        const PreparedScene prepared = prepareSceneText(sphereScene(z));
        const FrameTargets targets = renderPrepared(prepared, kWidth, kHeight);
        const Pixels<std::uint32_t> ids = readObjectIds(targets);
        const Pixels<float> depths = readViewDepth(targets);
        int covered = 0;
        double sumX = 0.0, sumY = 0.0;
        float worstDepth = 0.0f;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (*ids.at(x, y) < kSdfIdBase) continue;
                ++covered;
                sumX += x + 0.5;
                sumY += y + 0.5;
                // The parallel ray through this pixel, 1/16 unit a pixel from the centre:
                // where it meets the sphere, 5 - z - sqrt(1 - r^2) from the camera's plane. A
                // march stops within epsilon * t of the surface, which along a ray at an angle
                // acos(sqrt(1 - r^2)) to the normal is up to epsilon * t / sqrt(1 - r^2) early.
                const float dx = (float(x) + 0.5f - 48.0f) / 16.0f;
                const float dy = (float(y) + 0.5f - 32.0f) / 16.0f;
                const float r2 = dx * dx + dy * dy;
                if (r2 > 0.8f) continue; // the silhouette's grazing rays settle anywhere
                const float expected = 5.0f - z - std::sqrt(1.0f - r2);
                const float threshold = kEpsilon * (5.0f - z) / std::sqrt(1.0f - r2);
                worstDepth =
                    std::max(worstDepth, std::abs(*depths.at(x, y) - expected) / threshold);
            }
        }
        // The disc's area, pi r^2, gives its radius. A ray is a hit when it passes within the
        // hit threshold, epsilon * t (t about 5 - z at its nearest), of the sphere, so the
        // silhouette is a circle of radius 16 * (1 + epsilon * (5 - z)) pixels; pixel centres
        // inside a circle count its area to within a few pixels.
        const double radius = std::sqrt(covered / 3.14159265358979);
        const double expected = 16.0 * (1.0 + kEpsilon * (5.0 - z));
        EXPECT_NEAR(radius, expected, 0.05) << "z " << z << ": " << covered << " pixels";
        EXPECT_NEAR(sumX / covered, 48.0, 0.01) << "z " << z;
        EXPECT_NEAR(sumY / covered, 32.0, 0.01) << "z " << z;
        EXPECT_LE(worstDepth, 1.0f) << "z " << z << ": in hit thresholds";
    }
}

// The cylinders of the cone pass (the rays of an orthographic tile are parallel): no tile's
// start lies past the first surface of any of its pixels (a CPU sphere trace from the near
// plane along each pixel's own ray), and the image is the one drawn without the pass.
TEST(Orthographic, TheConePassCylindersStayConservative) {
    for (const char* path : {"samples/scenes/pawn.json", "samples/scenes/csg.json"}) {
        const PreparedScene prepared = openRepositoryScene(path);
        const Scene& scene = prepared.scene;
        const Camera camera = orthographic(scene.camera);
        Renderer& renderer = sharedRenderer();
        const FrameTargets withCone = renderPrepared(prepared, kWidth, kHeight, &camera);
        renderer.setConePass(false);
        const FrameTargets without = renderPrepared(prepared, kWidth, kHeight, &camera);
        renderer.setConePass(true);

        const Pixels<float> tiles = readConeTiles(withCone); // rows top first
        const FrameCamera frame = makeFrameCamera(camera, kWidth, kHeight);
        int hits = 0, skipped = 0, pastASurface = 0, mirrorDiffers = 0;
        for (int y = 0; y < kHeight; ++y) { // from the bottom
            for (int x = 0; x < kWidth; ++x) {
                const glm::vec3 origin = pixelRayOrigin(frame, float(x), float(y), kWidth, kHeight);
                const std::optional<SdfHit> hit =
                    sdfCastRay(prepared.sdf, scene.render, origin, frame.forward, frame.nearPlane,
                               scene.render.maxDistance, 1.0f);
                const float start =
                    *tiles.at(x / kConeTileSize, tiles.height - 1 - y / kConeTileSize);
                skipped += start > 2.0f * frame.nearPlane;
                if (hit) {
                    ++hits;
                    pastASurface += start > hit->t * (1.0f + 1e-4f);
                }
                const float cpu =
                    marchStart(prepared.sdf, scene.render, frame, x, y, kWidth, kHeight);
                mirrorDiffers +=
                    std::abs(std::max(start, frame.nearPlane) - cpu) > 1e-3f * std::max(cpu, 1.0f);
            }
        }
        EXPECT_GT(hits, kWidth * kHeight / 10) << path << ": too few SDF pixels to check";
        EXPECT_GT(skipped, kWidth * kHeight / 2) << path << ": the cone pass should skip";
        EXPECT_EQ(pastASurface, 0) << path;
        EXPECT_EQ(mirrorDiffers, 0) << path;

        const Pixels<std::uint32_t> ids = readObjectIds(withCone);
        const Pixels<std::uint32_t> idsWithout = readObjectIds(without);
        int differing = 0;
        for (std::size_t i = 0; i < ids.data.size(); ++i)
            differing += ids.data[i] != idsWithout.data[i];
        EXPECT_EQ(differing, 0) << path;
        EXPECT_TRUE(imagesMatch(readDisplayColor(withCone), readDisplayColor(without),
                                std::string("orthographic_cone_") +
                                    std::filesystem::path(path).stem().string(),
                                {12, 0.005}));
    }
}
