// File-level helpers of the glTF importer that need no tinygltf: URI decoding and confinement
// to the glTF file's folder, data URI sizes, the GLB container, JSON nesting depth and image
// decoding (stb_image, always RGBA8).
#pragma once

#include "core/limits.hpp"
#include "scene/mesh_asset.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace rmsc::gltf {

constexpr int kMaxImageDimension = limits::kTextureDimension; // images wider or taller are refused
constexpr int kMaxJsonDepth =
    limits::kGltfJsonDepth; // deeper JSON nesting is refused before parsing

// Decodes %XX escapes (RFC 3986). Returns nullopt for a '%' not followed by two hex digits or
// an escape that decodes to a NUL byte.
std::optional<std::string> percentDecode(std::string_view uri);

// Turns a percent-decoded relative URI into a path relative to the glTF file's folder.
// Refuses, with `why` set: empty URIs, absolute paths, URIs with a scheme (http:, file:, C:),
// backslashes, and ".." components that leave the folder.
std::optional<std::filesystem::path> resolveInFolder(std::string_view decodedUri, std::string& why);

// True for "data:" URIs.
bool isDataUri(std::string_view uri);

// The media type of a data URI ("image/png") and the number of bytes its base64 payload
// decodes to; nullopt with `why` set when it is not a base64 data URI.
struct DataUriInfo {
    std::string mediaType;
    std::uint64_t decodedSize = 0;
};
std::optional<DataUriInfo> inspectDataUri(std::string_view uri, std::string& why);

// True when the bytes start with the binary glTF magic "glTF".
bool hasGlbMagic(std::string_view bytes);

// The JSON and BIN chunks of a binary glTF, checked against the GLB layout rules (header
// length equals the file size, chunk lengths inside the file and 4-byte aligned, the first
// chunk JSON, an optional second chunk BIN). Views point into `bytes`.
struct GlbChunks {
    std::string_view json;
    std::string_view bin;
    bool hasBin = false;
};
std::optional<GlbChunks> splitGlb(std::string_view bytes, std::string& why);

// The deepest nesting of arrays and objects in a JSON text, counting strings correctly.
// Stops scanning once the depth exceeds `limit` and returns limit + 1.
int jsonNestingDepth(std::string_view text, int limit);

// The size an image's header states, read without decoding it. Nullopt, with `why` set, for
// data stb cannot decode and for images larger than kMaxImageDimension on either side (also
// those too large for stb to describe: "image is 60000x60000, expected at most 8192 ...").
struct ImageSize {
    int width = 0;
    int height = 0;
};
std::optional<ImageSize> readImageSize(const unsigned char* bytes, std::size_t size,
                                       std::string& why);

// Decodes a PNG/JPEG/BMP/GIF/... image into RGBA8, rows top to bottom. Refuses, with `why`
// set, what readImageSize refuses.
bool decodeImage(const unsigned char* bytes, std::size_t size, Image& out, std::string& why);

} // namespace rmsc::gltf
