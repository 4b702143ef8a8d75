// Reference image of samples/scenes/lighting.json (directional, point and spot lights, shadows
// both ways, AO, gradient sky, fog, FXAA) at 256x144, compared with
// tests/reference/lighting.png: a pixel differs when a channel is off by more than 8 of 255; at
// most 0.5% of pixels may differ.
#include "gpu_test_support.hpp"

using namespace rmsc;
using namespace rmsc::test;

TEST(LightingReference, LightingSampleMatchesWithinTolerance) {
    const PreparedScene prepared = openRepositoryScene("samples/scenes/lighting.json");
    const FrameTargets targets = renderPrepared(prepared, 256, 144);
    EXPECT_TRUE(imageMatchesReference(readDisplayColor(targets), "lighting"));
}
