// The edited scene compiled on a worker (editor/scene_preparing_job.hpp): a result per
// revision with the scene's program and its bounded twin, the newest request winning, and a
// scene that does not compile reported with the reader's message.
#include "editor/scene_preparing_job.hpp"

#include "core/diagnostics.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace rmsc;

namespace {

Scene sceneOf(const std::string& children) {
    Diagnostics diagnostics;
    const std::optional<Scene> scene = parseScene(
        R"({"version": 1, "sdf": {"children": [)" + children + "]}}", "edited.json", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.format();
    return scene ? *scene : Scene{};
}

std::string spheres(int count) {
    std::string out;
    for (int i = 0; i < count; ++i)
        out += (i ? ", " : "") +
               std::string(R"({"shape": "sphere", "radius": 0.2, "position": [)") +
               std::to_string(i) + ", 0, 0]}";
    return out;
}

} // namespace

TEST(ScenePreparingJob, PreparesTheNewestRevisionWithItsBoundedProgram) {
    editor::ScenePreparingJob job(diskFileSource());
    job.request(1, sceneOf(spheres(3)));
    job.request(2, sceneOf(spheres(40))); // before or while 1 is prepared: 2 is what is left
    job.waitUntilIdle();
    std::optional<editor::ScenePreparingResult> result = job.take();
    ASSERT_TRUE(result);
    EXPECT_EQ(result->revision, 2u);
    ASSERT_TRUE(result->prepared) << result->error;
    // 40 shapes and the 39 unions of them, and with the hierarchy its box tests besides (79
    // more, measured).
    EXPECT_EQ(result->prepared->sdf.instructions.size(), 79u);
    EXPECT_GT(result->bounded.instructions.size(), result->prepared->sdf.instructions.size());
    EXPECT_FALSE(job.take()); // taken once
    // The same as compiling it here.
    const editor::ScenePreparingResult here =
        editor::prepareEditedScene(sceneOf(spheres(40)), 2, diskFileSource());
    ASSERT_TRUE(here.prepared);
    EXPECT_EQ(here.prepared->sdf.instructions.size(), result->prepared->sdf.instructions.size());
    EXPECT_EQ(here.bounded.instructions.size(), result->bounded.instructions.size());
}

TEST(ScenePreparingJob, ASceneThatDoesNotCompileIsReported) {
    editor::ScenePreparingJob job(diskFileSource());
    Diagnostics diagnostics;
    std::optional<Scene> scene = parseScene(
        R"({"version": 1, "materials": {"m": {"base_color_texture": "no-such-image.png"}},
            "sdf": {"shape": "sphere", "material": "m"}})",
        "edited.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.format();
    job.request(7, *scene);
    job.waitUntilIdle();
    const std::optional<editor::ScenePreparingResult> result = job.take();
    ASSERT_TRUE(result);
    EXPECT_EQ(result->revision, 7u);
    EXPECT_FALSE(result->prepared);
    EXPECT_NE(result->error.find("no-such-image.png"), std::string::npos) << result->error;
}

// Mesh instances whose files do not load are left out, so the rest of the scene still draws:
// each instance keeps its index (the missing ones draw nothing) and the warning names the file.
// A scene that fails for anything else as well is not drawn.
TEST(ScenePreparingJob, MeshesThatDoNotLoadAreLeftOutAndSaid) {
    const std::string assets = std::string(RMSC_TEST_SOURCE_DIR) + "/samples/assets/";
    Diagnostics diagnostics;
    std::optional<Scene> scene =
        parseScene(R"({"version": 1, "meshes": [{"file": ")" + assets + R"(cube.gltf"},
            {"file": "no-such-mesh.glb"}, {"file": ")" +
                       assets + R"(sphere.gltf"},
            {"file": "no-such-mesh.glb", "position": [1, 0, 0]}],
            "sdf": {"shape": "sphere"}})",
                   "edited.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.format();
    const editor::ScenePreparingResult result =
        editor::prepareEditedScene(*scene, 3, diskFileSource());
    ASSERT_TRUE(result.prepared) << result.error;
    EXPECT_TRUE(result.error.empty());
    EXPECT_NE(result.warning.find("no-such-mesh.glb"), std::string::npos) << result.warning;
    EXPECT_NE(result.warning.find("/meshes/1"), std::string::npos) << result.warning;
    EXPECT_NE(result.warning.find("/meshes/3"), std::string::npos) << result.warning;
    const PreparedScene& prepared = *result.prepared;
    EXPECT_EQ(prepared.scene.meshes.size(), 4u) << "the document's instances, all of them";
    ASSERT_EQ(prepared.instanceAsset.size(), 4u);
    EXPECT_GE(prepared.instanceAsset[0], 0);
    EXPECT_EQ(prepared.instanceAsset[1], -1);
    EXPECT_GE(prepared.instanceAsset[2], 0);
    EXPECT_EQ(prepared.instanceAsset[3], -1);
    EXPECT_NE(prepared.instanceAsset[0], prepared.instanceAsset[2]);
    EXPECT_EQ(prepared.assets.size(), 2u);
    EXPECT_FALSE(prepared.sdf.instructions.empty());

    // And a texture missing as well: not drawn.
    std::optional<Scene> both = parseScene(
        R"({"version": 1, "meshes": [{"file": "no-such-mesh.glb"}],
            "materials": {"m": {"base_color_texture": "no-such-image.png"}},
            "sdf": {"shape": "sphere", "material": "m"}})",
        "edited.json", diagnostics);
    ASSERT_TRUE(both) << diagnostics.format();
    const editor::ScenePreparingResult broken =
        editor::prepareEditedScene(*both, 4, diskFileSource());
    EXPECT_FALSE(broken.prepared);
    EXPECT_NE(broken.error.find("no-such-image.png"), std::string::npos) << broken.error;
}

// A request's scene is copied over the scene of an earlier request the worker is done with
// (its memory used again): each result is still its own scene's, whatever the earlier ones
// held, larger or smaller, named otherwise.
TEST(ScenePreparingJob, ScenesCopiedOverEarlierOnesArePreparedAsTheirOwn) {
    editor::ScenePreparingJob job(diskFileSource());
    const std::vector<int> counts{40, 3, 40, 7, 7, 1};
    for (std::size_t i = 0; i < counts.size(); ++i) {
        Scene scene = sceneOf(spheres(counts[i]));
        scene.sdf->children[0].name = "first of " + std::to_string(counts[i]);
        job.request(i + 1, scene);
        job.waitUntilIdle();
        const std::optional<editor::ScenePreparingResult> result = job.take();
        ASSERT_TRUE(result);
        ASSERT_TRUE(result->prepared) << result->error;
        EXPECT_EQ(result->revision, i + 1);
        // n shapes and the n - 1 unions of them.
        EXPECT_EQ(result->prepared->sdf.instructions.size(), std::size_t(2 * counts[i] - 1));
        ASSERT_EQ(result->prepared->scene.sdf->children.size(), std::size_t(counts[i]));
        EXPECT_EQ(result->prepared->scene.sdf->children[0].name, scene.sdf->children[0].name);
        EXPECT_EQ(result->prepared->scene.sdf->children.back().transform.position,
                  scene.sdf->children.back().transform.position);
    }
}
