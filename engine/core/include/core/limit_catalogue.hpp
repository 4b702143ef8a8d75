// The limit catalogue: one row per constant of core/limits.hpp, saying what it bounds and what
// happens over it. `rmsc limits` prints it; docs/limits.md embeds limitCatalogueMarkdown()
// verbatim (a unit test checks it).
#pragma once

#include <span>
#include <string>

namespace rmsc {

struct Limit {
    const char* name;     // "Scene file size"
    double value;         // the constant's value (exact: every limit is a whole number)
    const char* unit;     // "bytes", "levels", "pixels a side", ...; "" for a plain count
    const char* bounds;   // what the limit applies to
    const char* exceeded; // what happens over it: where the input is refused, or what changes
    const char* constant; // its name in core/limits.hpp: "kSceneFileBytes"
};

std::span<const Limit> limitCatalogue();

// "64 MiB (67108864 bytes)", "256 levels", "16777216 (16 Mi)".
std::string limitValueText(const Limit& limit);

// The table of docs/limits.md: Limit, Value, Applies to, When exceeded.
std::string limitCatalogueMarkdown();

} // namespace rmsc
