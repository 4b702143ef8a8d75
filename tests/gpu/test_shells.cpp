// Mesh-shell mode (SdfNode::shell): a subtree drawn through a proxy mesh gives the image the
// fullscreen pass gives for it, from outside and from inside the proxy; shells, meshes and the
// fullscreen SDF meet where CPU ray casts say; only the pixels a proxy covers march.
#include "gpu_test_support.hpp"
#include "scene_text.hpp"

#include "render/frame.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <cmath>
#include <set>
#include <string>

using namespace rmsc;
using namespace rmsc::test;

namespace {

constexpr int kWidth = 160, kHeight = 96;

// A mesh floor, a fullscreen capsule, and two shells: a rotated, scaled smooth union with a
// twisted child (box proxy) and a torus (sphere proxy). No shadows or ambient occlusion: those
// see shells through the shadow maps instead of by marching, so they differ by design.
std::string shellScene(const std::string& camera) {
    return R"({"version": 1, "camera": )" + camera + R"(,
      "render": {"ambient": [0.1, 0.1, 0.1], "background": [0.1, 0.12, 0.15]},
      "materials": {"a": {"base_color": "#e07a5f", "roughness": 0.4},
                    "b": {"base_color": "#3d9a8b", "metallic": 0.5, "roughness": 0.3}},
      "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 3},
                 {"type": "point", "position": [1, 1.5, 2], "intensity": 5}],
      "meshes": [{"file": "../assets/plane.gltf", "scale": 3}],
      "sdf": {"op": "union", "children": [
        {"op": "smooth_union", "smoothness": 0.25, "position": [-0.7, 0.5, 0], "rotation": [10, 30, 0],
         "scale": 1.3, "material": "a", "shell": {"proxy": "box"}, "children": [
           {"shape": "sphere", "radius": 0.35},
           {"shape": "box", "half_extents": [0.15, 0.4, 0.15], "position": [0.35, 0, 0], "material": "b",
            "modifiers": [{"type": "twist", "amount": 90, "radius": 0.22}]}]},
        {"shape": "torus", "major_radius": 0.4, "minor_radius": 0.12, "position": [0.9, 0.45, 0.2],
         "rotation": [70, 0, 0], "material": "b", "shell": {"proxy": "sphere"}},
        {"shape": "capsule_between", "a": [-0.2, 0.1, 0.8], "b": [0.5, 0.3, 0.9], "radius": 0.15}]}})";
}

// The shell render and the all-fullscreen render agree: colour within 4/255 on all but 1% of
// pixels, ids equal on all but 1%, depth within 0.2% where both show an SDF node.
void expectSameAsFullscreen(const std::string& json, const std::string& name,
                            double minShellShare) {
    const PreparedScene shells = prepareSceneText(json);
    const PreparedScene fullscreen = prepareSceneText(json, ShellMode::Fullscreen);
    ASSERT_EQ(shells.shells.size(), 2u);
    ASSERT_TRUE(fullscreen.shells.empty());
    const FrameTargets a = renderPrepared(shells, kWidth, kHeight);
    const FrameTargets b = renderPrepared(fullscreen, kWidth, kHeight);
    EXPECT_TRUE(imagesMatch(readDisplayColor(a), readDisplayColor(b), name, {4, 0.01}));
    const Pixels<std::uint32_t> idsA = readObjectIds(a), idsB = readObjectIds(b);
    const Pixels<float> depthA = readViewDepth(a), depthB = readViewDepth(b);
    int differingIds = 0, differingDepths = 0, shellPixels = 0;
    // Object ids of the shells' nodes: 1 (the smooth union) to 3, and 4 (the torus).
    for (std::size_t i = 0; i < idsA.data.size(); ++i) {
        differingIds += idsA.data[i] != idsB.data[i];
        const bool shell = idsA.data[i] >= kSdfIdBase + 1 && idsA.data[i] <= kSdfIdBase + 4;
        shellPixels += shell;
        if (shell && idsA.data[i] == idsB.data[i])
            differingDepths +=
                std::abs(depthA.data[i] - depthB.data[i]) > 2e-3f * std::max(depthB.data[i], 1.0f);
    }
    const int pixels = int(idsA.data.size());
    EXPECT_GE(shellPixels, int(minShellShare * pixels)) << "too few shell pixels to compare";
    EXPECT_LE(differingIds, pixels / 100);
    EXPECT_LE(differingDepths, pixels / 100);
}

} // namespace

TEST(Shells, SameImageAsTheFullscreenPassFromOutside) {
    expectSameAsFullscreen(
        shellScene(R"({"position": [0.3, 1.6, 3.2], "target": [0, 0.4, 0], "fov": 45})"),
        "shells_outside", 0.08);
}

// The camera inside the smooth union's proxy box (checked), outside its content, looking at it:
// the proxy's front faces are behind the camera, its back faces still cover the view, and the
// march starts at the near plane.
TEST(Shells, SameImageAsTheFullscreenPassFromInsideTheProxy) {
    const PreparedScene probe = prepareSceneText(shellScene(R"({"position": [0, 1, 3]})"));
    ASSERT_FALSE(probe.shells.empty());
    const PreparedShell& blob = probe.shells[0];
    const glm::vec3 centre = 0.5f * (blob.clipMin + blob.clipMax);
    const glm::vec3 inside(centre.x, centre.y + 0.1f, blob.clipMax.z - 0.03f);
    ASSERT_GT(blob.clipMax.z - 0.03f, 0.36f) << "the camera must be outside the sphere (0.35)";
    const glm::vec3 eye = glm::vec3(blob.compiled.objectToWorld * glm::vec4(inside, 1.0f));
    const glm::vec3 target = glm::vec3(blob.compiled.objectToWorld * glm::vec4(centre, 1.0f));
    auto vec = [](glm::vec3 v) {
        return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) +
               "]";
    };
    expectSameAsFullscreen(shellScene(R"({"position": )" + vec(eye) + R"(, "target": )" +
                                      vec(target) + R"(, "fov": 70, "near": 0.01})"),
                           "shells_inside", 0.3);
}

// A shell sphere pierces a mesh quad and a fullscreen SDF box: every sampled pixel shows the
// object, and the depth, that a CPU ray cast finds (the sphere and box through the CPU evaluator
// of the whole tree compiled for the fullscreen pass, the quad analytically).
TEST(Shells, ShellsMeshesAndFullscreenSdfMeetWhereCpuRaysSay) {
    const std::string json = R"({"version": 1,
      "camera": {"position": [0.4, 1.6, 2.6], "target": [0, 0.1, 0], "fov": 45},
      "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 3}],
      "meshes": [{"file": "../assets/plane.gltf", "scale": 1.5}],
      "sdf": {"op": "union", "children": [
        {"shape": "sphere", "radius": 0.6, "position": [0, 0.15, 0], "shell": true},
        {"shape": "box", "half_extents": [0.3, 0.3, 0.3], "position": [0.6, 0.25, 0.1]}]}})";
    const PreparedScene prepared = prepareSceneText(json);
    ASSERT_EQ(prepared.shells.size(), 1u);
    Diagnostics diagnostics;
    const std::optional<SdfProgram> whole =
        compileSdf(*prepared.scene.sdf, 0, "test.json", diagnostics);
    ASSERT_TRUE(whole) << diagnostics.format();

    const FrameTargets targets = renderPrepared(prepared, kWidth, kHeight);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);
    const Pixels<float> depths = readViewDepth(targets);
    const Camera& camera = prepared.scene.camera;
    const FrameCamera frame = makeFrameCamera(camera, kWidth, kHeight);
    int sampled = 0, mismatches = 0, misses = 0, seen[3] = {0, 0, 0};
    std::string firstProblem;
    for (int row = 1; row < kHeight; row += 2) {
        for (int x = 1; x < kWidth; x += 2) {
            const glm::vec3 d =
                pixelRayDirection(frame, float(x), float(kHeight - 1 - row), kWidth, kHeight);
            const float forwardness = 1.0f / glm::length(d);
            const glm::vec3 rd = d * forwardness;
            // The quad: plane.gltf is 2 x 2 in xz, scaled by 1.5.
            float expectedT = kNoDepth;
            std::uint32_t expectedId = 0;
            if (rd.y < 0.0f) {
                const float t = -camera.position.y / rd.y;
                const glm::vec3 p = camera.position + rd * t;
                if (std::abs(p.x) <= 1.5f && std::abs(p.z) <= 1.5f) {
                    expectedT = t;
                    expectedId = kMeshIdBase;
                }
            }
            const std::optional<SdfHit> hit =
                sdfCastRay(*whole, prepared.scene.render, camera.position, rd,
                           camera.nearPlane / forwardness, std::min(expectedT, 100.0f));
            if (hit) {
                expectedT = hit->t;
                expectedId = sdfSurface(*whole, prepared.materials, hit->position).objectId;
            }
            ++sampled;
            const std::uint32_t gpuId = *ids.at(x, row);
            seen[expectedId == kMeshIdBase      ? 0
                 : expectedId == kSdfIdBase + 1 ? 1
                                                : 2] += expectedId != 0;
            const bool depthOk =
                expectedId == 0 || std::abs(*depths.at(x, row) - expectedT * forwardness) <=
                                       2e-3f * std::max(expectedT, 1.0f);
            misses += expectedId != 0 && gpuId == 0;
            if (gpuId != expectedId || !depthOk) {
                ++mismatches;
                if (firstProblem.empty())
                    firstProblem = "pixel " + std::to_string(x) + "," + std::to_string(row) +
                                   ": GPU id " + std::to_string(gpuId) + " depth " +
                                   std::to_string(*depths.at(x, row)) + ", CPU id " +
                                   std::to_string(expectedId) + " depth " +
                                   std::to_string(expectedT * forwardness);
            }
        }
    }
    // Each of the three must be visible, and the silhouettes may flip a few samples.
    EXPECT_GT(seen[0], sampled / 20) << "the quad should be visible";
    EXPECT_GT(seen[1], sampled / 20) << "the shell sphere should be visible";
    EXPECT_GT(seen[2], sampled / 50) << "the fullscreen box should be visible";
    EXPECT_LE(mismatches, sampled / 50) << firstProblem;
    // Of those, a pixel where the GPU shows nothing but the CPU hits: none, as measured on
    // llvmpipe.
    EXPECT_EQ(misses, 0) << firstProblem;
}

// Only the pixels a shell's proxy covers march it, and the fullscreen pass has nothing left to
// march when every shape is in a shell.
TEST(Shells, OnlyThePixelsOfTheProxyMarch) {
    const std::string json = R"({"version": 1,
      "camera": {"position": [0, 0, 6], "target": [0, 0, 0], "fov": 45},
      "sdf": {"shape": "sphere", "radius": 0.5, "shell": true}})";
    const PreparedScene shells = prepareSceneText(json);
    const PreparedScene fullscreen = prepareSceneText(json, ShellMode::Fullscreen);
    Renderer& renderer = sharedRenderer();
    renderPrepared(shells, kWidth, kHeight);
    const MarchStatistics inShells = renderer.lastMarchStatistics();
    renderPrepared(fullscreen, kWidth, kHeight);
    const MarchStatistics inFullscreen = renderer.lastMarchStatistics();
    EXPECT_EQ(inShells.fullscreen, 0u);
    EXPECT_EQ(inFullscreen.shells, 0u);
    // In the fullscreen pass the cone pass (render/cone_pass.hpp) leaves only the tiles around
    // the sphere to march; without it, every pixel marches.
    EXPECT_LT(inFullscreen.fullscreen, std::uint64_t(kWidth * kHeight / 5));
    renderer.setConePass(false);
    renderPrepared(fullscreen, kWidth, kHeight);
    renderer.setConePass(true);
    EXPECT_EQ(renderer.lastMarchStatistics().fullscreen, std::uint64_t(kWidth * kHeight));
    // The proxy box of a sphere of radius 0.5 seen from 6 units covers well under a tenth of
    // the frame, and at least the sphere's own disc.
    EXPECT_LT(inShells.shells, std::uint64_t(kWidth * kHeight / 10));
    const double pixelsPerUnit = kHeight / (2.0 * 6.0 * std::tan(glm::radians(22.5)));
    EXPECT_GT(double(inShells.shells), 3.14159 * std::pow(0.5 * pixelsPerUnit, 2.0) * 0.9);
}

// With shadows on, a shell shades itself as the fullscreen pass does: it receives its own soft
// SDF shadow and the shadow map's (which must not darken its lit side). Compared on the shell's
// own pixels: colour within 12/255 on all but 0.4% (the shadow map adds a little at the
// terminator; the clip box's crease in the soft-shadow estimate once printed a dark spot
// of 0.6%).
TEST(Shells, LitSideOfAShellIsNotDarkenedByItsOwnShadows) {
    const std::string json = R"({"version": 1,
      "camera": {"position": [0.3, 1.0, 0.6], "target": [0, 0.7, -1], "fov": 40},
      "render": {"ambient": [0.1, 0.1, 0.1], "shadows": {"enabled": true}},
      "lights": [{"type": "directional", "direction": [-0.5, -1, -0.35], "intensity": 3}],
      "meshes": [{"file": "../assets/plane.gltf", "scale": 4}],
      "sdf": {"shape": "box", "half_extents": [0.2, 0.45, 0.2], "position": [0, 0.63, -1],
              "scale": 1.4, "modifiers": [{"type": "twist", "amount": 120, "radius": 0.29}],
              "shell": {"proxy": "mesh", "mesh": "../assets/cube.gltf"}}})";
    const PreparedScene shell = prepareSceneText(json);
    const PreparedScene fullscreen = prepareSceneText(json, ShellMode::Fullscreen);
    const int width = 160, height = 120;
    const FrameTargets a = renderPrepared(shell, width, height);
    const FrameTargets b = renderPrepared(fullscreen, width, height);
    const Pixels<std::uint8_t> colourA = readDisplayColor(a), colourB = readDisplayColor(b);
    const Pixels<std::uint32_t> ids = readObjectIds(b);
    int shellPixels = 0, differing = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (*ids.at(x, y) != kSdfIdBase) continue;
            ++shellPixels;
            const std::uint8_t* p = colourA.at(x, y);
            const std::uint8_t* q = colourB.at(x, y);
            bool differs = false;
            for (int c = 0; c < 3; ++c)
                differs = differs || std::abs(int(p[c]) - int(q[c])) > 12;
            differing += differs;
        }
    EXPECT_GT(shellPixels, width * height / 4) << "the column should fill much of the view";
    EXPECT_LE(differing, shellPixels / 250) << differing << " of " << shellPixels;
    if (differing > shellPixels / 250) {
        EXPECT_TRUE(imagesMatch(colourA, colourB, "shells_self_shadow", {12, 0.004}));
    }
}

// More distinct shells than the renderer caches programs for (64): every one is drawn. The
// cache once dropped all its programs in the middle of preparing such a scene, and most shells
// vanished from the image without an error.
TEST(Shells, MoreShellsThanTheProgramCacheHoldsAreAllDrawn) {
    const int count = 66; // 11 x 6 balls, each of its own radius, so each has its own program
    std::string children;
    for (int i = 0; i < count; ++i) {
        const float x = -1.5f + 0.3f * float(i % 11), z = -0.75f + 0.3f * float(i / 11);
        children += std::string(i ? "," : "") + R"({"shape": "sphere", "radius": )" +
                    std::to_string(0.08f + 0.0005f * float(i)) + R"(, "position": [)" +
                    std::to_string(x) + ", 0, " + std::to_string(z) +
                    R"(], "shell": {"proxy": "box"}})";
    }
    const PreparedScene prepared = prepareSceneText(
        R"({"version": 1, "camera": {"position": [0, 3.2, 0.01], "target": [0, 0, 0], "fov": 60},
            "sdf": {"op": "union", "children": [)" +
        children + "]}}");
    ASSERT_EQ(prepared.shells.size(), std::size_t(count));
    const FrameTargets targets = renderPrepared(prepared, 160, 96);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);
    std::set<std::uint32_t> seen(ids.data.begin(), ids.data.end());
    seen.erase(0);
    EXPECT_EQ(seen.size(), std::size_t(count)) << "shells drawn";
    expectNoGlErrors();
}
