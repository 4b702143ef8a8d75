// rmsc public API: images read back from a render, and the outputs (AOVs) one can ask for.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace rmsc::api {

// What render() reads back (the outputs of `rmsc render --aov`).
enum class Aov {
    Color,  // 3 x uint8: the display image, tone mapped and sRGB encoded
    Depth,  // 1 x float: linear view depth in metres, +infinity where nothing was hit
    Normal, // 3 x float: world-space unit normal, 0 where nothing was hit
    Id,     // 1 x uint32: 0 background, 1 + i mesh instance i, 65536 + n SDF node n (pre-order)
    Steps,  // 1 x float: sphere-tracing steps of the pixel's march
};

// "color", "depth", "normal", "id", "steps"; throws Error (Usage) for anything else.
Aov parseAov(std::string_view name);

// Pixels, rows top first, channels interleaved, tightly packed.
struct Image {
    enum class Type { UInt8, Float32, UInt32 };
    int width = 0;
    int height = 0;
    int channels = 0;
    Type type = Type::UInt8;
    std::vector<std::uint8_t> bytes; // width * height * channels values of `type`

    template <class T> const T* data() const { return reinterpret_cast<const T*>(bytes.data()); }
};

} // namespace rmsc::api
