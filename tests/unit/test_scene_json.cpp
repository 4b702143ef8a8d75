// Scene files that are valid: every field read into the Scene, defaults, colour and rotation
// conventions, mesh path resolution, unknown-key warnings, loading through a FileSource,
// writing and reading back, and the generated primitive table in docs/scene-format.md.
#include "scene/scene_json.hpp"
#include "sdf/catalogue_docs.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

using namespace rmsc;

namespace {

std::optional<Scene> parse(const std::string& text, Diagnostics& d,
                           const std::filesystem::path& path = "scenes/test.json") {
    return parseScene(text, path, d);
}

glm::vec3 rotate(const Transform& t, glm::vec3 v) {
    return t.rotation * v;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// A scene that sets every field of the format to something other than its default.
const char* kFullScene = R"({
  "version": 1,
  "camera": {"position": [1, 2, 3], "target": [0, 0.5, 0], "up": [0, 0, 1], "fov": 60,
             "near": 0.1, "far": 50},
  "render": {"max_steps": 128, "max_distance": 80, "surface_epsilon": 0.002,
             "background": [0.1, 0.2, 0.3], "ambient": [0.01, 0.02, 0.03], "exposure": 1.5},
  "materials": {
    "red": {"base_color": "#d04030", "metallic": 0.25, "roughness": 0.4, "emissive": [0, 0, 0]},
    "glow": {"base_color": [0.1, 0.2, 0.3], "emissive": [2, 1, 0.5]}
  },
  "lights": [
    {"type": "directional", "name": "sun", "direction": [0, -2, 0], "color": [1, 0.9, 0.8],
     "intensity": 4},
    {"type": "directional"}
  ],
  "meshes": [
    {"name": "floor", "file": "../assets/plane.gltf", "position": [0, -1, 0],
     "rotation": [0, 90, 0], "scale": 2, "material": "red"},
    {"file": "helmet.gltf", "quaternion": [0, 0, 1, 1], "scale": [1, 2, 3]}
  ],
  "sdf": {"op": "smooth_union", "smoothness": 0.2, "name": "blob", "position": [0, 0, 1],
          "material": "glow", "children": [
    {"shape": "sphere", "radius": 0.75, "material": "red", "position": [0, 0.5, 0]},
    {"shape": "box", "half_extents": [0.4, 0.2, 0.4], "rotation": [0, 45, 0], "scale": [1, 2, 1]},
    {"op": "subtraction", "children": [
      {"shape": "torus", "major_radius": 1, "minor_radius": 0.25},
      {"shape": "plane"}
    ]}
  ]}
})";

} // namespace

TEST(SceneJson, ReadsEveryField) {
    Diagnostics d;
    const auto scene = parse(kFullScene, d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    EXPECT_EQ(scene->version, 1);
    EXPECT_EQ(scene->file, std::filesystem::path("scenes/test.json"));

    const Camera& c = scene->camera;
    EXPECT_EQ(c.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(c.target, glm::vec3(0, 0.5f, 0));
    EXPECT_EQ(c.up, glm::vec3(0, 0, 1));
    EXPECT_EQ(c.fovYDegrees, 60.0f);
    EXPECT_EQ(c.nearPlane, 0.1f);
    EXPECT_EQ(c.farPlane, 50.0f);

    const RenderSettings& r = scene->render;
    EXPECT_EQ(r.maxSteps, 128);
    EXPECT_EQ(r.maxDistance, 80.0f);
    EXPECT_EQ(r.surfaceEpsilon, 0.002f);
    EXPECT_EQ(r.background, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(r.ambient, glm::vec3(0.01f, 0.02f, 0.03f));
    EXPECT_EQ(r.exposure, 1.5f);

    ASSERT_EQ(scene->materials.size(), 2u);
    EXPECT_EQ(scene->materials[0].name, "red"); // file order
    EXPECT_EQ(scene->materials[0].metallic, 0.25f);
    EXPECT_EQ(scene->materials[0].roughness, 0.4f);
    EXPECT_EQ(scene->materials[1].name, "glow");
    EXPECT_EQ(scene->materials[1].baseColor, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(scene->materials[1].roughness, 0.5f); // default
    EXPECT_EQ(scene->materials[1].emissive, glm::vec3(2, 1, 0.5f));

    ASSERT_EQ(scene->lights.size(), 2u);
    EXPECT_EQ(scene->lights[0].name, "sun");
    EXPECT_EQ(scene->lights[0].type, LightType::Directional);
    EXPECT_EQ(scene->lights[0].direction, glm::vec3(0, -1, 0)); // normalized
    EXPECT_EQ(scene->lights[0].color, glm::vec3(1, 0.9f, 0.8f));
    EXPECT_EQ(scene->lights[0].intensity, 4.0f);
    EXPECT_EQ(scene->lights[1].intensity, 3.0f); // default
    EXPECT_NEAR(glm::length(scene->lights[1].direction), 1.0f, 1e-6f);

    ASSERT_EQ(scene->meshes.size(), 2u);
    const MeshInstance& floor = scene->meshes[0];
    EXPECT_EQ(floor.name, "floor");
    EXPECT_EQ(floor.file, "../assets/plane.gltf");
    EXPECT_EQ(floor.path, std::filesystem::path("assets/plane.gltf"));
    EXPECT_EQ(floor.pointer, "/meshes/0");
    EXPECT_EQ(floor.transform.position, glm::vec3(0, -1, 0));
    EXPECT_EQ(floor.transform.scale, glm::vec3(2.0f));
    EXPECT_EQ(floor.materialOverride, 0);
    const MeshInstance& helmet = scene->meshes[1];
    EXPECT_EQ(helmet.name, "helmet"); // the file stem
    EXPECT_EQ(helmet.path, std::filesystem::path("scenes/helmet.gltf"));
    EXPECT_EQ(helmet.transform.scale, glm::vec3(1, 2, 3));
    EXPECT_EQ(helmet.materialOverride, -1);
    EXPECT_EQ(helmet.pointer, "/meshes/1");

    ASSERT_TRUE(scene->sdf);
    const SdfNode& root = *scene->sdf;
    EXPECT_TRUE(root.isGroup);
    EXPECT_EQ(root.name, "blob");
    EXPECT_EQ(root.pointer, "/sdf");
    EXPECT_EQ(root.op, SdfOp::SmoothUnion);
    EXPECT_EQ(root.smoothness, 0.2f);
    EXPECT_EQ(root.material, 1);
    EXPECT_EQ(root.transform.position, glm::vec3(0, 0, 1));
    ASSERT_EQ(root.children.size(), 3u);

    const SdfNode& sphere = root.children[0];
    EXPECT_FALSE(sphere.isGroup);
    EXPECT_EQ(sphere.pointer, "/sdf/children/0");
    EXPECT_EQ(sphere.primitive, PrimitiveId::Sphere);
    EXPECT_EQ(sphere.params[0], 0.75f);
    EXPECT_EQ(sphere.material, 0);

    const SdfNode& box = root.children[1];
    EXPECT_EQ(box.primitive, PrimitiveId::Box);
    EXPECT_EQ(box.params[0], 0.4f);
    EXPECT_EQ(box.params[1], 0.2f);
    EXPECT_EQ(box.params[2], 0.4f);
    EXPECT_EQ(box.transform.scale, glm::vec3(1, 2, 1));
    EXPECT_EQ(box.material, -1); // inherits

    const SdfNode& cut = root.children[2];
    EXPECT_TRUE(cut.isGroup);
    EXPECT_EQ(cut.op, SdfOp::Subtraction);
    ASSERT_EQ(cut.children.size(), 2u);
    EXPECT_EQ(cut.children[1].pointer, "/sdf/children/2/children/1");
    const PrimitiveSpec& torus = *findPrimitive("torus");
    EXPECT_EQ(cut.children[0].params[paramOffset(torus, 0)], 1.0f);
    EXPECT_EQ(cut.children[0].params[paramOffset(torus, 1)], 0.25f);
    EXPECT_EQ(cut.children[1].primitive, PrimitiveId::Plane);
}

TEST(SceneJson, MissingSectionsAndFieldsTakeTheDefaults) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "camera": {"fov": 30},
        "sdf": {"shape": "round_box"}})",
                             d);
    ASSERT_TRUE(scene) << d.format();
    const Scene defaults;
    EXPECT_EQ(scene->camera.fovYDegrees, 30.0f);
    EXPECT_EQ(scene->camera.position, defaults.camera.position);
    EXPECT_EQ(scene->camera.farPlane, defaults.camera.farPlane);
    EXPECT_EQ(scene->render.maxSteps, defaults.render.maxSteps);
    EXPECT_EQ(scene->render.background, defaults.render.background);
    EXPECT_TRUE(scene->lights.empty());
    EXPECT_TRUE(scene->materials.empty());
    EXPECT_TRUE(scene->meshes.empty());
    ASSERT_TRUE(scene->sdf);
    const PrimitiveSpec& spec = *findPrimitive("round_box");
    EXPECT_EQ(scene->sdf->params, defaultParams(spec));
    EXPECT_EQ(scene->sdf->transform.position, glm::vec3(0.0f));
    EXPECT_EQ(scene->sdf->transform.scale, glm::vec3(1.0f));
    EXPECT_EQ(scene->sdf->material, -1);

    const auto empty = parse(R"({"version": 1})", d);
    ASSERT_TRUE(empty);
    EXPECT_FALSE(empty->sdf);
}

TEST(SceneJson, GroupWithoutOpIsAUnion) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "sdf": {"children": [{"shape": "sphere"}]}})", d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_TRUE(scene->sdf->isGroup);
    EXPECT_EQ(scene->sdf->op, SdfOp::Union);
}

TEST(SceneJson, HexColoursAreSrgbConvertedToLinear) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "materials": {
        "white": {"base_color": "#FFFFFF"}, "grey": {"base_color": "#808080"},
        "dark": {"base_color": "#0a0000"}, "mix": {"base_color": "#d04030"}}})",
                             d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_EQ(scene->materials[0].baseColor, glm::vec3(1.0f));
    // 128/255 is on the power segment of the sRGB curve: ((c + 0.055) / 1.055)^2.4.
    EXPECT_NEAR(scene->materials[1].baseColor.x, 0.2158605f, 1e-6f);
    // 10/255 = 0.0392 is below 0.04045: the linear segment, c / 12.92.
    EXPECT_NEAR(scene->materials[2].baseColor.x, 10.0f / 255.0f / 12.92f, 1e-7f);
    EXPECT_EQ(scene->materials[2].baseColor.y, 0.0f);
    EXPECT_NEAR(scene->materials[3].baseColor.x, 0.6307571f, 1e-6f); // 0xd0 = 208
    EXPECT_NEAR(scene->materials[3].baseColor.y, 0.0512695f, 1e-6f); // 0x40 = 64
    EXPECT_NEAR(scene->materials[3].baseColor.z, 0.0295568f, 1e-6f); // 0x30 = 48
}

TEST(SceneJson, EulerRotationIsXThenYThenZAboutFixedAxes) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "meshes": [
        {"file": "a.gltf", "rotation": [0, 90, 0]},
        {"file": "a.gltf", "rotation": [90, 90, 0]},
        {"file": "a.gltf", "rotation": [0, 0, 90]},
        {"file": "a.gltf", "rotation": [90, 0, 90]}]})",
                             d);
    ASSERT_TRUE(scene) << d.format();
    // Right-handed, +Y up: a quarter turn about +y takes +x to -z.
    expectNear(rotate(scene->meshes[0].transform, {1, 0, 0}), {0, 0, -1});
    // X first takes +y to +z, then Y takes +z to +x. (Y first would leave +y at +z.)
    expectNear(rotate(scene->meshes[1].transform, {0, 1, 0}), {1, 0, 0});
    expectNear(rotate(scene->meshes[2].transform, {1, 0, 0}), {0, 1, 0});
    // X takes +y to +z, Z leaves +z alone; Z first would take +y to -x, then X leaves it.
    expectNear(rotate(scene->meshes[3].transform, {0, 1, 0}), {0, 0, 1});
}

TEST(SceneJson, QuaternionIsXyzwAndNormalized) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "sdf": {"shape": "sphere",
        "quaternion": [0, 2, 0, 2]}})",
                             d);
    ASSERT_TRUE(scene) << d.format();
    const glm::quat q = scene->sdf->transform.rotation;
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
    EXPECT_NEAR(q.y, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(q.w, std::sqrt(0.5f), 1e-6f);
    expectNear(rotate(scene->sdf->transform, {1, 0, 0}), {0, 0, -1});
}

TEST(SceneJson, MeshPathsResolveAgainstTheSceneFolder) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "meshes": [
        {"file": "../assets/./plane.gltf"}, {"file": "models/box.gltf"},
        {"file": "/models/abs.gltf"}]})",
                             d, "project/scenes/main.json");
    ASSERT_TRUE(scene) << d.format();
    EXPECT_EQ(scene->meshes[0].path, std::filesystem::path("project/assets/plane.gltf"));
    EXPECT_EQ(scene->meshes[1].path, std::filesystem::path("project/scenes/models/box.gltf"));
    EXPECT_EQ(scene->meshes[2].path, std::filesystem::path("/models/abs.gltf"));
    EXPECT_EQ(scene->meshes[0].name, "plane");

    // A scene file with no folder part: paths stay relative to the working directory.
    const auto bare =
        parse(R"({"version": 1, "meshes": [{"file": "a/../b.gltf"}]})", d, "scene.json");
    ASSERT_TRUE(bare);
    EXPECT_EQ(bare->meshes[0].path, std::filesystem::path("b.gltf"));
}

TEST(SceneJson, UnknownKeysAreWarningsWithSuggestions) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "camera": {"fovv": 40},
        "sdf": {"shape": "sphere", "radus": 2, "colour": "red"}})",
                             d);
    ASSERT_TRUE(scene) << d.format(); // warnings alone still load
    EXPECT_EQ(d.errorCount(), 0);
    ASSERT_EQ(d.items.size(), 3u) << d.format();
    EXPECT_EQ(d.items[0].severity, Severity::Warning);
    EXPECT_EQ(d.items[0].location, "/camera/fovv");
    EXPECT_EQ(d.items[0].message, "unknown key \"fovv\"; did you mean \"fov\"?");
    EXPECT_EQ(d.items[1].location, "/sdf/radus");
    EXPECT_EQ(d.items[1].message, "unknown key \"radus\"; did you mean \"radius\"?");
    // Nothing close: no suggestion, but the known keys.
    EXPECT_EQ(d.items[2].location, "/sdf/colour");
    EXPECT_EQ(d.items[2].message.find("did you mean"), std::string::npos);
    EXPECT_NE(d.items[2].message.find("\"material\""), std::string::npos);
    EXPECT_EQ(scene->sdf->params[0], 0.5f); // the misspelt radius is not used
}

TEST(SceneJson, SmoothnessOnAHardOpIsAWarning) {
    Diagnostics d;
    const auto scene = parse(R"({"version": 1, "sdf": {"op": "union", "smoothness": 0.3,
        "children": [{"shape": "sphere"}]}})",
                             d);
    ASSERT_TRUE(scene);
    ASSERT_EQ(d.items.size(), 1u);
    EXPECT_EQ(d.items[0].severity, Severity::Warning);
    EXPECT_EQ(d.items[0].location, "/sdf/smoothness");
}

TEST(SceneJson, LoadsThroughAFileSource) {
    FileSource files;
    files.read = [](const std::filesystem::path& path,
                    std::string& error) -> std::optional<std::string> {
        if (path == "scenes/a.json")
            return std::string(R"({"version": 1, "render": {"exposure": 2}})");
        error = "no such file";
        return std::nullopt;
    };
    Diagnostics d;
    const auto scene = loadScene("scenes/a.json", files, d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_EQ(scene->render.exposure, 2.0f);
    EXPECT_EQ(scene->file, std::filesystem::path("scenes/a.json"));

    EXPECT_FALSE(loadScene("scenes/missing.json", files, d));
    ASSERT_EQ(d.items.size(), 1u);
    EXPECT_EQ(d.items[0].file, "scenes/missing.json");
    EXPECT_EQ(d.items[0].location, "");
    EXPECT_EQ(d.items[0].message, "cannot read scene file: no such file");
}

namespace {

void expectSameTransform(const Transform& a, const Transform& b, const std::string& what) {
    EXPECT_EQ(a.position, b.position) << what;
    EXPECT_EQ(a.rotation, b.rotation) << what;
    EXPECT_EQ(a.scale, b.scale) << what;
}

void expectSameNode(const SdfNode& a, const SdfNode& b) {
    EXPECT_EQ(a.name, b.name) << a.pointer;
    EXPECT_EQ(a.pointer, b.pointer);
    expectSameTransform(a.transform, b.transform, a.pointer);
    EXPECT_EQ(a.material, b.material) << a.pointer;
    EXPECT_EQ(a.isGroup, b.isGroup) << a.pointer;
    EXPECT_EQ(a.op, b.op) << a.pointer;
    EXPECT_EQ(a.smoothness, b.smoothness) << a.pointer;
    EXPECT_EQ(a.primitive, b.primitive) << a.pointer;
    EXPECT_EQ(a.params, b.params) << a.pointer;
    ASSERT_EQ(a.children.size(), b.children.size()) << a.pointer;
    for (std::size_t i = 0; i < a.children.size(); ++i)
        expectSameNode(a.children[i], b.children[i]);
}

// Field by field, bit-exact.
void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.version, b.version);
    EXPECT_EQ(a.file, b.file);
    EXPECT_EQ(a.camera.position, b.camera.position);
    EXPECT_EQ(a.camera.target, b.camera.target);
    EXPECT_EQ(a.camera.up, b.camera.up);
    EXPECT_EQ(a.camera.fovYDegrees, b.camera.fovYDegrees);
    EXPECT_EQ(a.camera.nearPlane, b.camera.nearPlane);
    EXPECT_EQ(a.camera.farPlane, b.camera.farPlane);
    EXPECT_EQ(a.render.maxSteps, b.render.maxSteps);
    EXPECT_EQ(a.render.maxDistance, b.render.maxDistance);
    EXPECT_EQ(a.render.surfaceEpsilon, b.render.surfaceEpsilon);
    EXPECT_EQ(a.render.background, b.render.background);
    EXPECT_EQ(a.render.ambient, b.render.ambient);
    EXPECT_EQ(a.render.exposure, b.render.exposure);
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.materials[i].name, b.materials[i].name);
        EXPECT_EQ(a.materials[i].baseColor, b.materials[i].baseColor);
        EXPECT_EQ(a.materials[i].metallic, b.materials[i].metallic);
        EXPECT_EQ(a.materials[i].roughness, b.materials[i].roughness);
        EXPECT_EQ(a.materials[i].emissive, b.materials[i].emissive);
    }
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].name, b.lights[i].name);
        EXPECT_EQ(a.lights[i].type, b.lights[i].type);
        EXPECT_EQ(a.lights[i].direction, b.lights[i].direction);
        EXPECT_EQ(a.lights[i].color, b.lights[i].color);
        EXPECT_EQ(a.lights[i].intensity, b.lights[i].intensity);
    }
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        EXPECT_EQ(a.meshes[i].name, b.meshes[i].name);
        EXPECT_EQ(a.meshes[i].file, b.meshes[i].file);
        EXPECT_EQ(a.meshes[i].path, b.meshes[i].path);
        EXPECT_EQ(a.meshes[i].pointer, b.meshes[i].pointer);
        EXPECT_EQ(a.meshes[i].materialOverride, b.meshes[i].materialOverride);
        expectSameTransform(a.meshes[i].transform, b.meshes[i].transform, a.meshes[i].pointer);
    }
    ASSERT_EQ(a.sdf.has_value(), b.sdf.has_value());
    if (a.sdf) expectSameNode(*a.sdf, *b.sdf);
}

} // namespace

TEST(SceneJson, WrittenSceneReadsBackIdentical) {
    Diagnostics d;
    const auto scene = parse(kFullScene, d);
    ASSERT_TRUE(scene) << d.format();
    const std::string text = sceneToJson(*scene);
    const auto again = parse(text, d);
    ASSERT_TRUE(again) << d.format() << text;
    EXPECT_TRUE(d.items.empty()) << d.format();
    expectSameScene(*scene, *again);
    EXPECT_EQ(sceneToJson(*again), text); // writing is deterministic

    // The format as documented: version first, 2-space indents, short numbers, Euler degrees
    // where they were typed.
    EXPECT_EQ(text.rfind("{\n  \"version\": 1,\n  \"camera\": {\n    \"position\": [1, 2, 3],", 0),
              0u)
        << text;
    EXPECT_NE(text.find("\"surface_epsilon\": 0.002,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"material\": \"red\""), std::string::npos);
    EXPECT_NE(text.find("\"half_extents\": [0.4, 0.2, 0.4]"), std::string::npos);
    EXPECT_NE(text.find("\"rotation\": [0, 90, 0]"), std::string::npos) << text;
    EXPECT_NE(text.find("\"rotation\": [0, 45, 0]"), std::string::npos) << text;
}

// A rotation is written as the Euler degrees it was typed in when they read back as exactly
// the same quaternion, and as that quaternion otherwise (a rotation turned in the editor): either
// way the scene reads back with every bit of it.
TEST(SceneJson, RotationsAreWrittenAsTypedWhereThatIsExact) {
    for (const std::string typed :
         {"[0, 30, 0]", "[10, 20, 30]", "[-45, 0, 120]", "[90, 90, 0]", "[0, 0, -0.5]"}) {
        Diagnostics d;
        const auto scene =
            parse(R"({"version": 1, "sdf": {"shape": "sphere", "rotation": )" + typed + "}}", d);
        ASSERT_TRUE(scene && scene->sdf) << d.format();
        const std::string text = sceneToJson(*scene);
        EXPECT_NE(text.find("\"rotation\": " + typed), std::string::npos) << text;
        const auto again = parse(text, d);
        ASSERT_TRUE(again && again->sdf) << d.format();
        EXPECT_EQ(again->sdf->transform.rotation, scene->sdf->transform.rotation) << text;
    }
    // Turned by an angle no short degrees give exactly.
    Scene scene;
    SdfNode node;
    node.transform.rotation = glm::normalize(glm::quat(0.9f, 0.1f, 0.2f, 0.3f));
    scene.sdf = node;
    const std::string text = sceneToJson(scene);
    EXPECT_NE(text.find("\"quaternion\": ["), std::string::npos) << text;
    EXPECT_EQ(text.find("\"rotation\""), std::string::npos) << text;
    Diagnostics d;
    const auto again = parse(text, d);
    ASSERT_TRUE(again && again->sdf) << d.format();
    EXPECT_EQ(again->sdf->transform.rotation, node.transform.rotation) << text;
}

TEST(SceneJson, WrittenFloatsKeepEveryBit) {
    Scene scene;
    scene.camera.fovYDegrees = std::nextafter(45.0f, 90.0f);
    scene.render.exposure = 1.0f / 3.0f;
    scene.render.surfaceEpsilon = 1e-7f;
    scene.render.maxDistance = 12345.678f;
    Diagnostics d;
    const auto again = parse(sceneToJson(scene), d);
    ASSERT_TRUE(again) << d.format();
    EXPECT_EQ(again->camera.fovYDegrees, scene.camera.fovYDegrees);
    EXPECT_EQ(again->render.exposure, scene.render.exposure);
    EXPECT_EQ(again->render.surfaceEpsilon, scene.render.surfaceEpsilon);
    EXPECT_EQ(again->render.maxDistance, scene.render.maxDistance);
}

TEST(SceneJson, WriterNeverWritesNonFiniteNumbers) {
    // Chosen behaviour: non-finite values are clamped (NaN -> 0, inf -> the largest float), so
    // the file is always valid JSON with finite numbers; the reader then names the bad field.
    Scene scene;
    scene.camera.position.x = std::numeric_limits<float>::quiet_NaN();
    scene.render.exposure = std::numeric_limits<float>::infinity();
    scene.lights.push_back({});
    scene.lights[0].intensity = -std::numeric_limits<float>::infinity();
    const std::string text = sceneToJson(scene);
    EXPECT_EQ(text.find("null"), std::string::npos) << text;
    EXPECT_EQ(text.find("nan"), std::string::npos) << text;
    EXPECT_EQ(text.find("inf"), std::string::npos) << text;
    Diagnostics d;
    const auto again = parse(text, d);
    EXPECT_FALSE(again);                        // the clamped values are out of range...
    EXPECT_EQ(d.errorCount(), 1) << d.format(); // ...exposure is fine (> 0), intensity is not
    EXPECT_EQ(d.items[0].location, "/lights/0/intensity");
}

TEST(SceneJson, WriterGivesCodeBuiltMaterialsUniqueNames) {
    Scene scene;
    scene.materials.resize(3);
    scene.materials[1].name = "steel";
    scene.materials[2].name = "steel";
    SdfNode node;
    node.material = 2;
    scene.sdf = node;
    Diagnostics d;
    const auto again = parse(sceneToJson(scene), d);
    ASSERT_TRUE(again) << d.format();
    ASSERT_EQ(again->materials.size(), 3u);
    EXPECT_EQ(again->materials[1].name, "steel");
    EXPECT_NE(again->materials[0].name, again->materials[2].name);
    EXPECT_EQ(again->sdf->material, 2);
}

namespace {

std::string readSourceFile(const std::string& relativePath) {
    std::ifstream file(std::string(RMSC_TEST_SOURCE_DIR) + "/" + relativePath);
    std::stringstream buffer;
    buffer << file.rdbuf();
    return buffer.str();
}

} // namespace

TEST(SceneJson, SampleScenesLoadCleanlyAndRoundTrip) {
    const auto folder = std::filesystem::path(RMSC_TEST_SOURCE_DIR) / "samples" / "scenes";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        ++count;
        const std::string name = "samples/scenes/" + entry.path().filename().string();
        Diagnostics d;
        const auto scene = parseScene(readSourceFile(name), name, d);
        ASSERT_TRUE(scene) << d.format();
        EXPECT_TRUE(d.items.empty()) << d.format();
        const auto again = parseScene(sceneToJson(*scene), name, d);
        ASSERT_TRUE(again) << d.format();
        expectSameScene(*scene, *again);
    }
    EXPECT_GT(count, 0);
}

TEST(SceneJson, DocsExampleIsAValidScene) {
    const std::string docs = readSourceFile("docs/scene-format.md");
    const std::size_t section = docs.find("## A complete example");
    ASSERT_NE(section, std::string::npos);
    const std::size_t from = docs.find("```json\n", section);
    ASSERT_NE(from, std::string::npos);
    const std::size_t to = docs.find("```", from + 8);
    ASSERT_NE(to, std::string::npos);
    Diagnostics d;
    const auto scene = parseScene(docs.substr(from + 8, to - from - 8), "scenes/example.json", d);
    ASSERT_TRUE(scene) << d.format();
    EXPECT_TRUE(d.items.empty()) << d.format();
    EXPECT_EQ(scene->meshes[0].path, std::filesystem::path("assets/plane.gltf"));
    ASSERT_TRUE(scene->sdf);
    EXPECT_EQ(scene->sdf->children.size(), 3u);
}

namespace {

// The text of docs/scene-format.md between <!-- name:begin --> and <!-- name:end -->.
std::string docsSection(const std::string& name) {
    const std::string docs = readSourceFile("docs/scene-format.md");
    const std::string begin = "<!-- " + name + ":begin -->\n";
    const std::string end = "<!-- " + name + ":end -->";
    const std::size_t from = docs.find(begin);
    const std::size_t to = docs.find(end);
    if (from == std::string::npos || to == std::string::npos || to < from) return "(missing)";
    return docs.substr(from + begin.size(), to - from - begin.size());
}

} // namespace

TEST(SceneJson, DocsContainTheGeneratedPrimitiveTable) {
    const std::string generated = primitiveCatalogueMarkdown();
    for (const PrimitiveSpec& spec : primitiveCatalogue())
        EXPECT_NE(generated.find("| `" + std::string(spec.name) + "` |"), std::string::npos);
    EXPECT_EQ(docsSection("primitives"), generated)
        << "regenerate the table in docs/scene-format.md from primitiveCatalogueMarkdown():\n"
        << generated;
}

TEST(SceneJson, DocsContainTheGeneratedModifierOperationAndProfileTables) {
    const std::string modifiers = modifierCatalogueMarkdown();
    for (const ModifierSpec& spec : modifierCatalogue()) {
        EXPECT_NE(modifiers.find("| `" + std::string(spec.name) + "` |"), std::string::npos);
        for (const ModifierParam& param : spec.params)
            EXPECT_NE(modifiers.find("`" + std::string(param.spec.key) + "`: "), std::string::npos);
    }
    EXPECT_NE(modifiers.find("`thickness`: number, required, range (0, 10000]"), std::string::npos);
    EXPECT_NE(modifiers.find("`axis`: \"x\", \"y\" or \"z\", default \"y\""), std::string::npos);
    const std::string operations = operationCatalogueMarkdown();
    EXPECT_NE(operations.find("| `chamfer_union` | required | ignored |"), std::string::npos);
    EXPECT_NE(operations.find("| `smooth_intersection` | required | optional |"),
              std::string::npos);
    const std::string profiles = profileCatalogueMarkdown();
    for (const ProfileSpec& spec : profileCatalogue())
        EXPECT_NE(profiles.find("| `" + std::string(spec.name) + "` |"), std::string::npos);
    EXPECT_NE(profiles.find("| `revolution` |"), std::string::npos);

    EXPECT_EQ(docsSection("modifiers"), modifiers)
        << "regenerate the table in docs/scene-format.md from modifierCatalogueMarkdown():\n"
        << modifiers;
    EXPECT_EQ(docsSection("operations"), operations)
        << "regenerate the table in docs/scene-format.md from operationCatalogueMarkdown():\n"
        << operations;
    EXPECT_EQ(docsSection("profiles"), profiles)
        << "regenerate the tables in docs/scene-format.md from profileCatalogueMarkdown():\n"
        << profiles;
}
