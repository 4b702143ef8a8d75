// The main menu bar: File, Edit, Add, View and Camera, and the scene's file name at the right.
// Items edit the document or the view settings themselves, or queue viewer commands.
#pragma once

#include "editor/document.hpp"
#include "view_settings.hpp"
#include "viewer_commands.hpp"

namespace rmsc::app {

// The menus; call between ImGui::BeginMainMenuBar and ImGui::EndMainMenuBar. `exporting`: an
// export runs (File > Export waits for it).
void drawMenus(editor::Document& document, ViewSettings& view, bool exporting,
               ViewerCommands& commands);
// The scene's file (or "(unsaved scene)"), with " *" when there are unsaved changes; after the
// menus.
void drawMenuBarTitle(const editor::Document& document);

} // namespace rmsc::app
