// The viewer's input queue (see input_queue.hpp).
#include "editor/input_queue.hpp"

#include <algorithm>

namespace rmsc::editor {
namespace {

using Kind = InputEvent::Kind;

// Events whose meaning depends on the modifiers held (a release means the same with any).
bool readsModifiers(const InputEvent& e) {
    return ((e.kind == Kind::Key || e.kind == Kind::Button) && e.down) || e.kind == Kind::Char ||
           e.kind == Kind::Scroll;
}

} // namespace

std::vector<InputEvent> InputQueue::takeFrame() {
    std::vector<InputEvent> taken;
    std::vector<int> keys, buttons; // transitioned this frame
    bool haveMods = false;
    int mods = 0;
    bool buttonMoved = false; // a button went down or up this frame
    bool focusMoved = false;  // a click or a key press that typed nothing, this frame
    while (!events_.empty()) {
        const InputEvent& e = events_.front();
        if (e.kind == Kind::Key || e.kind == Kind::Button) {
            std::vector<int>& seen = e.kind == Kind::Key ? keys : buttons;
            if (std::find(seen.begin(), seen.end(), e.code) != seen.end()) break;
        }
        // Once an event that reads the modifiers is taken, the frame's modifiers are its.
        const bool modless = e.kind == Kind::Marker || e.kind == Kind::Drop;
        if (!modless && haveMods && e.mods != mods) break;
        if (e.kind == Kind::Cursor && buttonMoved) break;
        if (e.kind == Kind::Char && (focusMoved || focusMovedLastFrame_)) break;

        if (e.kind == Kind::Key) keys.push_back(e.code);
        if (e.kind == Kind::Button) {
            buttons.push_back(e.code);
            buttonMoved = true;
            focusMoved = focusMoved || e.down;
        }
        if (e.kind == Kind::Key && e.down && e.mods == lastMods_) {
            // (A key that changes the modifiers is one of them.) A key that types sends its
            // character right after its press.
            const bool types = events_.size() > 1 && events_[1].kind == Kind::Char;
            focusMoved = focusMoved || !types;
        }
        if (e.kind != Kind::Drop) lastMods_ = e.mods;
        if (readsModifiers(e)) {
            haveMods = true;
            mods = e.mods;
        }
        const bool marker = e.kind == Kind::Marker;
        taken.push_back(e);
        events_.pop_front();
        if (marker) break;
    }
    focusMovedLastFrame_ = focusMoved;
    return taken;
}

} // namespace rmsc::editor
