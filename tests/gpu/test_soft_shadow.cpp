// SDF soft shadows on a convex shape alone: it cannot shadow its own lit side, so turning
// shadows on must not change a pixel of it. Guards the closest-approach estimate where the
// shadow ray leaves the surface head-on (the light along the normal), which once printed
// black specks there.
#include "gpu_test_support.hpp"

#include "render/readback.hpp"
#include "scene/scene_json.hpp"

using namespace rmsc;
using namespace rmsc::test;

namespace {

PreparedScene sphereFacingTheLight(bool shadows) {
    // The camera looks along the light, so the middle of the sphere faces the light head-on.
    const std::string text = std::string(R"({"version": 1,
          "camera": {"position": [0, 3, 3], "target": [0, 0, 0], "fov": 30},
          "render": {"ambient": [0.05, 0.05, 0.05])") +
                             (shadows ? R"(, "shadows": {"steps": 64, "softness": 0.05})" : "") +
                             R"(},
          "lights": [{"type": "directional", "direction": [0, -1, -1], "intensity": 3}],
          "sdf": {"shape": "sphere", "radius": 0.8}})";
    Diagnostics diagnostics;
    std::optional<Scene> scene = parseScene(text, "sphere.json", diagnostics);
    EXPECT_TRUE(scene) << diagnostics.format();
    std::optional<PreparedScene> prepared =
        prepareScene(std::move(*scene), diskFileSource(), diagnostics);
    EXPECT_TRUE(prepared) << diagnostics.format();
    return std::move(*prepared);
}

} // namespace

TEST(SoftShadow, AConvexShapeDoesNotShadowItsLitSide) {
    const FrameTargets lit = renderPrepared(sphereFacingTheLight(false), 64, 64);
    const FrameTargets shadowed = renderPrepared(sphereFacingTheLight(true), 64, 64);
    const Pixels<std::uint32_t> ids = readObjectIds(lit);
    int spherePixels = 0;
    for (std::uint32_t id : ids.data)
        spherePixels += id != 0;
    ASSERT_GT(spherePixels, 500);
    // Every pixel the same within 2/255 (the sphere faces the light over the whole view).
    EXPECT_TRUE(imagesMatch(readDisplayColor(shadowed), readDisplayColor(lit), "soft_shadow_convex",
                            {2, 0.0}));
}
