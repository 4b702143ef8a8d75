// What the editor has selected: nothing, one SDF node (by its path of child indices from the
// root), one mesh instance or one light (by index). Plain data, compared by value.
#pragma once

#include <vector>

namespace rmsc::editor {

enum class SelectionKind { None, Sdf, Mesh, Light };

struct Selection {
    SelectionKind kind = SelectionKind::None;
    std::vector<int> sdfPath; // Sdf: child indices from the root; empty = the root itself
    int index = -1;           // Mesh / Light: index into Scene::meshes / Scene::lights

    static Selection none() { return {}; }
    static Selection sdf(std::vector<int> path) {
        return {SelectionKind::Sdf, std::move(path), -1};
    }
    static Selection mesh(int i) { return {SelectionKind::Mesh, {}, i}; }
    static Selection light(int i) { return {SelectionKind::Light, {}, i}; }

    bool empty() const { return kind == SelectionKind::None; }
    bool operator==(const Selection&) const = default;
};

} // namespace rmsc::editor
