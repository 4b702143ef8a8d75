// Skinning on the GPU: a skinned mesh drawn with its joint matrices in the vertex shader
// matches the same pose skinned on the CPU and drawn as plain vertices (colour, view depth,
// normal and object id), for a strip bent 90 degrees by its second joint (with a JOINTS_1 /
// WEIGHTS_1 set) and for RiggedSimple; and a new pose uploads the joint matrices only.
#include "gltf_builder.hpp"
#include "gpu_test_support.hpp"

#include "prepare/scene_animation.hpp"
#include "render/readback.hpp"
#include "scene/scene_json.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace rmsc;
using namespace rmsc::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kSize = 128;

// A folder of this test's own: ctest runs the tests of this file in parallel processes.
fs::path folder() {
    const fs::path f = fs::temp_directory_path() / "rmsc_gpu_gltf_skinning" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(f);
    return f;
}

// A strip along +y from 0 to 2, x from 0 to 0.4 (vertices 0-1 at y 0, 2-3 at 1, 4-5 at 2), on
// node 0 (translated by (5, 0, 0), which skinning ignores) with skin 0: joint node 1 at the
// origin, its child joint node 2 at (0, 1, 0), which animation 0 turns from identity (t = 0) to
// 90 degrees about +z (t = 1). Rows 0 and 1 follow joint 0; vertex 4 is 0.75 joint 1 (set 0)
// and 0.25 joint 0 (set 1), vertex 5 half and half (set 0).
std::string bentStrip() {
    GltfBuilder b;
    const float w = 0.4f;
    const int p =
        b.accessor(std::vector<float>{0, 0, 0, w, 0, 0, 0, 1, 0, w, 1, 0, 0, 2, 0, w, 2, 0},
                   kFloatType, "VEC3", 6);
    const int joints0 = b.accessor(std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                                             0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0},
                                   kUnsignedByte, "VEC4", 6);
    const int weights0 =
        b.accessor(std::vector<float>{1, 0, 0, 0, 1,     0, 0, 0, 1,    0,    0, 0,
                                      1, 0, 0, 0, 0.75f, 0, 0, 0, 0.5f, 0.5f, 0, 0},
                   kFloatType, "VEC4", 6);
    const int joints1 = b.accessor(std::vector<std::uint8_t>(24, 0), kUnsignedByte, "VEC4", 6);
    const int weights1 = b.accessor(std::vector<float>{0, 0, 0, 0, 0,     0, 0, 0, 0, 0, 0, 0,
                                                       0, 0, 0, 0, 0.25f, 0, 0, 0, 0, 0, 0, 0},
                                    kFloatType, "VEC4", 6);
    const int indices = b.accessor(std::vector<std::uint16_t>{0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4},
                                   kUnsignedShort, "SCALAR", 12);
    const int inverseBind =
        b.accessor(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                      1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
                   kFloatType, "MAT4", 2);
    const float h = std::sqrt(0.5f);
    const int times = b.accessor(std::vector<float>{0, 1}, kFloatType, "SCALAR", 2);
    const int rotations =
        b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, h, h}, kFloatType, "VEC4", 2);
    return b.text(
        {{"scenes", {{{"nodes", {0, 1}}}}},
         {"nodes",
          {{{"mesh", 0}, {"skin", 0}, {"translation", {5, 0, 0}}},
           {{"children", {2}}},
           {{"translation", {0, 1, 0}}}}},
         {"skins", {{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBind}}}},
         {"materials",
          {{{"pbrMetallicRoughness",
             {{"baseColorFactor", {0.8, 0.5, 0.3, 1}},
              {"metallicFactor", 0},
              {"roughnessFactor", 0.5}}}}}},
         {"meshes",
          {{{"primitives",
             {{{"attributes",
                {{"POSITION", p},
                 {"JOINTS_0", joints0},
                 {"WEIGHTS_0", weights0},
                 {"JOINTS_1", joints1},
                 {"WEIGHTS_1", weights1}}},
               {"indices", indices},
               {"material", 0}}}}}}},
         {"animations",
          {{{"samplers", {{{"input", times}, {"output", rotations}}}},
            {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}}}}}}}});
}

// A scene placing `file` once, showing its animation 0 at `time`, lit by a directional light
// and a dim ambient term, black background.
PreparedScene openPosed(const fs::path& file, double time) {
    const json scene = {
        {"version", 1},
        {"camera", {{"position", {-0.3, 1, 5}}, {"target", {-0.3, 1, 0}}, {"fov", 45}}},
        {"render", {{"ambient", {0.2, 0.2, 0.2}}, {"background", {0, 0, 0}}}},
        {"lights", {{{"type", "directional"}, {"direction", {-0.3, -0.4, -1}}, {"intensity", 2}}}},
        {"meshes", {{{"file", file.string()}, {"animation", "0"}, {"time", time}}}}};
    const fs::path path = folder() / "scene.json";
    std::ofstream(path, std::ios::binary) << scene.dump();
    Diagnostics d;
    std::optional<PreparedScene> prepared = openScene(path, d);
    EXPECT_TRUE(prepared) << d.format();
    if (!prepared) throw std::runtime_error("cannot open the test scene");
    return std::move(*prepared);
}

fs::path writeStrip() {
    const fs::path file = folder() / "strip.gltf";
    std::ofstream(file, std::ios::binary) << bentStrip();
    return file;
}

// The pose skinned on the CPU only: the skinned primitives lose what the GPU skins them with,
// so they are uploaded as their CPU-posed vertices and drawn as plain ones.
void dropGpuSkins(PreparedScene& prepared) {
    for (MeshAsset& asset : prepared.assets) {
        for (MeshPrimitive& p : asset.primitives) {
            p.bindVertices.clear();
            p.skin.clear();
            p.jointBase = -1;
        }
        asset.jointMatrices.clear();
    }
}

int skinnedPrimitives(const PreparedScene& prepared) {
    int count = 0;
    for (const MeshAsset& asset : prepared.assets)
        for (const MeshPrimitive& p : asset.primitives)
            count += p.jointBase >= 0 ? 1 : 0;
    return count;
}

struct Targets {
    Pixels<float> color, depth, normals;
    Pixels<std::uint32_t> ids;
};

Targets draw(const GpuScene& gpu, const PreparedScene& prepared, const Camera& camera) {
    FrameTargets targets = createFrameTargets(kSize, kSize);
    sharedRenderer().render(gpu, camera, prepared.scene.render, targets);
    expectNoGlErrors();
    return {readHdrColor(targets), readViewDepth(targets), readNormals(targets),
            readObjectIds(targets)};
}

Targets draw(const PreparedScene& prepared, const Camera& camera) {
    sharedRenderer(); // the context uploadScene needs
    const GpuScene gpu = uploadScene(prepared);
    return draw(gpu, prepared, camera);
}

int meshPixels(const Targets& t) {
    int count = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            count += t.ids.at(x, y)[0] == kMeshIdBase ? 1 : 0;
    return count;
}

int differingIds(const Targets& a, const Targets& b) {
    int count = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            count += a.ids.at(x, y)[0] != b.ids.at(x, y)[0] ? 1 : 0;
    return count;
}

// The GPU-skinned frame against the CPU-posed one (float against double arithmetic, the
// targets RGBA16F but view depth R32F). Measured on llvmpipe: no pixel's id differs; for the
// strip nothing differs at all; for RiggedSimple colours by at most 1.2e-4, view depth by 1.3e-6
// of itself and normals by one half-float step (4.9e-4). The bounds: two pixels of coverage (an
// edge through a pixel centre), two half-float steps of colour at 1 (2 / 1024), 4e-6 of the
// depth, one half-float step of normal at 1 (1 / 1024).
void expectSameFrame(const Targets& gpu, const Targets& cpu) {
    EXPECT_LE(differingIds(gpu, cpu), 2) << "the skinned mesh covers other pixels than the pose";
    float color = 0.0f, depth = 0.0f, normal = 0.0f;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (gpu.ids.at(x, y)[0] != kMeshIdBase || cpu.ids.at(x, y)[0] != kMeshIdBase) continue;
            for (int c = 0; c < 3; ++c) {
                color = std::max(color, std::abs(gpu.color.at(x, y)[c] - cpu.color.at(x, y)[c]));
                normal =
                    std::max(normal, std::abs(gpu.normals.at(x, y)[c] - cpu.normals.at(x, y)[c]));
            }
            depth = std::max(depth, std::abs(gpu.depth.at(x, y)[0] - cpu.depth.at(x, y)[0]) /
                                        cpu.depth.at(x, y)[0]);
        }
    EXPECT_LE(color, 2.0f / 1024.0f);
    EXPECT_LE(depth, 4e-6f); // relative
    EXPECT_LE(normal, 1.0f / 1024.0f);
}

} // namespace

TEST(GltfSkinning, BentStripOnTheGpuMatchesTheCpuPose) {
    const fs::path file = writeStrip();
    const PreparedScene rest = openPosed(file, 0.0);
    const PreparedScene bent = openPosed(file, 1.0);
    PreparedScene cpu = openPosed(file, 1.0);
    ASSERT_EQ(skinnedPrimitives(bent), 1);
    dropGpuSkins(cpu);
    const Camera& camera = bent.scene.camera;
    const Targets restFrame = draw(rest, camera);
    const Targets gpuFrame = draw(bent, camera);
    const Targets cpuFrame = draw(cpu, camera);
    // The bend shows: a shader that ignored the joints would draw the rest pose.
    ASSERT_GT(meshPixels(cpuFrame), 300);
    EXPECT_GT(differingIds(restFrame, cpuFrame), meshPixels(cpuFrame) / 5);
    expectSameFrame(gpuFrame, cpuFrame);
}

TEST(GltfSkinning, RiggedSimpleOnTheGpuMatchesTheCpuPose) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    const fs::path file = gltfSamples() / "RiggedSimple.gltf";
    for (const double time : {0.5, 1.0, 2.0}) {
        const PreparedScene posed = openPosed(file, time);
        PreparedScene cpu = openPosed(file, time);
        ASSERT_GE(skinnedPrimitives(posed), 1);
        dropGpuSkins(cpu);
        // Framed on the rest pose's bounds, seen from the side it bends towards.
        const MeshAsset& asset = posed.assets.at(0);
        const glm::vec3 centre = 0.5f * (asset.boundsMin + asset.boundsMax);
        Camera camera = posed.scene.camera;
        camera.target = centre;
        camera.position = centre + glm::vec3(12.0f, 2.0f, 14.0f);
        const Targets gpuFrame = draw(posed, camera);
        const Targets cpuFrame = draw(cpu, camera);
        SCOPED_TRACE("time " + std::to_string(time));
        ASSERT_GT(meshPixels(cpuFrame), 300);
        expectSameFrame(gpuFrame, cpuFrame);
    }
}

TEST(GltfSkinning, ANewPoseUploadsOnlyTheJointMatrices) {
    const fs::path file = writeStrip();
    PreparedScene prepared = openPosed(file, 0.0);
    sharedRenderer(); // the context uploadScene needs
    GpuScene gpu = uploadScene(prepared);
    GpuMesh& mesh = gpu.meshes.at(0);
    ASSERT_EQ(mesh.primitives.size(), 1u);
    const GLuint vertexBuffer = mesh.primitives[0].vertices.id();
    const std::size_t bytes = prepared.assets[0].primitives[0].vertices.size() * sizeof(MeshVertex);
    std::vector<unsigned char> before(bytes), after(bytes);
    glGetNamedBufferSubData(vertexBuffer, 0, GLsizeiptr(bytes), before.data());

    Diagnostics d;
    ASSERT_TRUE(setSceneAnimationTime(prepared, 1.0, d)) << d.format();
    updateMeshVertices(prepared.assets[0], mesh);
    EXPECT_EQ(mesh.vertexBytesUploaded, 0u);
    EXPECT_EQ(mesh.jointBytesUploaded, prepared.assets[0].jointMatrices.size() * sizeof(glm::mat4));
    EXPECT_EQ(prepared.assets[0].jointMatrices.size(), 3u); // the node's world, two joints
    glGetNamedBufferSubData(vertexBuffer, 0, GLsizeiptr(bytes), after.data());
    EXPECT_EQ(before, after) << "the vertex buffer changed";

    // The matrices alone bend it: drawn, it is the CPU pose at t = 1.
    PreparedScene cpu = openPosed(file, 1.0);
    dropGpuSkins(cpu);
    const Camera& camera = prepared.scene.camera;
    expectSameFrame(draw(gpu, prepared, camera), draw(cpu, camera));
}
