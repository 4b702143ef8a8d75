// The ranges of the environment's keys (`environment`, its `sky` and `fog`): what the scene
// reader accepts (scene/lighting_json.cpp), what the schema states and what the inspector's
// fields allow, from one place. Colours are linear RGB >= 0 like every colour of the format.
#pragma once

#include "scene/scene.hpp"
#include "sdf/param_spec.hpp"

#include <array>
#include <string_view>

namespace rmsc {

// The sky types a file can name ("sky": {"type": ...}), in SkyType order after None.
struct SkyTypeName {
    SkyType type;
    std::string_view name;
};
inline constexpr std::array<SkyTypeName, 3> kSkyTypeNames = {
    {{SkyType::Constant, "constant"}, {SkyType::Gradient, "gradient"}, {SkyType::Image, "image"}}};

inline constexpr ParamRange kEnvironmentIntensityRange = {0.0, ParamRange{}.max, false, false,
                                                          Unit::Ratio}; // >= 0
inline constexpr ParamRange kSkyRotationRange = closedRange(-360.0, 360.0, Unit::Degrees);
inline constexpr ParamRange kFogDensityRange = closedRange(0.0, 10.0, Unit::PerMetre);

} // namespace rmsc
