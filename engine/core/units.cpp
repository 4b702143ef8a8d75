// The units' symbols and names (see core/units.hpp).
#include "core/units.hpp"

#include <iterator>

namespace rmsc {

std::string_view unitSymbol(Unit unit) {
    switch (unit) {
    case Unit::None:
    case Unit::Ratio:
    case Unit::Count:
        return "";
    case Unit::Metres:
        return "m";
    case Unit::Degrees:
        return "\xc2\xb0"; // the degree sign, in UTF-8
    case Unit::DegreesPerMetre:
        return "\xc2\xb0/m";
    case Unit::PerMetre:
        return "1/m";
    case Unit::Pixels:
        return "px";
    case Unit::Seconds:
        return "s";
    case Unit::Milliseconds:
        return "ms";
    case Unit::MetresPerSecond:
        return "m/s";
    case Unit::Candela:
        return "cd";
    case Unit::Lux:
        return "lx";
    }
    return "";
}

std::string_view unitPhrase(Unit unit) {
    switch (unit) {
    case Unit::None:
        return "";
    case Unit::PerMetre:
        return "per metre";
    case Unit::Ratio:
        return "a ratio";
    case Unit::Count:
        return "a count";
    default:
        break;
    }
    static const std::string_view phrases[] = {"",
                                               "in metres",
                                               "in degrees",
                                               "in degrees per metre",
                                               "",
                                               "",
                                               "",
                                               "in pixels",
                                               "in seconds",
                                               "in milliseconds",
                                               "in metres per second",
                                               "in candela",
                                               "in lux"};
    static_assert(std::size(phrases) == std::size_t(Unit::Lux) + 1);
    return phrases[std::size_t(unit)];
}

std::string_view unitName(Unit unit) {
    switch (unit) {
    case Unit::None:
        return "";
    case Unit::Metres:
        return "metres";
    case Unit::Degrees:
        return "degrees";
    case Unit::DegreesPerMetre:
        return "degrees per metre";
    case Unit::PerMetre:
        return "per metre";
    case Unit::Ratio:
        return "ratio";
    case Unit::Count:
        return "count";
    case Unit::Pixels:
        return "pixels";
    case Unit::Seconds:
        return "seconds";
    case Unit::Milliseconds:
        return "milliseconds";
    case Unit::MetresPerSecond:
        return "metres per second";
    case Unit::Candela:
        return "candela";
    case Unit::Lux:
        return "lux";
    }
    return "";
}

} // namespace rmsc
