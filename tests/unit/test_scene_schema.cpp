// docs/scene.schema.json against the reader: the shipped file is exactly what `rmsc schema`
// generates; the generator, which probes the reader for the keys and names it knows, found
// every one of them described and nothing else; every catalogue primitive and parameter
// appears with the catalogue's range, every modifier with its parameters' ranges, defaults and
// descriptions; every reference resolves.
#include "scene/scene_json.hpp"
#include "scene/scene_schema.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/primitives.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <sstream>

using namespace rmsc;
using nlohmann::ordered_json;

namespace {

const std::string kSchemaPath = std::string(RMSC_TEST_SOURCE_DIR) + "/docs/scene.schema.json";

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

ordered_json shippedSchema() {
    return ordered_json::parse(readFile(kSchemaPath));
}

} // namespace

TEST(SceneSchema, GeneratorDescribesExactlyTheKeysTheReaderKnows) {
    const SceneSchema schema = generateSceneSchema();
    std::string problems;
    for (const std::string& problem : schema.problems)
        problems += problem + "\n";
    EXPECT_TRUE(schema.problems.empty()) << problems;
}

TEST(SceneSchema, ShippedFileIsTheGeneratorsOutput) {
    const std::string shipped = readFile(kSchemaPath);
    ASSERT_FALSE(shipped.empty()) << kSchemaPath << " is missing";
    EXPECT_TRUE(shipped == generateSceneSchema().text)
        << "docs/scene.schema.json is out of date; refresh it with\n"
           "  BUILD/bin/rmsc schema > docs/scene.schema.json";
}

TEST(SceneSchema, IsDraft2020WithEveryDefinitionReachable) {
    const ordered_json schema = shippedSchema();
    EXPECT_EQ(schema["$schema"], "https://json-schema.org/draft/2020-12/schema");
    EXPECT_EQ(schema["required"], ordered_json::array({"version"}));
    EXPECT_EQ(schema["properties"]["version"]["const"], kSceneFormatVersion);
    // Every "$ref" names an existing definition.
    std::vector<const ordered_json*> stack = {&schema};
    int refs = 0;
    while (!stack.empty()) {
        const ordered_json* node = stack.back();
        stack.pop_back();
        if (node->is_object() && node->contains("$ref")) {
            const std::string ref = (*node)["$ref"];
            ASSERT_TRUE(ref.starts_with("#/$defs/")) << ref;
            EXPECT_TRUE(schema["$defs"].contains(ref.substr(8))) << ref;
            ++refs;
        }
        if (node->is_structured())
            for (const auto& child : *node)
                stack.push_back(&child);
    }
    EXPECT_GT(refs, 10);
}

TEST(SceneSchema, EveryCataloguePrimitiveAndParameterWithItsRange) {
    const ordered_json schema = shippedSchema();
    const ordered_json& choices = schema["$defs"]["node"]["oneOf"];
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        SCOPED_TRACE(std::string(spec.name));
        const std::string def = "shape_" + std::string(spec.name);
        EXPECT_NE(
            std::find(choices.begin(), choices.end(), ordered_json{{"$ref", "#/$defs/" + def}}),
            choices.end());
        ASSERT_TRUE(schema["$defs"].contains(def));
        const ordered_json& properties = schema["$defs"][def]["properties"];
        EXPECT_EQ(properties["shape"]["const"], std::string(spec.name));
        for (const ParamSpec& param : spec.params) {
            SCOPED_TRACE(std::string(param.name));
            ASSERT_TRUE(properties.contains(std::string(param.name)));
            ordered_json number = properties[std::string(param.name)];
            if (param.components == 3) {
                EXPECT_EQ(number["minItems"], 3);
                EXPECT_EQ(number["maxItems"], 3);
                number = number["items"];
            }
            EXPECT_EQ(number["type"], "number");
            EXPECT_EQ(number["minimum"].get<float>(), param.minValue);
            EXPECT_EQ(number["maximum"].get<float>(), param.maxValue);
        }
    }
}

TEST(SceneSchema, EveryCatalogueModifierWithItsRangesDefaultsAndRequiredKeys) {
    const ordered_json schema = shippedSchema();
    for (const ModifierSpec& spec : modifierCatalogue()) {
        SCOPED_TRACE(std::string(spec.name));
        const ordered_json& def = schema["$defs"]["modifier_" + std::string(spec.name)];
        ASSERT_TRUE(def.is_object());
        EXPECT_EQ(def["properties"]["type"]["const"], std::string(spec.name));
        EXPECT_EQ(def["description"], std::string(spec.description));
        std::vector<std::string> required = {"type"};
        for (const ModifierParam& param : spec.params) {
            SCOPED_TRACE(std::string(param.spec.key));
            const ordered_json& key = def["properties"][std::string(param.spec.key)];
            ASSERT_TRUE(key.is_object());
            EXPECT_EQ(key["description"], std::string(param.spec.description));
            EXPECT_EQ(key.contains("default"), !param.spec.required);
            if (param.spec.required) required.emplace_back(param.spec.key);
            if (param.spec.type != ParamType::Number) continue;
            const char* min = param.spec.range.minExclusive ? "exclusiveMinimum" : "minimum";
            const char* max = param.spec.range.maxExclusive ? "exclusiveMaximum" : "maximum";
            EXPECT_EQ(key[min].get<double>(), param.spec.range.min);
            EXPECT_EQ(key[max].get<double>(), param.spec.range.max);
            if (!param.spec.required) {
                EXPECT_EQ(key["default"].get<float>(), param.spec.value[0]);
            }
        }
        EXPECT_EQ(def["required"], ordered_json(required));
    }
}

// docs/scene-format.md says it documents every key: each key the schema names (every
// "properties" member, at any depth) appears there in backquotes, as the tables and the text
// name keys, or as a key of a JSON example ("density": ...).
TEST(SceneSchema, EveryKeyIsDocumentedInTheFormatDocs) {
    const std::string docs = readFile(std::string(RMSC_TEST_SOURCE_DIR) + "/docs/scene-format.md");
    ASSERT_FALSE(docs.empty());
    const ordered_json schema = ordered_json::parse(generateSceneSchema().text);
    std::set<std::string> keys;
    std::vector<const ordered_json*> stack = {&schema};
    while (!stack.empty()) {
        const ordered_json* node = stack.back();
        stack.pop_back();
        if (node->is_object() && node->contains("properties") && (*node)["properties"].is_object())
            for (const auto& [key, value] : (*node)["properties"].items())
                keys.insert(key);
        if (node->is_structured())
            for (const auto& child : *node)
                stack.push_back(&child);
    }
    EXPECT_GT(keys.size(), 100u);
    for (const std::string& key : keys)
        EXPECT_TRUE(docs.find("`" + key + "`") != std::string::npos ||
                    docs.find("\"" + key + "\":") != std::string::npos)
            << "the schema's key \"" << key << "\" is not documented in docs/scene-format.md";
}
