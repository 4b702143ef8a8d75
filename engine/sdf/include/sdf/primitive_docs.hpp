// Documentation generated from the primitive catalogue, so the docs cannot drift from the code:
// docs/scene-format.md embeds primitiveCatalogueMarkdown() verbatim (a unit test checks it).
#pragma once

#include <string>

namespace rmsc {

// A markdown table, one row per catalogue primitive: the "shape" name, each parameter with its
// type, default and valid range, whether the distance is exact or a bound, and a description.
std::string primitiveCatalogueMarkdown();

} // namespace rmsc
