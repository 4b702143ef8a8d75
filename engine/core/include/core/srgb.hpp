// The sRGB transfer functions (IEC 61966-2-1:1999): a hexadecimal colour in a scene file
// ("#rrggbb") is sRGB-encoded, colours in memory are linear. The reader decodes with them, the
// editor's colour pickers show and take sRGB through them, so a hex code means the same colour
// in the file and in the picker.
#pragma once

#include <glm/glm.hpp>

#include <string>

namespace rmsc {

// Decoding: c / 12.92 for c <= 0.04045, else ((c + 0.055) / 1.055)^2.4.
float srgbToLinear(float encoded);
// Encoding: 12.92 c for c <= 0.0031308, else 1.055 c^(1/2.4) - 0.055. Values above 1 (HDR
// colours) follow the same curve; negative ones the linear segment.
float linearToSrgb(float linear);
glm::vec3 srgbToLinear(glm::vec3 encoded);
glm::vec3 linearToSrgb(glm::vec3 linear);

// "#RRGGBB": a linear colour encoded to sRGB, each channel clamped to [0, 1] and rounded to the
// nearest of 256 steps (as the colour picker shows it).
std::string linearToSrgbHex(glm::vec3 linear);

} // namespace rmsc
