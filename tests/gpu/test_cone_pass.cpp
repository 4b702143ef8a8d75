// The cone pass (render/cone_pass.hpp, shaders/passes/cone.frag): no pixel's march starts past
// the first surface on its ray, the CPU mirror (sdfMarchCone on coneTile) finds the GPU's
// tiles, and the march pass it feeds draws the same image in fewer steps.
#include "gpu_test_support.hpp"

#include "render/frame.hpp"
#include "sdf/cpu_eval.hpp"

using namespace rmsc;
using namespace rmsc::test;

namespace {

constexpr int kWidth = 96, kHeight = 64;

// Every pixel's first surface by plain sphere tracing on the CPU from the near plane; its tile's
// start, read back from the GPU, must not lie beyond it. The tolerance (1e-4 of the distance)
// covers float differences between the GPU and the CPU.
void expectNoTileSkipsASurface(const std::string& scenePath) {
    const PreparedScene prepared = openRepositoryScene(scenePath);
    const Scene& scene = prepared.scene;
    const FrameTargets targets = renderPrepared(prepared, kWidth, kHeight);
    const Pixels<float> tiles = readConeTiles(targets); // rows top first
    const FrameCamera camera = makeFrameCamera(scene.camera, kWidth, kHeight);
    int hits = 0, skipped = 0, pastASurface = 0;
    std::string firstProblem;
    for (int y = 0; y < kHeight; ++y) { // from the bottom
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 d = pixelRayDirection(camera, float(x), float(y), kWidth, kHeight);
            const float forwardness = 1.0f / glm::length(d);
            const std::optional<SdfHit> hit =
                sdfCastRay(prepared.sdf, scene.render, camera.position, d * forwardness,
                           camera.nearPlane / forwardness, scene.render.maxDistance, 1.0f);
            const float start = *tiles.at(x / kConeTileSize, tiles.height - 1 - y / kConeTileSize);
            skipped += start > 2.0f * camera.nearPlane / forwardness;
            if (!hit) continue;
            ++hits;
            if (start > hit->t * (1.0f + 1e-4f)) {
                ++pastASurface;
                if (firstProblem.empty())
                    firstProblem = "pixel " + std::to_string(x) + "," + std::to_string(y) +
                                   " from the bottom: the tile starts at " + std::to_string(start) +
                                   ", the first surface is at " + std::to_string(hit->t);
            }
        }
    }
    EXPECT_GT(hits, kWidth * kHeight / 10) << scenePath << ": too few SDF pixels to check";
    EXPECT_GT(skipped, kWidth * kHeight / 2) << scenePath << ": the cone pass should skip";
    EXPECT_EQ(pastASurface, 0) << scenePath << ": " << firstProblem;
}

} // namespace

// Checked on exact distances (shapes, the grid), smooth blends and CSG, and on distances that
// are only bounds: the modifiers (twist, bend, displacement) and the fractals' estimates.
TEST(ConePass, NoTileStartsPastTheFirstSurfaceOfItsPixels) {
    for (const char* scene :
         {"samples/scenes/shapes.json", "samples/scenes/pawn.json", "samples/scenes/csg.json",
          "samples/scenes/smooth_blend.json", "samples/bench/grid_100.json",
          "samples/scenes/modifiers.json", "samples/scenes/fractals.json"})
        expectNoTileSkipsASurface(scene);
}

// The CPU mirror of the pass, used by the tests that compare GPU with CPU ray casts
// (marchStart), finds each tile's start within float noise.
TEST(ConePass, TheCpuMirrorFindsTheSameTiles) {
    const PreparedScene prepared = openRepositoryScene("samples/scenes/demo.json");
    const Scene& scene = prepared.scene;
    const FrameTargets targets = renderPrepared(prepared, kWidth, kHeight);
    const Pixels<float> tiles = readConeTiles(targets);
    const FrameCamera camera = makeFrameCamera(scene.camera, kWidth, kHeight);
    int differing = 0;
    std::string firstProblem;
    for (int ty = 0; ty < tiles.height; ++ty) {
        for (int tx = 0; tx < tiles.width; ++tx) {
            const ConeTile tile = coneTile(camera, tx, ty, kConeTileSize, kWidth, kHeight);
            const SdfConeMarch cpu = sdfMarchCone(prepared.sdf, scene.render, camera.position,
                                                  tile.axis, tile.chord, camera.nearPlane);
            const float gpu = *tiles.at(tx, tiles.height - 1 - ty);
            if (std::abs(gpu - cpu.distance) > 1e-3f * std::max(cpu.distance, 1.0f)) {
                ++differing;
                if (firstProblem.empty())
                    firstProblem = "tile " + std::to_string(tx) + "," + std::to_string(ty) +
                                   ": GPU " + std::to_string(gpu) + ", CPU " +
                                   std::to_string(cpu.distance);
            }
        }
    }
    EXPECT_LE(differing, tiles.width * tiles.height / 50) << firstProblem;
}

// With and without the pre-pass the march pass shows the same objects at the same depths (a hit
// may settle elsewhere in the surface's epsilon shell), and with it every pixel marches fewer
// steps, counting the tile's steps shared among its pixels.
TEST(ConePass, TheSameImageInFewerSteps) {
    const PreparedScene prepared = openRepositoryScene("samples/scenes/pawn.json");
    Renderer& renderer = sharedRenderer();
    const FrameTargets withCone = renderPrepared(prepared, kWidth, kHeight);
    renderer.setConePass(false);
    const FrameTargets without = renderPrepared(prepared, kWidth, kHeight);
    renderer.setConePass(true);

    const Pixels<std::uint32_t> ids = readObjectIds(withCone);
    const Pixels<std::uint32_t> idsWithout = readObjectIds(without);
    const Pixels<float> depths = readViewDepth(withCone);
    const Pixels<float> depthsWithout = readViewDepth(without);
    int differingIds = 0, differingDepths = 0, sdfPixels = 0;
    for (std::size_t i = 0; i < ids.data.size(); ++i) {
        sdfPixels += ids.data[i] >= kSdfIdBase;
        if (ids.data[i] != idsWithout.data[i])
            ++differingIds;
        else if (ids.data[i] >= kSdfIdBase && std::abs(depths.data[i] - depthsWithout.data[i]) >
                                                  1e-2f * std::max(depthsWithout.data[i], 1.0f))
            ++differingDepths;
    }
    EXPECT_GT(sdfPixels, kWidth * kHeight / 20);
    EXPECT_LE(differingIds, kWidth * kHeight / 200);
    EXPECT_LE(differingDepths, kWidth * kHeight / 200);
    EXPECT_TRUE(imagesMatch(readDisplayColor(withCone), readDisplayColor(without), "cone_pass_pawn",
                            {12, 0.02}));

    double steps = 0.0, stepsWithout = 0.0;
    for (float n : readMarchSteps(withCone).data)
        steps += n;
    const Pixels<float> tiles = readConeTiles(withCone);
    for (std::size_t i = 1; i < tiles.data.size(); i += 2)
        steps += tiles.data[i];
    for (float n : readMarchSteps(without).data)
        stepsWithout += n;
    const Pixels<float> tilesWithout = readConeTiles(without);
    for (std::size_t i = 0; i < tilesWithout.data.size(); ++i)
        ASSERT_EQ(tilesWithout.data[i], 0.0f) << "off, every tile starts at 0";
    EXPECT_LT(steps, 0.6 * stepsWithout);
}
