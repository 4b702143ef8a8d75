// Edits of the document that several menus, panels and shortcuts offer, each one undo step
// (the model is editor/scene_edits.hpp).
#pragma once

#include "editor/document.hpp"
#include "sdf/primitives.hpp"

namespace rmsc::app {

void addShape(editor::Document& document, const PrimitiveSpec& spec); // into the selection
void addGroup(editor::Document& document, SdfOp op);                  // into the selection
void addLight(editor::Document& document);
void duplicateSelection(editor::Document& document);
void deleteSelection(editor::Document& document); // nothing when nothing is selected

} // namespace rmsc::app
