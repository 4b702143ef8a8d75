// The cone march (sdf/cpu_eval.hpp, sdfMarchCone), the CPU mirror of the cone pass: no ray the
// cone holds meets a surface nearer than where the cone stops, including a surface the axis
// misses, and the cone does skip the empty space in front of the first surface.
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <string>

using namespace rmsc;

namespace {

SdfProgram compileText(const std::string& text, RenderSettings& settings) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = parseScene(text, "cone.json", diagnostics);
    EXPECT_TRUE(scene && scene->sdf) << diagnostics.format();
    if (!scene || !scene->sdf) return {};
    settings = scene->render;
    std::optional<SdfProgram> program = compileSdf(*scene->sdf, 0, "cone.json", diagnostics);
    EXPECT_TRUE(program) << diagnostics.format();
    return program ? std::move(*program) : SdfProgram{};
}

// Unit rays on the rim of the cone around -z of chord `chord` (|u - axis| = chord), and the
// axis itself.
std::vector<glm::vec3> raysOfTheCone(float chord) {
    // |u - a| = 2 sin(angle / 2) for unit u and a.
    const float angle = 2.0f * std::asin(0.5f * chord);
    std::vector<glm::vec3> rays = {{0, 0, -1}};
    for (int i = 0; i < 64; ++i) {
        const float around = glm::two_pi<float>() * float(i) / 64.0f;
        rays.push_back({std::sin(angle) * std::cos(around), std::sin(angle) * std::sin(around),
                        -std::cos(angle)});
    }
    return rays;
}

} // namespace

TEST(SdfConeMarch, NoRayOfTheConeMeetsASurfaceBeforeItsEnd) {
    // A ball the axis misses by 0.3 (its surface 0.3 beside the axis 6 units away), a tilted
    // plate, a smooth union: rim rays reach them before the axis does.
    const std::string scene = R"({"version": 1,
        "camera": {"position": [0, 0, 0], "target": [0, 0, -1]},
        "sdf": {"children": [
            {"shape": "sphere", "radius": 0.5, "position": [0.8, 0, -6]},
            {"shape": "box", "half_extents": [1, 1, 0.05], "position": [-1.2, 0.4, -9],
             "rotation": [30, 40, 0]},
            {"op": "smooth_union", "smoothness": 0.3, "children": [
                {"shape": "torus", "major_radius": 0.6, "minor_radius": 0.15, "position": [0, 0, -12]},
                {"shape": "sphere", "radius": 0.3, "position": [0, 0.5, -12]}]}]}})";
    RenderSettings settings;
    const SdfProgram program = compileText(scene, settings);
    ASSERT_FALSE(program.instructions.empty());
    for (float chord : {0.02f, 0.05f, 0.1f, 0.2f}) {
        SCOPED_TRACE("chord " + std::to_string(chord));
        const SdfConeMarch cone =
            sdfMarchCone(program, settings, glm::vec3(0.0f), {0, 0, -1}, chord, 0.05f);
        EXPECT_GT(cone.steps, 0);
        float nearest = settings.maxDistance;
        for (const glm::vec3& ray : raysOfTheCone(chord)) {
            const std::optional<SdfHit> hit = sdfCastRay(program, settings, glm::vec3(0.0f), ray,
                                                         0.0f, settings.maxDistance, 1.0f);
            if (hit) nearest = std::min(nearest, hit->t);
        }
        EXPECT_LE(cone.distance, nearest);
        // And it skips most of the way there: the rim of the widest cone reaches the ball at
        // about 4.3, the narrowest at about 5.4.
        EXPECT_GT(cone.distance, 0.6f * nearest);
    }
}

TEST(SdfConeMarch, AnEmptySceneOrAFullBudgetStopsSafely) {
    RenderSettings settings;
    const SdfConeMarch empty =
        sdfMarchCone(SdfProgram{}, settings, glm::vec3(0.0f), {0, 0, -1}, 0.1f, 0.05f);
    EXPECT_EQ(empty.steps, 0);
    EXPECT_EQ(empty.distance, 0.05f);

    const std::string scene = R"({"version": 1, "render": {"max_steps": 2},
        "sdf": {"shape": "sphere", "radius": 1, "position": [0, 0, -50]}})";
    const SdfProgram program = compileText(scene, settings);
    const SdfConeMarch cone =
        sdfMarchCone(program, settings, glm::vec3(0.0f), {0, 0, -1}, 0.01f, 0.05f);
    EXPECT_EQ(cone.steps, 2);
    EXPECT_LT(cone.distance, 49.0f); // where the budget ran out, short of the ball
    EXPECT_GT(cone.distance, 40.0f);
}
