// The lighting keys of scene files: point and spot lights, render "shadows" / "ao" / "fxaa",
// the "environment" section (sky, fog); values read, defaults kept, round trips through the
// writer, and every bad value reported at its JSON pointer.
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

using namespace rmsc;

namespace {

Scene parseOk(const std::string& text) {
    Diagnostics d;
    std::optional<Scene> scene = parseScene(text, "/scenes/ok.json", d);
    EXPECT_TRUE(scene.has_value()) << d.format();
    EXPECT_EQ(d.items.size(), 0u) << d.format();
    return scene ? *scene : Scene{};
}

// `text` must fail with exactly the errors at `locations`, the first containing `words`.
void expectErrors(const std::string& text, const std::vector<std::string>& locations,
                  const std::string& words) {
    Diagnostics d;
    EXPECT_FALSE(parseScene(text, "bad.json", d)) << text;
    std::vector<std::string> found;
    const Diagnostic* first = nullptr;
    for (const Diagnostic& item : d.items) {
        if (item.severity != Severity::Error) continue;
        found.push_back(item.location);
        if (!first) first = &item;
    }
    EXPECT_EQ(found, locations) << d.format();
    if (first) {
        EXPECT_NE(first->message.find(words), std::string::npos) << first->message;
    }
}

std::string withLight(const std::string& light) {
    return R"({"version": 1, "lights": [)" + light + "]}";
}

} // namespace

TEST(LightingJson, PointAndSpotLightsAreRead) {
    const Scene scene = parseOk(withLight(R"(
        {"type": "point", "name": "bulb", "position": [1, 2, 3], "color": [1, 0.5, 0.25],
         "intensity": 40, "range": 6},
        {"type": "spot", "position": [0, 4, 0], "direction": [0, -2, 0], "intensity": 100,
         "inner_angle": 10, "outer_angle": 30, "shadows": false, "shadow_softness": 0.2})"));
    ASSERT_EQ(scene.lights.size(), 2u);
    const Light& point = scene.lights[0];
    EXPECT_EQ(point.type, LightType::Point);
    EXPECT_EQ(point.position, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(point.range, 6.0f);
    EXPECT_FLOAT_EQ(point.intensity, 40.0f);
    EXPECT_TRUE(point.castShadows);
    const Light& spot = scene.lights[1];
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_EQ(spot.direction, glm::vec3(0, -1, 0)); // normalized
    EXPECT_FLOAT_EQ(spot.innerAngleDegrees, 10.0f);
    EXPECT_FLOAT_EQ(spot.outerAngleDegrees, 30.0f);
    EXPECT_FALSE(spot.castShadows);
    EXPECT_FLOAT_EQ(spot.shadowSoftness, 0.2f);
}

TEST(LightingJson, SpotDefaultsFollowKhrLightsPunctual) {
    const Scene scene = parseOk(withLight(R"({"type": "spot"})"));
    EXPECT_FLOAT_EQ(scene.lights[0].innerAngleDegrees, 0.0f);
    EXPECT_FLOAT_EQ(scene.lights[0].outerAngleDegrees, 45.0f);
    EXPECT_FLOAT_EQ(scene.lights[0].range, 0.0f); // unlimited
}

TEST(LightingJson, BadLightsAreReportedAtTheirPointers) {
    expectErrors(withLight(R"({"type": "point", "intensity": -2})"), {"/lights/0/intensity"},
                 "expected a number >= 0, got -2");
    expectErrors(withLight(R"({"type": "spot", "inner_angle": 30, "outer_angle": 20})"),
                 {"/lights/0/outer_angle"}, "expected \"outer_angle\" > \"inner_angle\"");
    expectErrors(withLight(R"({"type": "spot", "outer_angle": 95})"), {"/lights/0/outer_angle"},
                 "(0, 90]");
    expectErrors(withLight(R"({"type": "point", "range": 0})"), {"/lights/0/range"}, "> 0");
    expectErrors(withLight(R"({"type": "point", "shadows": "yes"})"), {"/lights/0/shadows"},
                 "expected true or false");
    // Every problem of a file in one pass.
    expectErrors(withLight(R"({"type": "spot", "intensity": -1, "outer_angle": 91},
                              {"type": "point", "position": [0, 1]})"),
                 {"/lights/0/intensity", "/lights/0/outer_angle", "/lights/1/position"}, ">= 0");
}

TEST(LightingJson, KeysOfOtherLightTypesAreWarnedAbout) {
    Diagnostics d;
    ASSERT_TRUE(
        parseScene(withLight(R"({"type": "point", "direction": [0, -1, 0]})"), "w.json", d));
    ASSERT_EQ(d.items.size(), 1u) << d.format();
    EXPECT_EQ(d.items[0].severity, Severity::Warning);
    EXPECT_EQ(d.items[0].location, "/lights/0/direction");
}

TEST(LightingJson, ShadowAoAndFxaaSettings) {
    const Scene off = parseOk(R"({"version": 1})");
    EXPECT_FALSE(off.render.shadows.enabled);
    EXPECT_EQ(off.render.ao.samples, 0);
    EXPECT_FALSE(off.render.fxaa);
    const Scene on = parseOk(R"({"version": 1, "render": {"shadows": {"steps": 32,
        "softness": 0.1, "map_size": 512, "pcf_radius": 2, "normal_offset": 2,
        "slope_bias": 1.5, "min_distance": 0.02, "max_distance": 20},
        "ao": {"distance": 0.5}, "fxaa": true}})");
    EXPECT_TRUE(on.render.shadows.enabled); // present means on
    EXPECT_EQ(on.render.shadows.steps, 32);
    EXPECT_EQ(on.render.shadows.mapSize, 512);
    EXPECT_EQ(on.render.shadows.pcfRadius, 2);
    EXPECT_FLOAT_EQ(on.render.shadows.slopeBias, 1.5f);
    EXPECT_EQ(on.render.ao.samples, 5); // present means on, with the default sample count
    EXPECT_FLOAT_EQ(on.render.ao.distance, 0.5f);
    EXPECT_TRUE(on.render.fxaa);
}

TEST(LightingJson, QualitySettingsHaveHardCaps) {
    expectErrors(R"({"version": 1, "render": {"shadows": {"steps": 100000}}})",
                 {"/render/shadows/steps"}, "[1, 256]");
    expectErrors(R"({"version": 1, "render": {"shadows": {"map_size": 16384}}})",
                 {"/render/shadows/map_size"}, "[256, 4096]");
    expectErrors(R"({"version": 1, "render": {"shadows": {"pcf_radius": 9}}})",
                 {"/render/shadows/pcf_radius"}, "[0, 3]");
    expectErrors(R"({"version": 1, "render": {"ao": {"samples": 64}}})", {"/render/ao/samples"},
                 "[0, 16]");
    expectErrors(R"({"version": 1, "render": {"shadows": {"min_distance": 2, "max_distance": 1}}})",
                 {"/render/shadows/max_distance"}, "\"max_distance\" > \"min_distance\"");
    expectErrors(R"({"version": 1, "render": {"fxaa": 1}})", {"/render/fxaa"},
                 "expected true or false");
}

TEST(LightingJson, EnvironmentSkiesAndFog) {
    const Scene gradient = parseOk(R"({"version": 1, "environment": {
        "sky": {"type": "gradient", "zenith": [0, 0, 1], "horizon": [1, 1, 1], "ground": [0.1, 0.1, 0.1]},
        "intensity": 0.5, "fog": {"color": [0.5, 0.5, 0.5], "density": 0.1}}})");
    EXPECT_EQ(gradient.environment.sky, SkyType::Gradient);
    EXPECT_EQ(gradient.environment.zenith, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(gradient.environment.intensity, 0.5f);
    EXPECT_FLOAT_EQ(gradient.environment.fogDensity, 0.1f);
    const Scene image = parseOk(R"({"version": 1, "environment": {
        "sky": {"type": "image", "file": "skies/noon.hdr", "rotation": 90}}})");
    EXPECT_EQ(image.environment.sky, SkyType::Image);
    EXPECT_EQ(image.environment.imagePath, std::filesystem::path("/scenes/skies/noon.hdr"));
    EXPECT_FLOAT_EQ(image.environment.rotationDegrees, 90.0f);
}

TEST(LightingJson, BadEnvironmentsAreReported) {
    expectErrors(R"({"version": 1, "environment": {"sky": {"type": "cloudy"}}})",
                 {"/environment/sky/type"},
                 "known sky types: \"constant\", \"gradient\", \"image\"");
    expectErrors(R"({"version": 1, "environment": {"sky": {"type": "image"}}})",
                 {"/environment/sky"}, "needs \"file\"");
    expectErrors(R"({"version": 1, "environment": {"fog": {"density": -1}}})",
                 {"/environment/fog/density"}, "[0, 10]");
    expectErrors(R"({"version": 1, "environment": {"fog": {"color": [1, 1, 1]}}})",
                 {"/environment/fog"}, "needs \"density\"");
    expectErrors(R"({"version": 1, "environment": {"intensity": -1}})", {"/environment/intensity"},
                 ">= 0");
}

// Turned off in the editor, shadows and occlusion keep their numbers through a save: turned on
// again, they are what the file had.
TEST(LightingJson, SettingsTurnedOffKeepTheirNumbers) {
    Scene scene = parseOk(R"({"version": 1, "render": {"shadows": {"steps": 48, "softness": 0.1},
        "ao": {"samples": 5, "distance": 0.4, "strength": 0.8}}})");
    scene.render.shadows.enabled = false;
    scene.render.ao.samples = 0;
    const std::string text = sceneToJson(scene);
    const Scene again = parseOk(text);
    EXPECT_FALSE(again.render.shadows.enabled) << text;
    EXPECT_EQ(again.render.shadows.steps, 48);
    EXPECT_FLOAT_EQ(again.render.shadows.softness, 0.1f);
    EXPECT_EQ(again.render.ao.samples, 0) << text;
    EXPECT_FLOAT_EQ(again.render.ao.distance, 0.4f);
    EXPECT_FLOAT_EQ(again.render.ao.strength, 0.8f);
    // Off with the default numbers: nothing is written for them.
    const std::string plain = sceneToJson(parseOk(R"({"version": 1})"));
    EXPECT_EQ(plain.find("shadows"), std::string::npos) << plain;
    EXPECT_EQ(plain.find("\"ao\""), std::string::npos) << plain;
}

TEST(LightingJson, WrittenScenesReadBackTheSame) {
    const Scene scene = parseOk(R"({"version": 1,
        "render": {"shadows": {"steps": 40, "pcf_radius": 2}, "ao": {"samples": 3}, "fxaa": true},
        "environment": {"sky": {"type": "constant", "color": [0.2, 0.3, 0.4]},
                        "fog": {"color": [1, 1, 1], "density": 0.2}},
        "lights": [{"type": "spot", "position": [1, 2, 3], "direction": [0, -1, 0],
                    "inner_angle": 5, "outer_angle": 25, "range": 9, "shadows": false},
                   {"type": "point", "position": [0, 1, 0], "shadow_softness": 0.3}]})");
    const Scene again = parseOk(sceneToJson(scene));
    EXPECT_EQ(again.render.shadows.steps, 40);
    EXPECT_EQ(again.render.shadows.pcfRadius, 2);
    EXPECT_EQ(again.render.ao.samples, 3);
    EXPECT_TRUE(again.render.fxaa);
    EXPECT_EQ(again.environment.sky, SkyType::Constant);
    EXPECT_EQ(again.environment.color, glm::vec3(0.2f, 0.3f, 0.4f));
    EXPECT_FLOAT_EQ(again.environment.fogDensity, 0.2f);
    ASSERT_EQ(again.lights.size(), 2u);
    EXPECT_EQ(again.lights[0].type, LightType::Spot);
    EXPECT_EQ(again.lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(again.lights[0].outerAngleDegrees, 25.0f);
    EXPECT_FLOAT_EQ(again.lights[0].range, 9.0f);
    EXPECT_FALSE(again.lights[0].castShadows);
    EXPECT_EQ(again.lights[1].type, LightType::Point);
    EXPECT_FLOAT_EQ(again.lights[1].shadowSoftness, 0.3f);
}
