// The viewer's keys and mouse inputs, in one table: what each does and in which section of the
// sheet it is listed. The shortcut handler (viewer/shortcuts.cpp) carries out the rows whose
// action is a command when their chord is pressed, and the view's handler
// (viewer/view_shortcuts.cpp) the rows of the view's keys (numpad views, orthographic,
// bookmarks); the menus show a command's keys from here; the F1 sheet and docs/viewer.md's key
// list are generated from it (a unit test keeps the docs equal to it). Rows whose action is
// Described are read by the camera or the gestures themselves (viewer/camera_controls.cpp,
// viewer/gesture_controls.cpp, viewport_pick.cpp): they are here so that the sheet and the docs
// list every input. GLFW-free: keys are named.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc::editor {

enum class ShortcutAction {
    // Carried out by the shortcut handler when the row's chord is pressed.
    Undo,
    Redo,
    Duplicate,
    Delete,
    Copy,
    Paste,
    GroupUnion,
    AddSearch, // the searchable add menu, at the mouse
    Open,
    Save,
    SaveAs,
    Screenshot,
    FrameSelection,
    ShortcutSheet, // shows or hides the sheet of every shortcut
    // The view's keys, carried out by the view's handler (viewer/view_shortcuts.cpp).
    ViewFront,
    ViewBack,
    ViewRight,
    ViewLeft,
    ViewTop,
    ViewBottom,
    ToggleOrthographic,
    StoreBookmark,  // the row's slot, 1..9
    RecallBookmark, // the row's slot, 1..9
    // Read by the camera, the gestures or the view's clicks themselves.
    Described,
};

// When a command row's chord counts.
enum class ShortcutScope {
    Always,    // even while a text field is being typed in (function keys)
    NotTyping, // unless a text field is being typed in (Ctrl chords)
    View,      // only while the panels leave the keyboard to the view, no gesture or gizmo drag
               // runs and the right mouse button (flying) is up
};

enum class ShortcutSection { Navigation, Views, Selection, Editing, Files, Help };
// In the order the sheet lists them.
inline constexpr ShortcutSection kShortcutSections[] = {
    ShortcutSection::Navigation, ShortcutSection::Views, ShortcutSection::Selection,
    ShortcutSection::Editing,    ShortcutSection::Files, ShortcutSection::Help};

struct Shortcut {
    std::string_view keys; // a chord ("Ctrl+Shift+Z", "Shift+A", "F12") for command rows; any
                           // text for Described rows ("W / A / S / D", "Alt + left drag")
    ShortcutAction action;
    ShortcutScope scope;
    ShortcutSection section;
    std::string_view description;
    int slot = 0; // a bookmark's (1..9); every slot's row has the same description
};

std::span<const Shortcut> shortcutTable();
// Whether the view's handler, not the command handler, carries out `action`.
bool isViewAction(ShortcutAction action);
std::string_view sectionName(ShortcutSection section); // "Navigation", ...

// A chord: modifier bits (editor/input_queue.hpp's InputModifier) and the key's name as written
// ("Z", "F12", "Delete").
struct Chord {
    int mods = 0;
    std::string key;
};
// "Ctrl+Shift+Z" -> {Ctrl | Shift, "Z"}, "Ctrl+Numpad 1" -> {Ctrl, "Numpad 1"}; nullopt for
// text that is not one chord (two keys, spaces other than a numpad key's, an unknown modifier,
// no key).
std::optional<Chord> parseChord(std::string_view keys);

// The keys of the first row that carries out `action` ("" when none does), for menus.
std::string_view shortcutKeys(ShortcutAction action);

// A line of the sheet: a row of the table, except that the rows of one action that differ only
// in their slot make one line ("Ctrl+1 .. Ctrl+9").
struct SheetLine {
    std::string keys;
    std::string_view description;
    ShortcutSection section;
};
std::vector<SheetLine> shortcutSheetLines();

// The sheet as markdown: one table per section, "| Keys | Does |"; docs/viewer.md holds it
// between <!-- shortcuts:begin --> and <!-- shortcuts:end -->.
std::string shortcutTableMarkdown();

} // namespace rmsc::editor
