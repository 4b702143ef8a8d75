// Builds small glTF files in tests: typed data appended to one embedded buffer, a buffer view
// and an accessor per array (optionally sparse), and the finished JSON text. Also where the
// Khronos sample models are (RMSC_GLTF_SAMPLES_DIR, outside the repository).
#pragma once

#include "core/file_source.hpp"
#include "scene/mesh_asset.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rmsc::test {

// The folder of the Khronos glTF sample models the tests read (see tests/CMakeLists.txt).
inline std::filesystem::path gltfSamples() {
    return RMSC_GLTF_SAMPLES_DIR;
}

// Skips the current test, saying why, when the sample models are not where the build expects.
#define RMSC_REQUIRE_GLTF_SAMPLES()                                                                \
    if (!std::filesystem::exists(::rmsc::test::gltfSamples() / "README.md"))                       \
    GTEST_SKIP() << "the Khronos glTF sample models are not at " << ::rmsc::test::gltfSamples()    \
                 << " (configure with -DRMSC_GLTF_SAMPLES_DIR=...)"

// A file source holding one file, mem/test.gltf, with `text`; and loading it.
inline FileSource memoryGltf(std::string text) {
    return {[text = std::move(text)](const std::filesystem::path& path,
                                     std::string& error) -> std::optional<std::string> {
        if (path.generic_string() == "mem/test.gltf") return text;
        error = "no such file";
        return std::nullopt;
    }};
}

inline std::optional<MeshAsset> loadGltfText(const std::string& text, Diagnostics& diagnostics) {
    return loadGltf("mem/test.gltf", memoryGltf(text), diagnostics);
}

inline std::string base64Encode(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 2]));
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? table[v & 63] : '=';
    }
    return out;
}

struct GltfBuilder {
    std::string bytes;
    nlohmann::json views = nlohmann::json::array();
    nlohmann::json accessors = nlohmann::json::array();

    // Appends `values` (4-byte aligned) as a buffer view; returns the view's index.
    template <typename T> int view(const std::vector<T>& values) {
        const std::size_t offset = bytes.size();
        bytes.resize(offset + values.size() * sizeof(T));
        std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
        while (bytes.size() % 4)
            bytes += '\0';
        views.push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
        return int(views.size() - 1);
    }

    // An accessor of `count` elements over a new view of `values`; returns its index.
    template <typename T>
    int accessor(const std::vector<T>& values, int componentType, const char* type,
                 std::size_t count, bool normalized = false) {
        nlohmann::json a = {{"bufferView", view(values)},
                            {"componentType", componentType},
                            {"type", type},
                            {"count", count}};
        if (normalized) a["normalized"] = true;
        accessors.push_back(a);
        return int(accessors.size() - 1);
    }

    // The document `gltf` (asset, meshes, materials...) with this builder's buffer, views and
    // accessors, as text.
    std::string text(nlohmann::json gltf) const {
        gltf["asset"] = {{"version", "2.0"}};
        gltf["accessors"] = accessors;
        gltf["bufferViews"] = views;
        gltf["buffers"] = {
            {{"byteLength", bytes.size()},
             {"uri", "data:application/octet-stream;base64," + base64Encode(bytes)}}};
        return gltf.dump();
    }
};

// glTF component types.
constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
              kUnsignedInt = 5125, kFloatType = 5126;

} // namespace rmsc::test
