// Shared document edits (see document_edits.hpp).
#include "document_edits.hpp"

#include "core/limits.hpp"
#include "editor/clipboard.hpp"
#include "editor/multi_selection.hpp"
#include "editor/new_object_place.hpp"
#include "editor/profile_edits.hpp"
#include "editor/scene_edits.hpp"
#include "editor/selection_edits.hpp"
#include "render/frame.hpp"
#include "scene/light_spec.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"

#include <string>

namespace rmsc::app {

using editor::Selection;

editor::NewObjectSpot newShapeSpot(const NewShapePlace& place) {
    // The ray through the view's centre, as the march pass builds it (from the centre of the
    // near plane for an orthographic view), between the near and the far plane.
    const FrameCamera frame = makeFrameCamera(place.camera, 2, 2);
    editor::PickRay ray;
    ray.origin = pixelRayOrigin(frame, 0.5f, 0.5f, 2, 2);
    ray.direction = frame.forward;
    ray.tMin = place.camera.nearPlane;
    ray.tMax = place.camera.farPlane;
    return editor::newObjectSpot(place.prepared, ray, place.fallbackDistance);
}

namespace {

// Adds `node` into the selection with its origin at the new shape's point, selected.
void addPlacedNode(editor::Document& document, const std::string& label, SdfNode node,
                   const NewShapePlace& place) {
    const editor::NewObjectSpot spot = newShapeSpot(place);
    document.apply(label, [&](Scene& scene, Selection& selection) {
        const std::vector<int> path = editor::insertSdfNode(scene, selection, std::move(node));
        editor::placeSdfNodeOn(scene, path, spot);
        selection = Selection::sdf(path);
    });
}

} // namespace

void addShape(editor::Document& document, const PrimitiveSpec& spec, const NewShapePlace& place) {
    addPlacedNode(document, "Add " + std::string(spec.name), editor::makeShape(spec.id), place);
}

void addGroup(editor::Document& document, SdfOp op) {
    document.apply("Add group", [&](Scene& scene, Selection& selection) {
        selection = Selection::sdf(editor::insertSdfNode(scene, selection, editor::makeGroup(op)));
    });
}

void addProfileShape(editor::Document& document, SdfProfileSolid solid,
                     const NewShapePlace& place) {
    addPlacedNode(document, "Add " + std::string(profileSolidSpec(solid).name),
                  editor::makeProfileShape(solid), place);
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
    const std::vector<Selection> items = editor::selectedItems(document);
    document.applyToSelection("Delete",
                              [&](Scene& scene, Selection& active, std::vector<Selection>& also) {
                                  editor::deleteItems(scene, items);
                                  active = Selection::none();
                                  also.clear();
                              });
}

bool groupSelection(editor::Document& document, SdfOp op) {
    const std::vector<Selection> items = editor::selectedItems(document);
    if (editor::outermostSdfPaths(document.scene(), items).empty()) return false;
    document.applyToSelection("Group into " + operationLabel(op),
                              [&](Scene& scene, Selection& active, std::vector<Selection>& also) {
                                  also.clear();
                                  if (auto group = editor::groupItems(scene, items, op))
                                      active = Selection::sdf(*group);
                              });
    return true;
}

bool pasteText(editor::Document& document, std::string_view text, std::string& message) {
    const std::optional<Scene> clip = editor::parseClipboardText(text, message);
    if (!clip) return false;
    if (!clip->sdf && clip->meshes.empty() && clip->lights.empty()) {
        message = "the clipboard's scene holds no objects, so nothing was pasted";
        return false;
    }
    editor::PasteResult result;
    document.applyToSelection("Paste",
                              [&](Scene& scene, Selection& active, std::vector<Selection>& also) {
                                  result = editor::pasteClip(scene, active, *clip);
                                  also = result.pasted;
                                  active = Selection::none();
                                  if (!also.empty()) {
                                      active = also.back();
                                      also.pop_back();
                                  }
                              });
    message = "pasted " + std::to_string(result.pasted.size()) + " object" +
              (result.pasted.size() == 1 ? "" : "s");
    if (result.lightsLeftOut > 0)
        message += "; " + std::to_string(result.lightsLeftOut) +
                   " light(s) left out: a scene holds at most " + std::to_string(limits::kLights) +
                   " lights";
    return true;
}

} // namespace rmsc::app
