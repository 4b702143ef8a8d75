// The ranges of the inspector's number fields, taken from the catalogue rows the scene reader
// checks those values against (sdf/param_spec.hpp for modifiers and profiles, the primitive
// catalogue, the operations' smoothness): a field accepts exactly the values the reader
// accepts. Fields clamp to inclusive float or int ends, so an exclusive end becomes the
// nearest float (or int) inside it, and an unbounded one the largest finite float.
// Each field's tooltip says what the value is, its unit and its range (fieldHelp); a value typed
// outside the range is clamped to it and the field says so for a few seconds (clampToField,
// clampNotice). GL-free.
#pragma once

#include "sdf/param_spec.hpp"
#include "sdf/primitives.hpp"

#include <string>
#include <string_view>

namespace rmsc::editor {

struct FloatFieldRange {
    float min = 0.0f; // inclusive
    float max = 0.0f; // inclusive
};

struct IntFieldRange {
    int min = 0; // inclusive
    int max = 0; // inclusive
};

FloatFieldRange floatFieldRange(const ParamRange& range);
IntFieldRange intFieldRange(const ParamRange& range);
// A primitive parameter's range (each component).
FloatFieldRange primitiveFieldRange(const ParamSpec& param);
// A group's smoothness (sdf/operations.hpp).
FloatFieldRange smoothnessFieldRange();

// A primitive parameter's range and unit as a ParamRange (closed at both ends).
ParamRange primitiveParamRange(const ParamSpec& param);

// The range as the help says it: "[0.001, 10]", "(0, 10000]", "> 0", ">= 0", "<= 10", "any".
std::string rangeText(const ParamRange& range);
// A field's tooltip: `description`, then "Unit: metres" (when it has one) and "Range: ...".
std::string fieldHelp(std::string_view description, const ParamRange& range);

// A value typed into a field, clamped to the field's range (NaN becomes its lower end).
struct ClampedValue {
    float value = 0.0f;
    bool clamped = false; // the value was outside the range
};
ClampedValue clampToField(float value, const FloatFieldRange& range);
struct ClampedInt {
    int value = 0;
    bool clamped = false;
};
ClampedInt clampToField(int value, const IntFieldRange& range);

// What the field says after clamping: "clamped to [0.001, 10] m", "clamped to > 0 m".
std::string clampNotice(const ParamRange& range);
// The notice shows this long after the value was clamped, and goes as soon as a value within
// the range is typed.
inline constexpr double kClampNoticeSeconds = 3.0;
// Whether a notice for a clamp at `clampedAt` (seconds; negative: none) shows at `now`.
bool clampNoticeShown(double clampedAt, double now);

} // namespace rmsc::editor
