// The ranges of the render settings' keys (`render`, `render.shadows`, `render.ao`): what the
// scene reader accepts (scene/lighting_json.cpp) and what the inspector's fields allow, from
// one place.
#pragma once

#include "sdf/param_spec.hpp"

namespace rmsc {

inline constexpr ParamRange kShadowStepsRange = closedRange(1, 256);
inline constexpr ParamRange kShadowSoftnessRange = closedRange(0.001, 1.0);
inline constexpr ParamRange kShadowMinDistanceRange = openClosedRange(0.0, 10.0);
inline constexpr ParamRange kShadowMaxDistanceRange = openClosedRange(0.0, 1e4);
inline constexpr ParamRange kShadowMapSizeRange = closedRange(256, 4096);
inline constexpr ParamRange kShadowPcfRadiusRange = closedRange(0, 3);
inline constexpr ParamRange kShadowNormalOffsetRange = closedRange(0.0, 10.0);
inline constexpr ParamRange kShadowSlopeBiasRange = closedRange(0.0, 10.0);
inline constexpr ParamRange kAoSamplesRange = closedRange(0, 16);
inline constexpr ParamRange kAoDistanceRange = openClosedRange(0.0, 10.0);
inline constexpr ParamRange kAoStrengthRange = closedRange(0.0, 4.0);

} // namespace rmsc
