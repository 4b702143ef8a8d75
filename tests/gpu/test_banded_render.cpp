// Rendering a frame in bands of rows (RenderRows, what the viewer's progressive refinement does)
// gives the same image as rendering it whole: every pass but the shadows is limited to the band,
// the shadow maps may be kept from the render before, and the post pass (FXAA reads neighbours)
// lags the band so it reads finished rows only.
#include "gpu_test_support.hpp"

#include <algorithm>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// Renders `prepared` at width x height in bands of `bandRows`, the post pass `lag` rows behind,
// after a render of the previous view (of `staleScene` when given); `keepShadowMaps`: the bands
// use the shadow maps that render drew.
Pixels<std::uint8_t> renderInBands(const PreparedScene& prepared, const RenderSettings& settings,
                                   int width, int height, int bandRows, int lag,
                                   bool keepShadowMaps = false,
                                   const GpuScene* staleScene = nullptr) {
    Renderer& renderer = sharedRenderer();
    const GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    FrameTargets targets = createFrameTargets(width, height);
    // Stale content first, as the viewer's image holds the previous view.
    Camera away = prepared.scene.camera;
    away.position += glm::vec3(0.7f, 0.4f, 0.0f);
    renderer.render(staleScene ? *staleScene : gpu, away, settings, targets);
    int post = 0;
    for (int begin = 0; begin < height; begin += bandRows) {
        const int end = std::min(height, begin + bandRows);
        const int postEnd = end == height ? height : std::max(post, end - lag);
        const RenderRows rows{begin, end, post, postEnd, keepShadowMaps};
        renderer.render(gpu, prepared.scene.camera, settings, targets, &rows);
        post = postEnd;
    }
    expectNoGlErrors();
    return readDisplayColor(targets);
}

} // namespace

TEST(BandedRender, EqualsTheWholeFrameWithFxaaAndMeshes) {
    // The demo: SDF shapes over a glTF mesh, shadows, AO; FXAA on.
    const PreparedScene prepared = openRepositoryScene("samples/scenes/demo.json");
    RenderSettings settings = prepared.scene.render;
    settings.fxaa = true;
    const int width = 96, height = 72;
    Renderer& renderer = sharedRenderer();
    const GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    FrameTargets whole = createFrameTargets(width, height);
    renderer.render(gpu, prepared.scene.camera, settings, whole);
    const Pixels<std::uint8_t> expected = readDisplayColor(whole);
    // Measured: identical (every channel of every pixel) for bands of 8 and 24 rows.
    const ImageTolerance exact{0, 0.0};
    EXPECT_TRUE(imagesMatch(renderInBands(prepared, settings, width, height, 8, 16), expected,
                            "banded_render_8", exact));
    EXPECT_TRUE(imagesMatch(renderInBands(prepared, settings, width, height, 24, 16), expected,
                            "banded_render_24", exact));
    // The bands may keep the shadow maps the render before them drew for the same scene (the
    // viewer's refinement does): the same image. Kept after a render whose sun came from
    // elsewhere, the maps are that render's: the test sees the bands skip the shadow pass.
    EXPECT_TRUE(imagesMatch(renderInBands(prepared, settings, width, height, 8, 16, true), expected,
                            "banded_render_kept_shadows", exact));
    GpuScene otherSun = uploadScene(prepared, SdfStrategy::Baked);
    std::vector<Light> lights = prepared.lights;
    ASSERT_FALSE(lights.empty());
    lights[0].direction = glm::vec3(-0.6f, -1.0f, 0.5f);
    setSceneLights(otherSun, prepared, lights);
    EXPECT_FALSE(
        imagesMatch(renderInBands(prepared, settings, width, height, 8, 16, true, &otherSun),
                    expected, "banded_render_other_shadows", exact));
    // Without the lag, FXAA reads rows of the stale image at each band's top: the test sees it.
    const Pixels<std::uint8_t> noLag = renderInBands(prepared, settings, width, height, 8, 0);
    EXPECT_FALSE(imagesMatch(noLag, expected, "banded_render_no_lag", exact));
}
