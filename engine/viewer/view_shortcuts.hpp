// The view's camera keys, rows of the one shortcut table (editor/shortcut_table.hpp, section
// Views) that the handler, the View and Camera menus' labels, the F1 sheet and docs/viewer.md
// follow: numpad 1 / 3 / 7 look from the front, the right and the top (with Ctrl from the
// opposite side), numpad 5 switches between a perspective and an orthographic view, Ctrl+1..9
// keep the view as bookmark 1..9 and 1..9 go back to it. What each does to the view is
// applyViewRequest; the menus call it too.
#pragma once

#include "editor/shortcut_table.hpp"
#include "editor_session.hpp"
#include "input_state.hpp"
#include "messages.hpp"

#include <optional>

namespace rmsc::app {

enum class ViewAction {
    FromFront,
    FromBack,
    FromRight,
    FromLeft,
    FromTop,
    FromBottom,
    ToggleOrthographic,
    StoreBookmark,  // slot 1..9
    RecallBookmark, // slot 1..9
    ToggleRoll,     // Q / E roll allowed, or the horizon kept level (and levelled now)
};

struct ViewRequest {
    ViewAction action = ViewAction::FromFront;
    int slot = 0; // the bookmark's
};

// The request a view row of the shortcut table stands for (nullopt for any other row).
std::optional<ViewRequest> viewRequestOf(const editor::Shortcut& row);
// The keys of a request's shortcut, for a menu item ("Numpad 5"), or nullptr when it has none.
const char* viewShortcutKeys(const ViewRequest& request);

// Carries out this frame's view keys, while the panels leave the keyboard to the view and no
// gesture or gizmo drag runs (`busy`).
void handleViewShortcuts(const InputState& input, bool busy, EditorSession& session,
                         Messages& messages);
// What a request does to the view (and the notice it leaves).
void applyViewRequest(EditorSession& session, const ViewRequest& request, Messages& messages);

} // namespace rmsc::app
