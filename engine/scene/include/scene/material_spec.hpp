// The ranges and units of a material's numbers (`materials`: metallic, roughness; a texture's
// scale, sharpness and strength): what the scene reader accepts (scene/scene_json.cpp,
// scene/material_texture_json.cpp) and what the inspector's fields allow, from one place.
#pragma once

#include "sdf/param_spec.hpp"

namespace rmsc {

inline constexpr ParamRange kMetallicRange = closedRange(0.0, 1.0, Unit::Ratio);
inline constexpr ParamRange kRoughnessRange = closedRange(0.0, 1.0, Unit::Ratio);
// Texture repeats per unit of the shape's local frame.
inline constexpr ParamRange kTextureScaleRange = openClosedRange(0.0, 1e4, Unit::PerMetre);
// The exponent of the triplanar blend weights.
inline constexpr ParamRange kTextureSharpnessRange = closedRange(1.0, 64.0);
// A normal map's x and y scale.
inline constexpr ParamRange kNormalStrengthRange = closedRange(0.0, 10.0, Unit::Ratio);

} // namespace rmsc
