// The table of the viewer's keys and mouse inputs (see editor/shortcut_table.hpp).
#include "editor/shortcut_table.hpp"

#include "editor/input_queue.hpp"

#include <cctype>

namespace rmsc::editor {
namespace {

using A = ShortcutAction;
using W = ShortcutScope;
using S = ShortcutSection;

constexpr std::string_view kKeepBookmark =
    "keep the view (place, direction, roll, projection) as the bookmark of that digit, for the "
    "session";
constexpr std::string_view kGoToBookmark = "go back to the bookmark of that digit";

// In the order the sheet lists them, section by section.
constexpr Shortcut kShortcuts[] = {
    {"Right mouse button held + mouse", A::Described, W::View, S::Navigation, "look around"},
    {"W / A / S / D", A::Described, W::View, S::Navigation,
     "fly forward / left / back / right (S scales a selection unless the right button is held)"},
    {"Space / Left Shift", A::Described, W::View, S::Navigation,
     "up / down (Left Shift only with the right button held: alone it is for Shift+click)"},
    {"Shift with a movement key", A::Described, W::View, S::Navigation, "4x speed"},
    {"Q / E", A::Described, W::View, S::Navigation,
     "roll, only with Camera > Allow roll on (off by default: the horizon stays level, and "
     "looking or orbiting stops at straight up or down; turning roll off levels the view)"},
    {"Mouse wheel over the view", A::Described, W::View, S::Navigation,
     "fly speed (x1.25 per notch); in an orthographic view, zoom (1.25 times less or more height "
     "per notch)"},
    {"Alt + left drag", A::Described, W::View, S::Navigation, "orbit around the selection"},
    {"F", A::FrameSelection, W::View, S::Navigation,
     "frame the selection (or the whole SDF); an orthographic view also takes its height"},

    // Blender's numpad views (with +Y up), at the point the view looked at, from as far.
    {"Numpad 1", A::ViewFront, W::View, S::Views, "look from the front (down -Z)"},
    {"Ctrl+Numpad 1", A::ViewBack, W::View, S::Views, "look from the back (down +Z)"},
    {"Numpad 3", A::ViewRight, W::View, S::Views, "look from the right (down -X)"},
    {"Ctrl+Numpad 3", A::ViewLeft, W::View, S::Views, "look from the left (down +X)"},
    {"Numpad 7", A::ViewTop, W::View, S::Views, "look from the top (down -Y, -Z up on screen)"},
    {"Ctrl+Numpad 7", A::ViewBottom, W::View, S::Views, "look from the bottom (up +Y)"},
    {"Numpad 5", A::ToggleOrthographic, W::View, S::Views,
     "switch between perspective and orthographic (the focus plane keeps its size)"},
    {"Ctrl+1", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 1},
    {"Ctrl+2", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 2},
    {"Ctrl+3", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 3},
    {"Ctrl+4", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 4},
    {"Ctrl+5", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 5},
    {"Ctrl+6", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 6},
    {"Ctrl+7", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 7},
    {"Ctrl+8", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 8},
    {"Ctrl+9", A::StoreBookmark, W::View, S::Views, kKeepBookmark, 9},
    {"1", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 1},
    {"2", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 2},
    {"3", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 3},
    {"4", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 4},
    {"5", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 5},
    {"6", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 6},
    {"7", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 7},
    {"8", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 8},
    {"9", A::RecallBookmark, W::View, S::Views, kGoToBookmark, 9},

    {"Click", A::Described, W::View, S::Selection,
     "select what is under the mouse (empty space: nothing)"},
    {"Shift+click", A::Described, W::View, S::Selection,
     "add to the selection, or make a selected object the active one (in the view and the Scene "
     "panel)"},

    {"Shift+A", A::AddSearch, W::View, S::Editing,
     "add menu at the mouse: type to search every shape, group, light and mesh; arrows and Enter"},
    {"Left drag on a gizmo handle", A::Described, W::View, S::Editing,
     "move / rotate / scale the selection along it (the tool is the view toolbar's; Ctrl held "
     "snaps to the toolbar's steps; Esc / right click cancels)"},
    {"G", A::Described, W::View, S::Editing, "move the selection with the mouse"},
    {"R", A::Described, W::View, S::Editing, "rotate the selection with the mouse"},
    {"S", A::Described, W::View, S::Editing, "scale the selection with the mouse"},
    {"X / Y / Z", A::Described, W::View, S::Editing,
     "during G / R / S: constrain to that axis (again: free)"},
    {"Ctrl held", A::Described, W::View, S::Editing,
     "during G / R / S: snap to the toolbar's steps (0.1 m, 15 degrees, 0.1 of the scale by "
     "default)"},
    {"Click / Enter", A::Described, W::View, S::Editing, "during G / R / S: keep the result"},
    {"Esc / right click", A::Described, W::View, S::Editing, "during G / R / S: cancel"},
    {"Ctrl+Z", A::Undo, W::NotTyping, S::Editing, "undo"},
    {"Ctrl+Shift+Z", A::Redo, W::NotTyping, S::Editing, "redo"},
    {"Ctrl+Y", A::Redo, W::NotTyping, S::Editing, "redo"},
    {"Ctrl+D", A::Duplicate, W::NotTyping, S::Editing, "duplicate the active object"},
    {"Delete", A::Delete, W::View, S::Editing, "delete everything selected"},
    {"Ctrl+C", A::Copy, W::NotTyping, S::Editing,
     "copy the selection to the system clipboard (as scene-file text)"},
    {"Ctrl+V", A::Paste, W::NotTyping, S::Editing,
     "paste the clipboard's objects next to the active object"},
    {"Ctrl+G", A::GroupUnion, W::NotTyping, S::Editing,
     "group the selected SDF nodes into a new union (Edit > Group selection: any operation)"},

    {"Ctrl+O", A::Open, W::NotTyping, S::Files, "open a scene file"},
    {"Ctrl+S", A::Save, W::NotTyping, S::Files, "save (Save As when the scene has no file yet)"},
    {"Ctrl+Shift+S", A::SaveAs, W::NotTyping, S::Files, "save as"},
    {"F12", A::Screenshot, W::Always, S::Files, "screenshot of the view, next to the scene file"},
    {"Drop a file on the window", A::Described, W::Always, S::Files,
     ".gltf / .glb: add it as a mesh where a new shape goes; .json: open it (asks first when "
     "there are unsaved changes)"},

    {"F1", A::ShortcutSheet, W::Always, S::Help, "show or hide this sheet of every shortcut"},
    {"Hover a field", A::Described, W::Always, S::Help,
     "its meaning, unit and valid range (a typed value outside it is clamped, and the field "
     "says so)"},
};

std::string_view trim(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.remove_suffix(1);
    return text;
}

int modifierNamed(std::string_view name) {
    if (name == "Ctrl") return kModCtrl;
    if (name == "Shift") return kModShift;
    if (name == "Alt") return kModAlt;
    if (name == "Super") return kModSuper;
    return 0;
}

// "Numpad 0" .. "Numpad 9": the one key name with a space.
bool isNumpadKey(std::string_view key) {
    return key.size() == 8 && key.substr(0, 7) == "Numpad " && key[7] >= '0' && key[7] <= '9';
}

// Table cells must not contain a bare "|".
std::string cell(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out;
}

} // namespace

std::span<const Shortcut> shortcutTable() {
    return kShortcuts;
}

bool isViewAction(ShortcutAction action) {
    switch (action) {
    case A::ViewFront:
    case A::ViewBack:
    case A::ViewRight:
    case A::ViewLeft:
    case A::ViewTop:
    case A::ViewBottom:
    case A::ToggleOrthographic:
    case A::StoreBookmark:
    case A::RecallBookmark:
        return true;
    default:
        return false;
    }
}

std::string_view sectionName(ShortcutSection section) {
    switch (section) {
    case S::Navigation:
        return "Navigation";
    case S::Views:
        return "Views";
    case S::Selection:
        return "Selection";
    case S::Editing:
        return "Editing";
    case S::Files:
        return "Files";
    case S::Help:
        return "Help";
    }
    return "";
}

std::optional<Chord> parseChord(std::string_view keys) {
    Chord chord;
    while (true) {
        const std::size_t plus = keys.find('+');
        const std::string_view part = keys.substr(0, plus);
        if (part.empty() || part != trim(part)) return std::nullopt;
        if (!isNumpadKey(part))
            for (char c : part)
                if (std::isspace(static_cast<unsigned char>(c))) return std::nullopt;
        if (plus == std::string_view::npos) {
            if (modifierNamed(part)) return std::nullopt; // a modifier alone is no chord
            chord.key = std::string(part);
            return chord;
        }
        const int bit = modifierNamed(part);
        if (!bit || (chord.mods & bit)) return std::nullopt;
        chord.mods |= bit;
        keys.remove_prefix(plus + 1);
    }
}

std::string_view shortcutKeys(ShortcutAction action) {
    if (action == A::Described) return "";
    for (const Shortcut& s : kShortcuts)
        if (s.action == action) return s.keys;
    return "";
}

std::vector<SheetLine> shortcutSheetLines() {
    std::vector<SheetLine> lines;
    const Shortcut* first = nullptr; // of the slotted rows being folded into the last line
    for (const Shortcut& s : kShortcuts) {
        if (s.slot != 0 && first && first->action == s.action) {
            lines.back().keys = std::string(first->keys) + " .. " + std::string(s.keys);
            continue;
        }
        first = s.slot != 0 ? &s : nullptr;
        lines.push_back({std::string(s.keys), s.description, s.section});
    }
    return lines;
}

std::string shortcutTableMarkdown() {
    const std::vector<SheetLine> lines = shortcutSheetLines();
    std::string out;
    for (const ShortcutSection section : kShortcutSections) {
        if (!out.empty()) out += "\n";
        out += "**" + std::string(sectionName(section)) + "**\n\n| Keys | Does |\n|---|---|\n";
        for (const SheetLine& line : lines)
            if (line.section == section)
                out += "| " + cell(line.keys) + " | " + cell(line.description) + " |\n";
    }
    return out;
}

} // namespace rmsc::editor
