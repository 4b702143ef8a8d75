// The main menu bar: File (with Open Recent), Edit, Add, View (what the view shows, the views
// along the axes, orthographic), Camera (framing, the scene camera, bookmarks, roll) and Help,
// and the scene's file name at the right. Items edit the document or the view settings
// themselves, or queue viewer commands; their shortcuts are the shortcut table's
// (editor/shortcut_table.hpp).
#pragma once

#include "document_edits.hpp"
#include "editor/document.hpp"
#include "editor_session.hpp"
#include "messages.hpp"
#include "view_settings.hpp"
#include "viewer_commands.hpp"

#include <filesystem>
#include <vector>

namespace rmsc::app {

// The menus; call between ImGui::BeginMainMenuBar and ImGui::EndMainMenuBar. New shapes go where
// `place` says; the View and Camera menus change the session's view. `exporting`: an export
// runs (File > Export waits for it). `recent`: the recent files, newest first
// (editor/recent_files.hpp); those missing are shown greyed.
void drawMenus(EditorSession& session, ViewSettings& view, const NewShapePlace& place,
               bool exporting, const std::vector<std::filesystem::path>& recent, Messages& messages,
               ViewerCommands& commands);
// The scene's file (or "(unsaved scene)"), with " *" when there are unsaved changes; after the
// menus.
void drawMenuBarTitle(const editor::Document& document);

} // namespace rmsc::app
