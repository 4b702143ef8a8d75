// The sRGB transfer functions (see srgb.hpp).
#include "core/srgb.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rmsc {

float srgbToLinear(float encoded) {
    const double c = encoded;
    return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

float linearToSrgb(float linear) {
    const double c = linear;
    return float(c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
}

glm::vec3 srgbToLinear(glm::vec3 encoded) {
    return {srgbToLinear(encoded.x), srgbToLinear(encoded.y), srgbToLinear(encoded.z)};
}

glm::vec3 linearToSrgb(glm::vec3 linear) {
    return {linearToSrgb(linear.x), linearToSrgb(linear.y), linearToSrgb(linear.z)};
}

std::string linearToSrgbHex(glm::vec3 linear) {
    const glm::vec3 encoded = linearToSrgb(linear);
    int channel[3];
    for (int c = 0; c < 3; ++c)
        channel[c] = int(std::clamp(encoded[c], 0.0f, 1.0f) * 255.0f + 0.5f);
    char text[8];
    std::snprintf(text, sizeof text, "#%02X%02X%02X", channel[0], channel[1], channel[2]);
    return text;
}

} // namespace rmsc
