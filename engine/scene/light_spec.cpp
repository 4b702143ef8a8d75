// Light type names (see scene/light_spec.hpp).
#include "scene/light_spec.hpp"

namespace rmsc {

std::string_view lightTypeName(LightType type) {
    switch (type) {
    case LightType::Point:
        return "point";
    case LightType::Spot:
        return "spot";
    case LightType::Directional:
        break;
    }
    return "directional";
}

std::optional<LightType> findLightType(std::string_view name) {
    for (const LightType type : kLightTypes)
        if (lightTypeName(type) == name) return type;
    return std::nullopt;
}

} // namespace rmsc
