// The ranges and units of the render settings' keys (`render`, `render.shadows`, `render.ao`):
// what the scene reader accepts (scene/scene_json.cpp, scene/lighting_json.cpp) and what the
// inspector's fields allow, from one place.
#pragma once

#include "core/limits.hpp"
#include "sdf/param_spec.hpp"

namespace rmsc {

inline constexpr ParamRange kMaxStepsRange = closedRange(1, limits::kMarchSteps, Unit::Count);
inline constexpr ParamRange kMaxDistanceRange = openClosedRange(0.0, 1e5, Unit::Metres);
// Relative: the hit threshold is this times the distance travelled.
inline constexpr ParamRange kSurfaceEpsilonRange = openClosedRange(0.0, 1.0, Unit::Ratio);
inline constexpr ParamRange kExposureRange = {0.0, ParamRange{}.max, true, false, Unit::Ratio};

inline constexpr ParamRange kShadowStepsRange = closedRange(1, 256, Unit::Count);
// The penumbra width factor w (Quilez's k = 1 / w).
inline constexpr ParamRange kShadowSoftnessRange = closedRange(0.001, 1.0, Unit::Ratio);
inline constexpr ParamRange kShadowMinDistanceRange = openClosedRange(0.0, 10.0, Unit::Metres);
inline constexpr ParamRange kShadowMaxDistanceRange = openClosedRange(0.0, 1e4, Unit::Metres);
inline constexpr ParamRange kShadowMapSizeRange = closedRange(256, 4096, Unit::Pixels);
inline constexpr ParamRange kShadowPcfRadiusRange = closedRange(0, 3, Unit::Pixels);
inline constexpr ParamRange kShadowNormalOffsetRange = closedRange(0.0, 10.0, Unit::Pixels);
// The polygon offset factor of the shadow-map pass.
inline constexpr ParamRange kShadowSlopeBiasRange = closedRange(0.0, 10.0, Unit::Ratio);
inline constexpr ParamRange kAoSamplesRange = closedRange(0, 16, Unit::Count);
inline constexpr ParamRange kAoDistanceRange = openClosedRange(0.0, 10.0, Unit::Metres);
inline constexpr ParamRange kAoStrengthRange = closedRange(0.0, 4.0, Unit::Ratio);

} // namespace rmsc
