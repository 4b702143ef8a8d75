// The editor model's multi-object commands: plain and Shift-clicks (editor/multi_selection.hpp),
// the whole selection in undo and redo, deleting and grouping everything selected
// (editor/selection_edits.hpp), world placements under a new parent (editor/world_placement.hpp),
// and copy and paste as scene-file text between scenes (editor/clipboard.hpp).
#include "core/limits.hpp"
#include "editor/clipboard.hpp"
#include "editor/document.hpp"
#include "editor/multi_selection.hpp"
#include "editor/scene_edits.hpp"
#include "editor/selection_edits.hpp"
#include "editor/world_placement.hpp"
#include "sdf/compiler.hpp"
#include "sdf/operations.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

// root union { a: sphere at (0, 1, 0), g: union at (2, 0, 0) turned 90 degrees about y, material
// "blue" { b: box, c: torus at (0, 0, 1) }, d: capsule, material "red" }, one mesh, one light.
Scene sampleScene() {
    Scene scene = emptyScene();
    scene.file = "/scenes/a/first.json";
    Material red;
    red.name = "red";
    red.baseColor = glm::vec3(0.8f, 0.1f, 0.1f);
    Material blue;
    blue.name = "blue";
    blue.baseColor = glm::vec3(0.1f, 0.1f, 0.8f);
    scene.materials = {red, blue};
    SdfNode root;
    root.isGroup = true;
    root.name = "root";
    SdfNode a = makeShape(PrimitiveId::Sphere);
    a.name = "a";
    a.transform.position = glm::vec3(0, 1, 0);
    SdfNode g;
    g.isGroup = true;
    g.name = "g";
    g.material = 1;
    g.transform.position = glm::vec3(2, 0, 0);
    g.transform.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    SdfNode b = makeShape(PrimitiveId::Box);
    b.name = "b";
    SdfNode c = makeShape(PrimitiveId::Torus);
    c.name = "c";
    c.transform.position = glm::vec3(0, 0, 1);
    g.children = {b, c};
    SdfNode d = makeShape(PrimitiveId::Capsule);
    d.name = "d";
    d.material = 0;
    root.children = {a, g, d};
    scene.sdf = root;
    MeshInstance mesh;
    mesh.name = "chair";
    mesh.file = "models/chair.gltf";
    mesh.path = "/scenes/a/models/chair.gltf";
    mesh.materialOverride = 0;
    scene.meshes.push_back(mesh);
    return scene;
}

std::string nameAt(const Scene& scene, const std::vector<int>& path) {
    const SdfNode* node = findSdfNode(scene, path);
    return node ? node->name : "<none>";
}

void expectSameMatrix(const glm::mat4& a, const glm::mat4& b) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[c][r], b[c][r], 1e-5f) << "column " << c << " row " << r;
}

bool compiles(const Scene& scene) {
    Diagnostics diagnostics;
    const bool ok = scene.sdf && compileSdf(*scene.sdf, 0, "test.json", diagnostics).has_value();
    if (!ok) ADD_FAILURE() << diagnostics.format();
    return ok;
}

} // namespace

TEST(EditorMultiSelect, ShiftClickAddsTogglesAndMakesActive) {
    Document document(sampleScene());
    const Selection a = Selection::sdf({0}), c = Selection::sdf({1, 1}), mesh = Selection::mesh(0);
    clickSelect(document, a, false);
    clickSelect(document, c, true);
    clickSelect(document, mesh, true);
    EXPECT_EQ(document.selection, mesh); // the last one added is active
    EXPECT_EQ(selectedItems(document), (std::vector<Selection>{a, c, mesh}));
    EXPECT_TRUE(isSelected(document, c));
    EXPECT_FALSE(isSelected(document, Selection::sdf({2})));
    clickSelect(document, a, true); // a selected one becomes active
    EXPECT_EQ(selectedItems(document), (std::vector<Selection>{c, mesh, a}));
    clickSelect(document, a, true); // the active one again: out, the one before takes over
    EXPECT_EQ(document.selection, mesh);
    EXPECT_EQ(selectedItems(document), (std::vector<Selection>{c, mesh}));
    clickSelect(document, Selection::none(), true); // Shift-click on empty space keeps all
    EXPECT_EQ(selectedItems(document).size(), 2u);
    clickSelect(document, Selection::sdf({2}), false); // a plain click: that one alone
    EXPECT_EQ(selectedItems(document), (std::vector<Selection>{Selection::sdf({2})}));
    clickSelect(document, Selection::none(), false);
    EXPECT_TRUE(selectedItems(document).empty());
}

TEST(EditorMultiSelect, UndoAndRedoRestoreTheWholeSelection) {
    Document document(sampleScene());
    clickSelect(document, Selection::sdf({0}), false);
    clickSelect(document, Selection::sdf({2}), true);
    const std::vector<Selection> before = selectedItems(document);
    document.applyToSelection("Delete",
                              [](Scene& scene, Selection& active, std::vector<Selection>& also) {
                                  deleteItems(scene, {Selection::sdf({0}), Selection::sdf({2})});
                                  active = Selection::none();
                                  also.clear();
                              });
    EXPECT_EQ(document.scene().sdf->children.size(), 1u);
    EXPECT_TRUE(selectedItems(document).empty());
    ASSERT_TRUE(document.undo());
    EXPECT_EQ(selectedItems(document), before);
    EXPECT_EQ(nameAt(document.scene(), {2}), "d");
    ASSERT_TRUE(document.redo());
    EXPECT_TRUE(selectedItems(document).empty());
}

TEST(EditorMultiSelect, ApplyKeepsOnlyWhatTheEditSelects) {
    // A structural edit through apply may move nodes: the other selected paths are dropped.
    Document document(sampleScene());
    clickSelect(document, Selection::sdf({0}), false);
    clickSelect(document, Selection::sdf({2}), true);
    document.apply("Add", [](Scene& scene, Selection& selection) {
        selection = Selection::sdf(
            insertSdfNode(scene, Selection::sdf({0}), makeShape(PrimitiveId::Plane)));
    });
    EXPECT_EQ(selectedItems(document), (std::vector<Selection>{Selection::sdf({1})}));
    // A commit drops what no longer exists; a removed active one gives way to the others.
    clickSelect(document, Selection::sdf({3}), true);
    clickSelect(document, Selection::mesh(0), true);
    document.editScene().meshes.clear();
    document.markChanged("Remove the mesh");
    document.commit();
    EXPECT_EQ(document.selection, Selection::sdf({3}));
    EXPECT_EQ(selectedItems(document),
              (std::vector<Selection>{Selection::sdf({1}), Selection::sdf({3})}));
}

TEST(EditorMultiSelect, DeleteRemovesEverySelectedObjectOnce) {
    Scene scene = sampleScene();
    scene.lights.push_back(scene.lights[0]);
    scene.lights[1].name = "second";
    // g and b (inside g): b goes with g; a, the mesh and the first light too.
    deleteItems(scene, {Selection::sdf({1, 0}), Selection::sdf({0}), Selection::sdf({1}),
                        Selection::mesh(0), Selection::light(0)});
    ASSERT_TRUE(scene.sdf);
    ASSERT_EQ(scene.sdf->children.size(), 1u);
    EXPECT_EQ(nameAt(scene, {0}), "d");
    EXPECT_TRUE(scene.meshes.empty());
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].name, "second");
    // Both children of g: g is left empty and goes too; the others stay in place.
    Scene other = sampleScene();
    deleteItems(other, {Selection::sdf({1, 1}), Selection::sdf({1, 0})});
    ASSERT_EQ(other.sdf->children.size(), 2u);
    EXPECT_EQ(nameAt(other, {0}), "a");
    EXPECT_EQ(nameAt(other, {1}), "d");
}

TEST(EditorMultiSelect, OutermostPathsAreInTreeOrderWithoutNestedOnes) {
    const Scene scene = sampleScene();
    EXPECT_EQ(
        outermostSdfPaths(scene, {Selection::sdf({2}), Selection::sdf({1, 1}), Selection::mesh(0),
                                  Selection::sdf({1}), Selection::sdf({9}), Selection::sdf({0})}),
        (std::vector<std::vector<int>>{{0}, {1}, {2}}));
}

TEST(EditorMultiSelect, GroupingSiblingsPutsTheGroupWhereTheFirstWas) {
    Scene scene = sampleScene();
    const auto path =
        groupItems(scene, {Selection::sdf({2}), Selection::sdf({0})}, SdfOp::SmoothUnion);
    ASSERT_TRUE(path);
    EXPECT_EQ(*path, (std::vector<int>{0}));
    const SdfNode* group = findSdfNode(scene, *path);
    ASSERT_TRUE(group && group->isGroup);
    EXPECT_EQ(group->op, SdfOp::SmoothUnion);
    EXPECT_GT(group->smoothness, 0.0f); // a smooth union needs one
    ASSERT_EQ(group->children.size(), 2u);
    EXPECT_EQ(group->children[0].name, "a"); // in tree order
    EXPECT_EQ(group->children[1].name, "d");
    EXPECT_EQ(group->children[0].transform.position, glm::vec3(0, 1, 0)); // same parent: as it was
    ASSERT_EQ(scene.sdf->children.size(), 2u);
    EXPECT_EQ(nameAt(scene, {1}), "g");
    EXPECT_TRUE(compiles(scene));
}

TEST(EditorMultiSelect, GroupingAcrossParentsKeepsWorldPlacesAndMaterials) {
    Scene scene = sampleScene();
    const glm::mat4 cWorld = sdfWorldMatrix(scene, {1, 1});
    const auto path =
        groupItems(scene, {Selection::sdf({1, 1}), Selection::sdf({0})}, SdfOp::Intersection);
    ASSERT_TRUE(path);
    EXPECT_EQ(*path, (std::vector<int>{0}));
    ASSERT_EQ(findSdfNode(scene, *path)->children.size(), 2u);
    EXPECT_EQ(nameAt(scene, {0, 1}), "c");
    expectSameMatrix(sdfWorldMatrix(scene, {0, 1}), cWorld); // still where it was
    // c inherited g's "blue"; out of g it names it itself.
    EXPECT_EQ(findSdfNode(scene, {0, 1})->material, 1);
    EXPECT_EQ(nameAt(scene, {1}), "g");
    EXPECT_EQ(findSdfNode(scene, {1})->children.size(), 1u);
    EXPECT_TRUE(compiles(scene));
    // When every child of g goes, g goes too.
    Scene other = sampleScene();
    ASSERT_TRUE(groupItems(other, {Selection::sdf({1, 0}), Selection::sdf({1, 1})}, SdfOp::Union));
    EXPECT_EQ(nameAt(other, {1, 0}), "group");
    EXPECT_EQ(nameAt(other, {1, 0, 1}), "c");
    EXPECT_EQ(other.sdf->children.size(), 3u);
}

TEST(EditorMultiSelect, GroupingTheRootWrapsTheTreeAndNothingRefuses) {
    Scene scene = sampleScene();
    EXPECT_FALSE(groupItems(scene, {Selection::mesh(0)}, SdfOp::Union));
    EXPECT_EQ(scene.sdf->name, "root"); // unchanged
    const auto path = groupItems(scene, {Selection::sdf({}), Selection::sdf({1})}, SdfOp::Union);
    ASSERT_TRUE(path);
    EXPECT_TRUE(path->empty());
    EXPECT_EQ(scene.sdf->name, "group");
    EXPECT_EQ(nameAt(scene, {0}), "root");
    EXPECT_TRUE(compiles(scene));
}

TEST(EditorWorldPlacement, MatricesTurnBackIntoTransforms) {
    Transform t;
    t.position = glm::vec3(1, -2, 3);
    t.rotation = glm::normalize(glm::quat(0.3f, 0.5f, -0.2f, 0.7f));
    t.scale = glm::vec3(2.5f);
    expectSameMatrix(transformFromMatrix(t.matrix()).matrix(), t.matrix());
    t.scale = glm::vec3(1.0f, 2.0f, 3.0f); // non-uniform, not sheared: exact too
    expectSameMatrix(transformFromMatrix(t.matrix()).matrix(), t.matrix());
    t.scale = glm::vec3(1.0f, 1.0f, -2.0f); // a mirror
    expectSameMatrix(transformFromMatrix(t.matrix()).matrix(), t.matrix());
}

TEST(EditorWorldPlacement, InheritedMaterialsAreFound) {
    const Scene scene = sampleScene();
    EXPECT_EQ(effectiveMaterial(scene, {1, 1}), 1); // from g
    EXPECT_EQ(effectiveMaterial(scene, {2}), 0);    // its own
    EXPECT_EQ(effectiveMaterial(scene, {0}), -1);   // none: the default
    EXPECT_EQ(effectiveMaterial(scene, {5}), -1);   // no such node
}

TEST(EditorClipboard, CopiesAndPastesIntoAnotherScene) {
    const Scene first = sampleScene();
    const std::string text = clipboardText(first, {Selection::sdf({1, 1}), Selection::sdf({2}),
                                                   Selection::mesh(0), Selection::light(0)});
    ASSERT_FALSE(text.empty());
    std::string error;
    const std::optional<Scene> clip = parseClipboardText(text, error);
    ASSERT_TRUE(clip) << error;
    // Only the materials used: blue (c, inherited) and red (d and the mesh).
    EXPECT_EQ(clip->materials.size(), 2u);

    // A second scene in another folder, with a "red" of its own and a moved group to paste into.
    Scene second = emptyScene();
    second.file = "/scenes/b/second.json";
    Material red;
    red.name = "red";
    red.baseColor = glm::vec3(1, 0, 0);
    second.materials = {red};
    SdfNode holder;
    holder.isGroup = true;
    holder.name = "holder";
    holder.transform.position = glm::vec3(0, 5, 0);
    holder.transform.scale = glm::vec3(2.0f);
    holder.children.push_back(makeShape(PrimitiveId::Sphere));
    SdfNode root;
    root.isGroup = true;
    root.children = {holder};
    second.sdf = root;

    const PasteResult pasted = pasteClip(second, Selection::sdf({0}), *clip);
    ASSERT_EQ(pasted.pasted.size(), 4u);
    EXPECT_EQ(pasted.pasted[0], Selection::sdf({0, 1})); // into the selected group, in order
    EXPECT_EQ(pasted.pasted[1], Selection::sdf({0, 2}));
    EXPECT_EQ(pasted.pasted[2], Selection::mesh(0));
    EXPECT_EQ(pasted.pasted[3], Selection::light(1));
    EXPECT_EQ(pasted.lightsLeftOut, 0);
    EXPECT_EQ(nameAt(second, {0, 1}), "c");
    EXPECT_EQ(nameAt(second, {0, 2}), "d");
    // Where they were in the world, whatever the group they went into.
    expectSameMatrix(sdfWorldMatrix(second, {0, 1}), sdfWorldMatrix(first, {1, 1}));
    expectSameMatrix(sdfWorldMatrix(second, {0, 2}), sdfWorldMatrix(first, {2}));
    // "red" is the second scene's own; "blue" is added.
    ASSERT_EQ(second.materials.size(), 2u);
    EXPECT_EQ(second.materials[1].name, "blue");
    EXPECT_EQ(findSdfNode(second, {0, 2})->material, 0);
    EXPECT_EQ(findSdfNode(second, {0, 1})->material, 1);
    EXPECT_EQ(second.meshes[0].materialOverride, 0);
    EXPECT_EQ(second.materials[0].baseColor, glm::vec3(1, 0, 0));
    // The mesh's file, relative to the second scene's folder, names the same file.
    EXPECT_EQ(second.meshes[0].file, "../a/models/chair.gltf");
    EXPECT_EQ(second.meshes[0].path, std::filesystem::path("/scenes/a/models/chair.gltf"));
    EXPECT_TRUE(compiles(second));
}

TEST(EditorClipboard, PastesNextToAShapeAndIntoAnEmptyScene) {
    const Scene first = sampleScene();
    const std::optional<Scene> clip = [&] {
        std::string error;
        return parseClipboardText(clipboardText(first, {Selection::sdf({0}), Selection::sdf({1})}),
                                  error);
    }();
    ASSERT_TRUE(clip);
    Scene scene = sampleScene();
    const PasteResult after = pasteClip(scene, Selection::sdf({0}), *clip);
    ASSERT_EQ(after.pasted.size(), 2u);
    EXPECT_EQ(nameAt(scene, {1}), "a");
    EXPECT_EQ(nameAt(scene, {2}), "g"); // the copy, a group, is not pasted into
    EXPECT_EQ(nameAt(scene, {3}), "g");
    EXPECT_EQ(findSdfNode(scene, {2})->children.size(), 2u);
    Scene empty = emptyScene();
    ASSERT_EQ(pasteClip(empty, Selection::none(), *clip).pasted.size(), 2u);
    EXPECT_EQ(nameAt(empty, {0}), "a");
    expectSameMatrix(sdfWorldMatrix(empty, {1, 1}), sdfWorldMatrix(first, {1, 1}));
    EXPECT_TRUE(compiles(empty));
}

TEST(EditorClipboard, LightsPastPastTheLimitAreLeftOut) {
    Scene scene = emptyScene();
    while (int(scene.lights.size()) < limits::kLights)
        scene.lights.push_back(scene.lights[0]);
    std::string error;
    const std::optional<Scene> clip =
        parseClipboardText(clipboardText(scene, {Selection::light(0), Selection::light(1)}), error);
    ASSERT_TRUE(clip) << error;
    const PasteResult result = pasteClip(scene, Selection::none(), *clip);
    EXPECT_TRUE(result.pasted.empty());
    EXPECT_EQ(result.lightsLeftOut, 2);
    EXPECT_EQ(int(scene.lights.size()), limits::kLights);
}

TEST(EditorClipboard, RefusesTextThatIsNotAScene) {
    std::string error;
    EXPECT_FALSE(parseClipboardText("a sphere, please", error));
    EXPECT_NE(error.find("no scene objects"), std::string::npos) << error;
    EXPECT_FALSE(parseClipboardText("", error));
    error.clear();
    EXPECT_FALSE(parseClipboardText(
        R"({"version": 1, "sdf": {"op": "union", "children": [{"shape": "sphere", "radius": -1}]}})",
        error));
    EXPECT_NE(error.find("/sdf/children/0/radius"), std::string::npos) << error;
    EXPECT_EQ(clipboardText(sampleScene(), {Selection::sdf({7}), Selection::mesh(3)}), "");
}
