// The shading code a frame's programs are built with (render/shading_code.hpp): the parts a
// frame has off (shadows, ambient occlusion, the SDF materials' textures) are left out of them,
// and leaving them out changes no pixel; a frame that turns a part off draws at once with
// programs that hold more.
#include "gpu_test_support.hpp"

#include "render/readback.hpp"
#include "render/shader_library.hpp"

#include <optional>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// A renderer of its own: the shared one may hold programs with more code for the same map,
// which a frame would draw with (Renderer::drawnShading).
Renderer freshRenderer() {
    sharedRenderer(); // the context first
    std::string error;
    std::optional<Renderer> renderer = Renderer::create(embeddedShaderFiles(), error);
    if (!renderer) throw std::runtime_error(error);
    return std::move(*renderer);
}

// The scene drawn with `settings` as its own (the lights' shadows and the programs follow
// them), the textures' code in or out; `code` is what the programs were built with.
Pixels<std::uint8_t> draw(Renderer& renderer, PreparedScene prepared,
                          const RenderSettings& settings, bool texturesCode, ShadingCode& code) {
    prepared.scene.render = settings;
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    gpu.shading.sdfTextures = texturesCode;
    FrameTargets targets = createFrameTargets(160, 96);
    renderer.render(gpu, prepared.scene.camera, settings, targets);
    expectNoGlErrors();
    code = shadingCode(settings, texturesCode);
    EXPECT_TRUE(renderer.hasPrograms(code, gpu.sdfMap));
    return readDisplayColor(targets);
}

RenderSettings withoutShadowsAndOcclusion(RenderSettings settings) {
    settings.shadows.enabled = false;
    settings.ao.samples = 0;
    return settings;
}

} // namespace

TEST(ShadingCode, CodeLeftOutChangesNoPixel) {
    Renderer renderer = freshRenderer();
    // Meshes, SDF objects and shells: the raster, march and shell passes all shade.
    PreparedScene prepared = openRepositoryScene("samples/scenes/shells.json");
    ASSERT_FALSE(prepared.shells.empty());
    ASSERT_FALSE(prepared.scene.meshes.empty());
    const RenderSettings off = withoutShadowsAndOcclusion(prepared.scene.render);
    ShadingCode leanCode, fullCode;
    const Pixels<std::uint8_t> lean = draw(renderer, prepared, off, false, leanCode);
    EXPECT_EQ(shadingDefines(leanCode).find("#define"), std::string::npos);

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
    const Pixels<std::uint8_t> full = draw(renderer, prepared, inert, true, fullCode);
    EXPECT_TRUE(fullCode == ShadingCode{});
    EXPECT_TRUE(imagesMatch(lean, full, "shading_code_left_out", {0, 0.0}));

    // And the code does something where it is on: the scene's own shadows and occlusion.
    ShadingCode ownCode;
    PreparedScene own = openRepositoryScene("samples/scenes/shells.json");
    RenderSettings shadowed = own.scene.render;
    shadowed.ao.samples = 5;
    shadowed.ao.strength = 1.0f;
    ASSERT_TRUE(shadowed.shadows.enabled);
    const Pixels<std::uint8_t> lit = draw(renderer, own, shadowed, true, ownCode);
    // (Measured: 1.5% of the pixels change by more than 8 at this size.)
    EXPECT_FALSE(imagesMatch(lit, lean, "shading_code_shadows_differ", {8, 0.01}))
        << "shadows and occlusion should change more than 1% of the picture";
}

// The editor's case: the user turns shadows and occlusion off, then on again.
TEST(ShadingCode, TurningPartsOffDrawsAtOnceWithTheCodeBuilt) {
    Renderer renderer = freshRenderer(); // (and the context, before the upload)
    const PreparedScene prepared = openRepositoryScene("samples/scenes/csg.json");
    const RenderSettings own = prepared.scene.render;
    ASSERT_TRUE(own.shadows.enabled && own.ao.samples > 0);
    const RenderSettings off = withoutShadowsAndOcclusion(own);
    const GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    const ShadingCode offCode = shadingCode(off, gpu.shading.sdfTextures);

    FrameTargets first = createFrameTargets(160, 96), turnedOff = createFrameTargets(160, 96);
    renderer.render(gpu, prepared.scene.camera, own, first);
    EXPECT_GT(renderer.lastCompileMs(), 0.0);
    renderer.render(gpu, prepared.scene.camera, off, turnedOff);
    EXPECT_EQ(renderer.lastCompileMs(), 0.0) << "turning parts off compiled";
    EXPECT_FALSE(renderer.hasPrograms(offCode, gpu.sdfMap));
    renderer.render(gpu, prepared.scene.camera, own, first);
    EXPECT_EQ(renderer.lastCompileMs(), 0.0) << "turning them on again compiled";
    expectNoGlErrors();

    // The picture with them off is the one their own programs draw.
    Renderer lean = freshRenderer();
    FrameTargets expected = createFrameTargets(160, 96);
    lean.render(gpu, prepared.scene.camera, off, expected);
    EXPECT_TRUE(lean.hasPrograms(offCode, gpu.sdfMap));
    EXPECT_TRUE(imagesMatch(readDisplayColor(turnedOff), readDisplayColor(expected),
                            "shading_code_turned_off", {0, 0.0}));
}
