// glTF import of malformed files: a corpus generated here from the valid sample cube (JSON and
// bytes modified in memory, served by an in-memory FileSource). Every file must be refused
// with an error naming the file and, where there is one, the glTF element at fault.
#include "scene/mesh_asset.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>

using namespace rmsc;
using nlohmann::json;

namespace {

const std::string kAssets = std::string(RMSC_TEST_SOURCE_DIR) + "/samples/assets/";

std::string readSample(const std::string& name) {
    std::string error;
    auto bytes = diskFileSource().read(kAssets + name, error);
    EXPECT_TRUE(bytes) << name << ": " << error;
    return bytes.value_or("");
}

const char* kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64Encode(const std::string& bytes) {
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

std::string base64Decode(const std::string& text) {
    std::string out;
    std::uint32_t bits = 0;
    int count = 0;
    for (char c : text) {
        const char* p = std::strchr(kBase64, c);
        if (c == '=' || p == nullptr) break;
        bits = (bits << 6) | std::uint32_t(p - kBase64);
        if ((count += 6) >= 8) {
            count -= 8;
            out += char((bits >> count) & 0xff);
        }
    }
    return out;
}

const std::string kDataPrefix = "data:application/octet-stream;base64,";

// The sample cube as JSON plus its decoded buffer, to be modified by each case.
struct Cube {
    json gltf;
    std::string buffer;

    std::string text() const {
        json copy = gltf;
        copy["buffers"][0]["uri"] = kDataPrefix + base64Encode(buffer);
        return copy.dump();
    }
    void setFloat(std::size_t offset, float value) { std::memcpy(&buffer[offset], &value, 4); }
};

Cube sampleCube() {
    Cube cube;
    cube.gltf = json::parse(readSample("cube.gltf"));
    const std::string uri = cube.gltf["buffers"][0]["uri"];
    cube.buffer = base64Decode(uri.substr(kDataPrefix.size()));
    return cube;
}

struct Case {
    std::string name;
    std::map<std::string, std::string> files; // path -> bytes
    std::string entry = "mem/model.gltf";
    std::string pointer; // an error must have exactly this location ("" = any)
};

FileSource memoryFiles(const std::map<std::string, std::string>& files) {
    return {[files](const std::filesystem::path& path,
                    std::string& error) -> std::optional<std::string> {
        const auto it = files.find(path.generic_string());
        if (it != files.end()) return it->second;
        error = "no such file";
        return std::nullopt;
    }};
}

Case cubeCase(std::string name, std::string pointer, const std::function<void(Cube&)>& edit) {
    Cube cube = sampleCube();
    edit(cube);
    Case c;
    c.name = std::move(name);
    c.pointer = std::move(pointer);
    c.files[c.entry] = cube.text();
    return c;
}

Case rawCase(std::string name, std::string entry, std::string bytes, std::string pointer = "") {
    Case c;
    c.name = std::move(name);
    c.entry = std::move(entry);
    c.files[c.entry] = std::move(bytes);
    c.pointer = std::move(pointer);
    return c;
}

std::uint32_t u32At(const std::string& bytes, std::size_t offset) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;
}

void setU32(std::string& bytes, std::size_t offset, std::uint32_t v) {
    std::memcpy(&bytes[offset], &v, 4);
}

// A PNG signature and IHDR claiming width x height (stb_image reads only the header to size it).
std::string pngHeader(std::uint32_t width, std::uint32_t height) {
    std::string png = "\x89PNG\r\n\x1a\n";
    const auto be32 = [&png](std::uint32_t v) {
        for (int i = 3; i >= 0; --i)
            png += char((v >> (8 * i)) & 0xff);
    };
    be32(13);
    png += "IHDR";
    be32(width);
    be32(height);
    png += std::string("\x08\x06\x00\x00\x00", 5);
    be32(0); // CRC (not checked by stb_image)
    return png;
}

// The cube with material 0 textured by image 0, whose JSON is `image`.
Case texturedCube(std::string name, std::string pointer, json image,
                  std::map<std::string, std::string> extraFiles = {}) {
    Case c = cubeCase(std::move(name), std::move(pointer), [&](Cube& cube) {
        cube.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
        cube.gltf["textures"] = {{{"source", 0}}};
        // json::array: clang reads `= {image}` as a copy of the image, gcc as an array of it.
        cube.gltf["images"] = json::array({image});
    });
    c.files.merge(extraFiles);
    return c;
}

std::vector<Case> corpus() {
    std::vector<Case> cases;
    const auto add = [&](Case c) { cases.push_back(std::move(c)); };

    // --- buffers, buffer views, accessors ---
    add(cubeCase("truncated buffer", "/buffers/0",
                 [](Cube& c) { c.buffer.resize(c.buffer.size() - 40); }));
    add(cubeCase("buffer view beyond buffer", "/bufferViews/0",
                 [](Cube& c) { c.gltf["bufferViews"][0]["byteLength"] = 4000; }));
    add(cubeCase("accessor beyond view", "/accessors/0",
                 [](Cube& c) { c.gltf["accessors"][0]["count"] = 25; }));
    add(cubeCase("stride smaller than element", "/accessors/0",
                 [](Cube& c) { c.gltf["bufferViews"][0]["byteStride"] = 8; }));
    add(cubeCase("huge count with stride", "/accessors/0", [](Cube& c) {
        c.gltf["bufferViews"][0]["byteStride"] = 252;
        c.gltf["accessors"][0]["count"] = std::numeric_limits<std::int32_t>::max();
    }));
    add(cubeCase("count overflowing 64 bits", "/accessors/0/count", [](Cube& c) {
        c.gltf["accessors"][0]["count"] = std::numeric_limits<std::uint64_t>::max() / 2;
    }));
    add(cubeCase("index value beyond vertex count", "/accessors/3", [](Cube& c) {
        const std::size_t offset = c.gltf["bufferViews"][3]["byteOffset"];
        const std::uint16_t bad = 24;
        std::memcpy(&c.buffer[offset + 10], &bad, 2);
    }));
    add(cubeCase("POSITION of type VEC2", "/accessors/0",
                 [](Cube& c) { c.gltf["accessors"][0]["type"] = "VEC2"; }));
    add(cubeCase("POSITION of UNSIGNED_SHORT", "/accessors/0",
                 [](Cube& c) { c.gltf["accessors"][0]["componentType"] = 5123; }));
    add(cubeCase("FLOAT indices", "/accessors/3", [](Cube& c) {
        c.gltf["accessors"][3]["componentType"] = 5126;
        c.gltf["accessors"][3]["count"] = 18;
    }));
    add(cubeCase("attribute counts differ", "/meshes/0/primitives/0/attributes/NORMAL",
                 [](Cube& c) { c.gltf["accessors"][1]["count"] = 20; }));
    add(cubeCase("NaN position", "/accessors/0",
                 [](Cube& c) { c.setFloat(16, std::numeric_limits<float>::quiet_NaN()); }));
    add(cubeCase("infinite normal", "/accessors/1", [](Cube& c) {
        const std::size_t offset = c.gltf["bufferViews"][1]["byteOffset"];
        c.setFloat(offset + 4, std::numeric_limits<float>::infinity());
    }));
    add(cubeCase("sparse count above the accessor's", "/accessors/0/sparse/count", [](Cube& c) {
        c.gltf["accessors"][0]["sparse"] = {
            {"count", 1000},
            {"indices", {{"bufferView", 3}, {"componentType", 5123}}},
            {"values", {{"bufferView", 0}}}};
    }));

    // --- references out of range ---
    add(cubeCase("node mesh out of range", "/nodes/0/mesh",
                 [](Cube& c) { c.gltf["nodes"][0]["mesh"] = 5; }));
    add(cubeCase("negative mesh index", "/nodes/0/mesh",
                 [](Cube& c) { c.gltf["nodes"][0]["mesh"] = -2; }));
    add(cubeCase("index that does not fit an int", "/nodes/0/mesh",
                 [](Cube& c) { c.gltf["nodes"][0]["mesh"] = 4294967296ull; }));
    add(cubeCase("material out of range", "/meshes/0/primitives/0/material",
                 [](Cube& c) { c.gltf["meshes"][0]["primitives"][0]["material"] = 7; }));
    add(cubeCase("scene node out of range", "/scenes/0/nodes/0",
                 [](Cube& c) { c.gltf["scenes"][0]["nodes"][0] = 9; }));
    add(cubeCase("default scene out of range", "/scene", [](Cube& c) { c.gltf["scene"] = 3; }));
    add(cubeCase(
        "attribute accessor out of range", "/meshes/0/primitives/0/attributes/POSITION",
        [](Cube& c) { c.gltf["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 42; }));
    add(cubeCase("indices accessor out of range", "/meshes/0/primitives/0/indices",
                 [](Cube& c) { c.gltf["meshes"][0]["primitives"][0]["indices"] = 4; }));
    add(cubeCase("accessor bufferView out of range", "/accessors/1/bufferView",
                 [](Cube& c) { c.gltf["accessors"][1]["bufferView"] = 17; }));
    add(cubeCase("bufferView buffer out of range", "/bufferViews/2/buffer",
                 [](Cube& c) { c.gltf["bufferViews"][2]["buffer"] = 1; }));
    add(cubeCase(
        "texture out of range", "/materials/0/pbrMetallicRoughness/baseColorTexture/index",
        [](Cube& c) {
            c.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
        }));
    add(texturedCube("image out of range", "/textures/0/source",
                     {{"uri", "data:image/png;base64,AAAA"}}));
    cases.back().files["mem/model.gltf"] = [&] {
        json g = json::parse(cases.back().files["mem/model.gltf"]);
        g["textures"][0]["source"] = 3;
        return g.dump();
    }();

    // --- node hierarchy ---
    add(cubeCase("node cycle", "/nodes/1", [](Cube& c) {
        c.gltf["nodes"].push_back({{"children", {2}}});
        c.gltf["nodes"].push_back({{"children", {1}}});
    }));
    add(cubeCase("node is its own child", "/nodes/0",
                 [](Cube& c) { c.gltf["nodes"][0]["children"] = {0}; }));
    add(cubeCase("node with two parents", "/nodes/2", [](Cube& c) {
        c.gltf["nodes"][0]["children"] = {2};
        c.gltf["nodes"].push_back({{"children", {2}}});
        c.gltf["nodes"].push_back(json::object());
    }));
    add(cubeCase("node chain 100 deep", "", [](Cube& c) {
        for (int i = 0; i < 100; ++i) {
            c.gltf["nodes"][std::size_t(i)]["children"] = {i + 1};
            c.gltf["nodes"].push_back(json::object());
        }
    }));
    add(cubeCase("matrix with 15 numbers", "/nodes/0/matrix",
                 [](Cube& c) { c.gltf["nodes"][0]["matrix"] = std::vector<double>(15, 1.0); }));

    // --- external files and URIs ---
    {
        Case c = rawCase("missing external buffer file", "mem/cube_external.gltf",
                         readSample("cube_external.gltf"), "/buffers/0/uri");
        add(c);
        c.name = "external buffer of the wrong size";
        c.pointer = "";
        c.files["mem/cube_external.bin"] = readSample("cube_external.bin").substr(8);
        add(c);
    }
    const auto externalUri = [&](std::string name, std::string uri) {
        Case c = rawCase(std::move(name), "mem/sub/cube_external.gltf", "", "/buffers/0/uri");
        json g = json::parse(readSample("cube_external.gltf"));
        g["buffers"][0]["uri"] = uri;
        c.files[c.entry] = g.dump();
        // The file exists, so only the confinement can refuse it.
        c.files["mem/cube_external.bin"] = readSample("cube_external.bin");
        c.files["/cube_external.bin"] = readSample("cube_external.bin");
        return c;
    };
    add(externalUri("buffer URI with ../", "../cube_external.bin"));
    add(externalUri("buffer URI with ../ after a folder", "x/../../cube_external.bin"));
    add(externalUri("buffer URI with percent-encoded ../", "%2e%2e/cube_external.bin"));
    add(externalUri("absolute buffer URI", "/cube_external.bin"));
    add(externalUri("buffer URI with a scheme", "file:///cube_external.bin"));
    add(externalUri("buffer URI with bad percent escape", "cube%zz.bin"));
    add(texturedCube("missing image file", "/images/0/uri", {{"uri", "missing.png"}}));
    add(texturedCube("image file that is not an image", "/images/0/uri", {{"uri", "text.png"}},
                     {{"mem/text.png", "this is not a PNG file"}}));
    add(texturedCube("data URI image that is not an image", "/images/0",
                     {{"uri", "data:image/png;base64," + base64Encode("not an image at all")}}));
    add(texturedCube("image larger than 8192", "/images/0",
                     {{"uri", "data:image/png;base64," + base64Encode(pngHeader(9000, 16))}}));
    add(texturedCube("image URI with ../", "/images/0/uri", {{"uri", "../checker.png"}}));
    add(texturedCube("absolute image URI", "/images/0/uri", {{"uri", "/tmp/checker.png"}}));
    add(cubeCase("image bufferView outside its buffer", "/images/0/bufferView", [](Cube& c) {
        c.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
        c.gltf["textures"] = {{{"source", 0}}};
        c.gltf["images"] = {{{"bufferView", 4}, {"mimeType", "image/png"}}};
        c.gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 800}, {"byteLength", 4000}});
    }));
    add(cubeCase("buffer data URI with a wrong media type", "/buffers/0/uri", [](Cube& c) {
        json g = json::parse(c.text());
        c.gltf = g;
    }));
    cases.back().files["mem/model.gltf"] = [&] {
        json g = json::parse(cases.back().files["mem/model.gltf"]);
        std::string uri = g["buffers"][0]["uri"];
        g["buffers"][0]["uri"] = "data:text/html;base64," + uri.substr(kDataPrefix.size());
        return g.dump();
    }();

    // --- JSON ---
    add(rawCase("invalid JSON", "mem/model.gltf", "{\"asset\": {\"version\": \"2.0\"}, "));
    add(rawCase("JSON that is not an object", "mem/model.gltf", "[1, 2, 3]"));
    add(rawCase("deeply nested JSON (100000 '[')", "mem/model.gltf", std::string(100000, '[')));
    add(rawCase("deeply nested extras", "mem/model.gltf",
                "{\"asset\":{\"version\":\"2.0\",\"extras\":" + std::string(5000, '[') +
                    std::string(5000, ']') + "}}"));
    add(cubeCase("missing asset version", "/asset/version",
                 [](Cube& c) { c.gltf.erase("asset"); }));
    add(cubeCase("glTF 1.0", "/asset/version",
                 [](Cube& c) { c.gltf["asset"]["version"] = "1.0"; }));
    add(cubeCase("unsupported required extension", "/extensionsRequired/0",
                 [](Cube& c) { c.gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"}; }));
    add(cubeCase("primitive without POSITION", "/meshes/0/primitives/0/attributes", [](Cube& c) {
        c.gltf["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
    }));

    // --- GLB container ---
    const std::string glb = readSample("cube.glb");
    add(rawCase("truncated GLB", "mem/cube.glb", glb.substr(0, glb.size() / 2)));
    add(rawCase("zero-length GLB", "mem/cube.glb", ""));
    add(rawCase("GLB header only, length 0", "mem/cube.glb",
                std::string("glTF\x02\0\0\0\0\0\0\0", 12)));
    {
        std::string bad = glb;
        setU32(bad, 12, u32At(bad, 12) + 4); // JSON chunk claims 4 more bytes
        add(rawCase("GLB JSON chunk length wrong", "mem/cube.glb", bad));
        bad = glb;
        const std::size_t binHeader = 20 + u32At(glb, 12);
        setU32(bad, binHeader, u32At(bad, binHeader) + 8); // BIN chunk runs past the end
        add(rawCase("GLB BIN chunk length wrong", "mem/cube.glb", bad));
        bad = glb;
        setU32(bad, 4, 1);
        add(rawCase("GLB version 1", "mem/cube.glb", bad));
        bad = glb;
        bad.resize(20 + u32At(glb, 12)); // no BIN chunk, but buffer 0 needs it
        setU32(bad, 8, std::uint32_t(bad.size()));
        add(rawCase("GLB without its BIN chunk", "mem/cube.glb", bad, "/buffers/0"));
    }

    // --- hostile inputs (also in tests/cli/hostile_inputs.py) ---
    add(cubeCase("light without a type", "/extensions/KHR_lights_punctual/lights/0/type",
                 [](Cube& c) {
                     c.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {{{"intensity", 2}}};
                 }));
    add(cubeCase("light colour that is not numbers",
                 "/extensions/KHR_lights_punctual/lights/0/color", [](Cube& c) {
                     c.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {
                         {{"type", "point"}, {"color", "red"}}};
                 }));
    add(cubeCase("scene root listed 3000 times", "/scenes/0/nodes/1",
                 [](Cube& c) { c.gltf["scenes"][0]["nodes"] = std::vector<int>(3000, 0); }));
    add(cubeCase("buffers over the byte budget", "/buffers/2/byteLength", [](Cube& c) {
        for (int i = 0; i < 2; ++i)
            c.gltf["buffers"].push_back({{"byteLength", 600u << 20}, {"uri", "big.bin"}});
    }));
    cases.back().files["mem/big.bin"] = "small";
    add(texturedCube("image of 60000 x 60000", "/images/0",
                     {{"uri", "data:image/png;base64," + base64Encode(pngHeader(60000, 60000))}}));
    return cases;
}

} // namespace

// The corpus holds 67 malformed files; every one must be refused, none may crash or hang.
TEST(GltfMalformed, Corpus67FilesAllRefusedWithFileAndPointer) {
    const std::vector<Case> cases = corpus();
    EXPECT_EQ(cases.size(), 67u);
    // RMSC_FUZZ_SEED_DIR=tests/fuzz/seeds/gltf writes the corpus's entry files as fuzzer seeds.
    if (const char* seedDir = std::getenv("RMSC_FUZZ_SEED_DIR")) {
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const std::filesystem::path entry = cases[i].entry;
            const auto bytes = cases[i].files.find(cases[i].entry);
            if (bytes == cases[i].files.end()) continue;
            char name[32];
            std::snprintf(name, sizeof name, "malformed-%02zu", i);
            std::ofstream(std::filesystem::path(seedDir) / (name + entry.extension().string()),
                          std::ios::binary)
                << bytes->second;
        }
    }
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Diagnostics diagnostics;
        const auto asset = loadGltf(c.entry, memoryFiles(c.files), diagnostics);
        EXPECT_FALSE(asset.has_value());
        ASSERT_TRUE(diagnostics.hasErrors());
        bool pointerFound = c.pointer.empty();
        for (const Diagnostic& d : diagnostics.items) {
            if (d.severity != Severity::Error) continue;
            EXPECT_EQ(d.file, c.entry);
            EXPECT_EQ(d.format().rfind(c.entry + ": ", 0), 0u) << d.format();
            EXPECT_FALSE(d.message.empty());
            pointerFound = pointerFound || d.location == c.pointer;
        }
        EXPECT_TRUE(pointerFound) << "expected an error at " << c.pointer << ", got:\n"
                                  << diagnostics.format();
    }
}

TEST(GltfMalformed, MessagesSayWhatWasExpected) {
    Cube cube = sampleCube();
    cube.gltf["accessors"][0]["type"] = "VEC2";
    Diagnostics diagnostics;
    EXPECT_FALSE(loadGltf("m/a.gltf", memoryFiles({{"m/a.gltf", cube.text()}}), diagnostics));
    EXPECT_NE(diagnostics.format().find("m/a.gltf: /accessors/0: used as POSITION of "
                                        "/meshes/0/primitives/0: expected VEC3 FLOAT, got VEC2"),
              std::string::npos)
        << diagnostics.format();

    Diagnostics sparse;
    cube = sampleCube();
    cube.gltf["accessors"][0]["sparse"] = {
        {"count", 1000},
        {"indices", {{"bufferView", 3}, {"componentType", 5123}}},
        {"values", {{"bufferView", 0}}}};
    EXPECT_FALSE(loadGltf("m/a.gltf", memoryFiles({{"m/a.gltf", cube.text()}}), sparse));
    EXPECT_NE(sparse.format().find("m/a.gltf: /accessors/0/sparse/count: expected from 1 to the "
                                   "accessor's count"),
              std::string::npos)
        << sparse.format();
}

TEST(GltfMalformed, UnmodifiedCubeThroughTheMemorySourceLoads) {
    // The corpus's starting point is valid, so each refusal above is due to its modification.
    Diagnostics diagnostics;
    const auto asset = loadGltf(
        "mem/model.gltf", memoryFiles({{"mem/model.gltf", sampleCube().text()}}), diagnostics);
    ASSERT_TRUE(asset) << diagnostics.format();
    EXPECT_EQ(asset->primitives.at(0).vertices.size(), 24u);
    Diagnostics glbDiagnostics;
    EXPECT_TRUE(loadGltf("mem/cube.glb", memoryFiles({{"mem/cube.glb", readSample("cube.glb")}}),
                         glbDiagnostics))
        << glbDiagnostics.format();
}
