// GL-free checks of the light packing and shadow-view planning (in the GPU test binary because
// they live in the engine library): the spot cone factor of KHR_lights_punctual, the shadow-view
// budget, and directional frusta that hold every caster.
#include "render/gpu_layout.hpp"
#include "render/shadow_views.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace rmsc;

// KHR_lights_punctual: the cone factor saturate(cos * scale + offset)^2 is 1 at the inner
// angle and 0 at the outer one.
TEST(LightPacking, SpotConeMatchesTheSpecification) {
    Light spot;
    spot.type = LightType::Spot;
    spot.innerAngleDegrees = 10.0f;
    spot.outerAngleDegrees = 30.0f;
    const GpuLight gpu = packLights({spot})[0];
    auto factor = [&](float degrees) {
        const float x = std::cos(glm::radians(degrees)) * gpu.spotShadow.x + gpu.spotShadow.y;
        return std::clamp(x, 0.0f, 1.0f);
    };
    EXPECT_NEAR(factor(10.0f), 1.0f, 1e-4f);
    EXPECT_NEAR(factor(30.0f), 0.0f, 1e-4f);
    EXPECT_GT(factor(20.0f), 0.0f);
    EXPECT_LT(factor(20.0f), 1.0f);
    EXPECT_EQ(gpu.directionType.w, float(kGpuSpot));
    EXPECT_EQ(gpu.spotShadow.z, 0.0f); // shadows off by default: no SDF shadow softness
}

// Every shadow-casting light gets views within the budget; a point light takes six.
TEST(LightPacking, ShadowViewPlanRespectsTheBudget) {
    ShadowSettings settings;
    settings.enabled = true;
    CasterBounds casters;
    casters.add({-1, 0, -1});
    casters.add({1, 1, 1});
    std::vector<Light> lights(3);
    lights[1].type = LightType::Point;
    lights[2].type = LightType::Point; // 1 + 6 + 6 > 12: the second point light gets none
    const ShadowViewPlan plan = planShadowViews(lights, casters, settings);
    EXPECT_EQ(plan.views.size(), 7u);
    EXPECT_EQ(plan.firstView, (std::vector<int>{0, 1, -1}));
    // The directional view holds every caster corner inside its clip volume.
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 corner(c & 1 ? 1 : -1, c & 2 ? 1 : 0, c & 4 ? 1 : -1, 1);
        const glm::vec4 clip = plan.views[0].lightViewProjection * corner;
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_LE(std::abs(clip[axis] / clip.w), 1.0f);
    }
    settings.enabled = false;
    EXPECT_TRUE(planShadowViews(lights, casters, settings).views.empty());
}
