// Material textures without GL: the glTF importer reads every texture kind with its sampler,
// TEXCOORD set and factors, generates tangents, and refuses bad texture references; scene
// materials' triplanar textures are read, shared, and refused with their JSON pointers when the
// file is missing, not an image, or one too many.
#include "prepare/prepared_scene.hpp"
#include "scene/gltf_geometry.hpp"
#include "scene/material_textures.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/scene_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace rmsc;
namespace fs = std::filesystem;

namespace {

const fs::path kAssets = fs::path(RMSC_TEST_SOURCE_DIR) / "samples/assets";

// A fresh folder with a copy of the sample textures in textures/.
fs::path scratchFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("rmsc_material_textures_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    fs::copy(kAssets / "textures", folder / "textures", fs::copy_options::recursive);
    return folder;
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

nlohmann::json texturedCubeJson() {
    std::ifstream in(kAssets / "textured_cube.gltf");
    return nlohmann::json::parse(in);
}

// Loads `gltf` written into a scratch folder; returns the asset (or nullopt) and diagnostics.
std::optional<MeshAsset> loadModified(const nlohmann::json& gltf, Diagnostics& diagnostics,
                                      const std::string& name) {
    const fs::path folder = scratchFolder(name);
    writeText(folder / "model.gltf", gltf.dump());
    return loadGltf(folder / "model.gltf", diskFileSource(), diagnostics);
}

bool hasMessage(const Diagnostics& d, const std::string& location, const std::string& words,
                Severity severity = Severity::Error) {
    for (const Diagnostic& item : d.items)
        if (item.severity == severity && item.location.find(location) != std::string::npos &&
            item.message.find(words) != std::string::npos)
            return true;
    return false;
}

} // namespace

TEST(MaterialTextures, GltfReadsEveryTextureKindWithSamplerAndTexCoord) {
    Diagnostics d;
    const auto asset = loadGltf(kAssets / "textured_cube.gltf", diskFileSource(), d);
    ASSERT_TRUE(asset) << d.format();
    EXPECT_FALSE(d.hasErrors()) << d.format();
    ASSERT_EQ(asset->materials.size(), 1u);
    ASSERT_EQ(asset->images.size(), 5u);
    const MeshMaterial& m = asset->materials[0];
    // textures[i] = {source i}; the file's samplers: 0 = {}, 1 = nearest/clamp, 2 = mirrored.
    EXPECT_EQ(m.baseColorTexture.image, 0);
    EXPECT_EQ(m.metallicRoughnessTexture.image, 1);
    EXPECT_EQ(m.normalTexture.image, 2);
    EXPECT_EQ(m.emissiveTexture.image, 3);
    EXPECT_EQ(m.occlusionTexture.image, 4);
    EXPECT_EQ(m.baseColorTexture.sampler.minFilter, 0x2703); // absent: linear mipmap linear
    EXPECT_EQ(m.baseColorTexture.sampler.wrapS, 10497);
    EXPECT_EQ(m.metallicRoughnessTexture.sampler.magFilter, 9728);
    EXPECT_EQ(m.metallicRoughnessTexture.sampler.minFilter, 9728);
    EXPECT_EQ(m.metallicRoughnessTexture.sampler.wrapS, 33071);
    EXPECT_EQ(m.metallicRoughnessTexture.sampler.wrapT, 33071);
    EXPECT_EQ(m.normalTexture.sampler.minFilter, 9985);
    EXPECT_EQ(m.normalTexture.sampler.wrapS, 33648);
    EXPECT_EQ(m.normalTexture.sampler.wrapT, 10497);
    EXPECT_EQ(m.emissiveTexture.sampler.wrapT, 10497); // texture without a sampler
    EXPECT_EQ(m.occlusionTexture.texCoord, 1);
    EXPECT_EQ(m.baseColorTexture.texCoord, 0);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.8f);
    EXPECT_FLOAT_EQ(m.normalScale, 1.0f);
    EXPECT_FLOAT_EQ(m.emissiveStrength, 2.0f);
    EXPECT_EQ(m.emissiveFactor, glm::vec3(1.0f));
    // Each image keeps its own size.
    EXPECT_EQ(asset->images[0].width, 256);
    EXPECT_EQ(asset->images[1].width, 64);
    EXPECT_EQ(asset->images[4].width, 32);
    // TEXCOORD_1 is the mirrored TEXCOORD_0 (make_assets.py: (1 - u, v)).
    for (const MeshVertex& v : asset->primitives.at(0).vertices) {
        EXPECT_FLOAT_EQ(v.uv1.x, 1.0f - v.uv.x);
        EXPECT_FLOAT_EQ(v.uv1.y, v.uv.y);
    }
}

TEST(MaterialTextures, GeneratedTangentsFollowPlusUAndPointTheBitangentUpTheImage) {
    Diagnostics d;
    const auto asset = loadGltf(kAssets / "textured_cube.gltf", diskFileSource(), d);
    ASSERT_TRUE(asset) << d.format();
    // make_assets.py's cube: on the face with normal sign * e[a], u grows along e[(a+1) % 3]
    // and v along e[(a+2) % 3]. So the tangent is e[(a+1) % 3]; the image's up is -dP/dv =
    // -e[(a+2) % 3], and cross(n, t) = sign * e[(a+2) % 3], so w = -sign.
    int checked = 0;
    for (const MeshVertex& v : asset->primitives.at(0).vertices) {
        int axis = 0;
        for (int i = 1; i < 3; ++i)
            if (std::abs(v.normal[i]) > std::abs(v.normal[axis])) axis = i;
        const float sign = v.normal[axis] > 0 ? 1.0f : -1.0f;
        glm::vec3 expected(0.0f);
        expected[(axis + 1) % 3] = 1.0f;
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent) - expected), 0.0f, 1e-5f);
        EXPECT_EQ(v.tangent.w, -sign);
        ++checked;
    }
    EXPECT_EQ(checked, 24);
}

TEST(MaterialTextures, TangentAttributeIsReadWhenPresent) {
    nlohmann::json gltf = texturedCubeJson();
    // A TANGENT accessor: 24 vec4 = (0, 0, 1, -1) for every vertex, appended as a data URI
    // buffer of its own.
    std::string bytes;
    for (int i = 0; i < 24; ++i) {
        const float t[4] = {0.0f, 0.0f, 1.0f, -1.0f};
        bytes.append(reinterpret_cast<const char*>(t), sizeof t);
    }
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16 |
                                std::uint32_t(std::uint8_t(bytes[i + 1])) << 8 |
                                std::uint32_t(std::uint8_t(bytes[i + 2]));
        for (int s = 18; s >= 0; s -= 6)
            b64 += table[(v >> s) & 63];
    }
    gltf["buffers"].push_back(
        {{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + b64}});
    const int buffer = int(gltf["buffers"].size()) - 1;
    gltf["bufferViews"].push_back({{"buffer", buffer}, {"byteLength", bytes.size()}});
    gltf["accessors"].push_back({{"bufferView", int(gltf["bufferViews"].size()) - 1},
                                 {"componentType", 5126},
                                 {"count", 24},
                                 {"type", "VEC4"}});
    gltf["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = int(gltf["accessors"].size()) - 1;
    Diagnostics d;
    const auto asset = loadModified(gltf, d, "tangent");
    ASSERT_TRUE(asset) << d.format();
    for (const MeshVertex& v : asset->primitives.at(0).vertices) {
        if (std::abs(v.normal.z) > 0.5f) continue; // (0, 0, 1) is re-orthogonalized away there
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent) - glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
        EXPECT_EQ(v.tangent.w, -1.0f);
    }
}

TEST(MaterialTextures, BadGltfTextureReferencesAreErrors) {
    {
        nlohmann::json gltf = texturedCubeJson();
        gltf["materials"][0]["normalTexture"]["index"] = 9;
        Diagnostics d;
        EXPECT_FALSE(loadModified(gltf, d, "index"));
        EXPECT_TRUE(hasMessage(d, "/materials/0/normalTexture/index", "")) << d.format();
    }
    {
        nlohmann::json gltf = texturedCubeJson();
        gltf["textures"][1]["sampler"] = 7;
        gltf["textures"][2]["source"] = 12;
        Diagnostics d;
        EXPECT_FALSE(loadModified(gltf, d, "sampler_source"));
        EXPECT_TRUE(hasMessage(d, "/textures/1/sampler", "")) << d.format();
        EXPECT_TRUE(hasMessage(d, "/textures/2/source", "")) << d.format();
    }
    {
        nlohmann::json gltf = texturedCubeJson();
        gltf["samplers"][1]["wrapS"] = 1234;
        gltf["samplers"][2]["magFilter"] = 9987; // a minification filter
        Diagnostics d;
        EXPECT_FALSE(loadModified(gltf, d, "sampler_values"));
        EXPECT_TRUE(hasMessage(d, "/samplers/1/wrapS", "CLAMP_TO_EDGE")) << d.format();
        EXPECT_TRUE(hasMessage(d, "/samplers/2/magFilter", "9728")) << d.format();
    }
    {
        // The occlusion texture reads TEXCOORD_1, which the primitive no longer has.
        nlohmann::json gltf = texturedCubeJson();
        gltf["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_1");
        Diagnostics d;
        EXPECT_FALSE(loadModified(gltf, d, "texcoord_missing"));
        EXPECT_TRUE(hasMessage(d, "/meshes/0/primitives/0/attributes", "TEXCOORD_1")) << d.format();
    }
    {
        nlohmann::json gltf = texturedCubeJson();
        gltf["materials"][0]["occlusionTexture"]["strength"] = 1.5;
        gltf["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
            -1;
        Diagnostics d;
        EXPECT_FALSE(loadModified(gltf, d, "factors"));
        EXPECT_TRUE(hasMessage(d, "/materials/0/occlusionTexture/strength", "0 to 1"))
            << d.format();
        EXPECT_TRUE(hasMessage(d, "emissiveStrength", ">= 0")) << d.format();
    }
    {
        // TEXCOORD_2 is valid glTF but not supported: a warning, the texture is dropped.
        nlohmann::json gltf = texturedCubeJson();
        gltf["materials"][0]["emissiveTexture"]["texCoord"] = 2;
        Diagnostics d;
        const auto asset = loadModified(gltf, d, "texcoord2");
        ASSERT_TRUE(asset) << d.format();
        EXPECT_TRUE(
            hasMessage(d, "/materials/0/emissiveTexture/texCoord", "TEXCOORD_2", Severity::Warning))
            << d.format();
        EXPECT_FALSE(asset->materials[0].emissiveTexture.present());
    }
}

TEST(MaterialTextures, LengyelTangentsOfAMirroredUvMappingFlipTheHandedness) {
    // One triangle in the xy plane, normal +z. u grows along +x; v along +y (so the image's up,
    // -dP/dv, is -y) in the first case and along -y in the second (mirrored).
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<glm::vec3> normals(3, glm::vec3(0, 0, 1));
    const std::vector<std::uint32_t> triangle = {0, 1, 2};
    const auto up = gltf::generateTangents(positions, normals, {{0, 0}, {1, 0}, {0, 1}}, triangle);
    const auto down =
        gltf::generateTangents(positions, normals, {{0, 1}, {1, 1}, {0, 0}}, triangle);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::length(glm::vec3(up[i]) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(glm::vec3(down[i]) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
        // cross(n, t) = +y. Image up is -y in the first mapping, +y in the second.
        EXPECT_EQ(up[i].w, -1.0f);
        EXPECT_EQ(down[i].w, 1.0f);
    }
}

namespace {

// Prepares a scene written into a scratch folder next to the sample textures.
std::optional<PreparedScene> prepareText(const std::string& sceneText, Diagnostics& d,
                                         const std::string& name) {
    const fs::path folder = scratchFolder(name);
    writeText(folder / "textures" / "not_an_image.png", "this is text, not a PNG");
    writeText(folder / "scene.json", sceneText);
    const FileSource files = diskFileSource();
    auto scene = loadScene(folder / "scene.json", files, d);
    if (!scene) return std::nullopt;
    return prepareScene(std::move(*scene), files, d);
}

std::string sceneWithMaterial(const std::string& material) {
    return R"({"version": 1, "materials": {"m": )" + material +
           R"(}, "sdf": {"shape": "sphere", "material": "m"}})";
}

} // namespace

TEST(MaterialTextures, SceneTexturesLoadSharedAndInTheirColourSpace) {
    Diagnostics d;
    const auto prepared = prepareText(R"({"version": 1, "materials": {
        "a": {"base_color_texture": {"file": "textures/bricks_color.png", "scale": 2,
                                     "sharpness": 6},
              "normal_texture": {"file": "textures/bricks_normal.png", "strength": 0.5},
              "roughness_texture": "textures/bricks_roughness.png"},
        "b": {"base_color_texture": "textures/bricks_color.png",
              "normal_texture": "textures/bricks_color.png"}},
        "sdf": {"shape": "sphere", "material": "a"}})",
                                      d, "load");
    ASSERT_TRUE(prepared) << d.format();
    // bricks_color as sRGB (shared by a and b), normal, roughness, bricks_color as linear.
    ASSERT_EQ(prepared->textures.size(), 4u);
    const Material& a = prepared->materials[0];
    const Material& b = prepared->materials[1];
    EXPECT_EQ(a.baseColorTexture.image, b.baseColorTexture.image);
    EXPECT_NE(b.normalTexture.image, b.baseColorTexture.image);
    EXPECT_TRUE(prepared->textures[std::size_t(a.baseColorTexture.image)].srgb);
    EXPECT_FALSE(prepared->textures[std::size_t(a.normalTexture.image)].srgb);
    EXPECT_FALSE(prepared->textures[std::size_t(b.normalTexture.image)].srgb);
    EXPECT_FLOAT_EQ(a.baseColorTexture.scale, 2.0f);
    EXPECT_FLOAT_EQ(a.baseColorTexture.sharpness, 6.0f);
    EXPECT_FLOAT_EQ(a.normalTexture.strength, 0.5f);
    EXPECT_EQ(prepared->textures[std::size_t(a.roughnessTexture.image)].image.width, 256);
}

TEST(MaterialTextures, MissingTextureFileNamesThePointer) {
    Diagnostics d;
    EXPECT_FALSE(prepareText(
        sceneWithMaterial(R"({"base_color_texture": {"file": "textures/nowhere.png"}})"), d,
        "missing"));
    EXPECT_TRUE(hasMessage(d, "/materials/m/base_color_texture/file", "cannot read texture"))
        << d.format();
}

TEST(MaterialTextures, TextureThatIsNotAnImageNamesThePointer) {
    Diagnostics d;
    EXPECT_FALSE(prepareText(
        sceneWithMaterial(R"({"normal_texture": "textures/not_an_image.png"})"), d, "not_image"));
    EXPECT_TRUE(hasMessage(d, "/materials/m/normal_texture", "not a usable image")) << d.format();
}

TEST(MaterialTextures, TextureFieldsAreChecked) {
    Diagnostics d;
    EXPECT_FALSE(prepareText(sceneWithMaterial(R"({
        "base_color_texture": {"scale": 2},
        "normal_texture": {"file": "textures/bricks_normal.png", "sharpness": 0.5},
        "roughness_texture": 3})"),
                             d, "fields"));
    EXPECT_TRUE(hasMessage(d, "/materials/m/base_color_texture", "\"file\"")) << d.format();
    EXPECT_TRUE(hasMessage(d, "/materials/m/normal_texture/sharpness", "")) << d.format();
    EXPECT_TRUE(hasMessage(d, "/materials/m/roughness_texture", "texture object")) << d.format();
}

TEST(MaterialTextures, OneTextureTooManyNamesTheLimit) {
    // Each file in two colour spaces: 10 distinct textures from 5 files (limit 8).
    std::string materials;
    const char* files[] = {"bricks_color", "bricks_normal", "bricks_roughness", "tiles_color",
                           "test_emissive"};
    for (int i = 0; i < 5; ++i) {
        if (i) materials += ",";
        materials += "\"m" + std::to_string(i) + "\": {\"base_color_texture\": \"textures/" +
                     files[i] + ".png\", \"normal_texture\": \"textures/" + files[i] + ".png\"}";
    }
    Diagnostics d;
    EXPECT_FALSE(prepareText(R"({"version": 1, "materials": {)" + materials + "}}", d, "many"));
    // m0..m3 fill the 8 units; both of m4's textures are reported, nothing else.
    EXPECT_TRUE(hasMessage(d, "/materials/m4/base_color_texture", "at most 8")) << d.format();
    EXPECT_TRUE(hasMessage(d, "/materials/m4/normal_texture", "at most 8")) << d.format();
    EXPECT_EQ(d.errorCount(), 2) << d.format();
}
