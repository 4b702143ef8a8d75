// glTF files built to cost time or memory out of proportion to their size, against the load
// budget (vertices, indices, texels, buffer bytes; per file and per scene) that is checked
// before anything is allocated: accessors without buffer views, images listed many times or
// larger than their bytes, buffers listed several times, roots listed thousands of times. Also
// KHR_lights_punctual lights without a type. The scene texel budget also holds material
// textures and the sky image.
#include "core/limits.hpp"
#include "scene/material_textures.hpp"
#include "scene/mesh_asset.hpp"
#include "scene/sky_image.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <map>
#include <set>

using namespace rmsc;
using nlohmann::json;

namespace {

const char* kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(const std::string& bytes) {
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 2]));
        out += kBase64[(v >> 18) & 63];
        out += kBase64[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kBase64[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kBase64[v & 63] : '=';
    }
    return out;
}

void bigEndian32(std::string& out, std::uint32_t v) {
    for (int i = 3; i >= 0; --i)
        out += char((v >> (8 * i)) & 0xff);
}

std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char c : bytes) {
        crc ^= c;
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void pngChunk(std::string& png, const std::string& type, const std::string& data) {
    bigEndian32(png, std::uint32_t(data.size()));
    png += type + data;
    bigEndian32(png, crc32(type + data));
}

// A valid greyscale PNG of `width` x `height` zeros (stored, uncompressed deflate); with
// `headerOnly`, its signature and IHDR alone, claiming that size.
std::string png(std::uint32_t width, std::uint32_t height, bool headerOnly = false) {
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string header;
    bigEndian32(header, width);
    bigEndian32(header, height);
    header += std::string("\x08\x00\x00\x00\x00", 5);
    pngChunk(png, "IHDR", header);
    if (headerOnly) return png;
    const std::string raw(std::size_t(height) * (width + 1), '\0'); // filter byte 0 per row
    std::string zlib = "\x78\x01";
    zlib += '\x01'; // one final stored block (raw is small)
    const auto n = std::uint16_t(raw.size());
    zlib += char(n & 0xff);
    zlib += char(n >> 8);
    zlib += char(~n & 0xff);
    zlib += char((~n >> 8) & 0xff);
    zlib += raw;
    std::uint32_t a = 1, b = 0;
    for (unsigned char c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    bigEndian32(zlib, b << 16 | a);
    pngChunk(png, "IDAT", zlib);
    pngChunk(png, "IEND", "");
    return png;
}

// One triangle (node 0 draws mesh 0) in a data URI buffer.
json triangle() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string bytes(reinterpret_cast<const char*>(positions), sizeof positions);
    return {{"asset", {{"version", "2.0"}}},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
            {"accessors",
             {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
            {"bufferViews", {{{"buffer", 0}, {"byteLength", bytes.size()}}}},
            {"buffers",
             {{{"byteLength", bytes.size()},
               {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}}};
}

// Files in memory; every path asked for is recorded in `asked`.
struct MemoryFiles {
    std::map<std::string, std::string> files;
    std::shared_ptr<std::set<std::string>> asked = std::make_shared<std::set<std::string>>();

    FileSource source() const {
        return {[files = files, asked = asked](const std::filesystem::path& path,
                                               std::string& error) -> std::optional<std::string> {
            asked->insert(path.generic_string());
            const auto it = files.find(path.generic_string());
            if (it != files.end()) return it->second;
            error = "no such file";
            return std::nullopt;
        }};
    }
};

std::optional<MeshAsset> load(const json& gltf, Diagnostics& d, MemoryFiles files = {},
                              GltfBudget* budget = nullptr) {
    files.files["mem/model.gltf"] = gltf.dump();
    if (budget) return loadGltf("mem/model.gltf", files.source(), d, *budget);
    return loadGltf("mem/model.gltf", files.source(), d);
}

// The one error of `d`: at `location`, containing `words`.
void expectError(const Diagnostics& d, const std::string& location, const std::string& words) {
    ASSERT_EQ(d.errorCount(), 1) << d.format();
    for (const Diagnostic& item : d.items) {
        if (item.severity != Severity::Error) continue;
        EXPECT_EQ(item.file, "mem/model.gltf");
        EXPECT_EQ(item.location, location) << d.format();
        EXPECT_NE(item.message.find(words), std::string::npos)
            << "message: " << item.message << "\nexpected to contain: " << words;
    }
}

} // namespace

TEST(GltfHostile, VerticesOfEveryInstanceAreCountedBeforeAnyIsRead) {
    // 64 primitives of 16 Mi - 1 vertices each, in an accessor without a buffer view: 600 bytes
    // of JSON claiming a billion vertices. Refused before a vertex is allocated.
    json gltf = triangle();
    gltf["accessors"].push_back(
        {{"componentType", 5126}, {"count", (16u << 20) - 1}, {"type", "VEC3"}});
    gltf["meshes"][0]["primitives"] = json::array();
    for (int i = 0; i < 64; ++i)
        gltf["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 1}}}});
    Diagnostics d;
    EXPECT_FALSE(load(gltf, d));
    expectError(d, "/nodes/0",
                "instancing /meshes/0 here brings the file's scene to 1073741760 vertices, more "
                "than the 16777216 allowed per glTF file (the limit \"glTF vertices\" in "
                "docs/limits.md)");
}

TEST(GltfHostile, IndicesOfStripsAreCountedAsTheTrianglesTheyBecome) {
    // A strip of n vertices becomes 3 (n - 2) triangle indices: 4 become 6.
    json gltf = triangle();
    gltf["accessors"].push_back({{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    gltf["meshes"][0]["primitives"][0] = {{"attributes", {{"POSITION", 1}}}, {"mode", 5}};
    GltfBudget budget;
    budget.indices = 5;
    Diagnostics d;
    EXPECT_FALSE(load(gltf, d, {}, &budget));
    expectError(d, "/nodes/0", "6 indices, more than the 5 left of the scene's 100663296");
    budget.indices = 6;
    Diagnostics fits;
    EXPECT_TRUE(load(gltf, fits, {}, &budget)) << fits.format();
    EXPECT_EQ(budget.indices, 0u);
}

TEST(GltfHostile, TheSceneBudgetIsSharedByItsFiles) {
    json gltf = triangle();
    gltf["nodes"].push_back({{"mesh", 0}});
    gltf["scenes"][0]["nodes"] = {0, 1};
    GltfBudget budget;
    Diagnostics d;
    ASSERT_TRUE(load(gltf, d, {}, &budget)) << d.format();
    EXPECT_EQ(budget.vertices, limits::kSceneGltfVertices - 6);
    EXPECT_EQ(budget.indices, limits::kSceneGltfIndices - 6);
    EXPECT_EQ(budget.texels, limits::kSceneTexels);

    // With 5 vertices left, the second instance goes over: refused there, nothing taken.
    budget.vertices = 5;
    Diagnostics over;
    EXPECT_FALSE(load(gltf, over, {}, &budget));
    expectError(over, "/nodes/1",
                "6 vertices, more than the 5 left of the scene's 33554432 for all its glTF files "
                "together (the limit \"Scene glTF vertices\" in docs/limits.md)");
    EXPECT_EQ(budget.vertices, 5u);
}

TEST(GltfHostile, AnImageListedManyTimesIsDecodedOnce) {
    const std::string uri = "data:image/png;base64," + base64(png(4, 2));
    json gltf = triangle();
    MemoryFiles files;
    files.files["mem/a.png"] = png(2, 2);
    // Images 0 to 2: one data URI; 3 and 4: one file, written two ways; 5: another copy of the
    // same bytes under another name, which is a different image.
    gltf["images"] = {{{"uri", uri}},     {{"uri", uri}},       {{"uri", uri}},
                      {{"uri", "a.png"}}, {{"uri", "./a.png"}}, {{"uri", "b.png"}}};
    files.files["mem/b.png"] = png(2, 2);
    gltf["textures"] = json::array();
    gltf["materials"] = json::array();
    for (int i = 0; i < 6; ++i) {
        gltf["textures"].push_back({{"source", i}});
        gltf["materials"].push_back(
            {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
    }
    GltfBudget budget;
    Diagnostics d;
    const auto asset = load(gltf, d, files, &budget);
    ASSERT_TRUE(asset) << d.format();
    ASSERT_EQ(asset->images.size(), 3u);
    EXPECT_EQ(asset->images[0].width, 4);
    const int expected[6] = {0, 0, 0, 1, 1, 2};
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(asset->materials[std::size_t(i)].baseColorTexture.image, expected[i]) << i;
    EXPECT_EQ(budget.texels, limits::kSceneTexels - (8 + 4 + 4));
}

TEST(GltfHostile, TexelsAreCheckedFromTheHeaderBeforeDecoding) {
    // The image claims 8192 x 8192 but holds no pixels: the budget refuses it on its header
    // (a decoder would only fail after allocating).
    json gltf = triangle();
    gltf["images"] = {{{"uri", "data:image/png;base64," + base64(png(8192, 8192, true))}}};
    GltfBudget budget;
    budget.texels = 1000;
    Diagnostics d;
    EXPECT_FALSE(load(gltf, d, {}, &budget));
    expectError(d, "/images/0",
                "image is 8192x8192, which brings the file's images to 67108864 texels, more than "
                "the 1000 left of the scene's 268435456 for all its glTF files together");

    // Two distinct images of 8192 x 8192 fit one file's budget, a third does not.
    json three = triangle();
    MemoryFiles files;
    for (const char* name : {"a.png", "b.png", "c.png"}) {
        three["images"].push_back({{"uri", name}});
        files.files[std::string("mem/") + name] = png(8192, 8192, true);
    }
    Diagnostics over;
    EXPECT_FALSE(load(three, over, files));
    // a.png and b.png pass the budget and fail to decode (no pixels); c.png is over it.
    bool budgetError = false;
    for (const Diagnostic& item : over.items)
        if (item.location == "/images/2/uri")
            budgetError =
                item.message.find("201326592 texels, more than the 134217728 allowed "
                                  "per glTF file (the limit \"glTF texels\"") != std::string::npos;
    EXPECT_TRUE(budgetError) << over.format();
}

TEST(GltfHostile, ImagesTooLargeForTheDecoderAreCalledTooLarge) {
    // stb_image cannot describe a 60000 x 60000 PNG (it refuses the size, then says "unknown
    // image type" having tried every other format).
    json gltf = triangle();
    gltf["images"] = {{{"uri", "data:image/png;base64," + base64(png(60000, 60000, true))}}};
    Diagnostics d;
    EXPECT_FALSE(load(gltf, d));
    expectError(d, "/images/0", "image is 60000x60000, expected at most 8192 on each side");

    // The same for a JPEG frame header (start of image, then a baseline start-of-frame).
    const std::string jpeg = std::string("\xff\xd8\xff\xc0\x00\x11\x08\xea\x60\xea\x60\x03", 12) +
                             std::string(12, '\x11');
    gltf["images"] = {{{"uri", "data:image/jpeg;base64," + base64(jpeg)}}};
    Diagnostics j;
    EXPECT_FALSE(load(gltf, j));
    expectError(j, "/images/0", "image is 60000x60000, expected at most 8192 on each side");
}

TEST(GltfHostile, BuffersAreBudgetedFromTheirByteLengthBeforeAnyIsRead) {
    // One 600 MiB file listed twice: 1.2 GiB of buffers. Refused at the second, unread.
    json gltf = triangle();
    for (int i = 0; i < 2; ++i)
        gltf["buffers"].push_back({{"byteLength", 600u << 20}, {"uri", "big.bin"}});
    MemoryFiles files;
    files.files["mem/big.bin"] = "small";
    Diagnostics d;
    EXPECT_FALSE(load(gltf, d, files));
    expectError(d, "/buffers/2/byteLength",
                "this buffer brings the file's buffers to 1258291236 bytes, more than the "
                "1073741824 allowed per glTF file (the limit \"glTF buffer bytes\"");
    EXPECT_EQ(files.asked->count("mem/big.bin"), 0u);
}

TEST(GltfHostile, ARootListedThousandsOfTimesIsReportedOnce) {
    json gltf = triangle();
    gltf["nodes"].push_back(json::object());
    gltf["scenes"][0]["nodes"] = json::array();
    for (int i = 0; i < 3000; ++i)
        gltf["scenes"][0]["nodes"].push_back(0);
    gltf["scenes"][0]["nodes"].push_back(1);
    gltf["scenes"][0]["nodes"].push_back(1);
    Diagnostics d;
    EXPECT_FALSE(load(gltf, d));
    ASSERT_EQ(d.errorCount(), 2) << d.format().substr(0, 1000);
    EXPECT_EQ(d.items[0].location, "/scenes/0/nodes/1");
    EXPECT_EQ(d.items[0].message, "/nodes/0 is listed 3000 times in the scene (first at "
                                  "/scenes/0/nodes/0), expected each root once");
    EXPECT_EQ(d.items[1].location, "/scenes/0/nodes/3001");
    EXPECT_EQ(d.items[1].message, "/nodes/1 is listed 2 times in the scene (first at "
                                  "/scenes/0/nodes/3000), expected each root once");
}

TEST(GltfHostile, ManyDistinctRootsAndInstancesLoad) {
    // 200000 roots drawing one triangle each: every check is linear in them.
    json gltf = triangle();
    gltf["nodes"] = json::array();
    gltf["scenes"][0]["nodes"] = json::array();
    for (int i = 0; i < 200000; ++i) {
        gltf["nodes"].push_back({{"mesh", 0}});
        gltf["scenes"][0]["nodes"].push_back(i);
    }
    Diagnostics d;
    const auto asset = load(gltf, d);
    ASSERT_TRUE(asset) << d.format().substr(0, 1000);
    EXPECT_EQ(asset->primitives.size(), 200000u);
}

TEST(GltfHostile, LightsWithoutATypeAreRefusedAtTheirPointerWithTheOtherErrors) {
    json gltf = triangle();
    gltf["extensionsUsed"] = {"KHR_lights_punctual"};
    gltf["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"intensity", 2}},
        {{"type", "spot"}},
        {{"type", "point"}, {"color", "red"}, {"range", "far"}},
        {{"type", "sun"}}};
    gltf["nodes"][0]["mesh"] = 5; // another error, which must not be hidden
    Diagnostics d;
    EXPECT_FALSE(load(gltf, d));
    std::set<std::string> locations;
    for (const Diagnostic& item : d.items)
        if (item.severity == Severity::Error) locations.insert(item.location);
    const std::string lights = "/extensions/KHR_lights_punctual/lights/";
    EXPECT_EQ(locations,
              (std::set<std::string>{lights + "0/type", lights + "1/spot", lights + "2/color",
                                     lights + "2/range", lights + "3/type", "/nodes/0/mesh"}))
        << d.format();
    EXPECT_NE(d.format().find(lights + "0/type: expected \"directional\", \"point\" or \"spot\", "
                                       "got nothing"),
              std::string::npos)
        << d.format();
}

// The scene's texel budget (limits::kSceneTexels) is shared by its glTF images, its material
// textures and its sky image, each checked from its header before it is decoded.
TEST(GltfHostile, MaterialTexturesAndTheSkyTakeFromTheSceneTexelBudget) {
    MemoryFiles files;
    files.files["mem/a.png"] = png(16, 8);
    files.files["mem/b.png"] = png(4, 4);
    std::vector<Material> materials(1);
    materials[0].baseColorTexture.file = "a.png";
    materials[0].baseColorTexture.path = "mem/a.png";
    materials[0].baseColorTexture.pointer = "/materials/m/base_color_texture/file";
    materials[0].normalTexture.file = "b.png";
    materials[0].normalTexture.path = "mem/b.png";
    materials[0].normalTexture.pointer = "/materials/m/normal_texture/file";

    // Room for both: they are taken out of it.
    GltfBudget budget;
    budget.texels = 16 * 8 + 4 * 4 + 100;
    std::vector<TextureImage> textures;
    Diagnostics ok;
    EXPECT_TRUE(loadMaterialTextures(materials, "s.json", files.source(), ok, textures, &budget))
        << ok.format();
    EXPECT_EQ(budget.texels, 100u);

    // A sky of 16 x 8 no longer fits; one of 10 x 10 does.
    Diagnostics sky;
    EXPECT_FALSE(
        loadSkyImage("mem/a.png", files.source(), "s.json", "/environment/sky/file", sky, &budget));
    ASSERT_EQ(sky.errorCount(), 1);
    EXPECT_EQ(sky.items[0].location, "/environment/sky/file");
    EXPECT_NE(sky.items[0].message.find("(16x8) brings the scene's images over the limit "
                                        "\"Scene texels\""),
              std::string::npos)
        << sky.items[0].message;
    files.files["mem/c.png"] = png(10, 10);
    Diagnostics fits;
    EXPECT_TRUE(loadSkyImage("mem/c.png", files.source(), "s.json", "/environment/sky/file", fits,
                             &budget));
    EXPECT_EQ(budget.texels, 0u);

    // Nothing is left for the textures of a second scene prepared with the same budget: the
    // first texture over it is refused, before decoding, at its pointer.
    std::vector<TextureImage> more;
    Diagnostics over;
    EXPECT_FALSE(loadMaterialTextures(materials, "s.json", files.source(), over, more, &budget));
    EXPECT_TRUE(more.empty());
    ASSERT_GE(over.errorCount(), 1);
    EXPECT_EQ(over.items[0].location, "/materials/m/base_color_texture/file");
    EXPECT_NE(over.items[0].message.find("\"Scene texels\""), std::string::npos)
        << over.items[0].message;
}

// stb_image does not describe a 60000 x 60000 PNG; the sky names it too large, as the glTF
// images and textures do.
TEST(GltfHostile, ASkyTooLargeForTheDecoderIsCalledTooLarge) {
    MemoryFiles files;
    files.files["mem/huge.png"] = png(60000, 60000, true);
    Diagnostics d;
    EXPECT_FALSE(
        loadSkyImage("mem/huge.png", files.source(), "s.json", "/environment/sky/file", d));
    ASSERT_EQ(d.errorCount(), 1);
    EXPECT_EQ(d.items[0].message,
              "the sky image is 60000x60000, expected at most 8192 on each side");
}
