// GPU test support: shared context, rendering, reference-image comparison.
#include "gpu_test_support.hpp"

#include "render/shader_library.hpp"
#include "sdf/cpu_eval.hpp"

#include <algorithm>
#include <cstdlib>

namespace rmsc::test {
namespace {

struct SharedGl {
    std::unique_ptr<HeadlessContext> context;
    std::optional<Renderer> renderer;
    bool llvmpipe = false; // GL_RENDERER names Mesa's llvmpipe
};

SharedGl& sharedGl() {
    static SharedGl gl = [] {
        SharedGl g;
        GlBackend backend = GlBackend::Auto;
        if (const char* name = std::getenv("RMSC_TEST_BACKEND")) parseGlBackend(name, backend);
        std::string error;
        g.context = createHeadlessContext(backend, true, error);
        if (!g.context) {
            ADD_FAILURE() << "no GL context for the GPU tests: " << error;
            std::abort();
        }
        g.renderer = Renderer::create(embeddedShaderFiles(), error);
        if (!g.renderer) {
            ADD_FAILURE() << error;
            std::abort();
        }
        g.llvmpipe = g.context->renderer().find("llvmpipe") != std::string::npos;
        return g;
    }();
    return gl;
}

} // namespace

Renderer& sharedRenderer() {
    return *sharedGl().renderer;
}

bool onLlvmpipe() {
    return sharedGl().llvmpipe;
}

void expectNoGlErrors() {
    const std::string errors = takeGlDebugErrors();
    EXPECT_TRUE(errors.empty()) << errors;
}

FrameTargets renderPrepared(const PreparedScene& prepared, int width, int height,
                            const Camera* camera, SdfStrategy strategy) {
    Renderer& renderer = sharedRenderer();
    const GpuScene gpu = uploadScene(prepared, strategy);
    FrameTargets targets = createFrameTargets(width, height);
    renderer.render(gpu, camera ? *camera : prepared.scene.camera, prepared.scene.render, targets);
    expectNoGlErrors();
    return targets;
}

float marchStart(const SdfProgram& program, const RenderSettings& settings,
                 const FrameCamera& camera, int x, int yFromBottom, int width, int height) {
    const ConeTile tile = coneTile(camera, x / kConeTileSize, yFromBottom / kConeTileSize,
                                   kConeTileSize, width, height);
    const SdfConeMarch cone = camera.orthographic
                                  ? sdfMarchCone(program, settings, tile.origin, tile.axis, 0.0f,
                                                 camera.nearPlane, tile.radius)
                                  : sdfMarchCone(program, settings, camera.position, tile.axis,
                                                 tile.chord, camera.nearPlane);
    const float forwardness =
        1.0f / glm::length(pixelRayDirection(camera, float(x), float(yFromBottom), width, height));
    return std::max(camera.nearPlane / forwardness, cone.distance);
}

PreparedScene openRepositoryScene(const std::string& relativePath) {
    Diagnostics diagnostics;
    std::optional<PreparedScene> prepared =
        openScene(std::filesystem::path(RMSC_TEST_SOURCE_DIR) / relativePath, diagnostics);
    EXPECT_TRUE(prepared.has_value()) << diagnostics.format();
    if (!prepared) throw std::runtime_error("cannot open " + relativePath);
    return std::move(*prepared);
}

std::filesystem::path testOutputDirectory() {
    const std::filesystem::path dir = std::filesystem::path(RMSC_TEST_BINARY_DIR) / "test-output";
    std::filesystem::create_directories(dir);
    return dir;
}

::testing::AssertionResult imageMatchesReference(const Pixels<std::uint8_t>& actual,
                                                 const std::string& name,
                                                 ImageTolerance tolerance) {
    const std::filesystem::path reference =
        std::filesystem::path(RMSC_TEST_SOURCE_DIR) / "tests" / "reference" / (name + ".png");
    const std::filesystem::path candidate = testOutputDirectory() / (name + ".candidate.png");
    std::error_code ignored;
    std::filesystem::remove(candidate, ignored); // a candidate is only ever this run's image
    std::string error;
    std::optional<Pixels<std::uint8_t>> expected = readPng8(reference, actual.channels, error);
    ::testing::AssertionResult result = ::testing::AssertionSuccess();
    if (expected) {
        result = imagesMatch(actual, *expected, name, tolerance);
    } else {
        const std::filesystem::path actualPath = testOutputDirectory() / (name + ".actual.png");
        writePng8(actualPath, actual, error);
        result = ::testing::AssertionFailure() << "no reference image " << reference
                                               << " (actual written to " << actualPath << ")";
    }
    if (result) return result;
    // A candidate never passes a test: it waits in the output folder for review and
    // tools/promote-references.sh, which commits it with a message saying what changed and why.
    const char* update = std::getenv("RMSC_UPDATE_REFERENCES");
    if (!update || std::string(update) != "1")
        return result << ". To propose this image as the reference, run again with "
                         "RMSC_UPDATE_REFERENCES=1";
    if (!writePng8(candidate, actual, error))
        return result << ". Cannot write the candidate " << candidate << ": " << error;
    return result
           << ". Candidate: " << candidate
           << "; after reviewing it: tools/promote-references.sh -m \"what changed and why\" "
           << name;
}

::testing::AssertionResult imagesMatch(const Pixels<std::uint8_t>& actual,
                                       const Pixels<std::uint8_t>& expectedImage,
                                       const std::string& name, ImageTolerance tolerance) {
    const Pixels<std::uint8_t>* expected = &expectedImage;
    std::string error;
    const std::filesystem::path actualPath = testOutputDirectory() / (name + ".actual.png");
    if (expected->width != actual.width || expected->height != actual.height) {
        writePng8(actualPath, actual, error);
        return ::testing::AssertionFailure()
               << name << ": size " << actual.width << "x" << actual.height
               << " differs from the expected " << expected->width << "x" << expected->height
               << ". Actual: " << actualPath;
    }

    Pixels<std::uint8_t> diff{actual.width, actual.height, 3, {}};
    diff.data.assign(std::size_t(actual.width) * actual.height * 3, 0);
    std::size_t differing = 0;
    int worst = 0;
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            int delta = 0;
            for (int c = 0; c < 3; ++c)
                delta =
                    std::max(delta, std::abs(int(actual.at(x, y)[c]) - int(expected->at(x, y)[c])));
            worst = std::max(worst, delta);
            std::uint8_t* d = diff.at(x, y);
            if (delta > tolerance.channelDelta) {
                ++differing;
                d[0] = 255; // differing pixels in red
            } else {
                d[0] = d[1] = d[2] = std::uint8_t(actual.at(x, y)[1] / 4); // context, dimmed
            }
        }
    }
    const double share = double(differing) / double(actual.width * actual.height);
    if (share <= tolerance.maxDifferingShare)
        return ::testing::AssertionSuccess() << share * 100 << "% pixels differ";
    const std::filesystem::path diffPath = testOutputDirectory() / (name + ".diff.png");
    writePng8(actualPath, actual, error);
    writePng8(diffPath, diff, error);
    return ::testing::AssertionFailure()
           << name << ": " << differing << " pixels (" << share * 100 << "%) differ by more than "
           << tolerance.channelDelta << " (worst " << worst << "); allowed "
           << tolerance.maxDifferingShare * 100 << "%. Actual: " << actualPath
           << ", diff: " << diffPath;
}

} // namespace rmsc::test
