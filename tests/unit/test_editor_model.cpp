// The editor model without a window: scene edits (insert, delete, duplicate, reparent and
// reorder SDF nodes; reorder meshes and lights), object-id mapping for picking and outlines,
// selection, undo/redo (including a multi-frame drag as one step), the dirty flag, save/load
// round trips, atomic saves with a backup, a failed save that keeps the old file and the edits,
// a save refused (nothing written) for a scene that would not load, and the file watcher.
#include "editor/document.hpp"
#include "editor/file_watcher.hpp"
#include "editor/fly_camera.hpp"
#include "editor/scene_edits.hpp"
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/operations.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <thread>
#include <unistd.h>

using namespace rmsc;
using namespace rmsc::editor;
namespace fs = std::filesystem;

namespace {

// root union { a: sphere, g: union { b: box, c: torus }, d: capsule }
Scene sampleScene() {
    Scene scene = emptyScene();
    SdfNode root;
    root.isGroup = true;
    root.name = "root";
    SdfNode a = makeShape(PrimitiveId::Sphere);
    a.name = "a";
    SdfNode g;
    g.isGroup = true;
    g.name = "g";
    g.transform.position = glm::vec3(2, 0, 0);
    SdfNode b = makeShape(PrimitiveId::Box);
    b.name = "b";
    SdfNode c = makeShape(PrimitiveId::Torus);
    c.name = "c";
    g.children = {b, c};
    SdfNode d = makeShape(PrimitiveId::Capsule);
    d.name = "d";
    root.children = {a, g, d};
    scene.sdf = root;
    return scene;
}

std::string nameAt(const Scene& scene, const std::vector<int>& path) {
    const SdfNode* node = findSdfNode(scene, path);
    return node ? node->name : "<none>";
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class EditorFiles : public ::testing::Test {
  protected:
    fs::path folder;
    void SetUp() override {
        folder = fs::temp_directory_path() /
                 ("rmsc-editor-" + std::to_string(::getpid()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder);
        fs::create_directories(folder);
    }
    void TearDown() override { fs::remove_all(folder); }
};

} // namespace

TEST(EditorSceneEdits, EveryNewGroupCompiles) {
    // The editor offers every operation of the catalogue: each new group must be valid, with
    // a second child for subtractions and a smoothness for the ops that need one.
    for (const OperationSpec& spec : operationCatalogue()) {
        SCOPED_TRACE(std::string(spec.name));
        const SdfNode group = editor::makeGroup(spec.op);
        EXPECT_EQ(group.op, spec.op);
        EXPECT_EQ(group.children.size(),
                  spec.combination == SdfOpCombination::Subtraction ? 2u : 1u);
        EXPECT_EQ(group.smoothness > 0.0f, takesSmoothness(spec.op));
        Diagnostics diagnostics;
        EXPECT_TRUE(compileSdf(group, 0, "new.json", diagnostics)) << diagnostics.format();
    }
}

TEST(EditorSceneEdits, FindsNodesByPathAndRejectsBadPaths) {
    const Scene scene = sampleScene();
    EXPECT_EQ(nameAt(scene, {}), "root");
    EXPECT_EQ(nameAt(scene, {1, 1}), "c");
    EXPECT_EQ(findSdfNode(scene, {3}), nullptr);
    EXPECT_EQ(findSdfNode(scene, {0, 0}), nullptr); // a shape has no children
    EXPECT_FALSE(selectionValid(scene, Selection::mesh(0)));
    EXPECT_TRUE(selectionValid(scene, Selection::light(0)));
}

TEST(EditorSceneEdits, InsertGoesIntoSelectedGroupOrAfterSelectedShape) {
    Scene scene = sampleScene();
    EXPECT_EQ(insertSdfNode(scene, Selection::sdf({1}), makeShape(PrimitiveId::Plane)),
              (std::vector<int>{1, 2}));
    EXPECT_EQ(insertSdfNode(scene, Selection::sdf({0}), makeShape(PrimitiveId::Ellipsoid)),
              (std::vector<int>{1}));
    EXPECT_EQ(nameAt(scene, {1}), "ellipsoid");
    EXPECT_EQ(nameAt(scene, {2}), "g");
    EXPECT_EQ(insertSdfNode(scene, Selection::none(), makeShape(PrimitiveId::Sphere)),
              (std::vector<int>{4}));
}

TEST(EditorSceneEdits, InsertIntoEmptySceneOrShapeRootMakesAGroup) {
    Scene scene = emptyScene();
    EXPECT_EQ(insertSdfNode(scene, Selection::none(), makeShape(PrimitiveId::Box)),
              (std::vector<int>{0}));
    ASSERT_TRUE(scene.sdf && scene.sdf->isGroup);
    scene.sdf = makeShape(PrimitiveId::Sphere);
    EXPECT_EQ(insertSdfNode(scene, Selection::sdf({}), makeShape(PrimitiveId::Box)),
              (std::vector<int>{1}));
    EXPECT_TRUE(scene.sdf->isGroup);
    EXPECT_EQ(scene.sdf->children.size(), 2u);
}

TEST(EditorSceneEdits, DeleteRemovesGroupsLeftEmpty) {
    Scene scene = sampleScene();
    ASSERT_TRUE(deleteSdfNode(scene, {1, 0}));
    ASSERT_TRUE(deleteSdfNode(scene, {1, 0})); // g is now empty and goes too
    EXPECT_EQ(scene.sdf->children.size(), 2u);
    EXPECT_EQ(nameAt(scene, {1}), "d");
    EXPECT_FALSE(deleteSdfNode(scene, {7}));
    ASSERT_TRUE(deleteSdfNode(scene, {}));
    EXPECT_FALSE(scene.sdf.has_value());
}

TEST(EditorSceneEdits, DuplicatePlacesACopyAfterTheOriginal) {
    Scene scene = sampleScene();
    const auto copy = duplicateSdfNode(scene, {1});
    ASSERT_TRUE(copy);
    EXPECT_EQ(*copy, (std::vector<int>{2}));
    EXPECT_EQ(nameAt(scene, {2}), "g copy");
    EXPECT_EQ(nameAt(scene, {2, 1}), "c");
    EXPECT_FALSE(duplicateSdfNode(scene, {}));
}

TEST(EditorSceneEdits, MoveReordersAndReparents) {
    Scene scene = sampleScene();
    // Reorder within the root: d before a.
    EXPECT_EQ(moveSdfNode(scene, {2}, {}, 0), (std::vector<int>{0}));
    EXPECT_EQ(nameAt(scene, {0}), "d");
    EXPECT_EQ(nameAt(scene, {1}), "a");
    // Reparent a into g (now at index 2), at the end.
    EXPECT_EQ(moveSdfNode(scene, {1}, {2}, -1), (std::vector<int>{1, 2}));
    EXPECT_EQ(nameAt(scene, {1}), "g");
    EXPECT_EQ(nameAt(scene, {1, 2}), "a");
    // Refused: into itself, into its own subtree, the root, onto a shape.
    EXPECT_FALSE(moveSdfNode(scene, {1}, {1}, -1));
    EXPECT_FALSE(moveSdfNode(scene, {1}, {1, 0}, -1));
    EXPECT_FALSE(moveSdfNode(scene, {}, {1}, -1));
    EXPECT_FALSE(moveSdfNode(scene, {0}, {1, 0}, -1));
}

namespace {

std::string meshNames(const Scene& scene) {
    std::string names;
    for (const MeshInstance& mesh : scene.meshes)
        names += mesh.name;
    return names;
}

std::string lightNames(const Scene& scene) {
    std::string names;
    for (const Light& light : scene.lights)
        names += light.name;
    return names;
}

} // namespace

TEST(EditorSceneEdits, ReordersMeshesAndLights) {
    Scene scene = emptyScene();
    scene.lights.clear();
    for (const char* name : {"a", "b", "c", "d"}) {
        MeshInstance mesh;
        mesh.name = name;
        mesh.transform.position.x = float(scene.meshes.size()); // travels with the instance
        scene.meshes.push_back(mesh);
        Light light;
        light.name = name;
        scene.lights.push_back(light);
    }
    EXPECT_EQ(moveMesh(scene, 0, 2), 2); // down: after the one that was at 2
    EXPECT_EQ(meshNames(scene), "bcad");
    EXPECT_FLOAT_EQ(scene.meshes[2].transform.position.x, 0.0f);
    EXPECT_EQ(moveMesh(scene, 3, 0), 0); // up: before the one that was at 0
    EXPECT_EQ(meshNames(scene), "dbca");
    EXPECT_EQ(moveMesh(scene, 1, 1), 1);
    EXPECT_EQ(meshNames(scene), "dbca");
    EXPECT_EQ(moveMesh(scene, 4, 0), -1); // out of range: nothing changes
    EXPECT_EQ(moveMesh(scene, 0, -1), -1);
    EXPECT_EQ(meshNames(scene), "dbca");
    EXPECT_EQ(moveLight(scene, 1, 3), 3);
    EXPECT_EQ(lightNames(scene), "acdb");
    EXPECT_EQ(moveLight(scene, 2, 1), 1);
    EXPECT_EQ(lightNames(scene), "adcb");
    EXPECT_EQ(moveLight(scene, 0, 9), -1);
    EXPECT_EQ(meshNames(scene), "dbca"); // lights moved, meshes did not
}

TEST(EditorDocument, ReorderingIsUndoableAndMovesTheSelection) {
    Scene scene = emptyScene();
    for (const char* name : {"b", "c"}) {
        Light light;
        light.name = name;
        scene.lights.push_back(light);
    }
    scene.lights[0].name = "a";
    Document doc(scene);
    doc.selection = Selection::light(0);
    doc.apply("Reorder lights", [](Scene& s, Selection& selection) {
        selection = Selection::light(moveLight(s, selection.index, 2));
    });
    EXPECT_EQ(lightNames(doc.scene()), "bca");
    EXPECT_EQ(doc.selection, Selection::light(2));
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(lightNames(doc.scene()), "abc");
    EXPECT_EQ(doc.selection, Selection::light(0));
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(lightNames(doc.scene()), "bca");
}

TEST(EditorSceneEdits, ObjectIdsMapToNodesInPreOrder) {
    const Scene scene = sampleScene();
    // Pre-order: root 0, a 1, g 2, b 3, c 4, d 5.
    EXPECT_EQ(selectionForObjectId(scene, kSdfIdBase + 4), Selection::sdf({1, 1}));
    EXPECT_EQ(selectionForObjectId(scene, kSdfIdBase + 5), Selection::sdf({2}));
    EXPECT_EQ(selectionForObjectId(scene, kSdfIdBase + 6), Selection::none());
    EXPECT_EQ(selectionForObjectId(scene, 0), Selection::none());
    const IdRange group = objectIdRange(scene, Selection::sdf({1}));
    EXPECT_EQ(group.first, kSdfIdBase + 2);
    EXPECT_EQ(group.last, kSdfIdBase + 5);
    const IdRange shape = objectIdRange(scene, Selection::sdf({2}));
    EXPECT_EQ(shape.last - shape.first, 1u);
}

// What the viewer outlines by: an edit of numbers keeps every id, a structural one does not.
TEST(EditorSceneEdits, SameObjectIdsUntilAStructuralEdit) {
    const Scene scene = sampleScene();
    Scene moved = scene;
    findSdfNode(moved, {1, 1})->transform.position = glm::vec3(0, 1, 0);
    moved.lights.clear(); // lights are not in the id buffer
    EXPECT_TRUE(sameObjectIds(scene, moved));
    Scene added = scene;
    insertSdfNode(added, Selection::sdf({1}), makeShape(PrimitiveId::Sphere));
    EXPECT_FALSE(sameObjectIds(scene, added));
    Scene regrouped = scene; // the same number of nodes, in another shape
    SdfNode last = regrouped.sdf->children.back();
    regrouped.sdf->children.pop_back();
    regrouped.sdf->children[1].children.push_back(last);
    EXPECT_FALSE(sameObjectIds(scene, regrouped));
    Scene withMesh = scene;
    withMesh.meshes.emplace_back();
    EXPECT_FALSE(sameObjectIds(scene, withMesh));
    Scene noSdf = scene;
    noSdf.sdf.reset();
    EXPECT_FALSE(sameObjectIds(scene, noSdf));
}

TEST(EditorSceneEdits, ObjectIdsAgreeWithTheCompiler) {
    // The ids the compiler gives shapes must be the ones picking maps back.
    Scene scene = sampleScene();
    std::string json = sceneToJson(scene);
    Diagnostics d;
    std::optional<Scene> parsed = parseScene(json, "x.json", d);
    ASSERT_TRUE(parsed) << d.format();
    EXPECT_EQ(selectionForObjectId(*parsed, kSdfIdBase + 3), Selection::sdf({1, 0}));
}

TEST(EditorSceneEdits, WorldMatrixComposesParents) {
    Scene scene = sampleScene();
    findSdfNode(scene, {1, 1})->transform.position = glm::vec3(0, 1, 0);
    const glm::mat4 world = sdfWorldMatrix(scene, {1, 1});
    EXPECT_FLOAT_EQ(world[3].x, 2.0f);
    EXPECT_FLOAT_EQ(world[3].y, 1.0f);
    const std::optional<Bounds> bounds = selectionBounds(scene, Selection::sdf({1, 1}));
    ASSERT_TRUE(bounds);
    EXPECT_FLOAT_EQ(bounds->center.x, 2.0f);
    EXPECT_GT(bounds->radius, 0.0f);
}

TEST(EditorDocument, UndoRedoRestoreSceneAndSelection) {
    Document doc(sampleScene());
    doc.apply("Add", [](Scene& s, Selection& sel) {
        sel = Selection::sdf(insertSdfNode(s, sel, makeShape(PrimitiveId::Box)));
    });
    EXPECT_EQ(doc.scene().sdf->children.size(), 4u);
    EXPECT_EQ(doc.selection, Selection::sdf({3}));
    doc.apply("Delete", [](Scene& s, Selection& sel) { sel = deleteSelected(s, sel); });
    EXPECT_EQ(doc.scene().sdf->children.size(), 3u);
    EXPECT_TRUE(doc.selection.empty());
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene().sdf->children.size(), 4u);
    EXPECT_EQ(doc.selection, Selection::sdf({3}));
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.scene().sdf->children.size(), 3u);
    EXPECT_FALSE(doc.undo());
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.scene().sdf->children.size(), 3u);
    EXPECT_FALSE(doc.redo());
}

TEST(EditorDocument, ADragOverManyFramesIsOneUndoStep) {
    Document doc(sampleScene());
    for (int frame = 1; frame <= 20; ++frame) {
        doc.editScene().sdf->children[0].params[0] = 1.0f + 0.1f * float(frame);
        doc.markChanged("Edit radius");
    }
    doc.commit();
    EXPECT_EQ(doc.historySize(), 1u);
    EXPECT_EQ(doc.undoLabel(), "Edit radius");
    doc.undo();
    EXPECT_FLOAT_EQ(doc.scene().sdf->children[0].params[0],
                    sampleScene().sdf->children[0].params[0]);
    doc.redo();
    EXPECT_FLOAT_EQ(doc.scene().sdf->children[0].params[0], 3.0f);
}

TEST(EditorDocument, UnlimitedHistoryAndANewEditDropsRedo) {
    Document doc(sampleScene());
    for (int i = 0; i < 500; ++i)
        doc.apply("Move", [i](Scene& s, Selection&) {
            s.sdf->children[0].transform.position.x = float(i);
        });
    EXPECT_EQ(doc.historySize(), 500u);
    for (int i = 0; i < 500; ++i)
        ASSERT_TRUE(doc.undo());
    EXPECT_FLOAT_EQ(doc.scene().sdf->children[0].transform.position.x, 0.0f);
    doc.redo();
    doc.apply("Other", [](Scene& s, Selection&) { s.lights.clear(); });
    EXPECT_FALSE(doc.canRedo());
    EXPECT_EQ(doc.historySize(), 2u);
}

TEST(EditorDocument, RevertPendingRestoresTheCommittedScene) {
    Document doc(sampleScene());
    doc.editScene().sdf->children[0].transform.position.y = 7.0f;
    doc.markChanged("Move");
    doc.revertPending();
    EXPECT_FLOAT_EQ(doc.scene().sdf->children[0].transform.position.y, 0.0f);
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(doc.historySize(), 0u);
}

TEST(EditorDocument, RevisionChangesOnEveryChange) {
    Document doc(sampleScene());
    const auto r0 = doc.revision();
    doc.apply("x", [](Scene& s, Selection&) { s.render.exposure = 2.0f; });
    const auto r1 = doc.revision();
    EXPECT_GT(r1, r0);
    doc.undo();
    EXPECT_GT(doc.revision(), r1);
}

TEST_F(EditorFiles, SaveLoadRoundTripAndDirtyFlag) {
    Document doc(sampleScene());
    EXPECT_FALSE(doc.dirty());
    doc.apply("Radius", [](Scene& s, Selection&) { s.sdf->children[0].params[0] = 0.75f; });
    EXPECT_TRUE(doc.dirty());
    std::string error;
    EXPECT_FALSE(doc.save(error)); // no file yet
    const fs::path path = folder / "scene.json";
    ASSERT_TRUE(doc.saveAs(path, error)) << error;
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(doc.file(), path);
    Diagnostics d;
    std::optional<Scene> loaded = loadSceneForEditing(path, d);
    ASSERT_TRUE(loaded) << d.format();
    EXPECT_EQ(sceneToJson(*loaded), sceneToJson(doc.scene()));
    EXPECT_FLOAT_EQ(loaded->sdf->children[0].params[0], 0.75f);
    EXPECT_EQ(findSdfNode(*loaded, {1, 1})->primitive, PrimitiveId::Torus);
    // Undo after a save makes the document dirty; redo back to the saved state is clean.
    doc.undo();
    EXPECT_TRUE(doc.dirty());
    doc.redo();
    EXPECT_FALSE(doc.dirty());
}

TEST_F(EditorFiles, SaveKeepsThePreviousVersionAsBackup) {
    const fs::path path = folder / "scene.json";
    Document doc(sampleScene());
    std::string error;
    ASSERT_TRUE(doc.saveAs(path, error)) << error;
    const std::string first = readFile(path);
    doc.apply("Exposure", [](Scene& s, Selection&) { s.render.exposure = 3.0f; });
    ASSERT_TRUE(doc.save(error)) << error;
    EXPECT_EQ(readFile(path.string() + ".bak"), first);
    EXPECT_NE(readFile(path), first);
    EXPECT_FALSE(fs::exists(folder / ".scene.json.tmp"));
    for (const auto& entry : fs::directory_iterator(folder)) // no temporary files left behind
        EXPECT_TRUE(entry.path().filename() == "scene.json" ||
                    entry.path().filename() == "scene.json.bak")
            << entry.path();
}

TEST_F(EditorFiles, FailedSaveKeepsTheOldFileAndTheEdits) {
    const fs::path path = folder / "scene.json";
    Document doc(sampleScene());
    std::string error;
    ASSERT_TRUE(doc.saveAs(path, error)) << error;
    const std::string before = readFile(path);
    doc.apply("Exposure", [](Scene& s, Selection&) { s.render.exposure = 5.0f; });
    // A folder where the file should be cannot be replaced.
    const fs::path blocked = folder / "blocked.json";
    fs::create_directories(blocked);
    error.clear();
    EXPECT_FALSE(doc.saveAs(blocked, error));
    EXPECT_NE(error.find("blocked.json"), std::string::npos) << error;
    EXPECT_TRUE(doc.dirty());
    EXPECT_EQ(doc.file(), path);
    EXPECT_FLOAT_EQ(doc.scene().render.exposure, 5.0f);
    EXPECT_EQ(readFile(path), before);
    // A missing folder: also refused with a reason, nothing changes.
    error.clear();
    EXPECT_FALSE(doc.saveAs(folder / "missing" / "scene.json", error));
    EXPECT_FALSE(error.empty());
    EXPECT_EQ(readFile(path), before);
}

// Typing smoothness 0 into a smooth group wrote "smoothness": 0, which rmsc refuses to load. A
// save reads its own text back first: an invalid scene writes nothing, and the error says where.
TEST_F(EditorFiles, AnInvalidSceneIsNotSavedAndTheErrorNamesItsPointer) {
    Scene scene = emptyScene();
    SdfNode root = makeGroup(SdfOp::Union);
    SdfNode smooth = makeGroup(SdfOp::SmoothUnion);
    smooth.children = {makeShape(PrimitiveId::Sphere), makeShape(PrimitiveId::Box)};
    root.children = {smooth};
    scene.sdf = root;
    const fs::path path = folder / "scene.json";
    Document doc(scene);
    std::string error;
    ASSERT_TRUE(doc.saveAs(path, error)) << error;
    const std::string before = readFile(path);

    doc.apply("Smoothness", [](Scene& s, Selection&) { s.sdf->children[0].smoothness = 0.0f; });
    EXPECT_FALSE(doc.save(error));
    EXPECT_NE(error.find("/sdf/children/0/smoothness: expected a number >= 0.001, got 0"),
              std::string::npos)
        << error;
    EXPECT_EQ(readFile(path), before) << "the old file is untouched";
    EXPECT_FALSE(fs::exists(path.string() + ".bak")) << "nothing was replaced";
    EXPECT_TRUE(doc.dirty());
    EXPECT_FLOAT_EQ(doc.scene().sdf->children[0].smoothness, 0.0f) << "the edit is kept";

    // Save As refuses it as well, and makes no file.
    const fs::path other = folder / "other.json";
    error.clear();
    EXPECT_FALSE(doc.saveAs(other, error));
    EXPECT_NE(error.find("/sdf/children/0/smoothness"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(other));
    EXPECT_EQ(doc.file(), path);

    // Once valid again, it saves.
    doc.apply("Smoothness", [](Scene& s, Selection&) { s.sdf->children[0].smoothness = 0.2f; });
    ASSERT_TRUE(doc.save(error)) << error;
    EXPECT_FALSE(doc.dirty());
    Diagnostics d;
    ASSERT_TRUE(loadSceneForEditing(path, d)) << d.format();
}

// The tree must also compile, as rmsc validate compiles it: a group whose every child is cut
// reads, but does not compile.
TEST_F(EditorFiles, ASceneWhoseTreeDoesNotCompileIsNotSaved) {
    Scene scene = sampleScene();
    SdfNode allCut = makeGroup(SdfOp::Union);
    allCut.children = {makeShape(PrimitiveId::Sphere)};
    allCut.children[0].cut = true;
    scene.sdf->children.push_back(allCut);
    Diagnostics read;
    ASSERT_TRUE(parseScene(sceneToJson(scene), "scene.json", read)) << read.format();
    Document doc(scene);
    std::string error;
    const fs::path path = folder / "scene.json";
    EXPECT_FALSE(doc.saveAs(path, error));
    EXPECT_NE(error.find("/sdf/children/3: every child of the group is marked \"cut\""),
              std::string::npos)
        << error;
    EXPECT_FALSE(fs::exists(path));
}

TEST_F(EditorFiles, WatcherSeesExternalEditsButNotItsOwnSync) {
    const fs::path path = folder / "scene.json";
    { std::ofstream(path) << "{}"; }
    FileWatcher watcher(path);
    EXPECT_FALSE(watcher.changed());
    fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(2));
    EXPECT_TRUE(watcher.changed());
    EXPECT_FALSE(watcher.changed()); // once per change
    FileWatcher folderWatcher(folder);
    { std::ofstream(folder / "new.glsl") << "x"; }
    EXPECT_TRUE(folderWatcher.changed());
    fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(2));
    folderWatcher.sync();
    EXPECT_FALSE(folderWatcher.changed());
}

TEST(EditorCamera, RoundTripsTheSceneCamera) {
    Camera c;
    c.position = glm::vec3(1, 2, 3);
    c.target = glm::vec3(0, 0.5f, 0);
    FlyCamera fly;
    fly.setFromCamera(c);
    const Camera back = fly.toCamera(c);
    EXPECT_NEAR(glm::distance(back.position, c.position), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(back.target, c.target), 0.0f, 1e-4f);
    EXPECT_NEAR(back.up.y, 1.0f, 0.2f); // upright: no roll
    EXPECT_NEAR(glm::dot(back.up, glm::normalize(c.target - c.position)), 0.0f, 1e-5f);
}

TEST(EditorCamera, MovesRollsOrbitsAndFrames) {
    FlyCamera fly;
    Camera c; // at (0, 1.5, 5) looking at the origin
    fly.setFromCamera(c);
    FlyInput forward;
    forward.moveForward = 1.0f;
    const glm::vec3 start = fly.position;
    fly.update(forward, 0.5f); // 2 m/s for half a second
    EXPECT_NEAR(glm::distance(fly.position, start), 1.0f, 1e-5f);
    forward.fast = true;
    fly.update(forward, 0.5f);
    EXPECT_NEAR(glm::distance(fly.position, start), 5.0f, 1e-4f);
    FlyInput roll;
    roll.roll = 1.0f;
    fly.update(roll, 0.5f);
    EXPECT_LT(fly.up().y, 0.99f); // rolled away from upright
    fly.setFromCamera(c);
    const float radius = glm::distance(fly.position, glm::vec3(0));
    fly.orbit(glm::vec3(0), glm::vec2(200, 0));
    EXPECT_NEAR(glm::distance(fly.position, glm::vec3(0)), radius, 1e-4f);
    EXPECT_GT(std::abs(fly.position.x), 0.1f);
    fly.frame(glm::vec3(10, 0, 0), 1.0f, 45.0f);
    EXPECT_NEAR(glm::distance(fly.position, glm::vec3(10, 0, 0)),
                1.0f / std::sin(glm::radians(22.5f)) * 1.1f, 1e-3f);
    fly.changeSpeed(1.0f);
    EXPECT_FLOAT_EQ(fly.speed, 2.5f);
}
