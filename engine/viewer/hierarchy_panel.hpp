// The Scene panel (left): buttons that add shapes, groups, lights and meshes; the SDF tree, the
// meshes and the lights, where a click selects and dragging reorders or regroups; and a short
// help text.
#pragma once

#include "document_edits.hpp"
#include "editor/document.hpp"
#include "panel_layout.hpp"
#include "viewer_commands.hpp"

namespace rmsc::app {

// New shapes go where `place` says.
void drawHierarchyPanel(editor::Document& document, const PanelLayout& layout,
                        const NewShapePlace& place, ViewerCommands& commands);

} // namespace rmsc::app
