// glTF KHR_lights_punctual import: a node's light becomes a scene light placed by the node's
// world transform (shining down its -Z axis), with the spot cone converted to degrees; bad
// values are errors at the light's glTF pointer.
#include "scene/mesh_asset.hpp"

#include <gtest/gtest.h>

#include <map>

using namespace rmsc;

namespace {

std::optional<MeshAsset> loadText(const std::string& text, Diagnostics& diagnostics) {
    FileSource files;
    files.read = [text](const std::filesystem::path& path,
                        std::string& error) -> std::optional<std::string> {
        if (path == "mem/lights.gltf") return text;
        error = "no such file";
        return std::nullopt;
    };
    return loadGltf("mem/lights.gltf", files, diagnostics);
}

std::string gltfWithLight(const std::string& light) {
    // Node 0 moves by (0, 2, 0) and turns -90 degrees about X (so its -Z points down); its
    // child, node 1, carries the light at (1, 0, 0) in node 0's space: world (1, 2, 0).
    return R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [)" +
           light + R"(]}},
      "scenes": [{"nodes": [0]}], "scene": 0,
      "nodes": [{"translation": [0, 2, 0], "rotation": [-0.7071068, 0, 0, 0.7071068], "children": [1]},
                {"translation": [1, 0, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}}]})";
}

} // namespace

TEST(GltfLights, SpotLightTakesTheNodeTransform) {
    Diagnostics d;
    const auto asset = loadText(gltfWithLight(R"({"type": "spot", "color": [1, 0.5, 0],
        "intensity": 12, "range": 7, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}})"),
                                d);
    ASSERT_TRUE(asset.has_value()) << d.format();
    ASSERT_EQ(asset->lights.size(), 1u);
    const Light& light = asset->lights[0];
    EXPECT_EQ(light.type, LightType::Spot);
    EXPECT_NEAR(light.position.x, 1.0f, 1e-5f);
    EXPECT_NEAR(light.position.y, 2.0f, 1e-5f);
    EXPECT_NEAR(light.position.z, 0.0f, 1e-5f);
    // -Z turned -90 degrees about X points down.
    EXPECT_NEAR(light.direction.y, -1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(light.intensity, 12.0f);
    EXPECT_FLOAT_EQ(light.range, 7.0f);
    EXPECT_NEAR(light.innerAngleDegrees, 0.2f * 180.0f / 3.14159265f, 1e-3f);
    EXPECT_NEAR(light.outerAngleDegrees, 0.5f * 180.0f / 3.14159265f, 1e-3f);
    EXPECT_EQ(light.color, glm::vec3(1.0f, 0.5f, 0.0f));
}

TEST(GltfLights, BadLightsAreErrorsAtTheirPointers) {
    Diagnostics d;
    loadText(gltfWithLight(R"({"type": "point", "intensity": -1})"), d);
    EXPECT_TRUE(d.hasErrors());
    EXPECT_NE(d.format().find("/extensions/KHR_lights_punctual/lights/0/intensity"),
              std::string::npos)
        << d.format();
    Diagnostics cone;
    loadText(gltfWithLight(
                 R"({"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.5}})"),
             cone);
    EXPECT_NE(cone.format().find("lights/0/spot/innerConeAngle"), std::string::npos)
        << cone.format();
}
