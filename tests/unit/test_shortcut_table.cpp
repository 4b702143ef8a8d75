// The viewer's shortcut table (editor/shortcut_table.hpp): command rows are single chords that no
// two rows share in one scope, every command has a row, chords parse as the handler reads them,
// and docs/viewer.md's key list is the table's markdown.
#include "editor/input_queue.hpp"
#include "editor/shortcut_table.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

using namespace rmsc::editor;

namespace {

std::string readSourceFile(const std::string& relativePath) {
    std::string path = RMSC_TEST_SOURCE_DIR;
    path += "/"; // (appended, not `+`: GCC 12 warns wrongly of -Warray-bounds on that)
    path += relativePath;
    std::ifstream file(path);
    std::stringstream buffer;
    buffer << file.rdbuf();
    return buffer.str();
}

} // namespace

TEST(ShortcutTable, ParsesChords) {
    const std::optional<Chord> redo = parseChord("Ctrl+Shift+Z");
    ASSERT_TRUE(redo);
    EXPECT_EQ(redo->mods, kModCtrl | kModShift);
    EXPECT_EQ(redo->key, "Z");
    const std::optional<Chord> add = parseChord("Shift+A");
    ASSERT_TRUE(add);
    EXPECT_EQ(add->mods, kModShift);
    EXPECT_EQ(add->key, "A");
    const std::optional<Chord> f12 = parseChord("F12");
    ASSERT_TRUE(f12);
    EXPECT_EQ(f12->mods, 0);
    EXPECT_EQ(f12->key, "F12");
    // A numpad key is the one key name with a space.
    const std::optional<Chord> back = parseChord("Ctrl+Numpad 1");
    ASSERT_TRUE(back);
    EXPECT_EQ(back->mods, kModCtrl);
    EXPECT_EQ(back->key, "Numpad 1");
    for (const char* notOne :
         {"", "Ctrl", "Ctrl+", "+Z", "W / A / S / D", "Ctrl+Ctrl+Z", "Hyper+Z", "Alt + left drag",
          "Shift+click here", "Numpad 12", "Numpad  1", "Numpad x", "Ctrl+Numpad 1 2"})
        EXPECT_FALSE(parseChord(notOne)) << notOne;
    // Key names are not checked here (the viewer resolves them to GLFW's): "Numpad" alone is a
    // one-word name like "F12".
}

TEST(ShortcutTable, CommandRowsAreChordsNoTwoRowsShare) {
    std::set<ShortcutAction> actions;
    std::set<std::pair<int, std::string>> chords;
    for (const Shortcut& s : shortcutTable()) {
        EXPECT_FALSE(s.keys.empty());
        EXPECT_FALSE(s.description.empty()) << s.keys;
        if (s.action == ShortcutAction::Described) continue;
        const std::optional<Chord> chord = parseChord(s.keys);
        ASSERT_TRUE(chord) << "a command row's keys are one chord: " << s.keys;
        // The handler matches exact modifiers, so one chord can do only one thing.
        EXPECT_TRUE(chords.insert({chord->mods, chord->key}).second) << "twice: " << s.keys;
        // Ctrl chords are taken unless a field is typed in (the view's keys only over the
        // view); plain keys would type into it.
        if (isViewAction(s.action)) {
            EXPECT_EQ(s.scope, ShortcutScope::View) << s.keys;
        } else if (chord->mods & kModCtrl) {
            EXPECT_EQ(s.scope, ShortcutScope::NotTyping) << s.keys;
        } else if (chord->key.size() > 1 && chord->key[0] == 'F') {
            EXPECT_EQ(s.scope, ShortcutScope::Always) << s.keys; // a function key
        } else {
            EXPECT_EQ(s.scope, ShortcutScope::View) << s.keys;
        }
        actions.insert(s.action);
    }
    // Every command has a row (the menus show its keys from there).
    for (int a = 0; a < int(ShortcutAction::Described); ++a) {
        EXPECT_TRUE(actions.contains(ShortcutAction(a))) << "action " << a << " has no row";
        EXPECT_FALSE(shortcutKeys(ShortcutAction(a)).empty());
    }
    EXPECT_EQ(shortcutKeys(ShortcutAction::Undo), "Ctrl+Z");
    EXPECT_EQ(shortcutKeys(ShortcutAction::Redo), "Ctrl+Shift+Z") << "the first row of an action";
    EXPECT_EQ(shortcutKeys(ShortcutAction::AddSearch), "Shift+A");
    EXPECT_EQ(shortcutKeys(ShortcutAction::ShortcutSheet), "F1");
    EXPECT_EQ(shortcutKeys(ShortcutAction::Described), "");
    EXPECT_EQ(shortcutKeys(ShortcutAction::ViewBack), "Ctrl+Numpad 1");
    EXPECT_EQ(shortcutKeys(ShortcutAction::ToggleOrthographic), "Numpad 5");
}

TEST(ShortcutTable, EveryBookmarkSlotHasItsDigit) {
    // Slot n is kept with Ctrl+n and gone back to with n; only the bookmark rows have a slot.
    std::set<int> stored, recalled;
    for (const Shortcut& s : shortcutTable()) {
        if (s.action == ShortcutAction::StoreBookmark) {
            EXPECT_EQ(s.keys, "Ctrl+" + std::to_string(s.slot));
            EXPECT_TRUE(stored.insert(s.slot).second) << s.keys;
        } else if (s.action == ShortcutAction::RecallBookmark) {
            EXPECT_EQ(s.keys, std::to_string(s.slot));
            EXPECT_TRUE(recalled.insert(s.slot).second) << s.keys;
        } else {
            EXPECT_EQ(s.slot, 0) << s.keys;
        }
    }
    const std::set<int> slots = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    EXPECT_EQ(stored, slots);
    EXPECT_EQ(recalled, slots);
}

TEST(ShortcutTable, MarkdownListsEveryRowBySection) {
    const std::string markdown = shortcutTableMarkdown();
    for (const Shortcut& s : shortcutTable()) {
        if (s.slot == 0) {
            EXPECT_NE(markdown.find("| " + std::string(s.keys) + " |"), std::string::npos)
                << s.keys;
        }
    }
    // The nine rows of a bookmark's action make one line.
    EXPECT_NE(markdown.find("| Ctrl+1 .. Ctrl+9 | keep the view"), std::string::npos);
    EXPECT_NE(markdown.find("| 1 .. 9 | go back to the bookmark"), std::string::npos);
    EXPECT_EQ(markdown.find("| Ctrl+5 |"), std::string::npos);
    EXPECT_EQ(shortcutSheetLines().size(), shortcutTable().size() - 16);
    EXPECT_LT(markdown.find("**Navigation**"), markdown.find("**Views**"));
    EXPECT_LT(markdown.find("**Views**"), markdown.find("**Editing**"));
    EXPECT_LT(markdown.find("**Editing**"), markdown.find("**Help**"));
    EXPECT_NE(markdown.find("| Shift+A | add menu at the mouse"), std::string::npos);
    EXPECT_NE(markdown.find("| F1 | show or hide this sheet"), std::string::npos);
}

TEST(ShortcutTable, DocsListTheTable) {
    const std::string docs = readSourceFile("docs/viewer.md");
    ASSERT_FALSE(docs.empty()) << "docs/viewer.md is missing";
    const std::string begin = "<!-- shortcuts:begin -->\n";
    const std::string end = "<!-- shortcuts:end -->";
    const std::size_t from = docs.find(begin);
    const std::size_t to = docs.find(end);
    ASSERT_NE(from, std::string::npos) << "docs/viewer.md has no " << begin;
    ASSERT_NE(to, std::string::npos);
    const std::string generated = shortcutTableMarkdown();
    EXPECT_EQ(docs.substr(from + begin.size(), to - from - begin.size()), generated)
        << "regenerate the key list in docs/viewer.md from shortcutTableMarkdown() "
           "(engine/editor/shortcut_table.cpp):\n"
        << generated;
}
