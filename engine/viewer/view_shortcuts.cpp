// The view's camera keys and what they do (see view_shortcuts.hpp).
#include "view_shortcuts.hpp"

#include "shortcuts.hpp"

#include <string>

namespace rmsc::app {
namespace {

editor::AxisView axisViewOf(ViewAction action) {
    switch (action) {
    case ViewAction::FromBack:
        return editor::AxisView::Back;
    case ViewAction::FromRight:
        return editor::AxisView::Right;
    case ViewAction::FromLeft:
        return editor::AxisView::Left;
    case ViewAction::FromTop:
        return editor::AxisView::Top;
    case ViewAction::FromBottom:
        return editor::AxisView::Bottom;
    default:
        return editor::AxisView::Front;
    }
}

} // namespace

std::optional<ViewRequest> viewRequestOf(const editor::Shortcut& row) {
    using editor::ShortcutAction;
    switch (row.action) {
    case ShortcutAction::ViewFront:
        return ViewRequest{ViewAction::FromFront};
    case ShortcutAction::ViewBack:
        return ViewRequest{ViewAction::FromBack};
    case ShortcutAction::ViewRight:
        return ViewRequest{ViewAction::FromRight};
    case ShortcutAction::ViewLeft:
        return ViewRequest{ViewAction::FromLeft};
    case ShortcutAction::ViewTop:
        return ViewRequest{ViewAction::FromTop};
    case ShortcutAction::ViewBottom:
        return ViewRequest{ViewAction::FromBottom};
    case ShortcutAction::ToggleOrthographic:
        return ViewRequest{ViewAction::ToggleOrthographic};
    case ShortcutAction::StoreBookmark:
        return ViewRequest{ViewAction::StoreBookmark, row.slot};
    case ShortcutAction::RecallBookmark:
        return ViewRequest{ViewAction::RecallBookmark, row.slot};
    default:
        return std::nullopt;
    }
}

const char* viewShortcutKeys(const ViewRequest& request) {
    for (const editor::Shortcut& row : editor::shortcutTable()) {
        const std::optional<ViewRequest> r = viewRequestOf(row);
        if (r && r->action == request.action && r->slot == request.slot)
            return row.keys.data(); // the table's literals end in NUL
    }
    return nullptr;
}

void handleViewShortcuts(const InputState& input, bool busy, EditorSession& session,
                         Messages& messages) {
    for (const BoundShortcut& s : boundShortcuts())
        if (const std::optional<ViewRequest> request = viewRequestOf(*s.row))
            if (shortcutPressed(s, input, busy)) applyViewRequest(session, *request, messages);
}

void applyViewRequest(EditorSession& session, const ViewRequest& request, Messages& messages) {
    editor::FlyCamera& camera = session.camera;
    switch (request.action) {
    case ViewAction::FromFront:
    case ViewAction::FromBack:
    case ViewAction::FromRight:
    case ViewAction::FromLeft:
    case ViewAction::FromTop:
    case ViewAction::FromBottom:
        camera.viewFrom(axisViewOf(request.action));
        break;
    case ViewAction::ToggleOrthographic:
        camera.setOrthographic(!camera.orthographic, session.sceneCamera.fovYDegrees);
        break;
    case ViewAction::StoreBookmark:
        if (session.bookmarks.store(request.slot, session.viewCamera()))
            messages.notice("view kept as bookmark " + std::to_string(request.slot) + " (press " +
                            std::to_string(request.slot) + " to go back to it)");
        break;
    case ViewAction::RecallBookmark:
        if (const std::optional<Camera> view = session.bookmarks.recall(request.slot))
            camera.setFromCamera(*view);
        else
            messages.notice("no bookmark " + std::to_string(request.slot) + " yet (Ctrl+" +
                            std::to_string(request.slot) + " keeps the view as one)");
        break;
    case ViewAction::ToggleRoll:
        camera.allowRoll = !camera.allowRoll;
        if (!camera.allowRoll) camera.level();
        break;
    }
}

} // namespace rmsc::app
