// What the editor draws while the user edits (editor/editing_map.hpp, render/shader_warmer.hpp):
// the baked map with the selection read from the buffer draws the baked image and follows
// buffer edits of the selection without a compile; the warmer builds maps on a second context
// of its own thread, the newest request replacing older ones, and reports maps that fail.
#include "gpu_test_support.hpp"

#include "render/readback.hpp"
#include "render/shader_library.hpp"
#include "render/shader_warmer.hpp"

#include <chrono>
#include <cstdlib>
#include <memory>
#include <optional>
#include <thread>

using namespace rmsc;
using namespace rmsc::test;

namespace {

FrameTargets renderMap(const PreparedScene& prepared, const std::string& map) {
    Renderer& renderer = sharedRenderer(); // the context first
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    gpu.sdfMap = map;
    FrameTargets targets = createFrameTargets(160, 96);
    renderer.render(gpu, prepared.scene.camera, prepared.scene.render, targets);
    expectNoGlErrors();
    return targets;
}

// A second context like the tests' own (same back end), made on the warmer's thread.
ShaderWarmer::ContextBinder secondaryContext() {
    return [](std::string& error) -> std::function<void()> {
        GlBackend backend = GlBackend::Auto;
        if (const char* name = std::getenv("RMSC_TEST_BACKEND")) parseGlBackend(name, backend);
        std::shared_ptr<HeadlessContext> context =
            createHeadlessContext(backend, false, error, true);
        if (!context) return nullptr;
        return [context]() mutable { context.reset(); };
    };
}

} // namespace

TEST(EditingMaps, TheSelectionLiveDrawsTheBakedImageAndFollowsTheBuffer) {
    PreparedScene prepared = openRepositoryScene("samples/scenes/csg.json");
    // The live range: the first shape and everything after it in pre-order up to half the tree.
    std::uint32_t firstShape = 0;
    for (const GpuSdfInstruction& in : prepared.sdf.instructions)
        if (SdfOpcode(in.opcode) == SdfOpcode::Shape && !firstShape) firstShape = in.objectId;
    ASSERT_NE(firstShape, 0u);
    const SdfLiveRange live{firstShape,
                            firstShape + std::uint32_t(prepared.sdf.nodePointers.size() / 2)};
    const std::string editing = generateSdfMap(prepared.sdf, SdfStrategy::Baked, {}, live);
    ASSERT_NE(editing.find("sdfUniformInstructions["), std::string::npos);

    const FrameTargets baked =
        renderMap(prepared, generateSdfMap(prepared.sdf, SdfStrategy::Baked));
    const FrameTargets mixed = renderMap(prepared, editing);
    EXPECT_TRUE(imagesMatch(readDisplayColor(mixed), readDisplayColor(baked), "editing_map_csg",
                            {2, 0.002}));

    // Grow the first shape in the buffer: the map's text stays, nothing compiles, the picture
    // changes as the baked map of the edited program draws it.
    for (GpuSdfInstruction& in : prepared.sdf.instructions)
        if (in.objectId == firstShape && SdfOpcode(in.opcode) == SdfOpcode::Shape)
            in.params[0] *= 1.3f;
    EXPECT_EQ(generateSdfMap(prepared.sdf, SdfStrategy::Baked, {}, live), editing);
    const FrameTargets edited = renderMap(prepared, editing);
    EXPECT_EQ(sharedRenderer().lastCompileMs(), 0.0) << "an edit of a live shape compiled";
    EXPECT_FALSE(imagesMatch(readDisplayColor(edited), readDisplayColor(mixed),
                             "editing_map_unchanged", {2, 0.002}))
        << "the edit should show";
    const FrameTargets bakedEdited =
        renderMap(prepared, generateSdfMap(prepared.sdf, SdfStrategy::Baked));
    EXPECT_TRUE(imagesMatch(readDisplayColor(edited), readDisplayColor(bakedEdited),
                            "editing_map_edited", {2, 0.002}));
}

// What the warmer does after each map it builds: its programs go, and drawing the map again
// builds them again and draws the same picture.
TEST(EditingMaps, ForgottenProgramsAreBuiltAgainAndDrawTheSame) {
    sharedRenderer(); // the context first
    std::string error;
    std::optional<Renderer> renderer = Renderer::create(embeddedShaderFiles(), error);
    ASSERT_TRUE(renderer) << error;
    const PreparedScene prepared = openRepositoryScene("samples/scenes/csg.json");
    const GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    FrameTargets first = createFrameTargets(96, 64), again = createFrameTargets(96, 64);
    renderer->render(gpu, prepared.scene.camera, prepared.scene.render, first);
    EXPECT_TRUE(renderer->hasPrograms(gpu.shading, gpu.sdfMap));
    renderer->forgetScenePrograms();
    EXPECT_FALSE(renderer->hasPrograms(gpu.shading, gpu.sdfMap));
    renderer->render(gpu, prepared.scene.camera, prepared.scene.render, again);
    EXPECT_TRUE(renderer->hasPrograms(gpu.shading, gpu.sdfMap));
    EXPECT_GT(renderer->lastCompileMs(), 0.0) << "the map was not built again";
    expectNoGlErrors();
    EXPECT_TRUE(imagesMatch(readDisplayColor(again), readDisplayColor(first),
                            "forgotten_programs_rebuilt", {0, 0.0}));
}

TEST(ShaderWarmer, BuildsTheNewestRequestAndReportsFailures) {
    sharedRenderer(); // the tests' context first: the warmer's is the second
    const PreparedScene prepared = openRepositoryScene("samples/bench/grid_10.json");
    const ShadingCode shading = sceneShading(prepared);
    auto mapFor = [&](std::uint32_t id) {
        return generateSdfMap(prepared.sdf, SdfStrategy::Baked, {}, SdfLiveRange{id, id});
    };
    const std::string a = mapFor(kSdfIdBase + 1), b = mapFor(kSdfIdBase + 2),
                      c = mapFor(kSdfIdBase + 3);
    ShaderWarmer warmer(secondaryContext(), embeddedShaderFiles());
    const auto shared = std::make_shared<const PreparedScene>(prepared);
    warmer.request(shared, {a});
    warmer.request(shared, {b});
    warmer.request(shared, {c});
    warmer.waitUntilIdle();
    EXPECT_TRUE(warmer.idle());
    EXPECT_EQ(warmer.takeError(), "");
    EXPECT_TRUE(warmer.isWarm(shading, c)) << "the newest request is built";
    EXPECT_FALSE(warmer.isWarm(shading, a) && warmer.isWarm(shading, b))
        << "b replaced a, or c replaced b";
    EXPECT_GT(warmer.buildMs(shading, c), 0.0);
    EXPECT_EQ(warmer.buildMs(shading, c + "\n"), 0.0) << "not warm";
    // Programs are a map with the shading code of its scene's settings: the same map for a
    // scene shaded otherwise is built again.
    auto shaded = std::make_shared<PreparedScene>(prepared);
    shaded->scene.render.shadows.enabled = !prepared.scene.render.shadows.enabled;
    const ShadingCode otherShading = sceneShading(*shaded);
    EXPECT_FALSE(otherShading == shading);
    EXPECT_FALSE(warmer.isWarm(otherShading, c));
    warmer.request(shaded, {c});
    warmer.waitUntilIdle();
    EXPECT_TRUE(warmer.isWarm(otherShading, c) && warmer.isWarm(shading, c));

    // A request is a list built in order; maps already warm are skipped.
    const std::size_t finished = warmer.finishedCount();
    const std::string d = mapFor(kSdfIdBase + 4), e = mapFor(kSdfIdBase + 5);
    warmer.request(shared, {c, d, e});
    warmer.waitUntilIdle();
    EXPECT_TRUE(warmer.isWarm(shading, d) && warmer.isWarm(shading, e));
    EXPECT_EQ(warmer.finishedCount(), finished + 2) << "c was warm already";

    // The map the warmer built is one the tests' context builds and draws.
    GpuScene gpu = uploadScene(prepared, SdfStrategy::Baked);
    gpu.sdfMap = c;
    std::string error;
    EXPECT_TRUE(sharedRenderer().prepare(gpu, error)) << error;

    // A map that does not build is reported, not retried, and the warmer goes on.
    const std::string broken = c + "\nthis is not GLSL\n";
    warmer.request(shared, {broken});
    warmer.waitUntilIdle();
    EXPECT_FALSE(warmer.isWarm(shading, broken));
    EXPECT_NE(warmer.takeError().find("background shader build failed"), std::string::npos);
    warmer.request(shared, {broken});
    EXPECT_TRUE(warmer.idle()) << "a failed map is not asked for again";
    warmer.request(shared, {a});
    warmer.waitUntilIdle();
    EXPECT_TRUE(warmer.isWarm(shading, a));
    expectNoGlErrors();
}

TEST(ShaderWarmer, ReportsTheProgressOfTheCurrentRequest) {
    sharedRenderer(); // the tests' context first: the warmer's is the second
    const PreparedScene prepared = openRepositoryScene("samples/bench/grid_10.json");
    auto mapFor = [&](std::uint32_t id) {
        return generateSdfMap(prepared.sdf, SdfStrategy::Baked, {}, SdfLiveRange{id, id});
    };
    ShaderWarmer warmer(secondaryContext(), embeddedShaderFiles());
    warmer.waitUntilIdle(); // started
    EXPECT_EQ(warmer.progress().total, 0) << "nothing asked for";
    warmer.request(std::make_shared<const PreparedScene>(prepared),
                   {mapFor(kSdfIdBase + 6), mapFor(kSdfIdBase + 7)});
    // Right after the request neither map can be built: each takes milliseconds at least.
    ShaderWarmer::Progress p = warmer.progress();
    EXPECT_EQ(p.total, 2);
    EXPECT_EQ(p.done, 0);
    // While it builds, two maps in all and fewer than two done; the seconds of one map grow.
    int lastDone = 0;
    double lastSeconds = 0.0;
    while (!warmer.idle()) {
        p = warmer.progress();
        if (p.total == 0) break; // finished between the two calls
        EXPECT_EQ(p.total, 2);
        EXPECT_GE(p.done, lastDone);
        EXPECT_LT(p.done, 2);
        if (p.done == lastDone) {
            EXPECT_GE(p.seconds, lastSeconds);
        }
        lastDone = p.done;
        lastSeconds = p.seconds;
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    warmer.waitUntilIdle();
    p = warmer.progress();
    EXPECT_EQ(p.total, 0) << "the request is done";
    EXPECT_EQ(p.done, 0);
    EXPECT_EQ(warmer.takeError(), "");
}

TEST(ShaderWarmer, WithoutAContextItSaysSoAndIgnoresRequests) {
    const PreparedScene prepared = openRepositoryScene("samples/bench/grid_1.json");
    ShaderWarmer warmer(
        [](std::string& error) -> std::function<void()> {
            error = "no context for this test";
            return nullptr;
        },
        embeddedShaderFiles());
    warmer.waitUntilIdle();
    EXPECT_NE(warmer.takeError().find("no context for this test"), std::string::npos);
    const std::string map = generateSdfMap(prepared.sdf, SdfStrategy::Baked);
    warmer.request(std::make_shared<const PreparedScene>(prepared), {map});
    EXPECT_TRUE(warmer.idle());
    EXPECT_FALSE(warmer.isWarm(sceneShading(prepared), map));
}
