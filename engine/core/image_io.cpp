// Image files and AOV encodings.
#include "core/image_io.hpp"

#include "core/atomic_file.hpp"

#include <png.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <system_error>

namespace rmsc {
namespace {

// Every encoder writes into memory; the bytes then go to disk through saveTextFileAtomically,
// which checks each write, the fsync and the close (a full disk is an error, never a
// truncated file renamed over the old one: the encoders' own stdio writes were not checked).
void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

void appendPngBytes(png_structp png, png_bytep data, png_size_t size) {
    static_cast<std::string*>(png_get_io_ptr(png))
        ->append(reinterpret_cast<const char*>(data), size);
}

void flushNothing(png_structp) {}

bool saveBytes(const std::filesystem::path& path, bool encoded, const std::string& bytes,
               std::string& error) {
    if (!encoded) {
        error = "cannot encode " + path.string();
        return false;
    }
    return saveTextFileAtomically(path, bytes, false, error);
}

// The 16-bit PNG of `image` (libpng; stb_image_write writes 8 bits only), or false.
bool encodePng16(const Pixels<std::uint16_t>& image, std::string& bytes) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    bool ok = false;
    if (png && info && !setjmp(png_jmpbuf(png))) {
        png_set_write_fn(png, &bytes, appendPngBytes, flushNothing);
        const int colorType = image.channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB;
        png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 16, colorType,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        png_set_swap(png); // PNG stores 16-bit samples big-endian
        for (int y = 0; y < image.height; ++y)
            png_write_row(png, reinterpret_cast<png_const_bytep>(image.at(0, y)));
        png_write_end(png, nullptr);
        ok = true;
    }
    png_destroy_write_struct(&png, &info);
    return ok;
}

} // namespace

bool writePng8(const std::filesystem::path& path, const Pixels<std::uint8_t>& image,
               std::string& error) {
    std::string bytes;
    const bool encoded =
        stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, image.channels,
                               image.data.data(), image.width * image.channels) != 0;
    return saveBytes(path, encoded, bytes, error);
}

bool writePng16(const std::filesystem::path& path, const Pixels<std::uint16_t>& image,
                std::string& error) {
    std::string bytes;
    const bool encoded = encodePng16(image, bytes);
    return saveBytes(path, encoded, bytes, error);
}

bool writePfm(const std::filesystem::path& path, const Pixels<float>& image, std::string& error) {
    std::string bytes = std::string(image.channels == 1 ? "Pf" : "PF") + "\n" +
                        std::to_string(image.width) + " " + std::to_string(image.height) +
                        "\n-1.0\n";
    for (int y = image.height - 1; y >= 0; --y)
        bytes.append(reinterpret_cast<const char*>(image.at(0, y)),
                     sizeof(float) * std::size_t(image.width) * std::size_t(image.channels));
    return saveBytes(path, true, bytes, error);
}

std::optional<Pixels<std::uint8_t>> readPng8(const std::filesystem::path& path, int channels,
                                             std::string& error) {
    int width = 0, height = 0, fileChannels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &fileChannels, channels);
    if (!data) {
        error = path.string() + ": " + stbi_failure_reason();
        return std::nullopt;
    }
    Pixels<std::uint8_t> image{width, height, channels, {}};
    image.data.assign(data, data + std::size_t(width) * height * channels);
    stbi_image_free(data);
    return image;
}

Pixels<std::uint16_t> encodeDepth16(const Pixels<float>& depth, float nearPlane, float farPlane) {
    Pixels<std::uint16_t> out{depth.width, depth.height, 1, {}};
    out.data.resize(depth.data.size());
    for (std::size_t i = 0; i < depth.data.size(); ++i) {
        const float normalized = (depth.data[i] - nearPlane) / (farPlane - nearPlane);
        out.data[i] = std::uint16_t(std::lround(65535.0f * std::clamp(normalized, 0.0f, 1.0f)));
    }
    return out;
}

Pixels<std::uint8_t> encodeNormals(const Pixels<float>& normals) {
    Pixels<std::uint8_t> out{normals.width, normals.height, 3, {}};
    out.data.resize(std::size_t(normals.width) * normals.height * 3);
    for (std::size_t i = 0; i < std::size_t(normals.width) * normals.height; ++i) {
        const float* n = &normals.data[i * 3];
        const bool hit = n[0] != 0.0f || n[1] != 0.0f || n[2] != 0.0f;
        for (int c = 0; c < 3; ++c)
            out.data[i * 3 + c] =
                hit ? std::uint8_t(std::lround(std::clamp(n[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255))
                    : 0;
    }
    return out;
}

void objectIdColor(std::uint32_t id, std::uint8_t rgb[3]) {
    if (id == 0) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return;
    }
    // A 32-bit integer hash (the "lowbias32" finalizer by Chris Wellons, hash-prospector).
    std::uint32_t h = id;
    h ^= h >> 16;
    h *= 0x7feb352dU;
    h ^= h >> 15;
    h *= 0x846ca68bU;
    h ^= h >> 16;
    // Keep colours away from black so no object looks like the background.
    rgb[0] = std::uint8_t(64 + (h & 0xff) % 192);
    rgb[1] = std::uint8_t(64 + ((h >> 8) & 0xff) % 192);
    rgb[2] = std::uint8_t(64 + ((h >> 16) & 0xff) % 192);
}

Pixels<std::uint8_t> encodeObjectIds(const Pixels<std::uint32_t>& ids) {
    Pixels<std::uint8_t> out{ids.width, ids.height, 3, {}};
    out.data.resize(ids.data.size() * 3);
    for (std::size_t i = 0; i < ids.data.size(); ++i)
        objectIdColor(ids.data[i], &out.data[i * 3]);
    return out;
}

Pixels<std::uint8_t> encodeStepsHeatmap(const Pixels<float>& steps, int maxSteps) {
    // Piecewise-linear ramp through black, blue, cyan, green, yellow, red.
    static const float ramp[6][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 1},
                                     {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    Pixels<std::uint8_t> out{steps.width, steps.height, 3, {}};
    out.data.resize(std::size_t(steps.width) * steps.height * 3);
    for (std::size_t i = 0; i < steps.data.size(); ++i) {
        const float x = std::clamp(steps.data[i] / float(std::max(maxSteps, 1)), 0.0f, 1.0f) * 5;
        const int k = std::min(int(x), 4);
        const float f = x - float(k);
        for (int c = 0; c < 3; ++c)
            out.data[i * 3 + c] = std::uint8_t(
                std::lround(255.0f * (ramp[k][c] + (ramp[k + 1][c] - ramp[k][c]) * f)));
    }
    return out;
}

} // namespace rmsc
