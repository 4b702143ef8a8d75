// Lit renders with each light type placed where the view ray passes through or along it: no
// pixel may be non-finite, and none may be a dark spike (far darker than every neighbour) on a
// smoothly lit floor. Guards the BRDF's terms at their edges (v.h and n.v rounding past 1).
#include "gpu_test_support.hpp"
#include "scene_text.hpp"

#include <cmath>
#include <string>
#include <utility>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// A floor plane of `material`, one light, the camera looking at the floor through the light's
// position (or along a directional light's direction). The image is odd in both sizes, so the
// centre pixel's ray is the camera's axis, through (0, 0.9, 1) to the floor at (0, 0, -2):
// there the directions to the eye and to a light on that axis are the same.
std::string litFloor(const std::string& light, const std::string& material) {
    return R"({"version": 1,
      "camera": {"position": [0, 1.5, 3], "target": [0, 0, -2], "fov": 60},
      "materials": {"floor": )" +
           material + R"(}, "lights": [)" + light + R"(],
      "sdf": {"shape": "plane", "material": "floor"}})";
}

float luminance(const float* rgb) {
    return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
}

void expectNoSpikes(const std::string& light, const std::string& material) {
    SCOPED_TRACE(light + " on " + material);
    const PreparedScene prepared = prepareSceneText(litFloor(light, material));
    const int width = 161, height = 91;
    const FrameTargets targets = renderPrepared(prepared, width, height);
    const Pixels<float> color = readHdrColor(targets);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);
    int nonFinite = 0, spikes = 0, lit = 0;
    for (int y = 1; y + 1 < height; ++y) {
        for (int x = 1; x + 1 < width; ++x) {
            const float* c = color.at(x, y);
            if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
                if (++nonFinite <= 5) ADD_FAILURE() << "non-finite colour at " << x << "," << y;
                continue;
            }
            // A spike: darker than a quarter of the darkest of its four neighbours on the same
            // object, those all lit.
            const std::uint32_t id = *ids.at(x, y);
            float darkest = 1e30f;
            bool sameObject = true;
            for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                darkest = std::min(darkest, luminance(color.at(x + dx, y + dy)));
                sameObject = sameObject && *ids.at(x + dx, y + dy) == id;
            }
            if (!sameObject || id == 0 || darkest < 0.01f) continue;
            ++lit;
            if (luminance(c) < 0.25f * darkest && ++spikes <= 5)
                ADD_FAILURE() << "dark spike at " << x << "," << y << ": " << luminance(c)
                              << " beside " << darkest;
        }
    }
    EXPECT_EQ(nonFinite, 0);
    EXPECT_EQ(spikes, 0);
    EXPECT_GT(lit, width * height / 4) << "the floor must be lit for the scan to mean anything";
}

void expectNoSpikes(const std::string& light) {
    expectNoSpikes(light, R"({"base_color": [0.6, 0.6, 0.6], "roughness": 0.8})");
    expectNoSpikes(light, R"({"base_color": [0.9, 0.7, 0.3], "metallic": 1, "roughness": 0.3})");
}

} // namespace

TEST(LightingSpikes, PointLightOnTheViewRay) {
    expectNoSpikes(R"({"type": "point", "position": [0, 0.9, 1.0], "intensity": 4})");
    expectNoSpikes(R"({"type": "point", "position": [0.013, 0.907, 1.0], "intensity": 4})");
}

TEST(LightingSpikes, SpotLightOnTheViewRay) {
    expectNoSpikes(R"({"type": "spot", "position": [0, 0.9, 1.0], "direction": [0, -1.5, -5],
                       "outer_angle": 80, "inner_angle": 30, "intensity": 4})");
}

TEST(LightingSpikes, DirectionalLightAlongTheView) {
    expectNoSpikes(R"({"type": "directional", "direction": [0, -1.5, -5], "intensity": 3})");
}
