// Shadows land where the geometry says, both ways: an SDF box over a mesh floor (the SDF casts
// by shadow marching), a mesh box over an SDF floor (the mesh casts through a shadow map), and
// an SDF box drawn as a shell over a mesh floor (the shell casts through the shadow map's
// depth-only shell variant only), for a directional, a point and a spot light. The scene has no
// ambient light, so a shadowed floor pixel is black. Each floor pixel's expected state comes from a
// CPU ray from the floor point to the light: through the CPU SDF evaluator for the SDF box, by
// ray/box slab intersection for the mesh box and the shell (an exact box). Only pixels whose state
// is the same at four points 0.06 units around them are used (no penumbra, no PCF edge). The GPU's
// shadow factor is the pixel's HDR colour divided by the same render with shadows disabled: below
// 0.15 counts as shadowed, above 0.85 as lit; at least 97% of each class must agree.
#include "gpu_test_support.hpp"
#include "scene_text.hpp"

#include "render/frame.hpp"
#include "sdf/cpu_eval.hpp"

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;

namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr float kBoxHalf = 0.4f;
const glm::vec3 kBoxCentre(0.0f, 1.0f, 0.0f);
constexpr float kFloorHalf = 2.8f; // the floor is 3 units a side; keep off its edge

enum class Caster { SdfBoxOverMeshFloor, MeshBoxOverSdfFloor, ShellBoxOverMeshFloor };

std::string sceneText(Caster caster, const std::string& light, bool shadows) {
    const std::string render =
        std::string(R"("render": {"ambient": [0, 0, 0], "shadows": {"enabled": )") +
        (shadows ? "true" : "false") + R"(, "softness": 0.01, "pcf_radius": 1, "map_size": 1024}})";
    std::string objects =
        caster == Caster::MeshBoxOverSdfFloor
            ? R"("meshes": [{"file": "../assets/cube.gltf", "scale": 0.8, "position": [0, 1, 0]}],
                 "sdf": {"shape": "plane", "normal": [0, 1, 0], "offset": 0})"
            : R"("meshes": [{"file": "../assets/plane.gltf", "scale": [3, 1, 3]}],
                 "sdf": {"shape": "box", "half_extents": [0.4, 0.4, 0.4], "position": [0, 1, 0]})";
    if (caster == Caster::ShellBoxOverMeshFloor)
        objects.insert(objects.rfind('}'), R"(, "shell": true)");
    return R"({"version": 1, "camera": {"position": [0.5, 6, 3.5], "target": [0, 0, 0], "fov": 50},
               )" +
           render + R"(, "lights": [)" + light + "], " + objects + "}";
}

// Ray/box slab intersection: does the segment o + t d, 0 < t < tMax, meet the box (grown by
// `margin` on every side)?
bool segmentHitsBox(glm::vec3 o, glm::vec3 d, float tMax, float margin = 0.0f) {
    float t0 = 0.0f, t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = kBoxCentre[axis] - kBoxHalf - margin;
        const float hi = kBoxCentre[axis] + kBoxHalf + margin;
        if (std::abs(d[axis]) < 1e-8f) {
            if (o[axis] < lo || o[axis] > hi) return false;
            continue;
        }
        float a = (lo - o[axis]) / d[axis], b = (hi - o[axis]) / d[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

struct LightGeometry {
    bool directional = false;
    glm::vec3 vector{0.0f}; // direction of travel, or position
};

// Is floor point p shadowed from the light, by the CPU geometry?
bool expectShadow(Caster caster, const PreparedScene& prepared, const LightGeometry& light,
                  glm::vec3 p) {
    glm::vec3 toLight = -glm::normalize(light.vector);
    float distance = 1e4f;
    if (!light.directional) {
        toLight = glm::normalize(light.vector - p);
        distance = glm::length(light.vector - p);
    }
    const glm::vec3 origin = p + glm::vec3(0.0f, 1e-3f, 0.0f);
    if (caster != Caster::SdfBoxOverMeshFloor) return segmentHitsBox(origin, toLight, distance);
    // The SDF tree is only the box: a CPU sphere-traced ray to the light.
    return sdfCastRay(prepared.sdf, prepared.scene.render, origin, toLight, 0.0f, distance)
        .has_value();
}

struct Tally {
    int shadow = 0, shadowAgree = 0, lit = 0, litAgree = 0;
};

Tally measure(Caster caster, const std::string& light, const LightGeometry& geometry) {
    const PreparedScene withShadows = prepareSceneText(sceneText(caster, light, true));
    const PreparedScene without = prepareSceneText(sceneText(caster, light, false));
    const Pixels<float> shadowed = readHdrColor(renderPrepared(withShadows, kWidth, kHeight));
    const Pixels<float> unshadowed = readHdrColor(renderPrepared(without, kWidth, kHeight));
    const Camera& camera = withShadows.scene.camera;
    const FrameCamera frame = makeFrameCamera(camera, kWidth, kHeight);
    Tally tally;
    for (int row = 0; row < kHeight; ++row) {
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 rd = glm::normalize(
                pixelRayDirection(frame, float(x), float(kHeight - 1 - row), kWidth, kHeight));
            if (rd.y >= 0.0f) continue;
            const float tFloor = -camera.position.y / rd.y;
            const glm::vec3 p = camera.position + rd * tFloor;
            if (std::abs(p.x) > kFloorHalf || std::abs(p.z) > kFloorHalf) continue;
            // The box, or its silhouette's anti-aliased edge, is in front.
            if (segmentHitsBox(camera.position, rd, tFloor, 0.05f)) continue;
            const bool inShadow = expectShadow(caster, withShadows, geometry, p);
            bool certain = true;
            const glm::vec3 offsets[4] = {
                {0.06f, 0, 0}, {-0.06f, 0, 0}, {0, 0, 0.06f}, {0, 0, -0.06f}};
            for (const glm::vec3& o : offsets)
                certain = certain && expectShadow(caster, withShadows, geometry, p + o) == inShadow;
            if (!certain) continue;
            const float* lit = unshadowed.at(x, row);
            const float reference = lit[0] + lit[1] + lit[2];
            if (reference < 0.02f) continue; // outside the spot's cone: nothing to compare
            const float* s = shadowed.at(x, row);
            const float ratio = (s[0] + s[1] + s[2]) / reference;
            if (inShadow) {
                ++tally.shadow;
                tally.shadowAgree += ratio < 0.15f;
            } else {
                ++tally.lit;
                tally.litAgree += ratio > 0.85f;
            }
        }
    }
    return tally;
}

void expectPlacement(Caster caster, const std::string& light, const LightGeometry& geometry) {
    const Tally t = measure(caster, light, geometry);
    EXPECT_GE(t.shadow, 40) << "too few pixels surely in shadow to check";
    EXPECT_GE(t.lit, 200) << "too few pixels surely lit to check";
    EXPECT_GE(t.shadowAgree, int(0.97 * t.shadow))
        << t.shadowAgree << " of " << t.shadow << " shadowed pixels are dark";
    EXPECT_GE(t.litAgree, int(0.97 * t.lit))
        << t.litAgree << " of " << t.lit << " lit pixels are lit";
}

const char* kDirectional =
    R"({"type": "directional", "direction": [-0.5, -1.0, -0.3], "intensity": 3})";
const LightGeometry kDirectionalGeometry{true, {-0.5f, -1.0f, -0.3f}};
const char* kPoint = R"({"type": "point", "position": [0.8, 2.5, 0.6], "intensity": 20})";
const LightGeometry kPointGeometry{false, {0.8f, 2.5f, 0.6f}};
const char* kSpot = R"({"type": "spot", "position": [-0.8, 2.8, 0.5], "direction": [0.3, -1, -0.2],
                        "intensity": 25, "inner_angle": 30, "outer_angle": 40})";
const LightGeometry kSpotGeometry{false, {-0.8f, 2.8f, 0.5f}};

} // namespace

TEST(ShadowPlacement, SdfBoxOnMeshFloorDirectional) {
    expectPlacement(Caster::SdfBoxOverMeshFloor, kDirectional, kDirectionalGeometry);
}
TEST(ShadowPlacement, SdfBoxOnMeshFloorPoint) {
    expectPlacement(Caster::SdfBoxOverMeshFloor, kPoint, kPointGeometry);
}
TEST(ShadowPlacement, SdfBoxOnMeshFloorSpot) {
    expectPlacement(Caster::SdfBoxOverMeshFloor, kSpot, kSpotGeometry);
}
TEST(ShadowPlacement, MeshBoxOnSdfFloorDirectional) {
    expectPlacement(Caster::MeshBoxOverSdfFloor, kDirectional, kDirectionalGeometry);
}
TEST(ShadowPlacement, MeshBoxOnSdfFloorPoint) {
    expectPlacement(Caster::MeshBoxOverSdfFloor, kPoint, kPointGeometry);
}
TEST(ShadowPlacement, MeshBoxOnSdfFloorSpot) {
    expectPlacement(Caster::MeshBoxOverSdfFloor, kSpot, kSpotGeometry);
}
TEST(ShadowPlacement, ShellBoxOnMeshFloorDirectional) {
    expectPlacement(Caster::ShellBoxOverMeshFloor, kDirectional, kDirectionalGeometry);
}
TEST(ShadowPlacement, ShellBoxOnMeshFloorPoint) {
    expectPlacement(Caster::ShellBoxOverMeshFloor, kPoint, kPointGeometry);
}
TEST(ShadowPlacement, ShellBoxOnMeshFloorSpot) {
    expectPlacement(Caster::ShellBoxOverMeshFloor, kSpot, kSpotGeometry);
}
