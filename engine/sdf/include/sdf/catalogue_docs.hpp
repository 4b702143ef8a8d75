// Documentation generated from the catalogues, so the docs cannot drift from the code:
// docs/scene-format.md embeds each table verbatim between markers (a unit test checks it).
#pragma once

#include <string>

namespace rmsc {

// A markdown table, one row per catalogue primitive: the "shape" name, each parameter with its
// type, default and valid range, whether the distance is exact or a bound, and a description.
std::string primitiveCatalogueMarkdown();
// One row per modifier: the "type" name, whether it acts on the point or the distance, each
// parameter (type, required or default, valid range with open or closed ends, description) and
// what it does.
std::string modifierCatalogueMarkdown();
// One row per operation: the "op" name, whether it needs "smoothness" and takes "blend", and
// what it makes of the children.
std::string operationCatalogueMarkdown();
// The profile solids ("shape": "extrusion", "revolution") and their keys, then one row per
// profile "type" with its parameters.
std::string profileCatalogueMarkdown();

} // namespace rmsc
