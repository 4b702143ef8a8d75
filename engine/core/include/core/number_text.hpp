// Numbers as text for messages and generated docs: the shortest decimal that reads back as the
// same value, in plain digits for everyday magnitudes (100000, not 1e+05; 0.15f as "0.15").
#pragma once

#include <string>

namespace rmsc {

std::string shortestNumberText(float value);
std::string shortestNumberText(double value);

// The float with the fewest significant digits (at most 7) within `ulps` floats of `value`:
// 30.000002f gives 30, -0.099999994f gives -0.1 (what float arithmetic on short decimals leaves
// a step off). Not finite, or nothing shorter near it: `value`.
float nearestShortDecimal(float value, int ulps = 2);

} // namespace rmsc
