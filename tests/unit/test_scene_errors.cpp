// Scene files that are wrong: each problem is an error at the exact JSON pointer (or line and
// column) of the offending value, with a message saying what was expected, and every problem
// in a file is reported in one pass.
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace rmsc;

namespace {

// Parses `text`, which must fail, and returns its diagnostics.
Diagnostics errorsOf(const std::string& text) {
    Diagnostics d;
    EXPECT_FALSE(parseScene(text, "bad.json", d)) << text;
    EXPECT_TRUE(d.hasErrors());
    for (const Diagnostic& item : d.items)
        EXPECT_EQ(item.file, "bad.json");
    return d;
}

// The one error `text` has; its location must be `location` and its message contain `words`.
void expectOneError(const std::string& text, const std::string& location,
                    const std::string& words) {
    const Diagnostics d = errorsOf(text);
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    const Diagnostic* error = nullptr;
    for (const Diagnostic& item : d.items)
        if (item.severity == Severity::Error) error = &item;
    EXPECT_EQ(error->location, location) << d.format();
    EXPECT_NE(error->message.find(words), std::string::npos)
        << "message: " << error->message << "\nexpected to contain: " << words;
}

std::string withSdf(const std::string& sdf) {
    return R"({"version": 1, "materials": {"red": {}, "blue": {}}, "sdf": )" + sdf + "}";
}

} // namespace

TEST(SceneErrors, NegativeRadiusNamesTheParameter) {
    expectOneError(withSdf(R"({"children": [{"shape": "box"}, {"shape": "box"},
        {"shape": "sphere"}, {"shape": "sphere", "radius": -1}]})"),
                   "/sdf/children/3/radius", "expected a number in [0, 10000], got -1");
}

TEST(SceneErrors, Vec3ParameterComponentOutOfRange) {
    expectOneError(withSdf(R"({"shape": "ellipsoid", "radii": [1, 0, 1]})"), "/sdf/radii/1",
                   "expected a number in [0.0001, 10000], got 0");
    expectOneError(withSdf(R"({"shape": "box", "half_extents": 1})"), "/sdf/half_extents",
                   "expected an array of 3 numbers, got a number");
}

// A range is checked on the float a number is kept as. The float nearest 0.001 lies just above
// 0.001, so a range ending at 0.001f (the gyroid's period, the death star's cut distance) took
// the float but refused the text "0.001" that the docs, the schema and the writer give for it;
// and a number that rounds to 0 is 0, which a range excluding 0 refuses.
TEST(SceneErrors, RangesHoldForTheFloatANumberIsKeptAs) {
    for (const char* sdf : {R"({"shape": "gyroid", "period": 0.001})",
                            R"({"shape": "death_star", "cut_distance": 0.001})"}) {
        Diagnostics d;
        EXPECT_TRUE(parseScene(withSdf(sdf), "ends.json", d)) << sdf << "\n" << d.format();
    }
    expectOneError(withSdf(R"({"shape": "gyroid", "period": 0.00099999})"), "/sdf/period",
                   "expected a number in [0.001, 10000], got 0.00099999");
    expectOneError(withSdf(R"({"op": "smooth_union", "smoothness": 1e-46,
        "children": [{"shape": "sphere"}]})"),
                   "/sdf/smoothness", "expected a number >= 0.001, got 1e-46");
    // A millimetre is the least smoothness: the seams' formulas divide by it.
    expectOneError(withSdf(R"({"op": "smooth_union", "smoothness": 0.00099,
        "children": [{"shape": "sphere"}]})"),
                   "/sdf/smoothness", "expected a number >= 0.001, got 0.00099");
    Diagnostics least;
    EXPECT_TRUE(parseScene(withSdf(R"({"op": "smooth_union", "smoothness": 0.001,
        "children": [{"shape": "sphere"}]})"),
                           "least.json", least))
        << least.format();
}

TEST(SceneErrors, UnknownShapeSuggestsTheNearestAndListsKnownShapesNearestFirst) {
    expectOneError(withSdf(R"({"shape": "spere"})"), "/sdf/shape",
                   "unknown shape \"spere\"; did you mean \"sphere\"? (known shapes: "
                   "\"sphere\", ");
    // The profile solids are shapes too.
    expectOneError(withSdf(R"({"shape": "revolutoin"})"), "/sdf/shape",
                   "; did you mean \"revolution\"?");
    // No suggestion for a name that is no typo of any.
    const Diagnostics d = errorsOf(withSdf(R"({"shape": "blob"})"));
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].message.find("did you mean"), std::string::npos) << d.format();
    EXPECT_NE(d.items[0].message.find("(known shapes: "), std::string::npos) << d.format();
}

TEST(SceneErrors, UnknownOpListsValidOps) {
    expectOneError(withSdf(R"({"op": "onion", "children": [{"shape": "sphere"}]})"), "/sdf/op",
                   "unknown op \"onion\"; valid ops: \"union\", ");
    const Diagnostics d = errorsOf(withSdf(R"({"op": "onion", "children": []})"));
    EXPECT_NE(d.items[0].message.find("\"smooth_intersection\""), std::string::npos);
}

TEST(SceneErrors, WrongTypesSayWhatWasExpected) {
    expectOneError(R"({"version": 1, "camera": {"fov": "wide"}})", "/camera/fov",
                   "expected a number in (0, 180), got a string");
    expectOneError(R"({"version": 1, "camera": {"position": [0, 1]}})", "/camera/position",
                   "expected an array of 3 numbers, got an array of 2");
    expectOneError(R"({"version": 1, "camera": {"position": [0, true, 1]}})", "/camera/position/1",
                   "expected a number, got a boolean");
    expectOneError(R"({"version": 1, "lights": {}})", "/lights",
                   "expected an array of lights, got an object");
    expectOneError(R"({"version": 1, "meshes": [{"file": 3}]})", "/meshes/0/file",
                   "expected a string, got a number");
    expectOneError(withSdf(R"({"shape": "sphere", "radius": null})"), "/sdf/radius", "got null");
    expectOneError(R"([1, 2])", "", "expected a scene object");
}

TEST(SceneErrors, VersionIsRequiredAndMustBeOne) {
    expectOneError(R"({"camera": {}})", "", "add \"version\": 1");
    expectOneError(R"({"version": 2, "sdf": {"shape": "nonsense"}})", "/version",
                   "this file is format version 2; this rmsc reads version 1 — upgrade rmsc");
    expectOneError(R"({"version": 0})", "/version", "this rmsc reads version 1");
    expectOneError(R"({"version": "1"})", "/version", "expected the integer 1, got a string");
}

TEST(SceneErrors, MissingVersionStillChecksTheRest) {
    const Diagnostics d = errorsOf(R"({"render": {"exposure": 0}})");
    ASSERT_EQ(d.errorCount(), 2) << d.format();
    EXPECT_EQ(d.items[1].location, "/render/exposure");
}

TEST(SceneErrors, NumbersTooLargeForAFloatAreRefused) {
    // nlohmann stops at 1e999 (or would parse it as infinity); the error names its pointer.
    expectOneError(withSdf(R"({"shape": "sphere", "radius": 1e999})"), "/sdf/radius",
                   "expected a finite number");
    expectOneError(R"({"version": 1, "camera": {"position": [0, -1e999, 0]}})",
                   "/camera/position/1", "expected a finite number");
    // Anywhere, even under a key the reader ignores.
    const Diagnostics d = errorsOf(R"({"version": 1, "notes": {"x": [1e999]}})");
    EXPECT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location, "/notes/x/0");
    // Finite as a double but not as a float.
    expectOneError(R"({"version": 1, "camera": {"position": [1e300, 0, 0]}})", "/camera/position/0",
                   "too large to represent");
}

TEST(SceneErrors, DuplicateKeysAreErrorsAtTheDuplicate) {
    expectOneError(R"({"version": 1, "camera": {"fov": 40, "near": 1, "fov": 50}})", "/camera/fov",
                   "duplicate key \"fov\"");
    expectOneError(R"({"version": 1, "lights": [{"type": "directional"},
        {"type": "directional", "name": "a", "name": "b"}]})",
                   "/lights/1/name", "duplicate key");
    expectOneError(R"({"version": 1, "version": 1})", "/version", "duplicate key");
    // The same key in sibling objects is fine.
    Diagnostics d;
    EXPECT_TRUE(parseScene(withSdf(R"({"children": [{"shape": "sphere", "name": "a"},
        {"shape": "sphere", "name": "b"}]})"),
                           "ok.json", d))
        << d.format();
}

TEST(SceneErrors, DeepNestingIsRefusedWithoutCrashing) {
    const std::string deep = std::string(200000, '[') + std::string(200000, ']');
    const Diagnostics tooDeep = errorsOf(deep);
    ASSERT_EQ(tooDeep.items.size(), 1u);
    EXPECT_EQ(tooDeep.items[0].location.size(), 256u * 2); // "/0" for each enclosing array
    EXPECT_NE(tooDeep.items[0].message.find("nested more than 256 levels"), std::string::npos);
    // 256 levels are fine as JSON (and then not a scene).
    const Diagnostics d = errorsOf(std::string(256, '[') + std::string(256, ']'));
    EXPECT_NE(d.items[0].message.find("expected a scene object"), std::string::npos);
    // Deeply nested SDF groups hit the same limit, at the pointer where it was passed.
    std::string sdf = R"({"shape": "sphere"})";
    for (int i = 0; i < 200; ++i)
        sdf = R"({"children": [)" + sdf + "]}";
    const Diagnostics nested = errorsOf(withSdf(sdf));
    ASSERT_EQ(nested.errorCount(), 1) << nested.format();
    EXPECT_EQ(nested.items[0].location.rfind("/sdf/children/0/children/0/", 0), 0u);
}

TEST(SceneErrors, MalformedJsonGivesLineAndColumn) {
    const std::string text = "{\n  \"version\": 1,\n  \"camera\" {}\n}";
    const Diagnostics d = errorsOf(text);
    ASSERT_EQ(d.items.size(), 1u);
    EXPECT_EQ(d.items[0].location, "line 3, column 12");
    EXPECT_NE(d.items[0].message.find("expected ':'"), std::string::npos) << d.items[0].message;
    EXPECT_EQ(d.items[0].message.find("json.exception"), std::string::npos);

    // Counted as nlohmann counts (the end of input is one past the last character), so the
    // location agrees with what nlohmann itself says.
    for (const std::string bad : {"{\"version\": 1,", "", "{\n\n  \"a\": [1, 2,, 3]}",
                                  "{\"a\": tru}", "{\"a\": \"\\x\"}\n"}) {
        const Diagnostics e = errorsOf(bad);
        ASSERT_EQ(e.items.size(), 1u) << bad;
        std::string nlohmannSays;
        try {
            const nlohmann::json parsed = nlohmann::json::parse(bad);
            (void)parsed;
        } catch (const nlohmann::json::parse_error& error) {
            nlohmannSays = error.what();
        }
        EXPECT_NE(nlohmannSays.find("at " + e.items[0].location + ":"), std::string::npos)
            << nlohmannSays << " vs " << e.items[0].location;
    }
    expectOneError("{\"version\": 1,", "line 1, column 15", "unexpected end of input");
    expectOneError("{\n\n  \"a\": [1, 2,, 3]}", "line 3, column 14", "unexpected ','");
}

TEST(SceneErrors, UnknownMaterialSuggestsTheNearest) {
    expectOneError(R"({"version": 1, "materials": {"red": {}, "blue": {}},
        "meshes": [{"file": "a.gltf", "material": "rde"}]})",
                   "/meshes/0/material",
                   "unknown material \"rde\"; did you mean \"red\"? (known materials: \"red\", "
                   "\"blue\")");
    expectOneError(withSdf(R"({"shape": "sphere", "material": "green"})"), "/sdf/material",
                   "unknown material \"green\"; known materials: \"red\", \"blue\"");
    expectOneError(R"({"version": 1, "sdf": {"shape": "sphere", "material": "red"}})",
                   "/sdf/material", "the scene defines no materials");
}

TEST(SceneErrors, SmoothOpNeedsSmoothness) {
    expectOneError(withSdf(R"({"op": "smooth_union", "children": [{"shape": "sphere"}]})"), "/sdf",
                   "op \"smooth_union\" needs \"smoothness\"");
    expectOneError(withSdf(R"({"op": "smooth_subtraction", "smoothness": 0,
        "children": [{"shape": "sphere"}]})"),
                   "/sdf/smoothness", "expected a number >= 0.001, got 0");
}

TEST(SceneErrors, NodeIsAShapeOrAGroupNotBoth) {
    expectOneError(withSdf(R"({"shape": "sphere", "children": []})"), "/sdf", "not both");
    expectOneError(withSdf(R"({"children": [{"shape": "box", "op": "union"}]})"), "/sdf/children/0",
                   "not both");
    expectOneError(withSdf(R"({"children": [{"name": "empty"}]})"), "/sdf/children/0",
                   "a node needs \"shape\"");
}

TEST(SceneErrors, TransformsAreChecked) {
    expectOneError(withSdf(R"({"shape": "sphere", "scale": 0})"), "/sdf/scale",
                   "expected a scale > 0, got 0");
    expectOneError(R"({"version": 1, "meshes": [{"file": "a.gltf", "scale": [1, -2, 1]}]})",
                   "/meshes/0/scale/1", "expected a scale > 0, got -2");
    expectOneError(withSdf(R"({"shape": "sphere", "rotation": [0, 0, 0],
        "quaternion": [0, 0, 0, 1]})"),
                   "/sdf", "either \"rotation\"");
    expectOneError(withSdf(R"({"shape": "sphere", "quaternion": [0, 0, 0, 0]})"), "/sdf/quaternion",
                   "non-zero quaternion");
    expectOneError(withSdf(R"({"shape": "sphere", "quaternion": [0, 0, 1]})"), "/sdf/quaternion",
                   "expected an array of 4 numbers");
}

TEST(SceneErrors, TooManyLightsNamesTheLimit) {
    std::string lights;
    for (int i = 0; i < 17; ++i)
        lights += std::string(i ? "," : "") + R"({"type": "directional"})";
    expectOneError(R"({"version": 1, "lights": [)" + lights + "]}", "/lights",
                   "at most 16 are supported");
}

TEST(SceneErrors, TooManySdfNodesNamesTheLimit) {
    std::string children;
    children.reserve(100000 * 20);
    for (int i = 0; i < 100000; ++i)
        children += i ? R"(,{"shape":"box"})" : R"({"shape":"box"})";
    // The root group is node 1, so its last child is node 100001.
    expectOneError(withSdf(R"({"children": [)" + children + "]}"), "/sdf/children/99999",
                   "more than 100000 nodes");
}

TEST(SceneErrors, LightsAreChecked) {
    expectOneError(R"({"version": 1, "lights": [{"type": "area"}]})", "/lights/0/type",
                   "unknown light type \"area\"; known types: \"directional\", \"point\", "
                   "\"spot\"");
    expectOneError(R"({"version": 1, "lights": [{"name": "sun"}]})", "/lights/0",
                   "missing \"type\"");
    expectOneError(R"({"version": 1, "lights": [{"type": "directional",
        "direction": [0, 0, 0]}]})",
                   "/lights/0/direction", "non-zero direction");
    expectOneError(R"({"version": 1, "lights": [{"type": "directional", "intensity": -1}]})",
                   "/lights/0/intensity", "expected a number >= 0, got -1");
}

TEST(SceneErrors, MaterialsAndColoursAreChecked) {
    expectOneError(R"({"version": 1, "materials": {"red": {"metallic": 1.5}}})",
                   "/materials/red/metallic", "expected a number in [0, 1], got 1.5");
    expectOneError(R"({"version": 1, "materials": {"a/b": {"roughness": -0.5}}})",
                   "/materials/a~1b/roughness", "expected a number in [0, 1], got -0.5");
    expectOneError(R"({"version": 1, "materials": {"red": {"base_color": "#12345"}}})",
                   "/materials/red/base_color", "expected a colour \"#rrggbb\"");
    expectOneError(R"({"version": 1, "materials": {"red": {"base_color": "#12345g"}}})",
                   "/materials/red/base_color", "expected a colour \"#rrggbb\"");
    expectOneError(R"({"version": 1, "render": {"background": [0, -0.1, 0]}})",
                   "/render/background/1", "expected a number >= 0, got -0.1");
    expectOneError(R"({"version": 1, "materials": {"red": 1}})", "/materials/red",
                   "expected an object, got a number");
}

TEST(SceneErrors, CameraAndRenderAreChecked) {
    expectOneError(R"({"version": 1, "camera": {"fov": 180}})", "/camera/fov",
                   "expected a number in (0, 180), got 180");
    expectOneError(R"({"version": 1, "camera": {"near": 0}})", "/camera/near",
                   "expected a number > 0, got 0");
    expectOneError(R"({"version": 1, "camera": {"near": 10, "far": 5}})", "/camera/far",
                   "expected \"far\" > \"near\"");
    expectOneError(R"({"version": 1, "camera": {"position": [1, 1, 1], "target": [1, 1, 1]}})",
                   "/camera/target", "equals its \"position\"");
    expectOneError(R"({"version": 1, "camera": {"position": [0, 5, 0], "target": [0, 0, 0]}})",
                   "/camera/up", "not parallel to the view direction");
    expectOneError(R"({"version": 1, "render": {"max_steps": 2.5}})", "/render/max_steps",
                   "expected an integer in [1, 4096], got 2.5");
    expectOneError(R"({"version": 1, "render": {"max_steps": 4097}})", "/render/max_steps",
                   "expected an integer in [1, 4096], got 4097");
    expectOneError(R"({"version": 1, "render": {"max_distance": 1e6}})", "/render/max_distance",
                   "expected a number in (0, 100000], got 1000000");
    expectOneError(R"({"version": 1, "render": {"surface_epsilon": 0}})", "/render/surface_epsilon",
                   "expected a number in (0, 1], got 0");
    expectOneError(R"({"version": 1, "render": {"exposure": -1}})", "/render/exposure",
                   "expected a number > 0, got -1");
}

TEST(SceneErrors, MeshesAreChecked) {
    expectOneError(R"({"version": 1, "meshes": [{"name": "x"}]})", "/meshes/0", "missing \"file\"");
    expectOneError(R"({"version": 1, "meshes": [{"file": ""}]})", "/meshes/0/file",
                   "expected the path of a glTF file");
}

TEST(SceneErrors, EveryProblemIsReportedInOnePass) {
    const Diagnostics d = errorsOf(R"({
      "version": 1,
      "camera": {"fov": -5},
      "render": {"max_steps": 0},
      "lights": [{"type": "area"}],
      "meshes": [{"file": "a.gltf", "scale": 0}],
      "sdf": {"children": [{"shape": "sphere", "radius": -1}, {"shape": "cube"},
                           {"shape": "box", "radus": 1}]}
    })");
    std::vector<std::string> locations;
    for (const Diagnostic& item : d.items)
        if (item.severity == Severity::Error) locations.push_back(item.location);
    EXPECT_EQ(locations, (std::vector<std::string>{
                             "/camera/fov", "/render/max_steps", "/lights/0/type",
                             "/meshes/0/scale", "/sdf/children/0/radius", "/sdf/children/1/shape"}))
        << d.format();
    EXPECT_EQ(d.errorCount(), 6);
    EXPECT_EQ(d.items.size(), 7u) << d.format(); // and the unknown-key warning
}
