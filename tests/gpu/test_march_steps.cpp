// The steps AOV: the march pass records each pixel's sphere-tracing steps (what the heatmap and
// `rmsc bench` show).
#include "gpu_test_support.hpp"

#include "render/readback.hpp"

using namespace rmsc;
using namespace rmsc::test;

TEST(MarchSteps, HitsTakeStepsWithinTheBudget) {
    const PreparedScene prepared = openRepositoryScene("samples/scenes/csg.json");
    const FrameTargets targets = renderPrepared(prepared, 96, 54);
    const Pixels<float> steps = readMarchSteps(targets);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);
    const float budget = float(prepared.scene.render.maxSteps);
    int sdfPixels = 0;
    for (std::size_t i = 0; i < steps.data.size(); ++i) {
        EXPECT_GE(steps.data[i], 0.0f);
        EXPECT_LE(steps.data[i], budget);
        if (ids.data[i] >= kSdfIdBase) {
            ++sdfPixels;
            EXPECT_GE(steps.data[i], 1.0f) << "an SDF hit takes at least one step";
        }
    }
    EXPECT_GT(sdfPixels, 100);
}

TEST(MarchSteps, ASceneWithoutSdfMarchesNothing) {
    PreparedScene prepared = openRepositoryScene("samples/scenes/gltf_instances.json");
    prepared.sdf = SdfProgram{}; // the meshes only
    const FrameTargets targets = renderPrepared(prepared, 64, 36);
    for (float n : readMarchSteps(targets).data)
        ASSERT_EQ(n, 0.0f);
}
