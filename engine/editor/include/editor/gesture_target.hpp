// What the move (G), rotate (R) and scale (S) gestures change: the selection's transform at the
// start (an SDF node's in its parent group, a mesh instance's, a light's position and direction
// as editor/light_edits.hpp makes them a transform), and putting the gesture's result back.
// GL-free.
#pragma once

#include "editor/selection.hpp"
#include "editor/transform_gesture.hpp"
#include "scene/scene.hpp"

#include <optional>

namespace rmsc::editor {

struct GestureTarget {
    Transform start;             // in the parent's frame
    glm::mat4 parentWorld{1.0f}; // the parent's world matrix (identity but for SDF nodes)
};

// The selection's transform, or nullopt when nothing is selected or the gesture `kind` would not
// change it (a point light does not rotate, no light scales, a directional light has no place).
std::optional<GestureTarget> gestureTarget(const Scene& scene, const Selection& selection,
                                           GestureKind kind);
// Gives the selection the transform `transform`; false when the selection does not exist.
bool setGestureTransform(Scene& scene, const Selection& selection, const Transform& transform);

} // namespace rmsc::editor
