// Edits of the document that several menus, panels and shortcuts offer, each one undo step
// (the model is editor/scene_edits.hpp).
#pragma once

#include "editor/document.hpp"
#include "sdf/primitives.hpp"

#include <glm/glm.hpp>

namespace rmsc::app {

void addShape(editor::Document& document, const PrimitiveSpec& spec);    // into the selection
void addProfileShape(editor::Document& document, SdfProfileSolid solid); // into the selection
void addGroup(editor::Document& document, SdfOp op);                     // into the selection
// A light of `type` at `position` (where the view looks), selected; nothing at the limit.
void addLight(editor::Document& document, LightType type, glm::vec3 position);
bool canAddLight(const editor::Document& document);
void duplicateSelection(editor::Document& document);
void deleteSelection(editor::Document& document); // nothing when nothing is selected

} // namespace rmsc::app
