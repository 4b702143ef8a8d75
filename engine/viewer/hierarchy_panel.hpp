// The Scene panel (left): buttons that add shapes, groups, lights and meshes; the SDF tree, the
// meshes and the lights, where a click selects and dragging reorders or regroups; and a short
// help text.
#pragma once

#include "editor/document.hpp"
#include "panel_layout.hpp"
#include "viewer_commands.hpp"

namespace rmsc::app {

void drawHierarchyPanel(editor::Document& document, const PanelLayout& layout,
                        ViewerCommands& commands);

} // namespace rmsc::app
