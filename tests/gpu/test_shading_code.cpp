// The shading code a frame's programs are built with (render/shading_code.hpp): the parts a
// frame has off (shadows, ambient occlusion, the SDF materials' textures) are left out of them,
// and leaving them out changes no pixel.
#include "gpu_test_support.hpp"

#include "render/readback.hpp"

using namespace rmsc;
using namespace rmsc::test;

namespace {

// The scene drawn with `settings` as its own (the lights' shadows and the programs follow
// them), the textures' code in or out.
Pixels<std::uint8_t> draw(PreparedScene prepared, const RenderSettings& settings, bool texturesCode,
                          std::string& shading) {
    Renderer& renderer = sharedRenderer();
    prepared.scene.render = settings;
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    gpu.sdfTextures = texturesCode;
    FrameTargets targets = createFrameTargets(160, 96);
    renderer.render(gpu, prepared.scene.camera, settings, targets);
    expectNoGlErrors();
    shading = shadingDefines(shadingCode(settings, texturesCode));
    EXPECT_TRUE(renderer.hasPrograms(shading, gpu.sdfMap));
    return readDisplayColor(targets);
}

} // namespace

TEST(ShadingCode, CodeLeftOutChangesNoPixel) {
    // Meshes, SDF objects and shells: the raster, march and shell passes all shade.
    PreparedScene prepared = openRepositoryScene("samples/scenes/shells.json");
    ASSERT_FALSE(prepared.shells.empty());
    ASSERT_FALSE(prepared.scene.meshes.empty());
    RenderSettings off = prepared.scene.render;
    off.shadows.enabled = false;
    off.ao.samples = 0;
    std::string leanShading, fullShading;
    const Pixels<std::uint8_t> lean = draw(prepared, off, false, leanShading);
    EXPECT_EQ(leanShading.find("#define"), std::string::npos) << leanShading;

    // Every part in, each doing nothing: shadows on with no light casting them, ambient
    // occlusion at strength 0, no material with a texture.
    for (Light& light : prepared.scene.lights)
        light.castShadows = false;
    for (Light& light : prepared.lights)
        light.castShadows = false;
    RenderSettings inert = off;
    inert.shadows.enabled = true;
    inert.ao.samples = 5;
    inert.ao.strength = 0.0f;
    const Pixels<std::uint8_t> full = draw(prepared, inert, true, fullShading);
    EXPECT_EQ(fullShading, shadingDefines(ShadingCode{}));
    EXPECT_TRUE(imagesMatch(lean, full, "shading_code_left_out", {0, 0.0}));

    // And the code does something where it is on: the scene's own shadows and occlusion.
    std::string ownShading;
    PreparedScene own = openRepositoryScene("samples/scenes/shells.json");
    RenderSettings shadowed = own.scene.render;
    shadowed.ao.samples = 5;
    shadowed.ao.strength = 1.0f;
    ASSERT_TRUE(shadowed.shadows.enabled);
    const Pixels<std::uint8_t> lit = draw(own, shadowed, false, ownShading);
    // (Measured: 1.5% of the pixels change by more than 8 at this size.)
    EXPECT_FALSE(imagesMatch(lit, lean, "shading_code_shadows_differ", {8, 0.01}))
        << "shadows and occlusion should change more than 1% of the picture";
}
