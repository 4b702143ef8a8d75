// The sRGB transfer functions (core/srgb.hpp, IEC 61966-2-1) that the scene reader decodes
// "#rrggbb" with and the editor's colour pickers show colours through: a linear 0.8 shows as
// #E7E7E7, and every hex code reads and shows as itself.
#include "core/srgb.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace rmsc;

TEST(Srgb, ALinearPointEightShowsAsE7) {
    EXPECT_EQ(linearToSrgbHex(glm::vec3(0.8f)), "#E7E7E7");
    EXPECT_EQ(int(linearToSrgb(0.8f) * 255.0f + 0.5f), 231);
    EXPECT_EQ(linearToSrgbHex(glm::vec3(0.0f, 0.5f, 1.0f)), "#00BCFF");
}

TEST(Srgb, FollowsTheStandardsCurve) {
    EXPECT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_NEAR(linearToSrgb(1.0f), 1.0f, 1e-6f);
    // The segments meet at linear 0.0031308, encoded 0.04045.
    EXPECT_NEAR(linearToSrgb(0.0031308f), 0.04045f, 1e-5f);
    EXPECT_NEAR(srgbToLinear(0.04045f), 0.0031308f, 1e-6f);
    EXPECT_NEAR(linearToSrgb(0.001f), 0.01292f, 1e-6f);
    EXPECT_NEAR(linearToSrgb(0.5f), 0.735357f, 1e-5f);
    // Inverse of each other, on [0, 1] and above (HDR colours such as emission).
    for (float x = 0.0f; x <= 4.0f; x += 0.01f) {
        EXPECT_NEAR(srgbToLinear(linearToSrgb(x)), x, 1e-5f * std::max(1.0f, x)) << x;
        EXPECT_LT(linearToSrgb(x), linearToSrgb(x + 0.01f)) << x;
    }
}

// The same hex code everywhere: each of the 256 codes, read from a scene file, shows as itself.
TEST(Srgb, EveryHexCodeReadFromAFileShowsAsItself) {
    for (int v = 0; v < 256; ++v) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "#%02X%02X%02X", v, 255 - v, v / 2);
        const std::string text =
            std::string(R"({"version": 1, "materials": {"m": {"base_color": ")") + hex + R"("}}})";
        Diagnostics d;
        const std::optional<Scene> scene = parseScene(text, "colours.json", d);
        ASSERT_TRUE(scene) << d.format();
        EXPECT_EQ(linearToSrgbHex(scene->materials[0].baseColor), hex);
    }
}
