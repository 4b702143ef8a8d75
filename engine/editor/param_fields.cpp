// The inspector's field ranges from the catalogue rows (see param_fields.hpp).
#include "editor/param_fields.hpp"

#include "sdf/operations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rmsc::editor {
namespace {

constexpr float kLargest = std::numeric_limits<float>::max();
constexpr float kInfinity = std::numeric_limits<float>::infinity();

bool above(double value, double end, bool exclusive) {
    return exclusive ? value > end : value >= end;
}

// The smallest finite float the range's lower end lets through.
float lowestFloat(double end, bool exclusive) {
    if (!std::isfinite(end)) return -kLargest;
    float f = float(end);
    while (!above(double(f), end, exclusive))
        f = std::nextafter(f, kInfinity);
    while (above(double(std::nextafter(f, -kInfinity)), end, exclusive))
        f = std::nextafter(f, -kInfinity);
    return f;
}

// The largest finite float the range's upper end lets through.
float highestFloat(double end, bool exclusive) {
    if (!std::isfinite(end)) return kLargest;
    return -lowestFloat(-end, exclusive);
}

} // namespace

FloatFieldRange floatFieldRange(const ParamRange& range) {
    return {lowestFloat(range.min, range.minExclusive),
            highestFloat(range.max, range.maxExclusive)};
}

IntFieldRange intFieldRange(const ParamRange& range) {
    constexpr double kLowest = std::numeric_limits<int>::min();
    constexpr double kHighest = std::numeric_limits<int>::max();
    double lo = std::isfinite(range.min) ? std::ceil(range.min) : kLowest;
    if (range.minExclusive && lo == range.min) lo += 1.0;
    double hi = std::isfinite(range.max) ? std::floor(range.max) : kHighest;
    if (range.maxExclusive && hi == range.max) hi -= 1.0;
    return {int(std::max(lo, kLowest)), int(std::min(hi, kHighest))};
}

FloatFieldRange primitiveFieldRange(const ParamSpec& param) {
    return floatFieldRange(closedRange(param.minValue, param.maxValue));
}

FloatFieldRange smoothnessFieldRange() {
    return floatFieldRange(smoothnessParam().range);
}

} // namespace rmsc::editor
