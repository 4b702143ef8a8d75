// Edits of everything selected at once (the active object and the others Shift-click added,
// editor/multi_selection.hpp): deleting them all, and grouping the selected SDF nodes into a new
// group of a chosen operation. Each keeps the scene valid to compile. GL-free.
#pragma once

#include "editor/selection.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <vector>

namespace rmsc::editor {

// Deletes every item (SDF nodes, meshes, lights; a node inside a deleted group goes with it).
void deleteItems(Scene& scene, const std::vector<Selection>& items);

// The SDF nodes among `items` that are not inside another of them, in tree (pre-)order.
std::vector<std::vector<int>> outermostSdfPaths(const Scene& scene,
                                                const std::vector<Selection>& items);

// Moves the selected SDF nodes (outermostSdfPaths; meshes and lights are left alone) into a new
// group of `op` put where the first of them was, in its parent. Each keeps its place in the
// world (its transform is rewritten for the new parent) and the material it was drawn with.
// Selecting the root wraps the whole tree. Returns the group's path, or nullopt (nothing
// changed) when no SDF node is among `items`.
std::optional<std::vector<int>> groupItems(Scene& scene, const std::vector<Selection>& items,
                                           SdfOp op);

} // namespace rmsc::editor
