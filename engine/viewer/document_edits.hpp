// Edits of the document that several menus, panels and shortcuts offer, each one undo step
// (the model is editor/scene_edits.hpp).
#pragma once

#include "editor/new_object_place.hpp"

#include "editor/document.hpp"
#include "prepare/prepared_scene.hpp"
#include "sdf/primitives.hpp"

#include <glm/glm.hpp>

#include <string>
#include <string_view>

namespace rmsc::app {

// What decides where a new shape goes (editor/new_object_place.hpp): the view's camera and
// the newest scene that compiled (nullptr: none yet), looked at only when a shape is added.
struct NewShapePlace {
    const PreparedScene* prepared = nullptr;
    Camera camera;                 // the view
    float fallbackDistance = 5.0f; // along the view when its centre ray meets nothing
};
// The world point under the view's centre (on the surface it meets, with its normal, else at
// the fallback distance).
editor::NewObjectSpot newShapeSpot(const NewShapePlace& place);

// A shape into the selection (its group, or next to it), resting on newShapeSpot(place).
void addShape(editor::Document& document, const PrimitiveSpec& spec, const NewShapePlace& place);
void addProfileShape(editor::Document& document, SdfProfileSolid solid, const NewShapePlace& place);
void addGroup(editor::Document& document, SdfOp op); // into the selection
// A light of `type` at `position` (where the view looks), selected; nothing at the limit.
void addLight(editor::Document& document, LightType type, glm::vec3 position);
bool canAddLight(const editor::Document& document);
void duplicateSelection(editor::Document& document); // the active object
void deleteSelection(editor::Document& document);    // everything selected; nothing when none
// The selected SDF nodes into a new group of `op` (editor/selection_edits.hpp), selected; false
// (nothing changed, no undo step) when no SDF node is selected.
bool groupSelection(editor::Document& document, SdfOp op);
// Pastes clipboard text (editor/clipboard.hpp) next to the active object and selects what it
// added. False with `message` saying why when the text is not a scene's; otherwise `message`
// says what was pasted (and how many lights did not fit).
bool pasteText(editor::Document& document, std::string_view text, std::string& message);

} // namespace rmsc::app
