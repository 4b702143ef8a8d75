// glTF vertex data as exporters write it: COLOR_0 in each of its formats, KHR_mesh_quantization
// (integer and normalized integer positions, normals, texture coordinates: a quantized cube
// matches the float one exactly) and sparse accessors, with their refusals.
#include "gltf_builder.hpp"
#include "scene/mesh_asset.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;
using nlohmann::json;

namespace {

// One primitive of `attributes` (names -> accessor indices) on node 0 with `node` merged in.
std::string meshGltf(const GltfBuilder& b, const json& attributes, const json& extra = {},
                     const json& node = json::object()) {
    json n = {{"mesh", 0}};
    n.merge_patch(node);
    json gltf = {{"scenes", {{{"nodes", {0}}}}},
                 {"scene", 0},
                 {"nodes", {n}},
                 {"meshes", {{{"primitives", {{{"attributes", attributes}}}}}}}};
    if (!extra.is_null()) gltf.merge_patch(extra);
    return b.text(gltf);
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

} // namespace

TEST(GltfVertexColors, Vec3FloatMultipliesWithAlphaOne) {
    GltfBuilder b;
    const int p = b.accessor(kTriangle, kFloatType, "VEC3", 3);
    const int c =
        b.accessor(std::vector<float>{1, 0, 0, 0, 0.5f, 0, 0.25f, 0.25f, 1}, kFloatType, "VEC3", 3);
    Diagnostics d;
    const auto asset = loadGltfText(meshGltf(b, {{"POSITION", p}, {"COLOR_0", c}}), d);
    ASSERT_TRUE(asset) << d.format();
    const auto& v = asset->primitives.at(0).vertices;
    EXPECT_EQ(v[0].color, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(v[1].color, glm::vec4(0, 0.5f, 0, 1));
    EXPECT_EQ(v[2].color, glm::vec4(0.25f, 0.25f, 1, 1));
}

TEST(GltfVertexColors, NormalizedIntegersDecodeToUnitRange) {
    GltfBuilder b;
    const int p = b.accessor(kTriangle, kFloatType, "VEC3", 3);
    const int c8 =
        b.accessor(std::vector<std::uint8_t>{255, 0, 51, 102, 0, 255, 0, 0, 0, 0, 255, 255},
                   kUnsignedByte, "VEC4", 3, true);
    const int c16 = b.accessor(
        std::vector<std::uint16_t>{65535, 0, 0, 65535, 0, 0, 0, 0, 13107, 13107, 13107, 65535},
        kUnsignedShort, "VEC4", 3, true);
    for (const int c : {c8, c16}) {
        Diagnostics d;
        const auto asset = loadGltfText(meshGltf(b, {{"POSITION", p}, {"COLOR_0", c}}), d);
        ASSERT_TRUE(asset) << d.format();
        const auto& v = asset->primitives.at(0).vertices;
        EXPECT_FLOAT_EQ(v[0].color.x, 1.0f);
        if (c == c8) {
            EXPECT_FLOAT_EQ(v[0].color.z, 0.2f); // 51 / 255
            EXPECT_FLOAT_EQ(v[0].color.w, 0.4f); // 102 / 255
            EXPECT_EQ(v[1].color, glm::vec4(0, 1, 0, 0));
        } else {
            EXPECT_EQ(v[0].color, glm::vec4(1, 0, 0, 1));
            EXPECT_FLOAT_EQ(v[2].color.y, 0.2f); // 13107 / 65535
        }
        EXPECT_FLOAT_EQ(v[2].color.w, 1.0f);
    }
}

TEST(GltfVertexColors, AbsentMeansWhite) {
    GltfBuilder b;
    const int p = b.accessor(kTriangle, kFloatType, "VEC3", 3);
    Diagnostics d;
    const auto asset = loadGltfText(meshGltf(b, {{"POSITION", p}}), d);
    ASSERT_TRUE(asset) << d.format();
    for (const MeshVertex& v : asset->primitives.at(0).vertices)
        EXPECT_EQ(v.color, glm::vec4(1.0f));
}

TEST(GltfVertexColors, SignedOrUnnormalizedIntegersAreRefused) {
    GltfBuilder b;
    const int p = b.accessor(kTriangle, kFloatType, "VEC3", 3);
    const int c =
        b.accessor(std::vector<std::int8_t>{1, 2, 3, 4, 5, 6, 7, 8, 9}, kByte, "VEC3", 3, true);
    Diagnostics d;
    EXPECT_FALSE(loadGltfText(meshGltf(b, {{"POSITION", p}, {"COLOR_0", c}}), d));
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location, "/accessors/1");
    EXPECT_NE(d.items[0].message.find("COLOR_0"), std::string::npos) << d.format();
    EXPECT_NE(d.items[0].message.find("normalized UNSIGNED_BYTE"), std::string::npos);
}

TEST(GltfVertexColors, SampleHasColouredChecks) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    Diagnostics d;
    const auto asset = loadGltf(gltfSamples() / "VertexColorTest.gltf", diskFileSource(), d);
    ASSERT_TRUE(asset) << d.format();
    // The checks' mesh is the one with COLOR_0: red, green and blue vertices among white.
    int red = 0, green = 0, blue = 0;
    for (const MeshPrimitive& p : asset->primitives)
        for (const MeshVertex& v : p.vertices) {
            red += v.color.x > 0.9f && v.color.y < 0.1f && v.color.z < 0.1f;
            green += v.color.y > 0.9f && v.color.x < 0.1f && v.color.z < 0.1f;
            blue += v.color.z > 0.9f && v.color.x < 0.1f && v.color.y < 0.1f;
        }
    EXPECT_GT(red, 0);
    EXPECT_GT(green, 0);
    EXPECT_GT(blue, 0);
}

namespace {

// A unit cube's 8 corners (+-1) and its 12 triangles, counter-clockwise from outside.
const std::vector<float> kCorners = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                     -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
const std::vector<std::uint16_t> kCubeIndices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7,
                                                 0, 1, 5, 0, 5, 4, 3, 6, 2, 3, 7, 6,
                                                 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};

std::string cubeGltf(bool quantized) {
    GltfBuilder b;
    json attributes;
    json node = json::object();
    if (quantized) {
        // Positions as SHORT integers scaled by the node (gltfpack's way), normals as
        // normalized BYTE, texture coordinates as normalized UNSIGNED_SHORT.
        std::vector<std::int16_t> positions;
        for (float c : kCorners)
            positions.push_back(std::int16_t(c * 2));
        attributes["POSITION"] = b.accessor(positions, kShort, "VEC3", 8);
        std::vector<std::int8_t> normals;
        for (float c : kCorners)
            normals.push_back(std::int8_t(c * 73)); // (+-73, +-73, +-73): the corner direction
        attributes["NORMAL"] = b.accessor(normals, kByte, "VEC3", 8, true);
        std::vector<std::uint16_t> uvs;
        for (std::size_t i = 0; i < 8; ++i)
            uvs.insert(uvs.end(),
                       {std::uint16_t(i % 2 ? 65535 : 0), std::uint16_t(i < 4 ? 0 : 65535)});
        attributes["TEXCOORD_0"] = b.accessor(uvs, kUnsignedShort, "VEC2", 8, true);
        node = {{"scale", {0.5, 0.5, 0.5}}};
    } else {
        attributes["POSITION"] = b.accessor(kCorners, kFloatType, "VEC3", 8);
        std::vector<float> normals;
        for (float c : kCorners)
            normals.push_back(c * 73.0f / 127.0f);
        attributes["NORMAL"] = b.accessor(normals, kFloatType, "VEC3", 8);
        std::vector<float> uvs;
        for (std::size_t i = 0; i < 8; ++i)
            uvs.insert(uvs.end(), {i % 2 ? 1.0f : 0.0f, i < 4 ? 0.0f : 1.0f});
        attributes["TEXCOORD_0"] = b.accessor(uvs, kFloatType, "VEC2", 8);
    }
    const int indices = b.accessor(kCubeIndices, kUnsignedShort, "SCALAR", kCubeIndices.size());
    json gltf = {
        {"scenes", {{{"nodes", {0}}}}},
        {"scene", 0},
        {"nodes", {json({{"mesh", 0}})}},
        {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", indices}}}}}}}};
    gltf["nodes"][0].merge_patch(node);
    if (quantized) {
        gltf["extensionsUsed"] = {"KHR_mesh_quantization"};
        gltf["extensionsRequired"] = {"KHR_mesh_quantization"};
    }
    return b.text(gltf);
}

} // namespace

TEST(GltfQuantization, QuantizedCubeMatchesTheFloatCubeExactly) {
    Diagnostics d1, d2;
    const auto reference = loadGltfText(cubeGltf(false), d1);
    const auto quantized = loadGltfText(cubeGltf(true), d2);
    ASSERT_TRUE(reference) << d1.format();
    ASSERT_TRUE(quantized) << d2.format();
    EXPECT_EQ(d2.items.size(), 0u) << d2.format();
    const auto& a = reference->primitives.at(0);
    const auto& q = quantized->primitives.at(0);
    // The float cube is at +-1 with no node scale; the quantized one stores +-2 and the node
    // halves it, so both are exactly +-1 (0.5 * 2 is exact in binary floating point).
    ASSERT_EQ(a.vertices.size(), q.vertices.size());
    EXPECT_EQ(a.indices, q.indices);
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
        EXPECT_EQ(a.vertices[i].position, q.vertices[i].position) << i;
        EXPECT_EQ(a.vertices[i].normal, q.vertices[i].normal) << i;
        EXPECT_EQ(a.vertices[i].uv, q.vertices[i].uv) << i;
    }
    EXPECT_EQ(reference->boundsMin, quantized->boundsMin);
    EXPECT_EQ(reference->boundsMax, quantized->boundsMax);
}

TEST(GltfQuantization, IntegerPositionsWithoutTheExtensionAreRefusedNamingIt) {
    std::string text = cubeGltf(true);
    json gltf = json::parse(text);
    gltf.erase("extensionsUsed");
    gltf.erase("extensionsRequired");
    Diagnostics d;
    EXPECT_FALSE(loadGltfText(gltf.dump(), d));
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location, "/accessors/0");
    EXPECT_NE(d.items[0].message.find("KHR_mesh_quantization"), std::string::npos) << d.format();
}

TEST(GltfQuantization, SignedNormalizedDecodesAsTheSpecificationSays) {
    // max(c / 127, -1): -128 and -127 are both -1; 127 is 1; 0 is 0.
    GltfBuilder b;
    const int p = b.accessor(std::vector<std::int8_t>{-128, 0, 127, -127, 64, 0, 0, 0, 0, 0, 0, 0},
                             kByte, "VEC3", 3, true);
    Diagnostics d;
    const auto asset = loadGltfText(
        meshGltf(b, {{"POSITION", p}}, {{"extensionsUsed", {"KHR_mesh_quantization"}}}), d);
    ASSERT_TRUE(asset) << d.format();
    const auto& v = asset->primitives.at(0).vertices;
    EXPECT_EQ(v[0].position, glm::vec3(-1, 0, 1));
    EXPECT_EQ(v[1].position, glm::vec3(-1, 64.0f / 127.0f, 0));
}

TEST(GltfSparse, SubstitutesTheListedElements) {
    // A base of three points and a sparse substitution of elements 0 and 2 (the way
    // SimpleSparseAccessor raises part of a grid).
    GltfBuilder b;
    const int base = b.view(kTriangle);
    const int indices = b.view(std::vector<std::uint16_t>{0, 2});
    const int values = b.view(std::vector<float>{5, 5, 5, 7, 7, 7});
    b.accessors.push_back(
        {{"bufferView", base},
         {"componentType", kFloatType},
         {"type", "VEC3"},
         {"count", 3},
         {"sparse",
          {{"count", 2},
           {"indices", {{"bufferView", indices}, {"componentType", kUnsignedShort}}},
           {"values", {{"bufferView", values}}}}}});
    Diagnostics d;
    const auto asset = loadGltfText(meshGltf(b, {{"POSITION", 0}}), d);
    ASSERT_TRUE(asset) << d.format();
    const auto& v = asset->primitives.at(0).vertices;
    EXPECT_EQ(v[0].position, glm::vec3(5, 5, 5));
    EXPECT_EQ(v[1].position, glm::vec3(1, 0, 0));
    EXPECT_EQ(v[2].position, glm::vec3(7, 7, 7));
}

TEST(GltfSparse, WithoutABufferViewTheBaseIsZeros) {
    GltfBuilder b;
    const int indices = b.view(std::vector<std::uint8_t>{1, 0, 0, 0});
    const int values = b.view(std::vector<float>{0, 2, 0});
    b.accessors.push_back(
        {{"componentType", kFloatType},
         {"type", "VEC3"},
         {"count", 3},
         {"sparse",
          {{"count", 1},
           {"indices", {{"bufferView", indices}, {"componentType", kUnsignedByte}}},
           {"values", {{"bufferView", values}}}}}});
    b.accessors.push_back({{"bufferView", b.view(kTriangle)},
                           {"componentType", kFloatType},
                           {"type", "VEC3"},
                           {"count", 3}});
    Diagnostics d;
    const auto asset = loadGltfText(meshGltf(b, {{"POSITION", 1}, {"NORMAL", 0}}), d);
    ASSERT_TRUE(asset) << d.format();
    const auto& v = asset->primitives.at(0).vertices;
    EXPECT_EQ(v[1].normal, glm::vec3(0, 1, 0)); // (0, 2, 0) normalized by the bake
}

TEST(GltfSparse, IndicesOutOfOrderOrOutOfRangeAreRefused) {
    for (const std::vector<std::uint16_t>& order :
         {std::vector<std::uint16_t>{2, 1}, std::vector<std::uint16_t>{0, 3}}) {
        GltfBuilder b;
        const int base = b.view(kTriangle);
        const int indices = b.view(order);
        const int values = b.view(std::vector<float>{5, 5, 5, 7, 7, 7});
        b.accessors.push_back(
            {{"bufferView", base},
             {"componentType", kFloatType},
             {"type", "VEC3"},
             {"count", 3},
             {"sparse",
              {{"count", 2},
               {"indices", {{"bufferView", indices}, {"componentType", kUnsignedShort}}},
               {"values", {{"bufferView", values}}}}}});
        Diagnostics d;
        EXPECT_FALSE(loadGltfText(meshGltf(b, {{"POSITION", 0}}), d));
        ASSERT_EQ(d.errorCount(), 1) << d.format();
        EXPECT_EQ(d.items[0].location, "/accessors/0/sparse/indices") << d.format();
        EXPECT_NE(d.items[0].message.find("strictly increasing"), std::string::npos);
    }
}

TEST(GltfSparse, ValuesPastTheirViewAreRefused) {
    GltfBuilder b;
    const int base = b.view(kTriangle);
    const int indices = b.view(std::vector<std::uint16_t>{0, 2});
    const int values = b.view(std::vector<float>{5, 5, 5}); // one value for two indices
    b.accessors.push_back(
        {{"bufferView", base},
         {"componentType", kFloatType},
         {"type", "VEC3"},
         {"count", 3},
         {"sparse",
          {{"count", 2},
           {"indices", {{"bufferView", indices}, {"componentType", kUnsignedShort}}},
           {"values", {{"bufferView", values}}}}}});
    Diagnostics d;
    EXPECT_FALSE(loadGltfText(meshGltf(b, {{"POSITION", 0}}), d));
    ASSERT_GE(d.errorCount(), 1) << d.format();
    EXPECT_EQ(d.items[0].location, "/accessors/0/sparse/values") << d.format();
}
