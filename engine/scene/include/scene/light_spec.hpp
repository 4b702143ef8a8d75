// The light types of the scene format ("lights": directional, point, spot) and the valid values
// of each light key, as the scene reader checks them (scene/lighting_json.cpp); the schema and
// the editor's light inspector take their ranges from here, so none of them can disagree.
#pragma once

#include "scene/scene.hpp"
#include "sdf/param_spec.hpp"

#include <array>
#include <optional>
#include <string_view>

namespace rmsc {

// Every light type, in LightType order.
inline constexpr std::array<LightType, 3> kLightTypes = {LightType::Directional, LightType::Point,
                                                         LightType::Spot};

// The JSON value of "type": "directional", "point", "spot".
std::string_view lightTypeName(LightType type);
std::optional<LightType> findLightType(std::string_view name);

// Which keys a type has besides type, name, color, intensity, shadows and shadow_softness.
constexpr bool hasPosition(LightType type) {
    return type != LightType::Directional;
}
constexpr bool hasDirection(LightType type) {
    return type != LightType::Point;
}
constexpr bool hasRange(LightType type) {
    return type != LightType::Directional;
}
constexpr bool hasCone(LightType type) {
    return type == LightType::Spot;
}

// The cone angles of a spot light follow glTF KHR_lights_punctual: outer at most 90 degrees,
// inner below outer.
inline constexpr double kMaxSpotAngleDegrees = 90.0;

// >= 0; in lux for a directional light, candela for the others (lightIntensityUnit).
inline constexpr ParamRange kLightIntensityRange = {0.0};
inline constexpr ParamRange kLightRangeRange = {0.0, ParamRange{}.max, true, false, Unit::Metres};
inline constexpr ParamRange kLightShadowSoftnessRange = closedRange(0.001, 1.0, Unit::Ratio);
inline constexpr ParamRange kSpotInnerAngleRange =
    closedRange(0.0, kMaxSpotAngleDegrees, Unit::Degrees);
inline constexpr ParamRange kSpotOuterAngleRange =
    openClosedRange(0.0, kMaxSpotAngleDegrees, Unit::Degrees);

// The unit of "intensity" for a light of `type`, as glTF's KHR_lights_punctual: lux for a
// directional light, candela for point and spot lights.
constexpr Unit lightIntensityUnit(LightType type) {
    return type == LightType::Directional ? Unit::Lux : Unit::Candela;
}
// Besides the ranges: "outer_angle" > "inner_angle", and "direction" is not [0, 0, 0].

} // namespace rmsc
