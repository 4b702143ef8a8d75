// Deleting and grouping everything selected (see selection_edits.hpp).
#include "editor/selection_edits.hpp"

#include "editor/scene_edits.hpp"
#include "editor/world_placement.hpp"
#include "sdf/operations.hpp"

#include <algorithm>
#include <functional>

namespace rmsc::editor {
namespace {

bool isPrefix(const std::vector<int>& prefix, const std::vector<int>& path) {
    return prefix.size() <= path.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
}

std::vector<int> indicesOf(const std::vector<Selection>& items, SelectionKind kind) {
    std::vector<int> indices;
    for (const Selection& item : items)
        if (item.kind == kind) indices.push_back(item.index);
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    return indices;
}

// Deletes the nodes at `paths` (none inside another), the last in tree order first: removing a
// node (and a group it leaves empty) moves no node that comes before it.
void deleteSdfPaths(Scene& scene, std::vector<std::vector<int>> paths) {
    std::sort(paths.begin(), paths.end());
    for (auto it = paths.rbegin(); it != paths.rend(); ++it)
        deleteSdfNode(scene, *it);
}

} // namespace

std::vector<std::vector<int>> outermostSdfPaths(const Scene& scene,
                                                const std::vector<Selection>& items) {
    std::vector<std::vector<int>> paths;
    for (const Selection& item : items)
        if (item.kind == SelectionKind::Sdf && findSdfNode(scene, item.sdfPath))
            paths.push_back(item.sdfPath);
    // Lexicographic order of child indices is the tree's pre-order; an ancestor sorts first.
    std::sort(paths.begin(), paths.end());
    paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
    std::vector<std::vector<int>> outermost;
    for (const std::vector<int>& path : paths)
        if (outermost.empty() || !isPrefix(outermost.back(), path)) outermost.push_back(path);
    return outermost;
}

void deleteItems(Scene& scene, const std::vector<Selection>& items) {
    deleteSdfPaths(scene, outermostSdfPaths(scene, items));
    const std::vector<int> meshes = indicesOf(items, SelectionKind::Mesh);
    for (auto it = meshes.rbegin(); it != meshes.rend(); ++it)
        deleteMesh(scene, *it);
    const std::vector<int> lights = indicesOf(items, SelectionKind::Light);
    for (auto it = lights.rbegin(); it != lights.rend(); ++it)
        deleteLight(scene, *it);
}

std::optional<std::vector<int>> groupItems(Scene& scene, const std::vector<Selection>& items,
                                           SdfOp op) {
    const std::vector<std::vector<int>> paths = outermostSdfPaths(scene, items);
    if (paths.empty()) return std::nullopt;
    SdfNode group;
    group.name = "group";
    group.isGroup = true;
    group.op = op;
    if (takesSmoothness(op)) group.smoothness = 0.1f;
    if (paths.front().empty()) { // the root: the whole tree goes into the new group
        group.children.push_back(std::move(*scene.sdf));
        scene.sdf = std::move(group);
        return std::vector<int>{};
    }
    // The group goes where the first node is; every other selected node comes after it in tree
    // order, so none is before it in its parent.
    const std::vector<int> parent(paths.front().begin(), paths.front().end() - 1);
    const int at = paths.front().back();
    const glm::mat4 toParent = glm::inverse(sdfWorldMatrix(scene, parent));
    for (const std::vector<int>& path : paths) {
        SdfNode node = *findSdfNode(scene, path);
        if (std::vector<int>(path.begin(), path.end() - 1) != parent) {
            node.transform = transformFromMatrix(toParent * sdfWorldMatrix(scene, path));
            node.material = effectiveMaterial(scene, path);
        }
        group.children.push_back(std::move(node));
    }
    SdfNode* parentNode = findSdfNode(scene, parent);
    parentNode->children.insert(parentNode->children.begin() + at, std::move(group));
    // The moved nodes' old places, one further on where they follow the group in its parent.
    std::vector<std::vector<int>> old = paths;
    for (std::vector<int>& path : old)
        if (isPrefix(parent, path) && path[parent.size()] >= at) ++path[parent.size()];
    deleteSdfPaths(scene, old);
    std::vector<int> groupPath = parent;
    groupPath.push_back(at);
    return groupPath;
}

} // namespace rmsc::editor
