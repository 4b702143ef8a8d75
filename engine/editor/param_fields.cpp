// The inspector's field ranges from the catalogue rows (see param_fields.hpp).
#include "editor/param_fields.hpp"

#include "core/number_text.hpp"
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

ParamRange primitiveParamRange(const ParamSpec& param) {
    return closedRange(param.minValue, param.maxValue, param.unit);
}

namespace {

std::string numberText(double value) {
    const float asFloat = float(value);
    return double(asFloat) == value ? shortestNumberText(asFloat) : shortestNumberText(value);
}

} // namespace

std::string rangeText(const ParamRange& range) {
    const bool low = std::isfinite(range.min), high = std::isfinite(range.max);
    if (low && high)
        return std::string(range.minExclusive ? "(" : "[") + numberText(range.min) + ", " +
               numberText(range.max) + (range.maxExclusive ? ")" : "]");
    if (low) return std::string(range.minExclusive ? "> " : ">= ") + numberText(range.min);
    if (high) return std::string(range.maxExclusive ? "< " : "<= ") + numberText(range.max);
    return "any";
}

std::string fieldHelp(std::string_view description, const ParamRange& range) {
    std::string out(description);
    if (!out.empty()) out += "\n";
    if (range.unit != Unit::None) out += "Unit: " + std::string(unitName(range.unit)) + "\n";
    return out + "Range: " + rangeText(range);
}

ClampedValue clampToField(float value, const FloatFieldRange& range) {
    if (std::isnan(value)) return {range.min, true};
    const float clamped = std::clamp(value, range.min, range.max);
    return {clamped, clamped != value};
}

ClampedInt clampToField(int value, const IntFieldRange& range) {
    const int clamped = std::clamp(value, range.min, range.max);
    return {clamped, clamped != value};
}

std::string clampNotice(const ParamRange& range) {
    const std::string_view symbol = unitSymbol(range.unit);
    return "clamped to " + rangeText(range) + (symbol.empty() ? "" : " " + std::string(symbol));
}

bool clampNoticeShown(double clampedAt, double now) {
    return clampedAt >= 0.0 && now >= clampedAt && now - clampedAt < kClampNoticeSeconds;
}

} // namespace rmsc::editor
