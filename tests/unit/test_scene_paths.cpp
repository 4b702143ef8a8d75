// Save As into another folder keeps every file reference of the scene: the path keys are found
// by walking the JSON Schema (the keys it describes as "relative to the scene file"), a scene
// using each of them is saved from folder A into its sibling B, and every saved path must name
// the same file from B, and the saved scene must load there with everything it references.
#include "editor/document.hpp"
#include "prepare/prepared_scene.hpp"
#include "scene/scene_json.hpp"
#include "scene/scene_paths.hpp"
#include "scene/scene_schema.hpp"

#include "temp_folder.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <set>

using namespace rmsc;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kAssets = fs::path(RMSC_TEST_SOURCE_DIR) / "samples" / "assets";

// Where the test scene uses each path key of the schema, and the sample file it names there.
struct PathKeyUse {
    const char* schemaLocation; // of the key's string schema in docs/scene.schema.json
    const char* pointer;        // of the key in the test scene
    const char* sample;         // in samples/assets/, copied into folder A
};
const PathKeyUse kUses[] = {
    {"/$defs/material/properties/base_color_texture/oneOf/0", "/materials/short/base_color_texture",
     "textures/bricks_color.png"},
    {"/$defs/material/properties/normal_texture/oneOf/0", "/materials/short/normal_texture",
     "textures/bricks_normal.png"},
    {"/$defs/material/properties/roughness_texture/oneOf/0", "/materials/short/roughness_texture",
     "textures/bricks_roughness.png"},
    {"/$defs/texture/properties/file", "/materials/long/base_color_texture/file",
     "textures/tiles_color.png"},
    {"/$defs/texture/properties/file", "/materials/long/roughness_texture/file",
     "textures/test_metal_rough.png"},
    {"/$defs/normal_texture/properties/file", "/materials/long/normal_texture/file",
     "textures/test_occlusion.png"},
    {"/$defs/mesh/properties/file", "/meshes/0/file", "cube_external.gltf"},
    {"/$defs/sky_image/properties/file", "/environment/sky/file", "textures/test_emissive.png"},
    {"/$defs/shell/properties/mesh", "/sdf/children/0/shell/mesh", "sphere.gltf"},
};

// Schema locations of every string the schema describes as a path relative to the scene file.
void findPathKeys(const json& node, const std::string& location, std::set<std::string>& out) {
    if (node.is_object()) {
        const auto type = node.find("type");
        const auto description = node.find("description");
        if (type != node.end() && *type == "string" && description != node.end() &&
            description->is_string() &&
            description->get<std::string>().ends_with("relative to the scene file"))
            out.insert(location);
        for (const auto& [key, value] : node.items())
            findPathKeys(value, location + "/" + key, out);
    } else if (node.is_array()) {
        for (std::size_t i = 0; i < node.size(); ++i)
            findPathKeys(node[i], location + "/" + std::to_string(i), out);
    }
}

// The file named at `pointer`: a string, or the "file" of an object there (the writer always
// writes textures as objects, also those read from the short form).
std::string fileAt(const json& scene, const char* pointer) {
    const json& value = scene.at(json::json_pointer(pointer));
    return value.is_object() ? value.at("file").get<std::string>() : value.get<std::string>();
}

class ScenePaths : public test::TempFolderTest {};

} // namespace

TEST_F(ScenePaths, EveryPathKeyOfTheSchemaIsUsedByTheTestScene) {
    std::set<std::string> keys;
    findPathKeys(json::parse(generateSceneSchema().text), "", keys);
    EXPECT_GE(keys.size(), 8u); // the walk finds the keys at all
    std::set<std::string> used;
    for (const PathKeyUse& use : kUses)
        used.insert(use.schemaLocation);
    for (const std::string& key : keys)
        EXPECT_TRUE(used.contains(key))
            << "the schema has a path key at " << key
            << " that the Save As test does not use: add it to kUses (and make forEachScenePath "
               "in engine/scene/scene_paths.cpp visit it)";
    for (const std::string& key : used)
        EXPECT_TRUE(keys.contains(key)) << key << " is no longer a path key of the schema";
}

TEST_F(ScenePaths, SaveAsIntoASiblingFolderKeepsEveryPath) {
    const fs::path a = folder_ / "A";
    const fs::path b = folder_ / "B";
    fs::create_directories(b);
    json scene = json::parse(R"({
        "version": 1,
        "materials": {"short": {}, "long": {"base_color_texture": {}, "normal_texture": {},
                                            "roughness_texture": {}}},
        "environment": {"sky": {"type": "image"}},
        "meshes": [{}],
        "sdf": {"op": "union", "children": [
            {"shape": "sphere", "material": "short", "shell": {"proxy": "mesh"}},
            {"shape": "box", "material": "long", "position": [2, 0, 0]}]}
    })");
    for (const PathKeyUse& use : kUses) {
        const fs::path sample = kAssets / use.sample;
        const fs::path copy = a / "files" / fs::path(use.sample).filename();
        fs::create_directories(copy.parent_path());
        fs::copy_file(sample, copy, fs::copy_options::overwrite_existing);
        if (sample.filename() == "cube_external.gltf")
            fs::copy_file(kAssets / "cube_external.bin", a / "files" / "cube_external.bin",
                          fs::copy_options::overwrite_existing);
        scene[json::json_pointer(use.pointer)] = "files/" + copy.filename().string();
    }
    write(a / "scene.json", scene.dump(2));

    Diagnostics diagnostics;
    std::optional<Scene> loaded = editor::loadSceneForEditing(a / "scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.format();
    ASSERT_TRUE(prepareScene(*loaded, diskFileSource(), diagnostics)) << diagnostics.format();
    editor::Document document(*loaded, a / "scene.json");
    std::string error;
    ASSERT_TRUE(document.saveAs(b / "scene.json", error)) << error;

    const json saved = json::parse(read(b / "scene.json"));
    for (const PathKeyUse& use : kUses) {
        const std::string original = fileAt(scene, use.pointer);
        ASSERT_TRUE(saved.contains(json::json_pointer(use.pointer))) << use.pointer;
        const std::string rewritten = fileAt(saved, use.pointer);
        EXPECT_EQ((b / rewritten).lexically_normal(), (a / original).lexically_normal())
            << use.pointer << " was saved as \"" << rewritten << "\"";
    }

    Diagnostics reloaded;
    std::optional<Scene> fromB = editor::loadSceneForEditing(b / "scene.json", reloaded);
    ASSERT_TRUE(fromB) << reloaded.format();
    EXPECT_TRUE(prepareScene(*fromB, diskFileSource(), reloaded)) << reloaded.format();
    std::vector<fs::path> before, after;
    forEachScenePath(*loaded, [&](const ScenePath& p) { before.push_back(p.path); });
    forEachScenePath(*fromB, [&](const ScenePath& p) { after.push_back(p.path); });
    EXPECT_EQ(before.size(), std::size(kUses));
    EXPECT_EQ(after, before);
}

// Undo and redo across a Save As into another folder keep the scene in the new file: a step
// from before the save holds the old file and paths written for it, and a path typed after the
// undo must resolve from the folder the document is saved in (the next save writes it there).
TEST_F(ScenePaths, UndoAndRedoAfterSaveAsKeepTheNewFolder) {
    const fs::path a = folder_ / "A";
    const fs::path b = folder_ / "B";
    fs::create_directories(a / "files");
    fs::create_directories(b);
    fs::copy_file(kAssets / "textures" / "bricks_color.png", a / "files" / "bricks.png");
    write(a / "scene.json", R"({"version": 1,
        "materials": {"m": {"base_color_texture": "files/bricks.png"}},
        "sdf": {"shape": "sphere", "material": "m"}})");
    Diagnostics diagnostics;
    std::optional<Scene> loaded = editor::loadSceneForEditing(a / "scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.format();
    ASSERT_TRUE(prepareScene(*loaded, diskFileSource(), diagnostics)) << diagnostics.format();
    editor::Document document(*loaded, a / "scene.json");
    document.apply("exposure",
                   [](Scene& scene, editor::Selection&) { scene.render.exposure = 2.0f; });
    std::string error;
    ASSERT_TRUE(document.saveAs(b / "scene.json", error)) << error;

    const auto expectInB = [&](const char* after) {
        SCOPED_TRACE(after);
        const Scene& scene = document.scene();
        EXPECT_EQ(scene.file, b / "scene.json");
        EXPECT_EQ(scene.materials[0].baseColorTexture.file, "../A/files/bricks.png");
        EXPECT_EQ(scene.materials[0].baseColorTexture.path,
                  (a / "files" / "bricks.png").lexically_normal());
        EXPECT_EQ(resolveScenePath(scene, "typed.png"), (b / "typed.png").lexically_normal());
    };
    ASSERT_TRUE(document.undo());
    EXPECT_EQ(document.scene().render.exposure, 1.0f);
    expectInB("undo");
    ASSERT_TRUE(document.redo());
    EXPECT_EQ(document.scene().render.exposure, 2.0f);
    expectInB("redo");
}

// Absolute files stay absolute; relative ones follow the folder.
TEST(ScenePathsRebase, AbsoluteFilesStayAbsolute) {
    Scene scene;
    MeshInstance absolute;
    absolute.file = "/models/a.gltf";
    absolute.path = "/models/a.gltf";
    MeshInstance relative;
    relative.file = "b.gltf";
    relative.path = "/scenes/one/b.gltf";
    scene.meshes = {absolute, relative};
    rebaseScenePaths(scene, "/scenes/two");
    EXPECT_EQ(scene.meshes[0].file, "/models/a.gltf");
    EXPECT_EQ(scene.meshes[1].file, "../one/b.gltf");
}
