// What gestures change (see gesture_target.hpp).
#include "editor/gesture_target.hpp"

#include "editor/light_edits.hpp"
#include "editor/scene_edits.hpp"

namespace rmsc::editor {

std::optional<GestureTarget> gestureTarget(const Scene& scene, const Selection& selection,
                                           GestureKind kind) {
    if (!selectionValid(scene, selection)) return std::nullopt;
    switch (selection.kind) {
    case SelectionKind::Sdf:
        return GestureTarget{findSdfNode(scene, selection.sdfPath)->transform,
                             sdfParentWorldMatrix(scene, selection.sdfPath)};
    case SelectionKind::Mesh:
        return GestureTarget{scene.meshes[std::size_t(selection.index)].transform};
    case SelectionKind::Light: {
        const Light& light = scene.lights[std::size_t(selection.index)];
        if (!gestureChangesLight(light.type, kind)) return std::nullopt;
        return GestureTarget{lightTransform(light)};
    }
    case SelectionKind::None:
        break;
    }
    return std::nullopt;
}

bool setGestureTransform(Scene& scene, const Selection& selection, const Transform& transform) {
    if (!selectionValid(scene, selection)) return false;
    switch (selection.kind) {
    case SelectionKind::Sdf:
        findSdfNode(scene, selection.sdfPath)->transform = transform;
        return true;
    case SelectionKind::Mesh:
        scene.meshes[std::size_t(selection.index)].transform = transform;
        return true;
    case SelectionKind::Light:
        setLightTransform(scene.lights[std::size_t(selection.index)], transform);
        return true;
    case SelectionKind::None:
        break;
    }
    return false;
}

} // namespace rmsc::editor
