// The hand-written yardstick maps in bench/ (timed by `rmsc bench --sdf-map`) draw their scene
// as the generated map does: the same colours, object ids and march steps, so comparing their
// times compares the cost of the same work.
#include "gpu_test_support.hpp"

#include "render/readback.hpp"

#include <fstream>
#include <sstream>

using namespace rmsc;
using namespace rmsc::test;

namespace {

std::string readRepositoryFile(const std::string& relativePath) {
    std::ifstream in(std::string(RMSC_TEST_SOURCE_DIR) + "/" + relativePath);
    EXPECT_TRUE(in) << relativePath;
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

FrameTargets renderWithMap(const PreparedScene& prepared, const std::string* map, int width,
                           int height) {
    Renderer& renderer = sharedRenderer();
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    if (map) gpu.sdfMap = "#line 1\n" + *map; // as `rmsc bench --sdf-map` does
    std::string error;
    EXPECT_TRUE(renderer.prepare(gpu, error)) << error;
    FrameTargets targets = createFrameTargets(width, height);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, targets);
    expectNoGlErrors();
    return targets;
}

} // namespace

TEST(HandWrittenMaps, DrawTheirSceneAsTheGeneratedMapDoes) {
    const std::pair<const char*, const char*> cases[] = {
        {"samples/bench/grid_10.json", "bench/grid_10.glsl"},
        {"samples/scenes/pawn.json", "bench/pawn.glsl"}};
    for (const auto& [scenePath, mapPath] : cases) {
        SCOPED_TRACE(mapPath);
        const PreparedScene prepared = openRepositoryScene(scenePath);
        const std::string map = readRepositoryFile(mapPath);
        const int width = 160, height = 120;
        const FrameTargets generated = renderWithMap(prepared, nullptr, width, height);
        const FrameTargets hand = renderWithMap(prepared, &map, width, height);
        const std::string name =
            std::string("hand_written_") + std::filesystem::path(mapPath).stem().string();
        EXPECT_TRUE(
            imagesMatch(readDisplayColor(hand), readDisplayColor(generated), name, {2, 0.002}));

        const Pixels<std::uint32_t> idsGenerated = readObjectIds(generated);
        const Pixels<std::uint32_t> idsHand = readObjectIds(hand);
        int differingIds = 0;
        int sdfPixels = 0;
        for (std::size_t i = 0; i < idsGenerated.data.size(); ++i) {
            differingIds += idsGenerated.data[i] != idsHand.data[i];
            sdfPixels += idsGenerated.data[i] >= kSdfIdBase;
        }
        EXPECT_GT(sdfPixels, width * height / 20) << "the scene should show SDF objects";
        EXPECT_LE(differingIds, width * height / 200);

        double stepsGenerated = 0.0, stepsHand = 0.0;
        for (float n : readMarchSteps(generated).data)
            stepsGenerated += n;
        for (float n : readMarchSteps(hand).data)
            stepsHand += n;
        EXPECT_NEAR(stepsHand, stepsGenerated, 0.01 * stepsGenerated);
    }
}
