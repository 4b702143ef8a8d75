// SDF material textures on the GPU: a triplanar texture is mapped in the shape's local space, so
// it stays attached when the shape moves, and a triplanar normal map bends the shading normal
// (the normal AOV) the way its tangent frame says. Scenes have no lights and a white ambient
// term, so the HDR colour is base colour + 0.04 (glTF F0 of a dielectric) with no dependence on
// position or view: textures are the only thing that varies.
#include "gpu_test_support.hpp"

#include "render/readback.hpp"
#include "scene/scene_json.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace rmsc;
using namespace rmsc::test;
namespace fs = std::filesystem;

namespace {

constexpr int kSize = 128;
constexpr float kCameraZ = 5.0f;
constexpr float kFovY = 30.0f;

// A folder of this test's own (ctest runs the tests of this file in parallel processes, which
// must not write the same scene.json) with checker.png (64 x 64, squares of 8 pixels: 1/8 of a
// repeat, white where (x / 8 + y / 8) is even, dark grey otherwise) and tilted_normal.png (every
// texel encodes the tangent-space normal (0.6, 0, 0.8)).
fs::path textureFolder() {
    const fs::path folder = fs::temp_directory_path() / "rmsc_gpu_material_textures" /
                            ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(folder);
    Pixels<std::uint8_t> checker{64, 64, 4, {}};
    Pixels<std::uint8_t> tilted{4, 4, 4, {}};
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::uint8_t v = ((x / 8 + y / 8) % 2 == 0) ? 255 : 40;
            checker.data.insert(checker.data.end(), {v, v, v, 255});
        }
    for (int i = 0; i < 16; ++i)
        tilted.data.insert(tilted.data.end(), {204, 128, 230, 255});
    std::string error;
    EXPECT_TRUE(writePng8(folder / "checker.png", checker, error)) << error;
    EXPECT_TRUE(writePng8(folder / "tilted_normal.png", tilted, error)) << error;
    return folder;
}

// A unit box (half extents 0.5) at `position` with the given material JSON, seen head-on from
// (0, 0, 5) with a 30 degree vertical field of view.
PreparedScene boxScene(const std::string& material, glm::vec3 position) {
    const fs::path folder = textureFolder();
    const std::string text =
        R"({"version": 1, "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov": 30},
            "render": {"ambient": [1, 1, 1], "background": [0, 0, 0]}, "lights": [],
            "materials": {"m": )" +
        material + R"(}, "sdf": {"shape": "box", "half_extents": [0.5, 0.5, 0.5], "position": [)" +
        std::to_string(position.x) + "," + std::to_string(position.y) + "," +
        std::to_string(position.z) + R"(], "material": "m"}})";
    std::ofstream(folder / "scene.json") << text;
    Diagnostics d;
    const FileSource files = diskFileSource();
    std::optional<Scene> scene = loadScene(folder / "scene.json", files, d);
    EXPECT_TRUE(scene) << d.format();
    std::optional<PreparedScene> prepared =
        scene ? prepareScene(std::move(*scene), files, d) : std::nullopt;
    EXPECT_TRUE(prepared) << d.format();
    return prepared ? std::move(*prepared) : PreparedScene{};
}

// The pixel showing world point p (on the box's front face, z = 0.5 + position z) in a
// kSize x kSize image, rows top first: the pinhole projection of the camera above.
glm::ivec2 pixelOf(glm::vec3 p) {
    const float halfHeight = (kCameraZ - p.z) * std::tan(glm::radians(kFovY * 0.5f));
    const float u = 0.5f + 0.5f * p.x / halfHeight, v = 0.5f - 0.5f * p.y / halfHeight;
    return {int(std::floor(u * kSize)), int(std::floor(v * kSize))};
}

float redAt(const Pixels<float>& hdr, glm::vec3 p) {
    const glm::ivec2 pixel = pixelOf(p);
    return hdr.at(pixel.x, pixel.y)[0];
}

} // namespace

TEST(SdfMaterialTextures, TriplanarTextureStaysAttachedToAMovingShape) {
    const std::string material =
        R"({"base_color": [1, 1, 1], "base_color_texture": {"file": "checker.png", "scale": 1}})";
    const glm::vec3 move(0.125f, 0.0f, 0.0f); // one checker square
    const PreparedScene before = boxScene(material, glm::vec3(0.0f));
    const PreparedScene after = boxScene(material, move);
    const Pixels<float> hdrBefore = readHdrColor(renderPrepared(before, kSize, kSize));
    const Pixels<float> hdrAfter = readHdrColor(renderPrepared(after, kSize, kSize));
    // Square centres on the front face (local z = 0.5), away from square edges by 1/16.
    int checked = 0;
    for (float x : {-0.3125f, -0.0625f, 0.1875f})
        for (float y : {-0.1875f, 0.0625f}) {
            const glm::vec3 q(x, y, 0.5f);
            const float a = redAt(hdrBefore, q);
            const float b = redAt(hdrAfter, q + move); // the same local point, moved
            const float sameWorldPoint = redAt(hdrAfter, q);
            // White squares give 1.04, dark ones (40/255 in sRGB = 0.021 linear) 0.061.
            EXPECT_TRUE(a > 0.9f || a < 0.15f) << "x " << x << " y " << y << ": " << a;
            EXPECT_NEAR(a, b, 0.03f) << "x " << x << " y " << y;
            // A texture fixed in world space would show the same colour here; it must not.
            EXPECT_GT(std::abs(a - sameWorldPoint), 0.5f) << "x " << x << " y " << y;
            ++checked;
        }
    EXPECT_EQ(checked, 6);
    expectNoGlErrors();
}

TEST(SdfMaterialTextures, TriplanarNormalMapBendsTheNormalAlongTheFaceTangent) {
    const PreparedScene flat = boxScene(R"({"base_color": [0.5, 0.5, 0.5]})", glm::vec3(0.0f));
    const PreparedScene mapped = boxScene(
        R"({"base_color": [0.5, 0.5, 0.5], "normal_texture": {"file": "tilted_normal.png"}})",
        glm::vec3(0.0f));
    const Pixels<float> flatNormals = readNormals(renderPrepared(flat, kSize, kSize));
    const Pixels<float> mappedNormals = readNormals(renderPrepared(mapped, kSize, kSize));
    // On the +z face the projection frame is T = +x, B = +y, A = +z, so the map's (0.6, 0, 0.8)
    // (texels 204, 128, 230: 0.6, 0.004, 0.804) becomes the world normal (0.6, 0, 0.8).
    for (const glm::vec3 q : {glm::vec3(0.0f, 0.0f, 0.5f), glm::vec3(-0.3f, 0.25f, 0.5f)}) {
        const glm::ivec2 pixel = pixelOf(q);
        const float* n0 = flatNormals.at(pixel.x, pixel.y);
        const float* n1 = mappedNormals.at(pixel.x, pixel.y);
        EXPECT_NEAR(n0[0], 0.0f, 0.01f);
        EXPECT_NEAR(n0[2], 1.0f, 0.01f);
        EXPECT_NEAR(n1[0], 0.6f, 0.03f);
        EXPECT_NEAR(n1[1], 0.0f, 0.03f);
        EXPECT_NEAR(n1[2], 0.8f, 0.03f);
    }
    expectNoGlErrors();
}
