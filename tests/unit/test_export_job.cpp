// The editor's export job (editor/export_job.hpp): the form checked before anything starts, an
// export on the worker thread that writes the file and reports its progress and outcome, a
// cancel that leaves nothing behind, errors reported as the outcome, the selected node found by
// its path in the scene as it is now (after edits that moved it), and the document's scene free
// to change while the export runs.
#include "editor/export_job.hpp"

#include "scene/scene_json.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstring>
#include <thread>

using namespace rmsc;
using editor::ExportForm;
using editor::ExportJob;

namespace {

Scene sceneOf(const std::string& sdfJson) {
    Diagnostics diagnostics;
    std::optional<Scene> scene =
        parseScene(R"({"version": 1, "materials": {"red": {"base_color": [1, 0, 0]}}, "sdf": )" +
                       sdfJson + "}",
                   "scene.json", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.format();
    return scene ? std::move(*scene) : Scene{};
}

const char* kTwoShapes = R"({"op": "union", "children": [
    {"shape": "sphere", "radius": 0.3, "material": "red"},
    {"shape": "box", "position": [2, 0, 0], "half_extents": [0.2, 0.3, 0.4]}]})";

// The POSITION bounds of a .glb's first primitive (its accessor's min and max).
Aabb glbBounds(const std::string& glb) {
    Aabb box;
    if (glb.size() < 20) return box;
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    const nlohmann::json doc = nlohmann::json::parse(glb.substr(20, jsonLength));
    for (const auto& primitive : doc["meshes"][0]["primitives"]) {
        const auto& accessor = doc["accessors"][primitive["attributes"]["POSITION"].get<int>()];
        box.add(glm::vec3(accessor["min"][0], accessor["min"][1], accessor["min"][2]));
        box.add(glm::vec3(accessor["max"][0], accessor["max"][1], accessor["max"][2]));
    }
    return box;
}

class ExportJobTest : public rmsc::test::TempFolderTest {
  protected:
    int filesIn() const {
        int files = 0;
        for (const auto& entry : std::filesystem::directory_iterator(folder_)) {
            (void)entry;
            ++files;
        }
        return files;
    }
};

} // namespace

TEST(ExportForm, PointerOfASelectedNode) {
    EXPECT_EQ(editor::sdfNodePointer({}), "/sdf");
    EXPECT_EQ(editor::sdfNodePointer({1, 0}), "/sdf/children/1/children/0");
}

TEST_F(ExportJobTest, FormIsCheckedBeforeAnythingStarts) {
    const Scene scene = sceneOf(kTwoShapes);
    ExportJob job;
    std::string error;
    ExportForm form;
    form.path = (folder_ / "mesh.ply").string();
    EXPECT_FALSE(job.start(scene, form, 1, error));
    EXPECT_NE(error.find("expected a .glb, .gltf, .obj or .stl"), std::string::npos) << error;
    form.path = (folder_ / "missing" / "mesh.glb").string();
    EXPECT_FALSE(job.start(scene, form, 1, error));
    EXPECT_NE(error.find("not a writable folder"), std::string::npos) << error;
    form.path = (folder_ / "mesh.glb").string();
    form.byVoxel = true;
    form.voxel = 0.0f;
    EXPECT_FALSE(job.start(scene, form, 1, error));
    EXPECT_NE(error.find("Voxel size"), std::string::npos) << error;
    form.byVoxel = false;
    form.resolution = 0;
    EXPECT_FALSE(job.start(scene, form, 1, error));
    EXPECT_NE(error.find("Resolution"), std::string::npos) << error;
    form.resolution = 16;
    form.tolerance = -0.1f;
    EXPECT_FALSE(job.start(scene, form, 1, error));
    EXPECT_NE(error.find("Tolerance"), std::string::npos) << error;
    form.tolerance = 0.1f;
    form.clip = true;
    form.bounds = Aabb{glm::vec3(0.0f), glm::vec3(1.0f, -1.0f, 1.0f)};
    EXPECT_FALSE(job.start(scene, form, 1, error));
    EXPECT_NE(error.find("Bounds"), std::string::npos) << error;
    EXPECT_FALSE(job.running());
    EXPECT_FALSE(job.takeOutcome());
    EXPECT_EQ(filesIn(), 0);
}

TEST_F(ExportJobTest, ExportsTheSelectedNodeOnItsThread) {
    Scene scene = sceneOf(kTwoShapes);
    // An edit after the scene was read: the box is now the first child, so its node still
    // carries the pointer it was read with (/sdf/children/1); the job finds it by its place now.
    std::swap(scene.sdf->children[0], scene.sdf->children[1]);
    ExportJob job;
    ExportForm form;
    form.path = (folder_ / "box.glb").string();
    form.node = editor::sdfNodePointer({0});
    form.resolution = 16;
    std::string error;
    ASSERT_TRUE(job.start(scene, form, 2, error)) << error;
    // The document's scene may change (or go) while the job runs: it exported a copy.
    scene = Scene{};
    job.wait();
    EXPECT_FALSE(job.running());
    EXPECT_DOUBLE_EQ(job.progress(), 1.0);
    const std::optional<editor::ExportOutcome> outcome = job.takeOutcome();
    ASSERT_TRUE(outcome);
    EXPECT_TRUE(outcome->written) << outcome->message;
    EXPECT_FALSE(outcome->cancelled);
    EXPECT_GT(outcome->triangles, 100u);
    EXPECT_EQ(outcome->materials, 1u);
    EXPECT_NE(outcome->message.find("exported /sdf/children/0 to"), std::string::npos)
        << outcome->message;
    EXPECT_FALSE(job.takeOutcome()) << "an outcome is handed out once";
    // The box (half extents 0.2, 0.3, 0.4 at x = 2), not the sphere.
    const Aabb box = glbBounds(read(folder_ / "box.glb"));
    EXPECT_NEAR(box.center().x, 2.0f, 1e-3f);
    EXPECT_NEAR(box.max.y - box.min.y, 0.6f, 1e-3f);
    EXPECT_NEAR(box.max.z - box.min.z, 0.8f, 1e-3f);
}

TEST_F(ExportJobTest, CancelWritesNothing) {
    const Scene scene = sceneOf(R"({"shape": "torus"})");
    ExportJob job;
    ExportForm form;
    form.path = (folder_ / "torus.stl").string();
    form.resolution = 400; // seconds of work: cancelled long before it ends
    std::string error;
    ASSERT_TRUE(job.start(scene, form, 1, error)) << error;
    EXPECT_TRUE(job.running());
    EXPECT_FALSE(job.start(scene, form, 1, error)) << "one export at a time";
    EXPECT_NE(error.find("an export is running"), std::string::npos) << error;
    job.cancel();
    const auto start = std::chrono::steady_clock::now();
    job.wait();
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0)
        << "the export stops soon after the cancel";
    const std::optional<editor::ExportOutcome> outcome = job.takeOutcome();
    ASSERT_TRUE(outcome);
    EXPECT_TRUE(outcome->cancelled);
    EXPECT_FALSE(outcome->written);
    EXPECT_NE(outcome->message.find("was not written"), std::string::npos) << outcome->message;
    EXPECT_EQ(filesIn(), 0) << "no file and no temporary file";
}

TEST_F(ExportJobTest, ErrorsAreTheOutcomeAndBoundsExportUnboundedContent) {
    const Scene scene = sceneOf(R"({"op": "union", "children": [
        {"shape": "sphere", "radius": 0.3}, {"shape": "plane"}]})");
    const editor::ExportContent content = editor::describeExportContent(scene, "/sdf");
    EXPECT_TRUE(content.found);
    EXPECT_FALSE(content.bounded);
    EXPECT_EQ(content.unboundedBy, "/sdf/children/1");
    const editor::ExportContent sphere = editor::describeExportContent(scene, "/sdf/children/0");
    EXPECT_TRUE(sphere.bounded);
    EXPECT_NEAR(sphere.box.max.x, 0.3f, 0.05f);
    EXPECT_FALSE(editor::describeExportContent(scene, "/sdf/children/5").found);

    ExportJob job;
    ExportForm form;
    form.path = (folder_ / "all.obj").string();
    form.resolution = 16;
    std::string error;
    ASSERT_TRUE(job.start(scene, form, 1, error)) << error;
    job.wait();
    std::optional<editor::ExportOutcome> outcome = job.takeOutcome();
    ASSERT_TRUE(outcome);
    EXPECT_FALSE(outcome->written);
    EXPECT_NE(outcome->message.find("/sdf/children/1: the content reaches infinity"),
              std::string::npos)
        << outcome->message;
    EXPECT_EQ(filesIn(), 0);
    // With bounds the same content exports, closed at the box's faces.
    form.clip = true;
    form.bounds = Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)};
    ASSERT_TRUE(job.start(scene, form, 1, error)) << error;
    job.wait();
    outcome = job.takeOutcome();
    ASSERT_TRUE(outcome);
    EXPECT_TRUE(outcome->written) << outcome->message;
    EXPECT_TRUE(std::filesystem::exists(folder_ / "all.obj"));
    EXPECT_TRUE(std::filesystem::exists(folder_ / "all.mtl"));
}
