// Structured libFuzzer harness of the glTF importer's accessor and image paths: the input bytes
// are read as parameters (accessor counts, component types, strides, offsets, sparse fields,
// buffer lengths, the width, height and depth of embedded PNG images) from which a small .glb is
// built, JSON chunk and binary chunk, and loaded with a small load budget. loadGltf must give an
// asset or diagnostics, never a crash, a sanitizer report or a hang, and an asset it gives must
// hold no more than the budget allowed. With RMSC_FUZZ_WRITE_GLB=FILE set, the .glb built
// from an input is also written to FILE (to keep a finding as a file regression input).
#include "scene/mesh_asset.hpp"

#include <fuzzer/FuzzedDataProvider.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

// Small enough that every refusal path is reached, large enough that valid inputs load.
constexpr std::uint64_t kVertices = 1u << 16;
constexpr std::uint64_t kIndices = 1u << 18;
constexpr std::uint64_t kTexels = 1u << 20;

std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (const char c : bytes) {
        crc ^= std::uint8_t(c);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void putBigEndian(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(char((value >> shift) & 0xff));
}

void putLittleEndian(std::string& out, std::uint32_t value) {
    for (int shift = 0; shift <= 24; shift += 8)
        out.push_back(char((value >> shift) & 0xff));
}

void pngChunk(std::string& out, const char* type, const std::string& data) {
    putBigEndian(out, std::uint32_t(data.size()));
    const std::string body = std::string(type, 4) + data;
    out += body;
    putBigEndian(out, crc32(body));
}

// A PNG whose header states the chosen size, depth and colour type; its pixel data is a zlib
// stream of stored blocks holding fuzzer bytes, so small images decode and others run short.
std::string png(FuzzedDataProvider& in) {
    static constexpr std::array<std::uint32_t, 8> kSizes{1, 2, 3, 16, 255, 1024, 8193, 65536};
    const std::uint32_t width =
        in.ConsumeBool() ? in.PickValueInArray(kSizes) : in.ConsumeIntegral<std::uint32_t>();
    const std::uint32_t height =
        in.ConsumeBool() ? in.PickValueInArray(kSizes) : in.ConsumeIntegral<std::uint32_t>();
    static constexpr std::array<std::uint8_t, 5> kDepths{1, 2, 4, 8, 16};
    static constexpr std::array<std::uint8_t, 5> kColours{0, 2, 3, 4, 6};
    std::string header;
    putBigEndian(header, width);
    putBigEndian(header, height);
    header.push_back(char(in.PickValueInArray(kDepths)));
    header.push_back(char(in.PickValueInArray(kColours)));
    header.append(2, '\0');                                  // compression, filter
    header.push_back(char(in.ConsumeIntegralInRange(0, 1))); // interlace
    std::string out("\x89PNG\r\n\x1a\n", 8);
    pngChunk(out, "IHDR", header);
    if (in.ConsumeBool()) pngChunk(out, "PLTE", in.ConsumeBytesAsString(3 * 4));
    const std::string raw = in.ConsumeBytesAsString(in.ConsumeIntegralInRange(0, 512));
    std::string zlib("\x78\x01", 2);
    zlib.push_back('\x01'); // the last block, stored
    const auto length = std::uint16_t(raw.size());
    zlib.push_back(char(length & 0xff));
    zlib.push_back(char(length >> 8));
    zlib.push_back(char(~length & 0xff));
    zlib.push_back(char((~length >> 8) & 0xff));
    zlib += raw;
    putBigEndian(zlib, 0); // the Adler-32, not checked by the decoder
    pngChunk(out, "IDAT", zlib);
    pngChunk(out, "IEND", "");
    return out;
}

// A count or an offset: usually small, sometimes at or past a boundary.
std::int64_t size(FuzzedDataProvider& in) {
    static constexpr std::array<std::int64_t, 10> kEdges{
        0, 1, 3, 4, 255, 256, 65536, 1 << 24, std::int64_t(1) << 31, -1};
    return in.ConsumeBool() ? in.ConsumeIntegralInRange<std::int64_t>(0, 64)
                            : in.PickValueInArray(kEdges);
}

// An index into a list of `count`, or one past it, or none (-1).
int reference(FuzzedDataProvider& in, int count) {
    return in.ConsumeIntegralInRange(-1, count);
}

void setReference(json& object, const char* key, int index) {
    if (index >= 0) object[key] = index;
}

std::string glb(const json& document, const std::string& bin) {
    std::string text = document.dump();
    while (text.size() % 4 != 0)
        text.push_back(' ');
    std::string binary = bin;
    while (binary.size() % 4 != 0)
        binary.push_back('\0');
    std::string out = "glTF";
    putLittleEndian(out, 2);
    putLittleEndian(out, std::uint32_t(12 + 8 + text.size() + 8 + binary.size()));
    putLittleEndian(out, std::uint32_t(text.size()));
    out += "JSON";
    out += text;
    putLittleEndian(out, std::uint32_t(binary.size()));
    out += std::string("BIN\0", 4);
    out += binary;
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size_) {
    FuzzedDataProvider in(data, size_);
    json document = {{"asset", {{"version", "2.0"}}}};

    // The images first, at the start of the binary chunk, then bytes for the accessors.
    std::string bin;
    std::vector<std::pair<std::size_t, std::size_t>> imageRanges;
    const int imageCount = in.ConsumeIntegralInRange(0, 3);
    for (int i = 0; i < imageCount; ++i) {
        const std::string image = png(in);
        imageRanges.emplace_back(bin.size(), image.size());
        bin += image;
        while (bin.size() % 4 != 0)
            bin.push_back('\0');
    }
    const std::size_t dataStart = bin.size();
    bin += in.ConsumeBytesAsString(in.ConsumeIntegralInRange(0, 1024));
    const std::int64_t byteLength = in.ConsumeBool() ? std::int64_t(bin.size()) : size(in);
    document["buffers"] = json::array({{{"byteLength", byteLength}}});

    json views = json::array();
    for (const auto& [offset, length] : imageRanges)
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
    const int viewCount = in.ConsumeIntegralInRange(1, 4);
    for (int i = 0; i < viewCount; ++i) {
        json view = {{"buffer", in.ConsumeIntegralInRange(0, 1)}};
        view["byteOffset"] = in.ConsumeBool() ? std::int64_t(dataStart) + size(in) : size(in);
        view["byteLength"] = in.ConsumeBool() ? std::int64_t(bin.size() - dataStart) : size(in);
        if (in.ConsumeBool()) view["byteStride"] = in.ConsumeIntegralInRange(0, 260);
        if (in.ConsumeBool()) view["target"] = in.ConsumeBool() ? 34962 : 34963;
        views.push_back(view);
    }
    const int firstDataView = int(imageRanges.size());
    const int allViews = int(views.size());
    document["bufferViews"] = views;

    static constexpr std::array<int, 8> kComponents{5120, 5121, 5122, 5123, 5125, 5126, 5124, 0};
    static constexpr std::array<const char*, 8> kTypes{"SCALAR", "VEC2", "VEC3", "VEC4",
                                                       "MAT2",   "MAT3", "MAT4", "VEC5"};
    json accessors = json::array();
    const int accessorCount = in.ConsumeIntegralInRange(1, 6);
    for (int i = 0; i < accessorCount; ++i) {
        json accessor = {{"componentType", in.PickValueInArray(kComponents)},
                         {"count", size(in)},
                         {"type", in.PickValueInArray(kTypes)}};
        const int view = in.ConsumeBool() ? in.ConsumeIntegralInRange(firstDataView, allViews)
                                          : reference(in, allViews);
        setReference(accessor, "bufferView", view);
        if (in.ConsumeBool()) accessor["byteOffset"] = size(in);
        if (in.ConsumeBool()) accessor["normalized"] = in.ConsumeBool();
        if (in.ConsumeBool()) {
            accessor["min"] = json::array({-1.0, -1.0, -1.0});
            accessor["max"] = json::array({1.0, 1.0, 1.0});
        }
        if (in.ConsumeBool()) {
            json indices = {{"bufferView", reference(in, allViews)},
                            {"componentType", in.PickValueInArray(kComponents)}};
            json values = {{"bufferView", reference(in, allViews)}};
            if (in.ConsumeBool()) indices["byteOffset"] = size(in);
            if (in.ConsumeBool()) values["byteOffset"] = size(in);
            accessor["sparse"] = {{"count", size(in)}, {"indices", indices}, {"values", values}};
        }
        accessors.push_back(accessor);
    }
    document["accessors"] = accessors;

    if (imageCount > 0) {
        json images = json::array(), textures = json::array();
        for (int i = 0; i < imageCount; ++i) {
            images.push_back({{"bufferView", i}, {"mimeType", "image/png"}});
            textures.push_back({{"source", in.ConsumeIntegralInRange(0, imageCount - 1)}});
        }
        document["images"] = images;
        document["textures"] = textures;
        json material = json::object();
        for (const char* slot : {"baseColorTexture", "metallicRoughnessTexture"})
            if (in.ConsumeBool())
                material["pbrMetallicRoughness"][slot] = {
                    {"index", in.ConsumeIntegralInRange(0, imageCount - 1)}};
        for (const char* slot : {"normalTexture", "emissiveTexture", "occlusionTexture"})
            if (in.ConsumeBool())
                material[slot] = {{"index", in.ConsumeIntegralInRange(0, imageCount - 1)}};
        document["materials"] = json::array({material});
    }

    static constexpr std::array<const char*, 6> kAttributes{"POSITION",   "NORMAL",  "TANGENT",
                                                            "TEXCOORD_0", "COLOR_0", "TEXCOORD_1"};
    json primitives = json::array();
    const int primitiveCount = in.ConsumeIntegralInRange(1, 3);
    for (int p = 0; p < primitiveCount; ++p) {
        json primitive = {
            {"attributes", {{"POSITION", in.ConsumeIntegralInRange(0, accessorCount - 1)}}}};
        for (std::size_t a = 1; a < kAttributes.size(); ++a)
            if (in.ConsumeBool())
                primitive["attributes"][kAttributes[a]] = reference(in, accessorCount);
        setReference(primitive, "indices", reference(in, accessorCount));
        if (in.ConsumeBool()) primitive["mode"] = in.ConsumeIntegralInRange(0, 7);
        if (imageCount > 0 && in.ConsumeBool()) primitive["material"] = 0;
        primitives.push_back(primitive);
    }
    document["meshes"] = json::array({{{"primitives", primitives}}});
    json nodes = json::array({{{"mesh", 0}}});
    if (in.ConsumeBool()) nodes.push_back({{"mesh", 0}, {"translation", {1.0, 0.0, 0.0}}});
    document["nodes"] = nodes;
    document["scenes"] =
        json::array({{{"nodes", nodes.size() == 1 ? json::array({0}) : json::array({0, 1})}}});
    document["scene"] = 0;

    const std::string file = glb(document, bin);
    if (const char* out = std::getenv("RMSC_FUZZ_WRITE_GLB"))
        std::ofstream(out, std::ios::binary) << file;
    const std::filesystem::path entry = "fuzz/model.glb";
    const rmsc::FileSource files{
        [&](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
            if (path == entry) return file;
            error = "no such file";
            return std::nullopt;
        }};
    rmsc::GltfBudget budget;
    budget.vertices = kVertices;
    budget.indices = kIndices;
    budget.texels = kTexels;
    rmsc::Diagnostics diagnostics;
    const auto asset = rmsc::loadGltf(entry, files, diagnostics, budget);
    if (asset.has_value() == diagnostics.hasErrors()) __builtin_trap();
    if (!asset) return 0;
    // What was taken out of the budget covers what the asset holds.
    std::uint64_t vertices = 0, indices = 0, texels = 0;
    for (const rmsc::MeshPrimitive& primitive : asset->primitives) {
        vertices += primitive.vertices.size();
        indices += primitive.indices.size();
    }
    for (const rmsc::Image& image : asset->images)
        texels += std::uint64_t(image.width) * std::uint64_t(image.height);
    if (budget.vertices > kVertices || budget.indices > kIndices || budget.texels > kTexels)
        __builtin_trap();
    if (vertices > kVertices - budget.vertices || indices > kIndices - budget.indices ||
        texels > kTexels - budget.texels)
        __builtin_trap();
    return 0;
}
