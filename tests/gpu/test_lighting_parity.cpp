// Parity of mesh and SDF shading: the same sphere (radius 0.5 at the origin) rendered once as
// an SDF sphere and once as the 64x32 glTF UV sphere (samples/assets/sphere.gltf), with the
// same material, lights, sky, shadows and AO, for each light type. Over the disc interior
// (pixels whose ray meets the analytic sphere at least 0.03 inside its silhouette), the display
// colours must agree: mean absolute difference below 1% of full scale and no more than 1% of
// pixels off by more than 8%. Reasoning for the bounds: the tessellated sphere's interpolated
// normals deviate from the true normal by well under a degree and its positions by < 1 mm, so
// only the terminator of shadows (SDF soft shadow on one, shadow map with normal offset on the
// other) and facet-level differences may remain.
#include "gpu_test_support.hpp"
#include "scene_text.hpp"

#include "render/frame.hpp"

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;

namespace {

constexpr int kSize = 128;

std::string sphereScene(bool asMesh, const std::string& light) {
    const std::string object =
        asMesh ? R"("meshes": [{"file": "../assets/sphere.gltf", "material": "paint"}])"
               : R"("sdf": {"shape": "sphere", "radius": 0.5, "material": "paint"})";
    return R"({"version": 1,
      "camera": {"position": [0.4, 0.6, 2.2], "target": [0, 0, 0], "fov": 35},
      "render": {"shadows": {"pcf_radius": 1}, "ao": {"samples": 4}},
      "environment": {"sky": {"type": "gradient", "zenith": [0.2, 0.3, 0.5],
                              "horizon": [0.4, 0.4, 0.4], "ground": [0.1, 0.08, 0.06]}},
      "materials": {"paint": {"base_color": [0.7, 0.35, 0.2], "roughness": 0.4}},
      "lights": [)" +
           light + "], " + object + "}";
}

struct Difference {
    int pixels = 0;
    double meanAbs = 0.0; // of 255
    int outliers = 0;     // a channel off by more than 8% of full scale
};

Difference compareDiscs(const std::string& light) {
    const PreparedScene sdf = prepareSceneText(sphereScene(false, light));
    const PreparedScene mesh = prepareSceneText(sphereScene(true, light));
    const Pixels<std::uint8_t> a = readDisplayColor(renderPrepared(sdf, kSize, kSize));
    const Pixels<std::uint8_t> b = readDisplayColor(renderPrepared(mesh, kSize, kSize));
    const FrameCamera camera = makeFrameCamera(sdf.scene.camera, kSize, kSize);
    Difference d;
    double sum = 0.0;
    for (int row = 0; row < kSize; ++row) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec3 rd = glm::normalize(
                pixelRayDirection(camera, float(x), float(kSize - 1 - row), kSize, kSize));
            // Distance of the ray's line from the sphere centre (the origin).
            const glm::vec3 o = sdf.scene.camera.position;
            const float missDistance = glm::length(o - rd * glm::dot(o, rd));
            if (missDistance > 0.5f - 0.03f) continue;
            ++d.pixels;
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const int delta = std::abs(int(a.at(x, row)[c]) - int(b.at(x, row)[c]));
                sum += delta;
                worst = std::max(worst, delta);
            }
            if (worst > int(0.08 * 255)) ++d.outliers;
        }
    }
    d.meanAbs = d.pixels ? sum / (3.0 * d.pixels) : 0.0;
    return d;
}

void expectParity(const std::string& light) {
    const Difference d = compareDiscs(light);
    EXPECT_GT(d.pixels, 1500) << "the disc should cover a good part of the image";
    EXPECT_LT(d.meanAbs, 0.01 * 255) << "mean absolute difference over the disc, of 255";
    EXPECT_LE(d.outliers, d.pixels / 100)
        << d.outliers << " of " << d.pixels << " pixels off by more than 8%";
}

} // namespace

TEST(LightingParity, DirectionalLight) {
    expectParity(R"({"type": "directional", "direction": [-0.5, -0.6, -0.4], "intensity": 3})");
}

TEST(LightingParity, PointLight) {
    expectParity(R"({"type": "point", "position": [1.0, 1.2, 1.0], "intensity": 6, "range": 5})");
}

TEST(LightingParity, SpotLight) {
    // The cone edge crosses the sphere, so the smooth inner/outer transition is compared too.
    expectParity(R"({"type": "spot", "position": [0.3, 1.5, 1.5], "direction": [-0.2, -0.7, -0.7],
                     "intensity": 10, "inner_angle": 8, "outer_angle": 16})");
}
