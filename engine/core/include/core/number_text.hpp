// Numbers as text for messages and generated docs: the shortest decimal that reads back as the
// same value, in plain digits for everyday magnitudes (100000, not 1e+05; 0.15f as "0.15").
#pragma once

#include <string>

namespace rmsc {

std::string shortestNumberText(float value);
std::string shortestNumberText(double value);

} // namespace rmsc
