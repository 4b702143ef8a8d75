// Over-relaxed sphere tracing (sdf/cpu_eval.hpp, sdfCastRay): against the plain march
// (relaxation 1) on the camera rays of a few scenes it finds the same surfaces and takes fewer
// steps, and its fallback keeps it from stepping through a thin plate that an over-relaxed
// march without the fallback passes, at the cost of one evaluation there.
#include "scene/scene_json.hpp"
#include "sdf/compiler.hpp"
#include "sdf/cpu_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace rmsc;

namespace {

struct MarchCase {
    std::string name;
    Scene scene;
    SdfProgram program;
};

MarchCase compileSceneText(const std::string& name, const std::string& text) {
    Diagnostics diagnostics;
    std::optional<Scene> scene = parseScene(text, name, diagnostics);
    EXPECT_TRUE(scene && scene->sdf) << name << ": " << diagnostics.format();
    if (!scene || !scene->sdf) return {name, Scene{}, SdfProgram{}};
    std::optional<SdfProgram> program = compileSdf(*scene->sdf, 0, name, diagnostics);
    EXPECT_TRUE(program) << name << ": " << diagnostics.format();
    return {name, *scene, program ? std::move(*program) : SdfProgram{}};
}

MarchCase compileSample(const std::string& relativePath) {
    std::ifstream in(std::string(RMSC_TEST_SOURCE_DIR) + "/" + relativePath);
    std::stringstream text;
    text << in.rdbuf();
    return compileSceneText(relativePath, text.str());
}

// A plate 4 mm thick facing the camera 3 units away, a ball behind it.
const char* kThinPlate = R"({"version": 1,
    "camera": {"position": [0, 0, 0], "target": [0, 0, -1], "fov": 30},
    "sdf": {"children": [
        {"shape": "box", "half_extents": [2, 2, 0.002], "position": [0, 0, -3]},
        {"shape": "sphere", "radius": 1, "position": [0, 0, -6]}]}})";

// Unit directions of a columns x rows grid of pixel centres through the scene's camera.
std::vector<glm::vec3> cameraRays(const Camera& camera, int columns, int rows) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float halfHeight = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    const float halfWidth = halfHeight * float(columns) / float(rows);
    std::vector<glm::vec3> rays;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < columns; ++x) {
            const float u = (2.0f * (float(x) + 0.5f) / float(columns) - 1.0f) * halfWidth;
            const float v = (2.0f * (float(y) + 0.5f) / float(rows) - 1.0f) * halfHeight;
            rays.push_back(glm::normalize(forward + u * right + v * up));
        }
    return rays;
}

// Over-relaxed sphere tracing without the fallback: what the relaxed march must not do.
std::optional<float> unsafeRelaxedMarch(const SdfProgram& program, const RenderSettings& settings,
                                        glm::vec3 origin, glm::vec3 direction, float relaxation) {
    float t = 0.0f;
    for (int i = 0; i < settings.maxSteps && t <= settings.maxDistance; ++i) {
        const float d = sdfDistance(program, origin + direction * t);
        if (d < settings.surfaceEpsilon * std::max(t, 1.0f)) return t;
        t += relaxation * d;
    }
    return std::nullopt;
}

} // namespace

TEST(SdfRelaxedMarch, RelaxationIsOverRelaxation) {
    // Keinert et al. 2014 use factors between 1 and 2; beyond 2 a step may pass a plane and the
    // fallback would run on every ray.
    EXPECT_GT(kSdfMarchRelaxation, 1.0f);
    EXPECT_LT(kSdfMarchRelaxation, 2.0f);
}

TEST(SdfRelaxedMarch, FindsTheSurfacesOfThePlainMarchInFewerSteps) {
    std::vector<MarchCase> cases;
    cases.push_back(compileSample("samples/scenes/pawn.json"));
    cases.push_back(compileSample("samples/bench/grid_10.json"));
    cases.push_back(compileSample("samples/scenes/modifiers.json")); // bounds, not exact distances
    long plainSteps = 0;
    long relaxedSteps = 0;
    for (const MarchCase& c : cases) {
        SCOPED_TRACE(c.name);
        ASSERT_FALSE(c.program.instructions.empty());
        const RenderSettings& settings = c.scene.render;
        const glm::vec3 ro = c.scene.camera.position;
        const float tMax = settings.maxDistance;
        int hits = 0;
        int disagreements = 0;
        long casePlain = 0, caseRelaxed = 0;
        for (const glm::vec3& rd : cameraRays(c.scene.camera, 48, 32)) {
            // Steps as the steps AOV counts them, hits and misses.
            casePlain += sdfMarchSteps(c.program, settings, ro, rd, 0.0f, tMax, 1.0f);
            caseRelaxed += sdfMarchSteps(c.program, settings, ro, rd, 0.0f, tMax);
            const std::optional<SdfHit> plain =
                sdfCastRay(c.program, settings, ro, rd, 0.0f, tMax, 1.0f);
            const std::optional<SdfHit> relaxed =
                sdfCastRay(c.program, settings, ro, rd, 0.0f, tMax);
            if (plain.has_value() != relaxed.has_value()) {
                // Only a ray that grazes a surface within epsilon may stop in one march and go
                // past in the other.
                ++disagreements;
                continue;
            }
            if (!plain) continue;
            ++hits;
            const float tolerance = settings.surfaceEpsilon * std::max(plain->t, 1.0f);
            EXPECT_LT(sdfDistance(c.program, relaxed->position), tolerance);
            // Both points lie within epsilon of the same surface, before the ray crosses it:
            // along the ray at most about epsilon / cos(angle to the normal) apart.
            const glm::vec3 normal = sdfNormal(c.program, plain->position, tolerance);
            const float cosine = std::abs(glm::dot(normal, rd));
            if (cosine > 0.1f) {
                EXPECT_NEAR(relaxed->t, plain->t, 2.0f * tolerance / cosine)
                    << "ray " << rd.x << ", " << rd.y << ", " << rd.z;
            }
        }
        EXPECT_GT(hits, 48 * 32 / 10) << "the camera should see the scene";
        EXPECT_LE(disagreements, 48 * 32 / 200);
        RecordProperty(c.name + " disagreements", disagreements);
        RecordProperty(c.name + " plain steps", int(casePlain));
        RecordProperty(c.name + " relaxed steps", int(caseRelaxed));
        EXPECT_LT(caseRelaxed, casePlain);
        plainSteps += casePlain;
        relaxedSteps += caseRelaxed;
    }
    EXPECT_LT(double(relaxedSteps), 0.95 * double(plainSteps));
}

TEST(SdfRelaxedMarch, StopsAtAThinPlateThatAnUnsafeRelaxationStepsThrough) {
    const MarchCase plate = compileSceneText("thin plate", kThinPlate);
    ASSERT_FALSE(plate.program.instructions.empty());
    const RenderSettings& settings = plate.scene.render;
    const float tMax = settings.maxDistance;
    int tunnelled = 0;
    for (const glm::vec3& rd : cameraRays(plate.scene.camera, 16, 16)) {
        // The plate's front face is at z = -2.998.
        const float plateT = 2.998f / -rd.z;
        const std::optional<SdfHit> hit =
            sdfCastRay(plate.program, settings, {0, 0, 0}, rd, 0.0f, tMax);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->t, plateT, 0.002f + settings.surfaceEpsilon * plateT);
        // Seen nearly head-on, the relaxed step passes the plate once and the fallback costs
        // one evaluation; the plain steps after it must not fail again.
        const std::optional<SdfHit> plain =
            sdfCastRay(plate.program, settings, {0, 0, 0}, rd, 0.0f, tMax, 1.0f);
        ASSERT_TRUE(plain);
        EXPECT_LE(hit->steps, plain->steps + 1);
        const std::optional<float> unsafe =
            unsafeRelaxedMarch(plate.program, settings, {0, 0, 0}, rd, kSdfMarchRelaxation);
        tunnelled += !unsafe || *unsafe > plateT + 0.01f;
    }
    EXPECT_GT(tunnelled, 0) << "the plate should be thin enough to step through";
}

// Head-on to a plane the relaxed step lands behind it; the fallback goes back and takes the
// plain step onto it: one evaluation more than the plain march.
TEST(SdfRelaxedMarch, FallsBackAtAPlaneHitHeadOn) {
    const MarchCase plane = compileSceneText("plane", R"({"version": 1,
        "sdf": {"shape": "plane", "normal": [0, 1, 0], "offset": 0}})");
    const std::optional<SdfHit> relaxed =
        sdfCastRay(plane.program, RenderSettings{}, {0, 2, 0}, {0, -1, 0}, 0.0f, 100.0f);
    ASSERT_TRUE(relaxed);
    EXPECT_NEAR(relaxed->t, 2.0f, 1e-5f);
    EXPECT_EQ(relaxed->steps, 3);
    const std::optional<SdfHit> plain =
        sdfCastRay(plane.program, RenderSettings{}, {0, 2, 0}, {0, -1, 0}, 0.0f, 100.0f, 1.0f);
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->steps, 2);
}

// A relaxed step that would pass tMax is taken plain, so a surface just before tMax is found.
TEST(SdfRelaxedMarch, FindsASurfaceJustBeforeTMax) {
    const MarchCase plane = compileSceneText("plane", R"({"version": 1,
        "sdf": {"shape": "plane", "normal": [0, 1, 0], "offset": 0}})");
    const std::optional<SdfHit> hit =
        sdfCastRay(plane.program, RenderSettings{}, {0, 2, 0}, {0, -1, 0}, 0.0f, 2.01f);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0f, 1e-5f);
}

// Rays that graze a plane where it meets the farthest distance: whether one hits does not
// depend on where its march starts. The march pass starts a tile's pixels where the cone pass
// stopped, so a decision that depended on the start drew the plane's cut-off edge in steps of
// a tile (the scale issue's tree at max_distance 9). The last step lands on the farthest
// distance, and the ray hits exactly when the plane is within epsilon * t of that point.
TEST(SdfRelaxedMarch, TheFarthestDistanceDecidesAGrazingRayWhereverItsMarchStarts) {
    const MarchCase c = compileSceneText("plane", R"({"version": 1,
        "sdf": {"shape": "plane", "normal": [0, 1, 0], "offset": 0}})");
    RenderSettings settings;
    settings.maxDistance = 9.0f;
    const glm::vec3 origin(0.0f, 0.5f, 0.0f);
    int decided = 0, hits = 0;
    // Downward angles whose plane hit lies from 8.5 to 9.5 away: the cut-off band.
    for (int i = 0; i <= 400; ++i) {
        const float reach = 8.5f + 0.0025f * float(i); // where the ray meets the plane
        const glm::vec3 direction =
            glm::normalize(glm::vec3(0.0f, -0.5f, std::sqrt(reach * reach - 0.25f)));
        const std::optional<SdfHit> first =
            sdfCastRay(c.program, settings, origin, direction, 0.0f, settings.maxDistance);
        for (const float start : {0.37f, 1.1f, 2.9f, 4.4f, 6.05f}) {
            const std::optional<SdfHit> other =
                sdfCastRay(c.program, settings, origin, direction, start, settings.maxDistance);
            ASSERT_EQ(first.has_value(), other.has_value())
                << "the ray meeting the plane " << reach << " away, marched from " << start;
        }
        ++decided;
        if (!first) continue;
        ++hits;
        // A hit is within the farthest distance, and on the plane to within epsilon * t.
        EXPECT_LE(first->t, settings.maxDistance);
        EXPECT_LT(std::abs(first->position.y), settings.surfaceEpsilon * first->t);
    }
    EXPECT_EQ(decided, 401);
    // Those meeting the plane before 9 hit; those far past it do not.
    EXPECT_GT(hits, 200);
    EXPECT_LT(hits, 401);
}
