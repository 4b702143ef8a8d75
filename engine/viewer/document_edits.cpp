// Shared document edits (see document_edits.hpp).
#include "document_edits.hpp"

#include "editor/scene_edits.hpp"

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

void addLight(editor::Document& document) {
    document.apply("Add light", [](Scene& scene, Selection& selection) {
        selection = Selection::light(editor::addLight(scene));
    });
}

void duplicateSelection(editor::Document& document) {
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
