// Every key of the SDF node, group, shape, modifier, profile, shell, light, material, texture and
// render-settings objects the scene schema defines has a control in the inspector
// (editor/inspector_keys.hpp) or is listed as left to another part of the editor, with why. The
// schema is the generator's own output, so a key added to the format fails here until the
// inspector edits it.
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

// The schema definitions the inspector covers: these names, or these prefixes.
bool inspected(const std::string& def) {
    static const std::set<std::string> names = {"group",          "shell",  "material", "texture",
                                                "normal_texture", "render", "shadows",  "ao"};
    for (const char* prefix : {"shape_", "modifier_", "profile_", "light_"})
        if (def.rfind(prefix, 0) == 0) return true;
    return names.count(def) > 0;
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
    for (const auto& [def, body] : schema["$defs"].items()) {
        if (!inspected(def) || !body.contains("properties")) continue;
        ++objects;
        for (const auto& [key, value] : body["properties"].items()) {
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
    EXPECT_GT(objects, 60);
    EXPECT_GT(keys, 500);
    for (const char* def : {"group", "shape_sphere", "shape_revolution", "modifier_repeat",
                            "profile_polygon", "light_spot", "material", "render", "shell"})
        EXPECT_TRUE(schema["$defs"].contains(def)) << def;
}

// Neither list names a key the schema does not have (a stale row after a key was renamed).
TEST(InspectorKeys, EveryListedKeyIsInTheSchema) {
    const ordered_json schema = ordered_json::parse(generateSceneSchema().text);
    for (const auto& rows : {editor::inspectorKeys(), editor::keysNotInInspector()})
        for (const editor::InspectorKey& row : rows) {
            ASSERT_TRUE(schema["$defs"].contains(row.object)) << row.object;
            EXPECT_TRUE(schema["$defs"][row.object]["properties"].contains(row.key))
                << row.object << "." << row.key;
            EXPECT_FALSE(row.control.empty()) << row.object << "." << row.key;
        }
}

TEST(InspectorKeys, BlendAndCutHaveControls) {
    const auto edited = byObject(editor::inspectorKeys());
    EXPECT_TRUE(edited.at("group").count("blend"));
    EXPECT_TRUE(edited.at("group").count("cut"));
    EXPECT_TRUE(edited.at("shape_box").count("cut"));
}
