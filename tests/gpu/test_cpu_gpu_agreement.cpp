// The GPU march agrees with the CPU evaluator: the depth and id AOVs of scenes with every
// primitive, operation and modifier match CPU ray casts through the same compiled program.
#include "gpu_test_support.hpp"
#include "scene_text.hpp"

#include "render/frame.hpp"
#include "sdf/cpu_eval.hpp"

using namespace rmsc;
using namespace rmsc::test;

namespace {

struct Agreement {
    int sampled = 0;
    int sdfHits = 0;
    int idMismatches = 0;
    int depthMismatches = 0;
    // Of the id mismatches, where the CPU hits SDF and the GPU shows nothing, but for grazes.
    int gpuMisses = 0;
    // Of the id mismatches, rays grazing a surface, whose two marches sampled them at
    // different points: where the GPU hit an SDF object the CPU's ray passed and the whole
    // program's distance at the GPU's hit is under the hit threshold there; or where the GPU
    // passed what the CPU hit, a surface the ray never enters (grazesOnly).
    int grazes = 0;
    std::string firstProblem;
};

// Does the ray only graze what it hit: within the hit threshold of a surface it never enters?
// The whole program's distance stays positive for four thresholds past the hit, so a march
// that samples the ray at other points may pass it.
bool grazesOnly(const SdfProgram& program, glm::vec3 ro, glm::vec3 rd, float t, float threshold) {
    for (int i = 0; i <= 16; ++i)
        if (sdfDistance(program, ro + rd * (t + 0.25f * threshold * float(i))) <= 0.0f)
            return false;
    return true;
}

// The helper itself: a ray into a sphere enters it; one passing half a threshold above it does
// not.
TEST(CpuGpuAgreement, AGrazeIsARayThatNeverEntersTheSurface) {
    const PreparedScene prepared = prepareSceneText(R"({"version": 1,
      "sdf": {"children": [{"shape": "sphere", "radius": 1}]}})");
    const float threshold = 0.01f;
    EXPECT_FALSE(
        grazesOnly(prepared.sdf, {-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 3.995f, threshold));
    EXPECT_TRUE(grazesOnly(prepared.sdf, {-5.0f, 1.0f + 0.5f * threshold, 0.0f}, {1.0f, 0.0f, 0.0f},
                           4.99f, threshold));
}

// Casts the ray of every `step`-th pixel on the CPU and compares with the GPU AOVs. Pixels
// where the GPU shows a mesh are checked too: the CPU ray, stopped at the mesh depth, must not
// hit an SDF object in front of it.
Agreement compare(const PreparedScene& prepared, int width, int height, int step,
                  SdfStrategy strategy = SdfStrategy::Baked, int firstRow = -1, int endRow = -1) {
    const FrameTargets targets = renderPrepared(prepared, width, height, nullptr, strategy);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);
    const Pixels<float> depths = readViewDepth(targets);
    const Scene& scene = prepared.scene;
    const FrameCamera frame = makeFrameCamera(scene.camera, width, height);
    Agreement a;
    for (int row = firstRow < 0 ? step / 2 : firstRow; row < (endRow < 0 ? height : endRow);
         row += step) {
        for (int x = step / 2; x < width; x += step) {
            ++a.sampled;
            const glm::vec3 d =
                pixelRayDirection(frame, float(x), float(height - 1 - row), width, height);
            const float forwardness = 1.0f / glm::length(d);
            const glm::vec3 rd = d * forwardness;
            const std::uint32_t gpuId = *ids.at(x, row);
            const float gpuDepth = *depths.at(x, row);
            const bool gpuSdf = gpuId >= kSdfIdBase;
            const float meshDepth = gpuSdf || gpuId == 0 ? kNoDepth : gpuDepth;
            const float tMax = std::min(scene.render.maxDistance, meshDepth / forwardness);
            const std::optional<SdfHit> hit = sdfCastRay(
                prepared.sdf, scene.render, scene.camera.position, rd,
                marchStart(prepared.sdf, scene.render, frame, x, height - 1 - row, width, height),
                tMax);
            std::uint32_t cpuId = gpuSdf ? 0 : gpuId;
            float cpuDepth = gpuSdf ? kNoDepth : gpuDepth;
            if (hit) {
                cpuId = sdfSurface(prepared.sdf, prepared.materials, hit->position).objectId;
                cpuDepth = hit->t * forwardness;
                ++a.sdfHits;
            }
            if (cpuId != gpuId) {
                ++a.idMismatches;
                const bool passedAGraze =
                    hit && gpuId == 0 &&
                    grazesOnly(prepared.sdf, scene.camera.position, rd, hit->t,
                               scene.render.surfaceEpsilon * std::max(hit->t, 1.0f));
                a.gpuMisses += hit && gpuId == 0 && !passedAGraze;
                const float gpuT = gpuDepth / forwardness;
                a.grazes +=
                    passedAGraze || (gpuSdf && !hit &&
                                     sdfDistance(prepared.sdf, scene.camera.position + rd * gpuT) <
                                         scene.render.surfaceEpsilon * std::max(gpuT, 1.0f));
                if (a.firstProblem.empty())
                    a.firstProblem = "pixel " + std::to_string(x) + "," + std::to_string(row) +
                                     ": GPU id " + std::to_string(gpuId) + ", CPU id " +
                                     std::to_string(cpuId);
            } else if (hit && std::abs(cpuDepth - gpuDepth) > 2e-3f * std::max(cpuDepth, 1.0f)) {
                ++a.depthMismatches;
                if (a.firstProblem.empty())
                    a.firstProblem = "pixel " + std::to_string(x) + "," + std::to_string(row) +
                                     ": GPU depth " + std::to_string(gpuDepth) + ", CPU depth " +
                                     std::to_string(cpuDepth);
            }
        }
    }
    return a;
}

// `minSdfShare`: the share of sampled pixels that must show SDF objects, so the check has
// something to compare.
void expectAgreement(const PreparedScene& prepared, const std::string& scenePath,
                     double minSdfShare) {
    const Agreement a = compare(prepared, 192, 108, 3);
    // Rays that graze a silhouette may stop one step apart on GPU (float32, fused
    // multiply-adds) and CPU; allow 1% of samples, no more.
    const int allowed = a.sampled / 100;
    EXPECT_GT(a.sdfHits, int(minSdfShare * a.sampled)) << "too few SDF pixels to compare";
    EXPECT_LE(a.idMismatches, allowed) << scenePath << ": " << a.firstProblem;
    EXPECT_LE(a.depthMismatches, allowed) << scenePath << ": " << a.firstProblem;
    // Of those, a GPU march that misses what the CPU hits (it gave up, or started past the
    // surface), but for rays that only graze a surface they never enter: none, as measured on
    // llvmpipe in every one of these scenes.
    EXPECT_EQ(a.gpuMisses, 0) << scenePath << ": " << a.firstProblem;
}

void expectAgreement(const std::string& scenePath, double minSdfShare) {
    expectAgreement(openRepositoryScene(scenePath), scenePath, minSdfShare);
}

} // namespace

TEST(CpuGpuAgreement, EveryPrimitive) {
    expectAgreement("samples/scenes/shapes.json", 0.5);
}
TEST(CpuGpuAgreement, EveryOperationWithMeshes) {
    expectAgreement("samples/scenes/csg.json", 0.12);
}
TEST(CpuGpuAgreement, ModifiersAndProfiles) {
    expectAgreement("samples/scenes/modifiers.json", 0.15);
}
// The taper alone, narrowing and widening, on a group, and in chains with other modifiers
// (not in modifiers.json, whose image is a reference).
TEST(CpuGpuAgreement, Taper) {
    const PreparedScene prepared = prepareSceneText(R"({"version": 1,
      "camera": {"position": [0, 1.2, 4.2], "target": [0, 0.1, 0], "fov": 45},
      "sdf": {"children": [
        {"shape": "capped_cylinder", "radius": 0.3, "half_height": 0.6, "position": [-1.5, 0, 0],
         "modifiers": [{"type": "taper", "amount": -1.1, "radius": 0.6}]},
        {"shape": "box", "half_extents": [0.3, 0.55, 0.3], "position": [-0.5, 0, 0],
         "modifiers": [{"type": "taper", "amount": 0.9, "radius": 0.55},
                       {"type": "twist", "amount": 60, "radius": 0.6}, {"type": "round", "radius": 0.02}]},
        {"op": "smooth_union", "smoothness": 0.1, "position": [0.55, 0, 0],
         "modifiers": [{"type": "taper", "amount": 0.7, "radius": 0.7}],
         "children": [{"shape": "sphere", "radius": 0.35, "position": [0, 0.3, 0]},
                      {"shape": "torus", "major_radius": 0.3, "minor_radius": 0.1, "position": [0, -0.3, 0]}]},
        {"shape": "sphere", "radius": 0.35, "position": [1.6, 0, 0],
         "modifiers": [{"type": "mirror", "axes": "x"}, {"type": "taper", "amount": -1.5, "radius": 0.4},
                       {"type": "displace", "amplitude": 0.03, "frequency": 6}]}]}})");
    expectAgreement(prepared, "the taper scene", 0.1);
}
TEST(CpuGpuAgreement, FullPrimitiveSet) {
    expectAgreement("samples/scenes/primitives.json", 0.75);
}
TEST(CpuGpuAgreement, BlendChamferRoundXor) {
    expectAgreement("samples/scenes/smooth_blend.json", 0.9);
}
TEST(CpuGpuAgreement, DemoScene) {
    expectAgreement("samples/scenes/demo.json", 0.04);
}

// The Cells strategy (the program pruned per cell, sdf/cell_pruning.hpp) against CPU ray casts
// through the whole program: a binary tree of 256 spheres whose levels alternate union and
// smooth union over a plane, seen to the horizon (where the interpreter used to run out of
// llvmpipe's loop budget and draw wrong tiles), and the samples with every operation and
// modifier.
TEST(CpuGpuAgreement, CellsOnASmoothTreeToTheHorizon) {
    const PreparedScene prepared = openRepositoryScene("samples/bench/tree_256.json");
    ASSERT_EQ(effectiveSdfStrategy(prepared.sdf, SdfStrategy::Baked), SdfStrategy::Cells);
    const Agreement a = compare(prepared, 96, 54, 2);
    // As tight as measured on llvmpipe: 1008 of 1296 samples hit (the rest is sky above the
    // horizon), one grazing ray's id differs, no depth.
    EXPECT_GT(a.sdfHits, a.sampled * 3 / 4);
    EXPECT_LE(a.idMismatches, 1) << a.firstProblem;
    EXPECT_EQ(a.depthMismatches, 0) << a.firstProblem;
    EXPECT_EQ(a.gpuMisses, 0) << a.firstProblem;
}

// The largest tree of the benchmarks, 4,096 spheres in twelve levels of union and smooth
// union over the plane, to the horizon: sparse samples, because each CPU step evaluates all
// 4,096 spheres.
TEST(CpuGpuAgreement, CellsOnTheLargestSmoothTree) {
    const PreparedScene prepared = openRepositoryScene("samples/bench/tree_4096.json");
    ASSERT_EQ(effectiveSdfStrategy(prepared.sdf, SdfStrategy::Baked), SdfStrategy::Cells);
    const Agreement a = compare(prepared, 80, 45, 4);
    // As tight as measured on llvmpipe: 160 of 220 samples hit, no id or depth differs.
    EXPECT_GT(a.sdfHits, a.sampled * 2 / 3);
    EXPECT_EQ(a.idMismatches, 0) << a.firstProblem;
    EXPECT_EQ(a.depthMismatches, 0) << a.firstProblem;
    EXPECT_EQ(a.gpuMisses, 0) << a.firstProblem;
}

// The horizon fault: every pixel of the rows around the horizon of the 4,096-sphere tree at
// 160x90 (rows 16 to 26; the horizon is row 21). Rays there run past the cells' grid, where the
// whole program runs; when that program evaluated the tree whole at each step, llvmpipe's loop
// budget (shared by every loop of an invocation) ran out within a few steps and the pixel kept
// the background: 52 pixels of row 21 missed the plane the CPU's rays hit. The tree's halves
// are now skipped by their floors' boxes there (sdf_bvh.cpp, isFlooredUnionPart).
TEST(CpuGpuAgreement, CellsOnTheLargestSmoothTreeAlongTheHorizon) {
    const PreparedScene prepared = openRepositoryScene("samples/bench/tree_4096.json");
    const Agreement a = compare(prepared, 160, 90, 1, SdfStrategy::Cells, 16, 27);
    // As tight as measured on llvmpipe: of 1,760 pixels, the 852 below the horizon hit, none
    // differs.
    EXPECT_GT(a.sdfHits, a.sampled / 3);
    EXPECT_EQ(a.gpuMisses, 0) << a.firstProblem;
    EXPECT_EQ(a.idMismatches, 0) << a.firstProblem;
    EXPECT_EQ(a.depthMismatches, 0) << a.firstProblem;
}

// Where every surface lies inside the cells' grid (no plane, no infinite repetition), marches
// end where their rays leave the grid's cube (sdfRayEnd in common/sdf_cells.glsl) instead of
// running the whole program outside it to the farthest distance: the 1,000-shape grid, whose
// rays mostly pass between its shapes, against CPU ray casts that march to the end. A cube
// placed wrong, or a flag set for a scene with a plane, would lose hits.
TEST(CpuGpuAgreement, CellsOnABoundedSceneEndRaysAtTheGrid) {
    const PreparedScene grid = openRepositoryScene("samples/bench/grid_1000.json");
    const PreparedScene tree = openRepositoryScene("samples/bench/tree_256.json");
    sharedRenderer(); // the context
    const auto everySurfaceInside = [](const PreparedScene& prepared) {
        const GpuScene gpu = uploadScene(prepared, SdfStrategy::Cells);
        GpuSdfCellHeader header;
        glGetNamedBufferSubData(gpu.sdfCells.id(), 0, sizeof header, &header);
        return header.info.w;
    };
    EXPECT_EQ(everySurfaceInside(grid), 1u);
    EXPECT_EQ(everySurfaceInside(tree), 0u); // its plane reaches past any grid
    const Agreement a = compare(grid, 128, 72, 1, SdfStrategy::Cells);
    // As tight as measured on llvmpipe: 2,099 of 9,216 pixels hit; 1 id differs, a ray grazing
    // a shape it never enters, which the CPU's march stopped on (within its hit threshold) and
    // the GPU's stepped past; no depth differs. (Before far cells took the program's floor,
    // 3 ids differed, rays the GPU's march stopped on and the CPU's passed.)
    EXPECT_GT(a.sdfHits, a.sampled / 10);
    EXPECT_EQ(a.gpuMisses, 0) << a.firstProblem;
    EXPECT_EQ(a.idMismatches, a.grazes) << a.firstProblem;
    EXPECT_LE(a.grazes, 1); // as measured
    EXPECT_EQ(a.depthMismatches, 0) << a.firstProblem;
}

// Every operation, modifier and profile of the samples through the Cells strategy: depth and
// ids as the CPU casts them through the whole program. (Its far cells' constants change soft
// shadows, not what is hit: see sdf/cell_pruning.hpp.)
TEST(CpuGpuAgreement, CellsOnEveryOperationAndModifier) {
    for (const char* name : {"csg", "modifiers", "smooth_blend"}) {
        SCOPED_TRACE(name);
        const PreparedScene prepared =
            openRepositoryScene(std::string("samples/scenes/") + name + ".json");
        const Agreement a = compare(prepared, 128, 72, 2, SdfStrategy::Cells);
        // As measured on llvmpipe: at least 391 of 2304 samples hit, no id or depth differs.
        EXPECT_GT(a.sdfHits, a.sampled / 6);
        EXPECT_EQ(a.idMismatches, 0) << a.firstProblem;
        EXPECT_EQ(a.depthMismatches, 0) << a.firstProblem;
        EXPECT_EQ(a.gpuMisses, 0) << a.firstProblem;
    }
}
