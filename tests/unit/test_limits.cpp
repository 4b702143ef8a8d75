// The limits of core/limits.hpp as the scene reader applies them: a scene over a limit is
// refused with an error naming the limit, one at the limit loads. Also the version field's
// migration messages. (Lights, SDF nodes, nesting: test_scene_errors.cpp.)
#include "core/limits.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

using namespace rmsc;

namespace {

// The errors of `text`; `loads` says whether the scene must load.
Diagnostics parseExpecting(const std::string& text, bool loads) {
    Diagnostics d;
    EXPECT_EQ(parseScene(text, "big.json", d).has_value(), loads) << d.format().substr(0, 2000);
    return d;
}

std::string repeated(const std::string& item, int count) {
    std::string out;
    for (int i = 0; i < count; ++i)
        out += (i ? "," : "") + item;
    return out;
}

void expectLimitError(const Diagnostics& d, const std::string& location, int limit) {
    ASSERT_EQ(d.errorCount(), 1) << d.format().substr(0, 2000);
    EXPECT_EQ(d.items[0].location, location);
    EXPECT_NE(d.items[0].message.find("at most " + std::to_string(limit)), std::string::npos)
        << d.items[0].message;
    EXPECT_NE(d.items[0].message.find("(the limit)"), std::string::npos) << d.items[0].message;
}

} // namespace

TEST(SceneLimits, FileSizeOverTheLimitIsRefusedBeforeParsing) {
    // Valid JSON padded with spaces: only the size is wrong.
    std::string text = "{\"version\": 1}";
    text.resize(limits::kSceneFileBytes + 1, ' ');
    const Diagnostics d = parseExpecting(text, false);
    expectLimitError(d, "", int(limits::kSceneFileBytes));
    EXPECT_NE(d.items[0].message.find(std::to_string(limits::kSceneFileBytes + 1) + " bytes"),
              std::string::npos);
    text.resize(limits::kSceneFileBytes); // exactly at the limit
    parseExpecting(text, true);
}

TEST(SceneLimits, MeshCountOverTheLimitIsRefused) {
    const std::string mesh = R"({"file": "a.gltf"})";
    expectLimitError(parseExpecting(R"({"version": 1, "meshes": [)" +
                                        repeated(mesh, limits::kMeshInstances + 1) + "]}",
                                    false),
                     "/meshes", limits::kMeshInstances);
    const Diagnostics atLimit = parseExpecting(
        R"({"version": 1, "meshes": [)" + repeated(mesh, limits::kMeshInstances) + "]}", true);
    EXPECT_EQ(atLimit.errorCount(), 0);
}

TEST(SceneLimits, MaterialCountOverTheLimitIsRefused) {
    std::string materials;
    for (int i = 0; i <= limits::kMaterials; ++i)
        materials += (i ? "," : "") + ("\"m" + std::to_string(i) + "\": {}");
    expectLimitError(parseExpecting(R"({"version": 1, "materials": {)" + materials + "}}", false),
                     "/materials", limits::kMaterials);
}

TEST(SceneLimits, LightLimitIsTheOneInLimitsHpp) {
    const std::string light = R"({"type": "directional"})";
    expectLimitError(parseExpecting(R"({"version": 1, "lights": [)" +
                                        repeated(light, limits::kLights + 1) + "]}",
                                    false),
                     "/lights", limits::kLights);
}

TEST(SceneLimits, MarchStepsAreCapped) {
    const Diagnostics d = parseExpecting(R"({"version": 1, "render": {"max_steps": )" +
                                             std::to_string(limits::kMarchSteps + 1) + "}}",
                                         false);
    ASSERT_EQ(d.errorCount(), 1);
    EXPECT_EQ(d.items[0].location, "/render/max_steps");
    EXPECT_NE(d.items[0].message.find(std::to_string(limits::kMarchSteps)), std::string::npos);
}

// Only version 1 exists: every other value is refused with what to do about it.
TEST(SceneVersion, EveryOtherVersionSaysHowToMigrate) {
    struct Case {
        std::string text;
        std::string location;
        std::string advice;
    };
    const Case cases[] = {
        {R"({"camera": {}})", "", "add \"version\": 1"},
        {R"({"version": 0})", "/version", "To migrate, write \"version\": 1"},
        {R"({"version": -3})", "/version", "To migrate, write \"version\": 1"},
        {R"({"version": 2})", "/version", "this rmsc reads version 1 — upgrade rmsc"},
        {R"({"version": 18446744073709551615})", "/version", "upgrade rmsc"},
        {R"({"version": 1.5})", "/version", "expected the integer 1, got 1.5"},
        {R"({"version": null})", "/version", "expected the integer 1, got null"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        const Diagnostics d = parseExpecting(c.text, false);
        ASSERT_EQ(d.errorCount(), 1) << d.format();
        EXPECT_EQ(d.items[0].location, c.location);
        EXPECT_NE(d.items[0].message.find(c.advice), std::string::npos) << d.items[0].message;
    }
    EXPECT_EQ(parseExpecting(R"({"version": 1})", true).errorCount(), 0);
}
