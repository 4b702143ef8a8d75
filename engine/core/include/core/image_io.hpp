// Images in memory and on disk: 8-bit PNG (stb_image_write), 16-bit grey PNG (libpng), and
// float PFM; PNG reading (stb_image) for reference-image tests. Also the AOV encodings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rmsc {

template <class T> struct Pixels {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<T> data; // width * height * channels, top row first

    const T* at(int x, int y) const { return &data[(std::size_t(y) * width + x) * channels]; }
    T* at(int x, int y) { return &data[(std::size_t(y) * width + x) * channels]; }
};

// Each returns false and sets `error` on failure. Files are written to a temporary name in the
// same folder and renamed, so a failed write never leaves a half-written file.
bool writePng8(const std::filesystem::path& path, const Pixels<std::uint8_t>& image,
               std::string& error);
bool writePng16(const std::filesystem::path& path, const Pixels<std::uint16_t>& image,
                std::string& error);
// Portable float map (grey "Pf" or colour "PF"), little-endian, bottom row first per the format.
bool writePfm(const std::filesystem::path& path, const Pixels<float>& image, std::string& error);

// Reads an 8-bit PNG (converted to `channels` channels).
std::optional<Pixels<std::uint8_t>> readPng8(const std::filesystem::path& path, int channels,
                                             std::string& error);

// AOV encodings (docs/cli.md): linear view depth as 16 bits, value =
// round(65535 * (depth - near) / (far - near)) clamped, 65535 where nothing was hit;
// world normals as RGB8 = (n * 0.5 + 0.5) * 255, black where nothing was hit; object ids as a
// stable colour per id (black = background).
Pixels<std::uint16_t> encodeDepth16(const Pixels<float>& viewDepth, float nearPlane,
                                    float farPlane);
Pixels<std::uint8_t> encodeNormals(const Pixels<float>& normals);
Pixels<std::uint8_t> encodeObjectIds(const Pixels<std::uint32_t>& ids);
// March steps as a heatmap: 0 black, then blue, green, yellow, red at maxSteps (RGB).
Pixels<std::uint8_t> encodeStepsHeatmap(const Pixels<float>& steps, int maxSteps);
// The colour of one object id (a hash, so neighbouring ids get unlike colours).
void objectIdColor(std::uint32_t id, std::uint8_t rgb[3]);

} // namespace rmsc
