// glTF material settings as exporters write them: alphaMode and alphaCutoff, doubleSided,
// KHR_texture_transform (offset, rotation, scale, texCoord override: the matrix the extension
// defines) and KHR_materials_unlit, with their refusals; and TextureTransformTest's values
// (AlphaBlendModeTest is checked where it is drawn, tests/gpu/test_gltf_samples.cpp).
#include "gltf_builder.hpp"
#include "scene/mesh_asset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

using namespace rmsc;
using namespace rmsc::test;
using nlohmann::json;

namespace {

// A 1x1 PNG (opaque white), as a data URI.
const char* kPixel =
    "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAAC0lEQVR4"
    "nGP4DwQACfsD/fteaysAAAAASUVORK5CYII=";

// One triangle with TEXCOORD_0 and TEXCOORD_1 and the material `material`.
std::optional<MeshAsset> loadMaterial(const json& material, Diagnostics& d,
                                      const json& extra = json::object()) {
    GltfBuilder b;
    const std::vector<float> uvs = {0, 0, 1, 0, 0, 1};
    const int p = b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloatType, "VEC3", 3);
    const int uv0 = b.accessor(uvs, kFloatType, "VEC2", 3);
    const int uv1 = b.accessor(uvs, kFloatType, "VEC2", 3);
    json gltf = {{"scenes", {{{"nodes", {0}}}}},
                 {"scene", 0},
                 {"nodes", {{{"mesh", 0}}}},
                 {"images", {{{"uri", kPixel}}}},
                 {"textures", {{{"source", 0}}}},
                 {"materials", {material}},
                 {"meshes",
                  {{{"primitives",
                     {{{"attributes", {{"POSITION", p}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}}},
                       {"material", 0}}}}}}}};
    gltf.merge_patch(extra);
    return loadGltf("mem/test.gltf", memoryGltf(b.text(gltf)), d);
}

} // namespace

TEST(GltfMaterials, AlphaModesAndCutoff) {
    struct Case {
        json material;
        AlphaMode mode;
        float cutoff;
    };
    for (const Case& c :
         {Case{json::object(), AlphaMode::Opaque, 0.5f},
          Case{{{"alphaMode", "MASK"}}, AlphaMode::Mask, 0.5f},
          Case{{{"alphaMode", "MASK"}, {"alphaCutoff", 0.25}}, AlphaMode::Mask, 0.25f},
          Case{{{"alphaMode", "BLEND"}}, AlphaMode::Blend, 0.5f}}) {
        Diagnostics d;
        const auto asset = loadMaterial(c.material, d);
        ASSERT_TRUE(asset) << d.format();
        EXPECT_EQ(asset->materials.at(0).alphaMode, c.mode) << c.material.dump();
        EXPECT_FLOAT_EQ(asset->materials.at(0).alphaCutoff, c.cutoff);
    }
}

TEST(GltfMaterials, BadAlphaModeOrCutoffIsRefused) {
    for (const auto& [material, pointer] :
         {std::pair{json{{"alphaMode", "CLIP"}}, "/materials/0/alphaMode"},
          std::pair{json{{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}},
                    "/materials/0/alphaCutoff"}}) {
        Diagnostics d;
        EXPECT_FALSE(loadMaterial(material, d));
        ASSERT_GE(d.errorCount(), 1) << d.format();
        bool found = false;
        for (const Diagnostic& item : d.items)
            found = found || item.location == pointer;
        EXPECT_TRUE(found) << pointer << ": " << d.format();
    }
}

TEST(GltfMaterials, DoubleSidedAndUnlit) {
    Diagnostics d;
    auto asset = loadMaterial(
        {{"doubleSided", true}, {"extensions", {{"KHR_materials_unlit", json::object()}}}}, d,
        {{"extensionsUsed", {"KHR_materials_unlit"}}});
    ASSERT_TRUE(asset) << d.format();
    EXPECT_EQ(d.items.size(), 0u) << d.format();
    EXPECT_TRUE(asset->materials.at(0).doubleSided);
    EXPECT_TRUE(asset->materials.at(0).unlit);
    asset = loadMaterial(json::object(), d);
    ASSERT_TRUE(asset);
    EXPECT_FALSE(asset->materials.at(0).doubleSided);
    EXPECT_FALSE(asset->materials.at(0).unlit);
}

TEST(GltfMaterials, TextureTransformIsTheExtensionsMatrix) {
    const json transform = {{"offset", {0.5, -0.25}},
                            {"rotation", std::numbers::pi / 2},
                            {"scale", {2, 3}},
                            {"texCoord", 1}};
    Diagnostics d;
    const auto asset =
        loadMaterial({{"pbrMetallicRoughness",
                       {{"baseColorTexture",
                         {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}},
                      {"emissiveTexture", {{"index", 0}}}},
                     d, {{"extensionsUsed", {"KHR_texture_transform"}}});
    ASSERT_TRUE(asset) << d.format();
    const MeshMaterial& m = asset->materials.at(0);
    EXPECT_EQ(m.baseColorTexture.texCoord, 1); // the extension's texCoord wins
    EXPECT_EQ(m.emissiveTexture.texCoord, 0);
    // translation * rotation * scale with rotation pi / 2: (u, v) -> (3 v + 0.5, -2 u - 0.25).
    const glm::vec2 u = m.baseColorTexture.transform.apply({1, 0});
    const glm::vec2 v = m.baseColorTexture.transform.apply({0, 1});
    EXPECT_NEAR(u.x, 0.5f, 1e-6f);
    EXPECT_NEAR(u.y, -2.25f, 1e-6f);
    EXPECT_NEAR(v.x, 3.5f, 1e-6f);
    EXPECT_NEAR(v.y, -0.25f, 1e-6f);
    // Without the extension the identity.
    EXPECT_EQ(m.emissiveTexture.transform.apply({0.3f, 0.7f}), glm::vec2(0.3f, 0.7f));
}

TEST(GltfMaterials, BadTextureTransformIsRefusedAtItsPointer) {
    Diagnostics d;
    EXPECT_FALSE(loadMaterial(
        {{"normalTexture",
          {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {1}}}}}}}}},
        d));
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location,
              "/materials/0/normalTexture/extensions/KHR_texture_transform/scale");
}

TEST(GltfMaterials, TextureTransformSampleRotatesAndScales) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    Diagnostics d;
    const auto asset = loadGltf(gltfSamples() / "TextureTransformTest.gltf", diskFileSource(), d);
    ASSERT_TRUE(asset) << d.format();
    std::map<std::string, const MeshMaterial*> byName;
    for (const MeshMaterial& m : asset->materials)
        byName[m.name] = &m;
    ASSERT_TRUE(byName.count("Rotation") && byName.count("Scale") && byName.count("Offset U"));
    // The README: the arrow rotated by 22.5 degrees, scaled 1.5x; offsets shift U.
    EXPECT_NEAR(byName["Rotation"]->baseColorTexture.transform.rotation,
                22.5f * std::numbers::pi_v<float> / 180.0f, 1e-4f);
    EXPECT_FLOAT_EQ(byName["Scale"]->baseColorTexture.transform.scale.x, 1.5f);
    EXPECT_NE(byName["Offset U"]->baseColorTexture.transform.offset.x, 0.0f);
}
