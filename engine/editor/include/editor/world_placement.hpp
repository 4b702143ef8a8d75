// Keeping an SDF node where it is while it changes parent (grouping, pasting): its world matrix
// turned back into a position, rotation and scale under the new parent, and the material it
// shows when it inherits one. GL-free.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace rmsc::editor {

// The transform whose matrix() is `m`, for a matrix made of a translation, a rotation and a
// scale along the rotated axes (any product of Transform matrices with uniform scales is one).
// A sheared matrix (non-uniform scales under a rotation) gets the nearest such transform: the
// columns' lengths as the scale and their orthonormalised directions as the rotation.
Transform transformFromMatrix(const glm::mat4& m);

// The material the node at `path` is drawn with: its own, or the nearest group's above it that
// sets one; -1 (the default material) when none does or the path does not exist.
int effectiveMaterial(const Scene& scene, const std::vector<int>& path);

} // namespace rmsc::editor
