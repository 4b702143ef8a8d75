// Selecting several objects: a plain click selects one object alone, a Shift-click adds it to
// the selection (or takes it out again), as in Blender and most 3D tools. The document keeps the
// active object (Document::selection, what the inspector edits) and the others
// (Document::alsoSelected); these functions keep the two consistent. GL-free.
#pragma once

#include "editor/document.hpp"

#include <vector>

namespace rmsc::editor {

// A click on `item` (none: empty space). Without `extend`, `item` becomes the whole selection.
// With it, `item` is added and made active; clicking the active object again takes it out (the
// one added before it becomes active), clicking another selected one makes that active.
void clickSelect(Document& document, const Selection& item, bool extend);

// True when `item` is the active object or one of the others.
bool isSelected(const Document& document, const Selection& item);

// Every selected object, in the order they were added: the others, then the active one last.
std::vector<Selection> selectedItems(const Document& document);

} // namespace rmsc::editor
