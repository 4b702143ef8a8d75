// The Scene panel (left): buttons that add shapes, groups, lights and meshes; the SDF tree, the
// meshes and the lights, where a click selects and dragging reorders or regroups; and a short
// help text.
#pragma once

#include "document_edits.hpp"
#include "editor/document.hpp"
#include "panel_layout.hpp"
#include "viewer_commands.hpp"

namespace rmsc::app {

// What the panel keeps from one frame to the next.
struct HierarchyPanelState {
    // The active selection the panel last brought into view. A new one (a click in the view, an
    // undo, a new shape) has its groups opened and its row scrolled into view: in a tree of
    // thousands of rows the selected one is otherwise somewhere out of sight.
    editor::Selection revealed;
};

// New shapes go where `place` says.
void drawHierarchyPanel(editor::Document& document, HierarchyPanelState& state,
                        const PanelLayout& layout, const NewShapePlace& place,
                        ViewerCommands& commands);

} // namespace rmsc::app
