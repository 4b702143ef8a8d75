// Every key of every object the scene schema defines (its top level and each "$defs" entry with
// properties: SDF nodes, groups, shapes, modifiers, profiles, shells, lights, materials,
// textures, render settings, the camera, meshes, the environment, skies and fog) has a control
// in the inspector (editor/inspector_keys.hpp) or is listed as left to another part of the
// editor, with why. The schema is the generator's own output, so a key added to the format
// fails here until the inspector edits it.
#include "editor/inspector_keys.hpp"
#include "scene/scene_schema.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>

using namespace rmsc;
using nlohmann::ordered_json;

namespace {

// Every object of the schema that has keys: the top level (editor::kSceneObject) and each
// "$defs" entry with "properties" (the others, such as "node" or "sky", are unions of these).
std::map<std::string, ordered_json> schemaObjects(const ordered_json& schema) {
    std::map<std::string, ordered_json> objects;
    objects[editor::kSceneObject] = schema["properties"];
    for (const auto& [def, body] : schema["$defs"].items())
        if (body.contains("properties")) objects[def] = body["properties"];
    return objects;
}

std::map<std::string, std::set<std::string>>
byObject(const std::vector<editor::InspectorKey>& rows) {
    std::map<std::string, std::set<std::string>> keys;
    for (const editor::InspectorKey& row : rows)
        keys[row.object].insert(row.key);
    return keys;
}

} // namespace

TEST(InspectorKeys, EverySchemaKeyHasAControl) {
    const ordered_json schema = ordered_json::parse(generateSceneSchema().text);
    const auto edited = byObject(editor::inspectorKeys());
    const auto leftOut = byObject(editor::keysNotInInspector());
    int objects = 0;
    int keys = 0;
    for (const auto& [def, properties] : schemaObjects(schema)) {
        ++objects;
        for (const auto& [key, value] : properties.items()) {
            ++keys;
            const bool hasControl = edited.count(def) && edited.at(def).count(key);
            const bool excused = leftOut.count(def) && leftOut.at(def).count(key);
            EXPECT_TRUE(hasControl || excused)
                << "the schema's \"" << def << "\" key \"" << key
                << "\" has no control in the inspector (editor/inspector_keys.cpp)";
            EXPECT_FALSE(hasControl && excused) << def << "." << key << " is in both lists";
        }
    }
    // Every kind of object was found: a renamed definition would otherwise check nothing.
    EXPECT_GT(objects, 70);
    EXPECT_GT(keys, 550);
    for (const char* def :
         {"group", "shape_sphere", "shape_revolution", "modifier_repeat", "profile_polygon",
          "light_spot", "material", "render", "shell", "camera", "mesh", "environment",
          "sky_constant", "sky_gradient", "sky_image", "fog"})
        EXPECT_TRUE(schema["$defs"].contains(def)) << def;
    // Only the unions of other objects are left out of the walk.
    for (const auto& [def, body] : schema["$defs"].items())
        EXPECT_TRUE(body.contains("properties") || body.contains("oneOf")) << def;
}

// Neither list names a key the schema does not have (a stale row after a key was renamed).
TEST(InspectorKeys, EveryListedKeyIsInTheSchema) {
    const ordered_json schema = ordered_json::parse(generateSceneSchema().text);
    const auto objects = schemaObjects(schema);
    for (const auto& rows : {editor::inspectorKeys(), editor::keysNotInInspector()})
        for (const editor::InspectorKey& row : rows) {
            ASSERT_TRUE(objects.count(row.object)) << row.object;
            EXPECT_TRUE(objects.at(row.object).contains(row.key)) << row.object << "." << row.key;
            EXPECT_FALSE(row.control.empty()) << row.object << "." << row.key;
        }
}

TEST(InspectorKeys, BlendAndCutHaveControls) {
    const auto edited = byObject(editor::inspectorKeys());
    EXPECT_TRUE(edited.at("group").count("blend"));
    EXPECT_TRUE(edited.at("group").count("cut"));
    EXPECT_TRUE(edited.at("shape_box").count("cut"));
}

// The keys issue 18 found without a control: the camera's frame, a mesh's file, the sky of each
// type, its intensity and the fog.
TEST(InspectorKeys, CameraMeshEnvironmentAndFogHaveControls) {
    const auto edited = byObject(editor::inspectorKeys());
    for (const char* key : {"position", "target", "up", "fov", "near", "far"})
        EXPECT_TRUE(edited.at("camera").count(key)) << key;
    EXPECT_TRUE(edited.at("mesh").count("file"));
    EXPECT_TRUE(edited.at("environment").count("intensity"));
    EXPECT_TRUE(edited.at("sky_image").count("file"));
    EXPECT_TRUE(edited.at("sky_image").count("rotation"));
    EXPECT_TRUE(edited.at("sky_gradient").count("zenith"));
    EXPECT_TRUE(edited.at("fog").count("density"));
}
