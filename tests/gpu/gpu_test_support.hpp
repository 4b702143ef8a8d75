// Support for tests that need a GL context: one headless context per test process (backend
// from RMSC_TEST_BACKEND, default auto) and whether it is llvmpipe, rendering a prepared scene
// to frame targets, and comparing images with a reference PNG under a stated tolerance, writing
// actual, diff and (on request) candidate images when they differ.
#pragma once

#include "core/image_io.hpp"
#include "gl/context.hpp"
#include "prepare/prepared_scene.hpp"
#include "render/readback.hpp"
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

namespace rmsc::test {

// The process-wide context and renderer; the first call creates them (GL debug output on).
Renderer& sharedRenderer();

// Whether the shared context runs on Mesa's llvmpipe (its GL_RENDERER, read once). Tolerances
// that exist only because of llvmpipe apply when this is true; other drivers get the strict one.
bool onLlvmpipe();

// Fails the current test if KHR_debug reported a GL error since the last call.
void expectNoGlErrors();

// Renders `prepared` at width x height with its own camera, unless `camera` is given.
FrameTargets renderPrepared(const PreparedScene& prepared, int width, int height,
                            const Camera* camera = nullptr,
                            SdfStrategy strategy = SdfStrategy::Baked);

// Where the march pass starts the ray of pixel (x, yFromBottom) of a width x height frame, as
// a distance along the unit ray: the near plane, or farther where the cone pass found the
// pixel's tile free that far (sdfMarchCone on the tile's cone, as shaders/passes/cone.frag).
// CPU ray casts that start there follow the GPU's steps.
float marchStart(const SdfProgram& program, const RenderSettings& settings,
                 const FrameCamera& camera, int x, int yFromBottom, int width, int height);

// Opens a scene file from the repository (path relative to the repository root).
PreparedScene openRepositoryScene(const std::string& relativePath);

// Where tests write their output images (actual, diff, candidate): <build>/test-output/.
std::filesystem::path testOutputDirectory();

struct ImageTolerance {
    int channelDelta = 8;             // a pixel differs if any channel differs by more than this
    double maxDifferingShare = 0.005; // the images match if at most this share of pixels differ
};

// Compares `actual` (RGBA8) with tests/reference/<name>.png. On a mismatch writes
// <output>/<name>.actual.png and <name>.diff.png and returns a failure naming them. With
// RMSC_UPDATE_REFERENCES=1 a mismatch also writes <output>/<name>.candidate.png for review and
// tools/promote-references.sh; the result is still the failure. tests/reference/ is never
// written.
::testing::AssertionResult imageMatchesReference(const Pixels<std::uint8_t>& actual,
                                                 const std::string& name,
                                                 ImageTolerance tolerance = {});

// Compares two images of one size under `tolerance`; on a mismatch writes
// <output>/<name>.actual.png (of `actual`) and <name>.diff.png and names them.
::testing::AssertionResult imagesMatch(const Pixels<std::uint8_t>& actual,
                                       const Pixels<std::uint8_t>& expected,
                                       const std::string& name, ImageTolerance tolerance = {});

} // namespace rmsc::test
