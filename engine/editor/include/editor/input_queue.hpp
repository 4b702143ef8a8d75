// The viewer's input queue: every key, character, mouse button, wheel and cursor transition in
// the order it happened, each with the modifiers held at that moment, handed out one frame at a
// time so that nothing is lost, merged or reordered. Dear ImGui 1.86 (Debian 12's) samples key
// and button states once per frame, so a frame takes at most one transition of each key and
// button (a press in one frame, its release in the next), keeps the modifiers of the events it
// takes the same, and lets typed characters wait until a click or a non-typing key taken before
// them has moved the focus. GL- and window-free: key and button codes are the caller's.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace rmsc::editor {

// Modifier bits of InputEvent::mods.
enum InputModifier : int { kModShift = 1, kModCtrl = 2, kModAlt = 4, kModSuper = 8 };

struct InputEvent {
    enum class Kind {
        Key,    // `code` went down or up
        Char,   // `code` is a typed Unicode character
        Button, // mouse button `code` went down or up
        Scroll, // `value` is the wheel's offset
        Cursor, // the mouse moved to `value` (window pixels)
        Drop,   // a file was dropped on the window: `path`
        Marker  // a point in the stream (a replay script's screenshot, say): `code` is the caller's
    } kind = Kind::Marker;
    int code = 0;
    bool down = false;
    int mods = 0; // InputModifier bits held at this event (a modifier key's own included once down)
    glm::vec2 value{0.0f};
    double time = 0.0;     // when it arrived, in the caller's seconds
    std::string path = {}; // Drop: the file
};

class InputQueue {
  public:
    void push(const InputEvent& event) { events_.push_back(event); }
    bool empty() const { return events_.empty(); }
    std::size_t size() const { return events_.size(); }

    // Takes the events of the next frame, oldest first. Stops before an event that
    //  - is a second transition of a key or button this frame;
    //  - carries other modifiers than a key or button press, character or wheel step taken
    //    this frame (a Ctrl+Z whose Ctrl goes up right after it is still a Ctrl+Z);
    //  - moves the cursor after a button transition this frame (a click lands where it was);
    //  - is a character, in a frame that took, or right after a frame that took, a button
    //    press or a press of a key that typed nothing and is no modifier (Tab, Enter, a
    //    click: the focus may move).
    // A marker ends the frame that takes it (what follows it happens in a later frame). A drop
    // neither reads nor changes the modifiers.
    // Everything after the stop waits, in order, for the next frame.
    std::vector<InputEvent> takeFrame();

  private:
    std::deque<InputEvent> events_;
    bool focusMovedLastFrame_ = false;
    int lastMods_ = 0; // of the last event taken
};

} // namespace rmsc::editor
