// The exporter's compute-shader sampler (render/gpu_field_sampler.hpp): its distances against
// the CPU evaluator's at the same lattice points, and exports sampled by it against exports
// sampled on the CPU, on llvmpipe.
#include "gpu_test_support.hpp"

#include "export/sdf_export.hpp"
#include "render/gpu_field_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// As the formula parity test: |gpu - cpu| <= kRelative * max(|cpu|, scale), the scale the
// content's size (the shaders' fused multiply-adds and library functions round differently).
constexpr float kRelative = 1e-4f;

std::function<SdfLattice(const SdfProgram&)> gpuSampler(std::optional<GpuFieldSampler>& keep,
                                                        std::string& error) {
    return [&keep, &error](const SdfProgram& program) -> SdfLattice {
        keep = GpuFieldSampler::create(program, error);
        if (!keep) return {};
        return [&keep](glm::vec3 origin, float spacing, const glm::ivec3* starts, std::size_t count,
                       int side, float* out) {
            return keep->sample(origin, spacing, starts, count, side, out);
        };
    };
}

void expectLatticeMatchesCpu(const std::string& sceneFile) {
    SCOPED_TRACE(sceneFile);
    sharedRenderer(); // the context
    const PreparedScene prepared = openRepositoryScene(sceneFile);
    Diagnostics diagnostics;
    const std::optional<ExportField> field =
        exportField(prepared.scene, "", std::nullopt, diagnostics);
    ASSERT_TRUE(field) << diagnostics.format();
    std::string error;
    const std::optional<GpuFieldSampler> sampler = GpuFieldSampler::create(*field->program, error);
    ASSERT_TRUE(sampler) << error;
    // Random lattices of 7^3 points over the content's box, spacing a tenth of its size.
    const glm::vec3 size = field->box.max - field->box.min;
    const float scale = std::max(size.x, std::max(size.y, size.z));
    const float spacing = 0.1f * scale;
    std::mt19937 random(7);
    std::uniform_int_distribution<int> at(-4, 8);
    std::vector<glm::ivec3> starts(24);
    for (glm::ivec3& s : starts)
        s = {at(random), at(random), at(random)};
    constexpr int kSide = 7;
    std::vector<float> gpu(starts.size() * kSide * kSide * kSide, -12345.0f);
    ASSERT_TRUE(
        sampler->sample(field->box.min, spacing, starts.data(), starts.size(), kSide, gpu.data()));
    int checked = 0, differing = 0;
    for (std::size_t s = 0, i = 0; s < starts.size(); ++s)
        for (int z = 0; z < kSide; ++z)
            for (int y = 0; y < kSide; ++y)
                for (int x = 0; x < kSide; ++x, ++i) {
                    const glm::vec3 p =
                        field->box.min + spacing * glm::vec3(starts[s] + glm::ivec3(x, y, z));
                    const float cpu = field->field.distance(p);
                    ++checked;
                    if (std::abs(gpu[i] - cpu) > kRelative * std::max(std::abs(cpu), scale) &&
                        ++differing <= 5)
                        ADD_FAILURE() << "at (" << p.x << ", " << p.y << ", " << p.z << "): GPU "
                                      << gpu[i] << ", CPU " << cpu;
                }
    EXPECT_EQ(differing, 0) << "of " << checked << " points";
    expectNoGlErrors();
}

// An export of `sceneFile` sampled by the GPU and one sampled on the CPU: both closed
// 2-manifolds, the same triangles within `share`.
void expectExportsAgree(const std::string& sceneFile, ExportSettings settings, double share) {
    SCOPED_TRACE(sceneFile);
    sharedRenderer();
    const PreparedScene prepared = openRepositoryScene(sceneFile);
    Diagnostics diagnostics;
    const std::optional<SdfExport> cpu = exportSdf(prepared.scene, settings, diagnostics);
    ASSERT_TRUE(cpu) << diagnostics.format();
    EXPECT_FALSE(cpu->latticeSampled);
    std::optional<GpuFieldSampler> keep;
    std::string error;
    settings.latticeSampler = gpuSampler(keep, error);
    const std::optional<SdfExport> gpu = exportSdf(prepared.scene, settings, diagnostics);
    ASSERT_TRUE(gpu) << diagnostics.format();
    ASSERT_TRUE(gpu->latticeSampled) << error;
    EXPECT_TRUE(meshTopology(gpu->mesh).closedManifold());
    EXPECT_EQ(countSelfIntersections(gpu->mesh), 0);
    const double cpuTriangles = double(cpu->mesh.triangles.size());
    EXPECT_NEAR(double(gpu->mesh.triangles.size()), cpuTriangles, share * cpuTriangles);
    EXPECT_EQ(gpu->grid.cells, cpu->grid.cells);
    expectNoGlErrors();
}

} // namespace

TEST(GpuFieldSampler, AgreesWithTheCpuEvaluatorOnTheCsgSample) {
    expectLatticeMatchesCpu("samples/scenes/csg.json");
}

TEST(GpuFieldSampler, AgreesWithTheCpuEvaluatorOnTheModifiersSample) {
    expectLatticeMatchesCpu("samples/scenes/modifiers.json");
}

TEST(GpuFieldSampler, AnExportSampledByTheGpuIsTheCpusMesh) {
    ExportSettings settings;
    settings.resolution = 40;
    expectExportsAgree("samples/scenes/pawn.json", settings, 0.01);
}

TEST(GpuFieldSampler, AnExportCutToBoundsIsCutTheSameOnTheGpu) {
    // The shapes sample stands on a plane: unbounded, so cut to a box, which the GPU's samples
    // must be cut to as well (uncut samples would leave the mesh open at the box's faces).
    ExportSettings settings;
    settings.resolution = 32;
    settings.bounds = Aabb{{-3.0f, -0.3f, -1.4f}, {3.0f, 1.2f, 1.6f}};
    expectExportsAgree("samples/scenes/shapes.json", settings, 0.01);
}
