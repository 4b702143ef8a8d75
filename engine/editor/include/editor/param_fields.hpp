// The ranges of the inspector's number fields, taken from the catalogue rows the scene reader
// checks those values against (sdf/param_spec.hpp for modifiers and profiles, the primitive
// catalogue, the operations' smoothness): a field accepts exactly the values the reader
// accepts. Fields clamp to inclusive float or int ends, so an exclusive end becomes the
// nearest float (or int) inside it, and an unbounded one the largest finite float. GL-free.
#pragma once

#include "sdf/param_spec.hpp"
#include "sdf/primitives.hpp"

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

} // namespace rmsc::editor
