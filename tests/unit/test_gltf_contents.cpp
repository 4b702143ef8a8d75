// What the viewer lists of a mesh's glTF file (editor/gltf_contents.hpp): its animations with
// their durations, its cameras and scenes; the view through a camera at the mesh's pose, placed
// by the mesh's transform; a mesh's "scene" choosing the glTF scene drawn, in the scene format
// and when preparing the scene.
#include "editor/gltf_contents.hpp"
#include "gltf_builder.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

using namespace rmsc;
using namespace rmsc::editor;
using namespace rmsc::test;
using nlohmann::json;

namespace {

// A triangle drawn by node 0 (scene "A") and by node 1 at x = 5 (scene "B"); camera 0 "Front"
// (perspective) on node 2 at z = 5 in scene A, moved by animation "Move" from y = 0 at t = 0 to
// y = 2 at t = 2; camera 1 (orthographic) on no node.
std::string contentsGltf() {
    GltfBuilder b;
    const int positions =
        b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloatType, "VEC3", 3);
    const int times = b.accessor(std::vector<float>{0, 2}, kFloatType, "SCALAR", 2);
    b.accessors[std::size_t(times)]["min"] = {0};
    b.accessors[std::size_t(times)]["max"] = {2};
    const int moves = b.accessor(std::vector<float>{0, 0, 5, 0, 2, 5}, kFloatType, "VEC3", 2);
    const json gltf = {
        {"scene", 0},
        {"scenes", {{{"name", "A"}, {"nodes", {0, 2}}}, {{"name", "B"}, {"nodes", {1}}}}},
        {"nodes",
         {{{"mesh", 0}},
          {{"mesh", 0}, {"translation", {5, 0, 0}}},
          {{"camera", 0}, {"translation", {0, 0, 5}}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", positions}}}}}}}}},
        {"cameras",
         {{{"name", "Front"},
           {"type", "perspective"},
           {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100}}}},
          {{"type", "orthographic"},
           {"orthographic", {{"xmag", 1}, {"ymag", 2}, {"znear", 0.1}, {"zfar", 50}}}}}},
        {"animations",
         {{{"name", "Move"},
           {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "translation"}}}}}},
           {"samplers", {{{"input", times}, {"output", moves}}}}}}}};
    return b.text(gltf);
}

// The glTF placed at (1, 0, 0) with scale 2, showing "Move" at 1 s, drawing glTF scene `scene`.
std::optional<PreparedScene> prepared(int scene, Diagnostics& d) {
    Scene s;
    MeshInstance mesh;
    mesh.file = "test.gltf";
    mesh.path = "mem/test.gltf";
    mesh.transform.position = {1, 0, 0};
    mesh.transform.scale = glm::vec3(2);
    mesh.animation = "Move";
    mesh.time = 1.0;
    mesh.gltfScene = scene;
    s.meshes.push_back(mesh);
    return prepareScene(s, memoryGltf(contentsGltf()), d);
}

} // namespace

TEST(GltfContents, ListsAnimationsCamerasAndScenes) {
    Diagnostics d;
    const std::optional<PreparedScene> p = prepared(-1, d);
    ASSERT_TRUE(p) << d.format();
    const std::optional<GltfContents> c = gltfContents(*p, 0);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->animations, std::vector<std::string>{"0 Move"});
    EXPECT_EQ(c->durations, std::vector<double>{2.0});
    EXPECT_EQ(c->cameras, (std::vector<std::string>{"0 Front", "1 (orthographic)"}));
    EXPECT_EQ(c->scenes, (std::vector<std::string>{"0 A", "1 B"}));
    EXPECT_EQ(c->scene, 0);
    EXPECT_EQ(c->animation, 0);
    EXPECT_FALSE(gltfContents(*p, 1)) << "no such mesh";
}

TEST(GltfContents, ViewThroughACameraAtThePoseInTheWorld) {
    Diagnostics d;
    const std::optional<PreparedScene> p = prepared(-1, d);
    ASSERT_TRUE(p) << d.format();
    std::string why;
    const std::optional<Camera> view = gltfCameraView(*p, 0, 0, why);
    ASSERT_TRUE(view) << why;
    // At 1 s the node is at (0, 1, 5); the mesh moves it to (1, 0, 0) + 2 * (0, 1, 5).
    EXPECT_NEAR(view->position.x, 1.0f, 1e-5f);
    EXPECT_NEAR(view->position.y, 2.0f, 1e-5f);
    EXPECT_NEAR(view->position.z, 10.0f, 1e-5f);
    const glm::vec3 forward = glm::normalize(view->target - view->position);
    EXPECT_NEAR(forward.z, -1.0f, 1e-5f) << "looks down the node's -Z";
    EXPECT_NEAR(view->up.y, 1.0f, 1e-5f);
    EXPECT_NEAR(view->nearPlane, 0.2f, 1e-6f) << "planes scale with the mesh";
    EXPECT_NEAR(view->fovYDegrees, glm::degrees(0.8f), 1e-3f);
    EXPECT_FALSE(gltfCameraView(*p, 0, 1, why)) << "camera 1 is on no node";
    EXPECT_NE(why.find("not placed"), std::string::npos) << why;
}

TEST(GltfContents, AMeshDrawsTheSceneItNames) {
    Diagnostics d;
    const std::optional<PreparedScene> p = prepared(1, d);
    ASSERT_TRUE(p) << d.format();
    EXPECT_EQ(gltfContents(*p, 0)->scene, 1);
    EXPECT_NEAR(p->assets[0].boundsMin.x, 5.0f, 1e-5f) << "scene B's node draws at x = 5";
    std::string why;
    EXPECT_FALSE(gltfCameraView(*p, 0, 0, why)) << "scene B places no camera";

    Diagnostics missing;
    EXPECT_FALSE(prepared(2, missing));
    EXPECT_NE(missing.format().find("there is no scene 2"), std::string::npos) << missing.format();
}

TEST(GltfContents, TheSceneKeyRoundTrips) {
    Diagnostics d;
    const std::optional<Scene> scene = parseScene(
        R"({"version": 1, "meshes": [{"file": "a.gltf", "scene": 1}, {"file": "b.gltf"}]})",
        "mem/scene.json", d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_EQ(scene->meshes[0].gltfScene, 1);
    EXPECT_EQ(scene->meshes[1].gltfScene, -1);
    const json written = json::parse(sceneToJson(*scene));
    EXPECT_EQ(written["meshes"][0]["scene"], 1);
    EXPECT_FALSE(written["meshes"][1].contains("scene"));
    Diagnostics bad;
    EXPECT_FALSE(parseScene(R"({"version": 1, "meshes": [{"file": "a.gltf", "scene": -1}]})",
                            "mem/scene.json", bad));
    EXPECT_NE(bad.format().find("/meshes/0/scene"), std::string::npos) << bad.format();
}
