// glTF features on the GPU, each on a small file the test writes itself where the answer is
// known: COLOR_0 multiplies the base colour, doubleSided culls or flips back faces (in the image
// and in shadows), a MASK edge lands on the pixel its cutoff says (in the image and in a shadow),
// BLEND panes composite "over" an SDF object behind them in back-to-front order without hiding it
// from the depth and id AOVs, KHR_texture_transform moves a texture as its matrix says,
// KHR_materials_unlit shows the base colour as it is, lines and points are drawn unlit where
// they project and nowhere else.
#include "gltf_builder.hpp"
#include "gpu_test_support.hpp"

#include "render/frame.hpp"
#include "render/raster_pass.hpp"
#include "scene/scene_json.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace rmsc;
using namespace rmsc::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// A folder of this test's own: ctest runs the tests of this file in parallel processes.
fs::path folder() {
    const fs::path f = fs::temp_directory_path() / "rmsc_gpu_gltf_features" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(f);
    return f;
}

// A quad x, y in [-1, 1] at z = 0 facing +z (or -z when `flipped`), as a glTF document: u runs
// with x, v down the image (v = (1 - y) / 2); TEXCOORD_1 is u mirrored. `colors` (RGBA per
// corner: (-1,-1), (1,-1), (1,1), (-1,1)) becomes COLOR_0 when not empty.
json quadGltf(GltfBuilder& b, const json& material, const std::vector<float>& colors = {},
              bool flipped = false, const json& images = json::array()) {
    const std::vector<float> positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const float nz = flipped ? -1.0f : 1.0f;
    json attributes = {
        {"POSITION", b.accessor(positions, kFloatType, "VEC3", 4)},
        {"NORMAL", b.accessor(std::vector<float>{0, 0, nz, 0, 0, nz, 0, 0, nz, 0, 0, nz},
                              kFloatType, "VEC3", 4)},
        {"TEXCOORD_0",
         b.accessor(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}, kFloatType, "VEC2", 4)},
        {"TEXCOORD_1",
         b.accessor(std::vector<float>{1, 1, 0, 1, 0, 0, 1, 0}, kFloatType, "VEC2", 4)}};
    if (!colors.empty()) attributes["COLOR_0"] = b.accessor(colors, kFloatType, "VEC4", 4);
    const std::vector<std::uint16_t> indices = flipped
                                                   ? std::vector<std::uint16_t>{0, 2, 1, 0, 3, 2}
                                                   : std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3};
    json gltf = {{"scenes", {{{"nodes", {0}}}}},
                 {"scene", 0},
                 {"nodes", {{{"mesh", 0}}}},
                 {"materials", {material}},
                 {"meshes",
                  {{{"primitives",
                     {{{"attributes", attributes},
                       {"indices", b.accessor(indices, kUnsignedShort, "SCALAR", 6)},
                       {"material", 0}}}}}}}};
    if (!images.empty()) {
        gltf["images"] = images;
        json textures = json::array();
        for (std::size_t i = 0; i < images.size(); ++i)
            textures.push_back({{"source", i}, {"sampler", 0}});
        gltf["textures"] = textures;
        gltf["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}}; // nearest, repeat
        gltf["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_unlit"};
    }
    return gltf;
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// A scene of the given mesh placements (one object: one placement) and SDF tree, seen from (0, 0,
// 4) towards the origin (fov 45), lit by `lights` and a white ambient term, black background.
PreparedScene openTestScene(const json& meshes, const json& lights = json::array(),
                            const json& sdf = nullptr, const json& render = json::object(),
                            const json& camera = nullptr) {
    json scene = {{"version", 1},
                  {"camera", {{"position", {0, 0, 4}}, {"target", {0, 0, 0}}, {"fov", 45}}},
                  {"render", {{"ambient", {1, 1, 1}}, {"background", {0, 0, 0}}}},
                  {"lights", lights},
                  {"meshes", meshes.is_object() ? json::array({meshes}) : meshes}};
    scene["render"].merge_patch(render);
    if (!camera.is_null()) scene["camera"] = camera;
    if (!sdf.is_null()) scene["sdf"] = sdf;
    const fs::path path = folder() / "scene.json";
    writeText(path, scene.dump());
    Diagnostics d;
    const FileSource files = diskFileSource();
    std::optional<Scene> loaded = loadScene(path, files, d);
    EXPECT_TRUE(loaded) << d.format();
    std::optional<PreparedScene> prepared =
        loaded ? prepareScene(std::move(*loaded), files, d) : std::nullopt;
    EXPECT_TRUE(prepared) << d.format();
    return prepared ? std::move(*prepared) : PreparedScene{};
}

// Writes `gltf` (with `b`'s data) as NAME.gltf and returns the placement of it.
json place(const std::string& name, const GltfBuilder& b, const json& gltf,
           const json& transform = json::object()) {
    writeText(folder() / (name + ".gltf"), b.text(gltf));
    json placement = {{"file", name + ".gltf"}};
    placement.merge_patch(transform);
    return placement;
}

// The pixel (column, row from the top) showing world point p through the scene's camera.
glm::ivec2 pixelOf(const PreparedScene& prepared, glm::vec3 p) {
    const FrameCamera camera = makeFrameCamera(prepared.scene.camera, kWidth, kHeight);
    const glm::vec4 clip = camera.viewProjection * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {int(std::floor((ndc.x * 0.5f + 0.5f) * kWidth)),
            int(std::floor((0.5f - ndc.y * 0.5f) * kHeight))};
}

glm::vec3 hdrAt(const Pixels<float>& hdr, glm::ivec2 pixel) {
    const float* c = hdr.at(pixel.x, pixel.y);
    return {c[0], c[1], c[2]};
}

// The colour targets are RGBA16F: one step of a half float between 1 and 2 (11 bits). The
// comparisons below measured 0 on llvmpipe (the unlit colour 3.9e-4: 0.6 rounded to a half);
// the bound allows one rounding another driver may do differently.
constexpr float kHalfFloatStep = 1.0f / 1024.0f;

void expectColorNear(glm::vec3 actual, glm::vec3 expected, float tolerance,
                     const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

// A PNG in the test folder; returns its glTF image entry.
json pngImage(const std::string& name, int width, int height,
              const std::vector<std::uint8_t>& rgba) {
    std::string error;
    EXPECT_TRUE(writePng8(folder() / name, Pixels<std::uint8_t>{width, height, 4, rgba}, error))
        << error;
    return {{"uri", name}};
}

} // namespace

TEST(GltfFeatures, VertexColorMultipliesTheBaseColor) {
    // Factor (0.5, 1, 1) times COLOR_0 (1, 0.25, 0.5) must shade like factor (0.5, 0.25, 0.5).
    GltfBuilder a, b;
    const std::vector<float> color = {1, 0.25f, 0.5f, 1, 1, 0.25f, 0.5f, 1,
                                      1, 0.25f, 0.5f, 1, 1, 0.25f, 0.5f, 1};
    const json pbr = {{"metallicFactor", 0}, {"roughnessFactor", 0.6}};
    json withColor = {{"pbrMetallicRoughness", pbr}};
    withColor["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 1, 1, 1};
    json product = {{"pbrMetallicRoughness", pbr}};
    product["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 0.25, 0.5, 1};
    const json sun = {{{"type", "directional"}, {"direction", {-0.3, -0.4, -1}}, {"intensity", 2}}};
    const PreparedScene colored =
        openTestScene({place("vc", a, quadGltf(a, withColor, color))}, sun);
    const PreparedScene plain = openTestScene({place("vc_plain", b, quadGltf(b, product))}, sun);
    const Pixels<float> x = readHdrColor(renderPrepared(colored, kWidth, kHeight));
    const Pixels<float> y = readHdrColor(renderPrepared(plain, kWidth, kHeight));
    for (const glm::vec3 p :
         {glm::vec3(0, 0, 0), glm::vec3(-0.6f, 0.5f, 0), glm::vec3(0.7f, -0.7f, 0)}) {
        const glm::ivec2 pixel = pixelOf(colored, p);
        const glm::vec3 c = hdrAt(x, pixel);
        expectColorNear(c, hdrAt(y, pixel), kHalfFloatStep, "vertex colour");
        EXPECT_GT(c.x, 1.5f * c.y) << "green was not multiplied by 0.25";
    }
    expectNoGlErrors();
}

TEST(GltfFeatures, DoubleSidedCullsOrFlipsBackFaces) {
    // The quad faces away from the camera: single-sided it is not drawn at all; double-sided it
    // is, with its normal turned towards the camera (+z).
    GltfBuilder a, b;
    const PreparedScene single =
        openTestScene({place("back1", a, quadGltf(a, json::object(), {}, true))});
    const PreparedScene both =
        openTestScene({place("back2", b, quadGltf(b, {{"doubleSided", true}}, {}, true))});
    const FrameTargets t1 = renderPrepared(single, kWidth, kHeight);
    const Pixels<std::uint32_t> ids1 = readObjectIds(t1);
    const FrameTargets t2 = renderPrepared(both, kWidth, kHeight);
    const Pixels<std::uint32_t> ids2 = readObjectIds(t2);
    const Pixels<float> normals = readNormals(t2);
    const glm::ivec2 centre = pixelOf(both, glm::vec3(0.2f, 0.3f, 0));
    EXPECT_EQ(ids1.at(centre.x, centre.y)[0], 0u) << "a single-sided back face was drawn";
    EXPECT_EQ(ids2.at(centre.x, centre.y)[0], kMeshIdBase);
    EXPECT_NEAR(normals.at(centre.x, centre.y)[2], 1.0f, 1e-3f) << "back face normal not flipped";
    expectNoGlErrors();
}

TEST(GltfFeatures, MaskEdgeIsWhereTheCutoffSays) {
    // Alpha runs linearly from 0 at x = -1 to 1 at x = 1 (COLOR_0): with cutoff 0.3 the quad is
    // drawn for x >= -0.4 and nothing left of it.
    GltfBuilder b;
    const std::vector<float> ramp = {1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0};
    const PreparedScene prepared = openTestScene(
        {place("mask", b, quadGltf(b, {{"alphaMode", "MASK"}, {"alphaCutoff", 0.3}}, ramp))});
    const Pixels<std::uint32_t> ids = readObjectIds(renderPrepared(prepared, kWidth, kHeight));
    const FrameCamera camera = makeFrameCamera(prepared.scene.camera, kWidth, kHeight);
    const int row = kHeight / 2;
    int checked = 0;
    for (int x = pixelOf(prepared, {-0.95f, 0, 0}).x; x <= pixelOf(prepared, {0.95f, 0, 0}).x;
         ++x) {
        // The world x at this pixel centre on the plane z = 0.
        const glm::vec3 ray = pixelRayDirection(camera, x, kHeight - 1 - row, kWidth, kHeight);
        const float worldX = camera.position.x + ray.x * (camera.position.z / -ray.z);
        const float alpha = (worldX + 1.0f) / 2.0f;
        if (std::abs(alpha - 0.3f) < 0.004f) continue; // the pixel the edge runs through
        EXPECT_EQ(ids.at(x, row)[0], alpha >= 0.3f ? kMeshIdBase : 0u) << "column " << x;
        ++checked;
    }
    EXPECT_GT(checked, 30);
    expectNoGlErrors();
}

TEST(GltfFeatures, MaskCutOutCastsNoShadow) {
    // A horizontal MASK quad at y = 1 over a floor at y = 0, the light slanting along +x so
    // shadows shift by +1 in x. Alpha is 1 at x = -1 and 0 at x = 1 (cutoff 0.5): the kept half
    // (x < 0) shades the floor at 0 < x < 1, the cut half would have shaded 1 < x < 2.
    GltfBuilder q, f;
    const std::vector<float> ramp = {1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 0, 1, 1, 1, 1};
    const json mask =
        place("mask_shadow", q, quadGltf(q, {{"alphaMode", "MASK"}, {"doubleSided", true}}, ramp),
              {{"position", {0, 1, 0}}, {"rotation", {-90, 0, 0}}});
    const json floor = place("floor", f, quadGltf(f, json::object()),
                             {{"position", {1, 0, 0}}, {"rotation", {-90, 0, 0}}, {"scale", 3}});
    const json light = {{{"type", "directional"}, {"direction", {1, -1, 0}}, {"intensity", 3}}};
    const json camera = {
        {"position", {1.5, 6, 0}}, {"target", {1.5, 0, 0}}, {"up", {0, 0, -1}}, {"fov", 50}};
    const PreparedScene prepared =
        openTestScene({mask, floor}, light, nullptr,
                      {{"ambient", {0.05, 0.05, 0.05}}, {"shadows", {{"pcf_radius", 0}}}}, camera);
    const Pixels<float> hdr = readHdrColor(renderPrepared(prepared, kWidth, kHeight));
    const float shaded = hdrAt(hdr, pixelOf(prepared, {0.5f, 0, 0.5f})).y;
    const float underCut = hdrAt(hdr, pixelOf(prepared, {1.5f, 0, 0.5f})).y;
    const float open = hdrAt(hdr, pixelOf(prepared, {2.5f, 0, 0.5f})).y;
    EXPECT_LT(shaded, 0.3f * open) << "the kept half casts no shadow";
    EXPECT_NEAR(underCut, open, 0.02f * open) << "the cut-out half casts a shadow";
    expectNoGlErrors();
}

TEST(GltfFeatures, SingleSidedSurfaceCastsOnlyWhereTheLightSeesItsFront) {
    // A horizontal quad at y = 1 over a floor at y = 0, the light slanting along +x so the
    // shadow falls at 1 < x < 3, where the camera above sees the floor past the quad. The shadow
    // pass culls faces as the raster pass does, seen from the light: a single-sided quad facing
    // down (its back to the light) casts nothing; facing up, double-sided, or mirrored by its
    // glTF node so that it faces up, it casts.
    struct Case {
        const char* name;
        bool flipped;
        bool doubleSided;
        bool mirrored;
        bool casts;
    };
    const Case cases[] = {{"up", false, false, false, true},
                          {"down", true, false, false, false},
                          {"down_double", true, true, false, true},
                          {"down_mirrored", true, false, true, true}};
    GltfBuilder f;
    const json floor = place("floor", f, quadGltf(f, json::object()),
                             {{"position", {2, 0, 0}}, {"rotation", {-90, 0, 0}}, {"scale", 3}});
    const json light = {{{"type", "directional"}, {"direction", {2, -1, 0}}, {"intensity", 3}}};
    const json camera = {
        {"position", {2, 6, 0}}, {"target", {2, 0, 0}}, {"up", {0, 0, -1}}, {"fov", 50}};
    const json render = {{"ambient", {0.05, 0.05, 0.05}}, {"shadows", {{"pcf_radius", 0}}}};
    // The floor's colour there without the quad.
    const PreparedScene bare = openTestScene({floor}, light, nullptr, render, camera);
    const glm::ivec2 under = pixelOf(bare, {2.0f, 0, 0.5f});
    const float lit = hdrAt(readHdrColor(renderPrepared(bare, kWidth, kHeight)), under).y;
    ASSERT_GT(lit, 0.1f) << "the floor is not lit";
    for (const Case& c : cases) {
        GltfBuilder q;
        json gltf = quadGltf(q, c.doubleSided ? json{{"doubleSided", true}} : json::object(), {},
                             c.flipped);
        if (c.mirrored) gltf["nodes"][0]["scale"] = {1, 1, -1};
        const json quad =
            place(c.name, q, gltf, {{"position", {0, 1, 0}}, {"rotation", {-90, 0, 0}}});
        const PreparedScene prepared = openTestScene({quad, floor}, light, nullptr, render, camera);
        const float shade = hdrAt(readHdrColor(renderPrepared(prepared, kWidth, kHeight)), under).y;
        if (c.casts)
            EXPECT_LT(shade, 0.3f * lit) << c.name << ": no shadow";
        else
            EXPECT_NEAR(shade, lit, kHalfFloatStep) << c.name << ": a back face cast a shadow";
    }
    expectNoGlErrors();
}

// The continuous window position (x from the left, y from the top, in pixels) of world point p.
glm::vec2 windowOf(const PreparedScene& prepared, glm::vec3 p) {
    const FrameCamera camera = makeFrameCamera(prepared.scene.camera, kWidth, kHeight);
    const glm::vec4 clip = camera.viewProjection * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * kWidth, (0.5f - ndc.y * 0.5f) * kHeight};
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 e = b - a;
    const float s = glm::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0f, 1.0f);
    return glm::length(p - (a + s * e));
}

TEST(GltfFeatures, LinesAndPointsAreDrawnWhereTheyProject) {
    // One mesh with a primitive of each mode 0 to 3 in the plane z = 0, seen face on, lit by a
    // strong light: LINES (a horizontal and a slanted segment), LINE_LOOP (a triangle, closed),
    // LINE_STRIP (a V) and POINTS (two). Every pixel drawn must lie on a projected segment (its
    // centre within a pixel of it) or in a point's 3x3 square, every stretch of each segment must
    // be drawn, and each shows the base colour unlit, at the plane's depth, with the mesh's id.
    using Segment = std::pair<glm::vec3, glm::vec3>;
    const std::vector<std::vector<glm::vec3>> strips = {
        {{-1.8f, 0.9f, 0}, {1.8f, 0.9f, 0}, {-1.6f, -1.2f, 0}, {-0.6f, -0.1f, 0}}, // LINES
        {{0.4f, -1.2f, 0}, {1.6f, -1.2f, 0}, {1.6f, -0.2f, 0}},                    // LINE_LOOP
        {{-1.2f, 0.6f, 0}, {-0.3f, 0.1f, 0}, {0.6f, 0.6f, 0}},                     // LINE_STRIP
        {{1.9f, 0.2f, 0}, {-1.95f, -0.45f, 0}}};                                   // POINTS
    const int modes[] = {1, 2, 3, 0};
    std::vector<Segment> segments = {{strips[0][0], strips[0][1]}, {strips[0][2], strips[0][3]}};
    for (std::size_t i = 0; i < 3; ++i)
        segments.push_back({strips[1][i], strips[1][(i + 1) % 3]});
    for (std::size_t i = 0; i < 2; ++i)
        segments.push_back({strips[2][i], strips[2][i + 1]});
    GltfBuilder b;
    json primitives = json::array();
    for (std::size_t p = 0; p < strips.size(); ++p) {
        std::vector<float> positions;
        for (const glm::vec3& v : strips[p])
            positions.insert(positions.end(), {v.x, v.y, v.z});
        primitives.push_back(
            {{"attributes",
              {{"POSITION", b.accessor(positions, kFloatType, "VEC3", strips[p].size())}}},
             {"mode", modes[p]},
             {"material", 0}});
    }
    const glm::vec3 base(0.2f, 0.6f, 0.9f);
    const json gltf = {
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"materials",
         {{{"pbrMetallicRoughness", {{"baseColorFactor", {base.x, base.y, base.z, 1}}}}}}},
        {"meshes", {{{"primitives", primitives}}}}};
    const json sun = {{{"type", "directional"}, {"direction", {0, 0, -1}}, {"intensity", 8}}};
    const PreparedScene prepared = openTestScene({place("lines", b, gltf)}, sun);
    const FrameTargets targets = renderPrepared(prepared, kWidth, kHeight);
    const Pixels<std::uint32_t> ids = readObjectIds(targets);
    const Pixels<float> hdr = readHdrColor(targets);
    const Pixels<float> depth = readViewDepth(targets);

    std::vector<std::pair<glm::vec2, glm::vec2>> projected;
    for (const Segment& s : segments)
        projected.push_back({windowOf(prepared, s.first), windowOf(prepared, s.second)});
    std::vector<glm::vec2> points;
    for (const glm::vec3& p : strips[3])
        points.push_back(windowOf(prepared, p));
    int drawn = 0;
    std::vector<glm::vec2> drawnCentres;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::uint32_t id = ids.at(x, y)[0];
            if (id == 0) continue;
            ++drawn;
            const glm::vec2 centre(float(x) + 0.5f, float(y) + 0.5f);
            drawnCentres.push_back(centre);
            float nearest = 1e9f;
            for (const auto& [a, b2] : projected)
                nearest = std::min(nearest, distanceToSegment(centre, a, b2));
            bool inPoint = false;
            for (const glm::vec2& p : points)
                inPoint = inPoint || glm::all(glm::lessThanEqual(glm::abs(centre - p),
                                                                 glm::vec2(0.5f * kGltfPointSize)));
            EXPECT_TRUE(nearest <= 1.0f || inPoint)
                << "pixel " << x << ", " << y << " drawn " << nearest << " px from every line";
            EXPECT_EQ(id, kMeshIdBase) << "pixel " << x << ", " << y;
            expectColorNear(hdrAt(hdr, {x, y}), base, kHalfFloatStep,
                            "unlit at " + std::to_string(x) + ", " + std::to_string(y));
            EXPECT_NEAR(depth.at(x, y)[0], 4.0f, 1e-3f) << "pixel " << x << ", " << y;
        }
    // Each segment is drawn all along: every point of it has a drawn pixel centre within a pixel
    // and a half (GL's diamond-exit rule may leave out the pixel a segment ends in).
    for (const auto& [a, b2] : projected) {
        const int steps = int(glm::length(b2 - a) * 2.0f);
        for (int i = 1; i < steps; ++i) {
            const glm::vec2 q = a + (b2 - a) * (float(i) / float(steps));
            float nearest = 1e9f;
            for (const glm::vec2& c : drawnCentres)
                nearest = std::min(nearest, glm::length(c - q));
            EXPECT_LE(nearest, 1.5f) << "a gap in the line at " << q.x << ", " << q.y;
        }
    }
    for (const glm::vec2& p : points)
        EXPECT_EQ(ids.at(int(p.x), int(p.y))[0], kMeshIdBase)
            << "the point at " << p.x << ", " << p.y;
    EXPECT_GT(drawn, 150);
    expectNoGlErrors();
}

TEST(GltfFeatures, BlendPanesCompositeOverAnSdfObjectBackToFront) {
    // An SDF sphere (radius 0.5 at z = -1) behind two BLEND panes: pane A (alpha 0.25) at
    // z = 0.5 and pane B (alpha 0.5) at z = 0, A listed first. In linear HDR the result is
    // A over (B over sphere), which depends on the order: drawn in file order it would differ.
    const json sphere = {{"shape", "sphere"}, {"radius", 0.5}, {"position", {0, 0, -1}}};
    const auto pane = [](GltfBuilder& b, glm::vec4 color) {
        json m = {
            {"alphaMode", "BLEND"},
            {"extensions", {{"KHR_materials_unlit", json::object()}}},
            {"pbrMetallicRoughness", {{"baseColorFactor", {color.x, color.y, color.z, color.w}}}}};
        json gltf = quadGltf(b, m);
        gltf["extensionsUsed"] = {"KHR_materials_unlit"};
        return gltf;
    };
    GltfBuilder a, b;
    const json paneA =
        place("pane_a", a, pane(a, {1, 0, 0, 0.25f}), {{"position", {0, 0, 0.5}}, {"scale", 0.4}});
    const json paneB =
        place("pane_b", b, pane(b, {0, 0, 1, 0.5f}), {{"position", {0, 0, 0}}, {"scale", 0.6}});
    const PreparedScene alone = openTestScene(json::array(), json::array(), sphere);
    const PreparedScene glass = openTestScene({paneA, paneB}, json::array(), sphere);
    const FrameTargets behindTargets = renderPrepared(alone, kWidth, kHeight);
    const FrameTargets glassTargets = renderPrepared(glass, kWidth, kHeight);
    const Pixels<float> behind = readHdrColor(behindTargets);
    const Pixels<float> through = readHdrColor(glassTargets);
    const glm::ivec2 centre = pixelOf(glass, {0, 0, 0});
    const glm::vec3 s = hdrAt(behind, centre);
    ASSERT_GT(s.y, 0.1f) << "the sphere is not there to be seen";
    const glm::vec3 overB = 0.5f * glm::vec3(0, 0, 1) + 0.5f * s;
    const glm::vec3 expected = 0.25f * glm::vec3(1, 0, 0) + 0.75f * overB;
    expectColorNear(hdrAt(through, centre), expected, kHalfFloatStep, "A over (B over the sphere)");
    // Only pane B (0.6 wide) covers this pixel: B over the background (black).
    const glm::ivec2 edge = pixelOf(glass, {0.5f, 0, 0});
    expectColorNear(hdrAt(through, edge), 0.5f * glm::vec3(0, 0, 1) + 0.5f * hdrAt(behind, edge),
                    kHalfFloatStep, "B over the background");
    // The panes write no depth and no id: the AOVs show the sphere.
    EXPECT_EQ(readObjectIds(glassTargets).at(centre.x, centre.y)[0],
              readObjectIds(behindTargets).at(centre.x, centre.y)[0]);
    EXPECT_NEAR(readViewDepth(glassTargets).at(centre.x, centre.y)[0], 4.5f, 0.02f);
    expectNoGlErrors();
}

TEST(GltfFeatures, TextureTransformMovesTheTexture) {
    // A 2x2 texture (red, green / blue, white) with nearest filtering, repeated; the material's
    // KHR_texture_transform (offset, rotation 90 degrees, scale) and texCoord 1 (u mirrored).
    // Each sampled point must show the texel the transform's matrix names.
    GltfBuilder b;
    const std::vector<std::uint8_t> texels = {255, 0, 0,   255, 0,   255, 0,   255,
                                              0,   0, 255, 255, 255, 255, 255, 255};
    const glm::vec3 palette[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    TextureTransform transform;
    transform.offset = {0.25f, 0.5f};
    transform.rotation = 1.5707963f;
    transform.scale = {0.5f, 1.5f};
    const json ext = {{"offset", {transform.offset.x, transform.offset.y}},
                      {"rotation", transform.rotation},
                      {"scale", {transform.scale.x, transform.scale.y}},
                      {"texCoord", 1}};
    const json material = {
        {"extensions", {{"KHR_materials_unlit", json::object()}}},
        {"pbrMetallicRoughness",
         {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", ext}}}}}}}};
    const PreparedScene prepared = openTestScene({place(
        "transformed", b,
        quadGltf(b, material, {}, false, json::array({pngImage("quad4.png", 2, 2, texels)})))});
    const Pixels<float> hdr = readHdrColor(renderPrepared(prepared, kWidth, kHeight));
    int checked = 0;
    for (float x = -0.9f; x < 0.95f; x += 0.15f)
        for (float y = -0.9f; y < 0.95f; y += 0.15f) {
            const glm::vec2 uv1((1.0f - x) / 2.0f, (1.0f - y) / 2.0f); // TEXCOORD_1: u mirrored
            const glm::vec2 t = transform.apply(uv1) * 2.0f;           // in texels
            const glm::vec2 inTexel = t - glm::floor(t);
            // Skip points near a texel edge, where one pixel's footprint straddles two texels.
            if (glm::any(glm::lessThan(inTexel, glm::vec2(0.12f))) ||
                glm::any(glm::greaterThan(inTexel, glm::vec2(0.88f))))
                continue;
            const int tx = int(std::floor(t.x)) & 1, ty = int(std::floor(t.y)) & 1;
            const glm::vec3 c = hdrAt(hdr, pixelOf(prepared, {x, y, 0}));
            expectColorNear(c, palette[ty * 2 + tx], kHalfFloatStep,
                            "at x " + std::to_string(x) + " y " + std::to_string(y));
            ++checked;
        }
    EXPECT_GT(checked, 40);
    expectNoGlErrors();
}

TEST(GltfFeatures, UnlitShowsTheBaseColorUnderAnyLight) {
    GltfBuilder b, c;
    const json factor = {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}};
    json unlit = {{"pbrMetallicRoughness", factor},
                  {"extensions", {{"KHR_materials_unlit", json::object()}}}};
    const json strong = {{{"type", "directional"}, {"direction", {0, 0, -1}}, {"intensity", 8}}};
    json gltf = quadGltf(b, unlit);
    gltf["extensionsUsed"] = {"KHR_materials_unlit"};
    const PreparedScene prepared = openTestScene({place("unlit", b, gltf)}, strong);
    const PreparedScene lit =
        openTestScene({place("lit", c, quadGltf(c, {{"pbrMetallicRoughness", factor}}))}, strong);
    const Pixels<float> hdr = readHdrColor(renderPrepared(prepared, kWidth, kHeight));
    const Pixels<float> litHdr = readHdrColor(renderPrepared(lit, kWidth, kHeight));
    for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(0.8f, 0.8f, 0)})
        expectColorNear(hdrAt(hdr, pixelOf(prepared, p)), {0.2f, 0.4f, 0.6f}, kHalfFloatStep,
                        "unlit");
    EXPECT_GT(hdrAt(litHdr, pixelOf(lit, {0, 0, 0})).z, 0.8f) << "lighting would change it";
    expectNoGlErrors();
}
