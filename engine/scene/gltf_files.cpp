// URI confinement, data URIs, the GLB container, JSON depth and image decoding for the glTF
// importer.
#include "gltf_files.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace rmsc::gltf {

namespace {

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

bool isBase64Char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
           c == '/';
}

std::uint32_t readU32(std::string_view bytes, std::size_t offset) {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data()) + offset;
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;

} // namespace

std::optional<std::string> percentDecode(std::string_view uri) {
    std::string out;
    out.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out += uri[i];
            continue;
        }
        if (i + 2 >= uri.size()) return std::nullopt;
        const int hi = hexValue(uri[i + 1]);
        const int lo = hexValue(uri[i + 2]);
        if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) return std::nullopt;
        out += char(hi * 16 + lo);
        i += 2;
    }
    return out;
}

std::optional<std::filesystem::path> resolveInFolder(std::string_view uri, std::string& why) {
    if (uri.empty()) {
        why = "empty URI, expected a file name relative to the glTF file";
        return std::nullopt;
    }
    if (uri.find('\0') != std::string_view::npos) {
        why = "URI contains a NUL byte";
        return std::nullopt;
    }
    if (uri.front() == '/') {
        why = "absolute URIs are not allowed, expected a path relative to the glTF file";
        return std::nullopt;
    }
    if (uri.find('\\') != std::string_view::npos) {
        why = "backslashes are not allowed in URIs, expected '/' separators";
        return std::nullopt;
    }
    // A scheme is letters, digits, '+', '-', '.' followed by ':' before any '/'.
    const std::size_t colon = uri.find(':');
    if (colon != std::string_view::npos && colon < uri.find('/')) {
        why = "URI scheme \"" + std::string(uri.substr(0, colon)) +
              "\" is not supported, expected a data URI or a relative file path";
        return std::nullopt;
    }
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= uri.size()) {
        std::size_t end = uri.find('/', start);
        if (end == std::string_view::npos) end = uri.size();
        const std::string_view part = uri.substr(start, end - start);
        if (part == "..") {
            if (parts.empty()) {
                why = "URI leaves the glTF file's folder (\"..\"), expected a file inside it";
                return std::nullopt;
            }
            parts.pop_back();
        } else if (!part.empty() && part != ".") {
            parts.emplace_back(part);
        }
        start = end + 1;
    }
    if (parts.empty()) {
        why = "URI names the folder itself, expected a file";
        return std::nullopt;
    }
    std::filesystem::path result;
    for (const std::string& part : parts)
        result /= part;
    return result;
}

bool isDataUri(std::string_view uri) {
    return uri.substr(0, 5) == "data:";
}

std::optional<DataUriInfo> inspectDataUri(std::string_view uri, std::string& why) {
    const std::size_t comma = uri.find(',');
    const std::string_view marker = ";base64";
    if (!isDataUri(uri) || comma == std::string_view::npos || comma < 5 + marker.size() ||
        uri.substr(comma - marker.size(), marker.size()) != marker) {
        why = "expected a base64 data URI (\"data:<media type>;base64,...\")";
        return std::nullopt;
    }
    DataUriInfo info;
    info.mediaType = std::string(uri.substr(5, comma - marker.size() - 5));
    std::string_view payload = uri.substr(comma + 1);
    std::size_t padding = 0;
    while (!payload.empty() && payload.back() == '=' && padding < 2) {
        payload.remove_suffix(1);
        ++padding;
    }
    for (char c : payload) {
        if (!isBase64Char(c)) {
            why = "data URI payload is not valid base64";
            return std::nullopt;
        }
    }
    if (payload.size() % 4 == 1) {
        why = "data URI payload is truncated base64";
        return std::nullopt;
    }
    info.decodedSize = std::uint64_t(payload.size()) * 3 / 4;
    return info;
}

bool hasGlbMagic(std::string_view bytes) {
    return bytes.substr(0, 4) == "glTF";
}

std::optional<GlbChunks> splitGlb(std::string_view bytes, std::string& why) {
    if (bytes.size() < 12) {
        why = "binary glTF is " + std::to_string(bytes.size()) +
              " bytes, shorter than its 12-byte header";
        return std::nullopt;
    }
    const std::uint32_t version = readU32(bytes, 4);
    const std::uint32_t length = readU32(bytes, 8);
    if (version != 2) {
        why = "binary glTF version " + std::to_string(version) + ", expected 2";
        return std::nullopt;
    }
    if (length != bytes.size()) {
        why = "binary glTF header says " + std::to_string(length) + " bytes but the file has " +
              std::to_string(bytes.size()) + " (truncated or corrupt)";
        return std::nullopt;
    }
    GlbChunks chunks;
    std::uint64_t offset = 12;
    for (int index = 0; offset < length; ++index) {
        if (offset + 8 > length) {
            why = "chunk " + std::to_string(index) + " header at byte " + std::to_string(offset) +
                  " runs past the end of the file";
            return std::nullopt;
        }
        const std::uint32_t chunkLength = readU32(bytes, std::size_t(offset));
        const std::uint32_t chunkType = readU32(bytes, std::size_t(offset) + 4);
        const std::uint64_t dataStart = offset + 8;
        if (dataStart + chunkLength > length) {
            why = "chunk " + std::to_string(index) + " says " + std::to_string(chunkLength) +
                  " bytes but only " + std::to_string(length - dataStart) + " remain in the file";
            return std::nullopt;
        }
        if (chunkLength % 4 != 0) {
            why = "chunk " + std::to_string(index) + " length " + std::to_string(chunkLength) +
                  " is not a multiple of 4";
            return std::nullopt;
        }
        const std::string_view data = bytes.substr(std::size_t(dataStart), chunkLength);
        if (index == 0) {
            if (chunkType != kChunkJson || chunkLength == 0) {
                why = "the first chunk must be a non-empty JSON chunk";
                return std::nullopt;
            }
            chunks.json = data;
        } else if (index == 1 && chunkType == kChunkBin) {
            chunks.bin = data;
            chunks.hasBin = true;
        } else if (chunkType == kChunkJson || chunkType == kChunkBin) {
            why = "chunk " + std::to_string(index) + " repeats a JSON or BIN chunk";
            return std::nullopt;
        } // other chunk types are ignored, as the GLB specification asks
        offset = dataStart + chunkLength;
    }
    if (chunks.json.empty()) {
        why = "binary glTF has no JSON chunk";
        return std::nullopt;
    }
    return chunks;
}

int jsonNestingDepth(std::string_view text, int limit) {
    int depth = 0;
    int deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > deepest) deepest = depth;
            if (deepest > limit) return limit + 1;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

namespace {

std::uint32_t readU32BigEndian(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 |
           std::uint32_t(p[3]);
}

// The size a PNG's IHDR chunk or a JPEG's frame header states, for images stb_image will not
// describe (it refuses sizes whose pixels overflow its int arithmetic and then reports only
// "unknown image type", having tried every other format). Nullopt when neither is found.
std::optional<std::pair<std::uint32_t, std::uint32_t>> statedSize(const unsigned char* bytes,
                                                                  std::size_t size) {
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size >= 24 && std::memcmp(bytes, kPng, 8) == 0 && std::memcmp(bytes + 12, "IHDR", 4) == 0)
        return std::pair{readU32BigEndian(bytes + 16), readU32BigEndian(bytes + 20)};
    if (size < 4 || bytes[0] != 0xff || bytes[1] != 0xd8) return std::nullopt;
    // JPEG: segments after the start-of-image marker, up to a start-of-frame (SOF0 to SOF15
    // but DHT, JPG and DAC), which holds precision, height and width.
    std::size_t at = 2;
    while (at + 4 <= size) {
        if (bytes[at] != 0xff) return std::nullopt;
        const unsigned char marker = bytes[at + 1];
        if (marker == 0xff) { // fill byte
            ++at;
            continue;
        }
        if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) { // no length
            at += 2;
            continue;
        }
        const std::size_t length = std::size_t(bytes[at + 2]) << 8 | bytes[at + 3];
        if (length < 2) return std::nullopt;
        if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 &&
            marker != 0xcc) {
            if (length < 7 || at + 9 > size) return std::nullopt;
            const std::uint32_t height = std::uint32_t(bytes[at + 5]) << 8 | bytes[at + 6];
            const std::uint32_t width = std::uint32_t(bytes[at + 7]) << 8 | bytes[at + 8];
            return std::pair{width, height};
        }
        if (marker == 0xd9 || marker == 0xda) return std::nullopt; // end, or scan data
        at += 2 + length;
    }
    return std::nullopt;
}

std::string sizeRefusal(std::uint64_t width, std::uint64_t height) {
    return "image is " + std::to_string(width) + "x" + std::to_string(height) +
           ", expected at most " + std::to_string(kMaxImageDimension) + " on each side";
}

} // namespace

std::optional<ImageSize> readImageSize(const unsigned char* bytes, std::size_t size,
                                       std::string& why) {
    if (bytes == nullptr || size == 0) {
        why = "image data is empty";
        return std::nullopt;
    }
    if (size > std::size_t(std::numeric_limits<int>::max())) {
        why = "image data is larger than 2 GiB";
        return std::nullopt;
    }
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels)) {
        const auto stated = statedSize(bytes, size);
        if (stated && (stated->first > std::uint32_t(kMaxImageDimension) ||
                       stated->second > std::uint32_t(kMaxImageDimension))) {
            why = sizeRefusal(stated->first, stated->second);
            return std::nullopt;
        }
        const char* reason = stbi_failure_reason();
        why = std::string("not a decodable image (") + (reason ? reason : "unknown format") +
              "), expected PNG or JPEG data";
        return std::nullopt;
    }
    if (width <= 0 || height <= 0 || width > kMaxImageDimension || height > kMaxImageDimension) {
        why = sizeRefusal(std::uint64_t(std::max(width, 0)), std::uint64_t(std::max(height, 0)));
        return std::nullopt;
    }
    return ImageSize{width, height};
}

bool decodeImage(const unsigned char* bytes, std::size_t size, Image& out, std::string& why) {
    const auto stated = readImageSize(bytes, size, why);
    if (!stated) return false;
    int width = stated->width, height = stated->height, channels = 0;
    stbi_set_flip_vertically_on_load_thread(0);
    unsigned char* pixels = stbi_load_from_memory(bytes, int(size), &width, &height, &channels, 4);
    if (pixels == nullptr) {
        const char* reason = stbi_failure_reason();
        why = std::string("image could not be decoded (") + (reason ? reason : "unknown") + ")";
        return false;
    }
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels, pixels + std::size_t(width) * std::size_t(height) * 4);
    stbi_image_free(pixels);
    return true;
}

} // namespace rmsc::gltf
