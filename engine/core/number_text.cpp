// Shortest round-trip number text (core/number_text.hpp), by std::to_chars.
#include "core/number_text.hpp"

#include <charconv>
#include <cmath>

namespace rmsc {
namespace {

// Exponents only for extremes.
template <typename T> std::string shortestText(T value) {
    char buffer[128];
    const T magnitude = value < 0 ? -value : value;
    const bool fixed = magnitude == 0 || (magnitude >= T(1e-5) && magnitude < T(1e15));
    const auto result =
        fixed ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
              : std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

} // namespace

std::string shortestNumberText(float value) {
    return shortestText(value);
}

std::string shortestNumberText(double value) {
    return shortestText(value);
}

float nearestShortDecimal(float value, int ulps) {
    if (!std::isfinite(value)) return value;
    float low = value, high = value;
    for (int i = 0; i < ulps; ++i) {
        low = std::nextafter(low, -INFINITY);
        high = std::nextafter(high, INFINITY);
    }
    for (int digits = 1; digits <= 7; ++digits) {
        char buffer[64];
        const auto written = std::to_chars(buffer, buffer + sizeof buffer, value,
                                           std::chars_format::scientific, digits - 1);
        float rounded = value;
        std::from_chars(buffer, written.ptr, rounded);
        if (rounded >= low && rounded <= high) return rounded;
    }
    return value;
}

} // namespace rmsc
