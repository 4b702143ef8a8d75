// One JSON key of a catalogue row that the scene format reads by name (the parameters of
// modifiers, profiles and profile solids): its type, whether it is required, its default, the
// valid range of its numbers and the text that describes it. The scene reader, the writer, the
// schema and the docs tables all take these from the catalogues (sdf/modifiers.hpp,
// sdf/profiles.hpp), so they cannot disagree.
#pragma once

#include "core/units.hpp"

#include <array>
#include <limits>
#include <string>
#include <string_view>

namespace rmsc {

enum class ParamType {
    Number,  // a JSON number
    Integer, // a JSON number without a fraction
    Vec2,    // [x, y]
    Vec3,    // [x, y, z]
    IVec3,   // [x, y, z] of integers
    Bool,    // true or false
    Axes,    // a string of one to three different axes among "x", "y", "z", e.g. "xz"
    Axis,    // "x", "y" or "z" (stored as 0, 1, 2)
    Points,  // an array of [x, y] points (a polygon's corners)
};

// The valid values of each number of a parameter (each component, element or coordinate), and
// their unit; each end is inclusive unless marked exclusive.
struct ParamRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minExclusive = false;
    bool maxExclusive = false;
    Unit unit = Unit::None; // what the docs and the inspector write after the numbers
};

constexpr ParamRange closedRange(double lo, double hi, Unit unit = Unit::None) {
    return {lo, hi, false, false, unit};
}
// (lo, hi]: lengths that must not be 0.
constexpr ParamRange openClosedRange(double lo, double hi, Unit unit = Unit::None) {
    return {lo, hi, true, false, unit};
}
// Any number, in `unit`.
constexpr ParamRange unboundedRange(Unit unit) {
    return {.unit = unit};
}

struct SdfParamSpec {
    std::string_view key; // JSON key, e.g. "period"
    ParamType type;
    bool required = false; // a missing key is an error: missing "key" (description)
    // Default of an optional parameter, per component; Bool 0 or 1, Axis 0, 1 or 2.
    std::array<float, 3> value{};
    ParamRange range{}; // of each number; unbounded where not given
    // What the value is, with its units: ends the reader's "missing" message and describes
    // the key in the docs and the schema.
    std::string_view description;
    // How range errors name the value ("expected a period in [0, 10000]"); "" for "a number".
    std::string_view noun = {};
    // false: the writer leaves the key out while it holds its default (a feature turned off).
    bool writtenAtDefault = true;
};

// A problem of a row's values that the parameters' own ranges cannot catch (a catalogue row's
// `check`): at `key` of the object, at element `element` of it (-1: the whole value).
struct ParamProblem {
    std::string_view key;
    int element = -1;
    std::string message;
};

} // namespace rmsc
