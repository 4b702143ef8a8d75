// Shared document edits (see document_edits.hpp).
#include "document_edits.hpp"

#include "core/limits.hpp"
#include "editor/profile_edits.hpp"
#include "editor/scene_edits.hpp"
#include "scene/light_spec.hpp"
#include "sdf/profiles.hpp"

#include <string>

namespace rmsc::app {

using editor::Selection;

void addShape(editor::Document& document, const PrimitiveSpec& spec) {
    document.apply("Add " + std::string(spec.name), [&](Scene& scene, Selection& selection) {
        selection =
            Selection::sdf(editor::insertSdfNode(scene, selection, editor::makeShape(spec.id)));
    });
}

void addGroup(editor::Document& document, SdfOp op) {
    document.apply("Add group", [&](Scene& scene, Selection& selection) {
        selection = Selection::sdf(editor::insertSdfNode(scene, selection, editor::makeGroup(op)));
    });
}

void addProfileShape(editor::Document& document, SdfProfileSolid solid) {
    document.apply("Add " + std::string(profileSolidSpec(solid).name),
                   [&](Scene& scene, Selection& selection) {
                       selection = Selection::sdf(editor::insertSdfNode(
                           scene, selection, editor::makeProfileShape(solid)));
                   });
}

void addLight(editor::Document& document, LightType type, glm::vec3 position) {
    if (!canAddLight(document)) return;
    document.apply("Add " + std::string(lightTypeName(type)) + " light",
                   [&](Scene& scene, Selection& selection) {
                       selection = Selection::light(editor::addLight(scene, type, position));
                   });
}

bool canAddLight(const editor::Document& document) {
    return int(document.scene().lights.size()) < limits::kLights;
}

void duplicateSelection(editor::Document& document) {
    // No copy of a light past the limit, and no empty step in the undo history.
    if (document.selection.kind == editor::SelectionKind::Light && !canAddLight(document)) return;
    document.apply("Duplicate", [](Scene& scene, Selection& selection) {
        selection = editor::duplicateSelected(scene, selection);
    });
}

void deleteSelection(editor::Document& document) {
    if (document.selection.empty()) return;
    document.apply("Delete", [](Scene& scene, Selection& selection) {
        selection = editor::deleteSelected(scene, selection);
    });
}

} // namespace rmsc::app
