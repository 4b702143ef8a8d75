// The viewer's input queue (editor/input_queue.hpp): quick input is handed out frame by frame
// without losing, merging or reordering anything, with the modifiers each event had.
#include "editor/input_queue.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

using namespace rmsc::editor;
using Kind = InputEvent::Kind;

namespace {

constexpr int kCtrl = 341, kShift = 340, kZ = 90, kTab = 258, kA = 65, kB = 66, kX = 88;

InputEvent key(int code, bool down, int mods) {
    return {Kind::Key, code, down, mods};
}
InputEvent button(int code, bool down, int mods = 0) {
    return {Kind::Button, code, down, mods};
}
InputEvent character(char c, int mods = 0) {
    return {Kind::Char, c, false, mods};
}
InputEvent cursor(float x, float y) {
    return {Kind::Cursor, 0, false, 0, {x, y}};
}

std::vector<std::vector<InputEvent>> allFrames(InputQueue& queue) {
    std::vector<std::vector<InputEvent>> frames;
    for (int i = 0; i < 1000 && !queue.empty(); ++i)
        frames.push_back(queue.takeFrame());
    EXPECT_TRUE(queue.empty());
    return frames;
}

// The frames a key press of `code` with `mods` was taken in.
std::vector<int> pressFrames(const std::vector<std::vector<InputEvent>>& frames, int code,
                             int mods) {
    std::vector<int> out;
    for (std::size_t f = 0; f < frames.size(); ++f)
        for (const InputEvent& e : frames[f])
            if (e.kind == Kind::Key && e.code == code && e.down && e.mods == mods)
                out.push_back(int(f));
    return out;
}

bool sameEvent(const InputEvent& a, const InputEvent& b) {
    return a.kind == b.kind && a.code == b.code && a.down == b.down && a.mods == b.mods &&
           a.value == b.value;
}

} // namespace

TEST(InputQueue, TwoQuickCtrlZTapsArriveAsTwoCtrlZ) {
    // Both taps, Ctrl included, happen between two frames.
    InputQueue queue;
    for (int tap = 0; tap < 2; ++tap) {
        queue.push(key(kCtrl, true, kModCtrl));
        queue.push(key(kZ, true, kModCtrl));
        queue.push(key(kZ, false, kModCtrl));
        queue.push(key(kCtrl, false, 0));
    }
    const auto frames = allFrames(queue);
    EXPECT_EQ(pressFrames(frames, kZ, kModCtrl).size(), 2u);
    EXPECT_TRUE(pressFrames(frames, kZ, 0).empty());
}

TEST(InputQueue, ACtrlReleasedRightAfterZWaitsForTheNextFrame) {
    // Ctrl held since an earlier frame; Z goes down, then Ctrl up, then Z up, all in one frame
    // interval: the frame that takes Z must still hold Ctrl (it was a Ctrl+Z).
    InputQueue queue;
    queue.push(key(kCtrl, true, kModCtrl));
    ASSERT_EQ(queue.takeFrame().size(), 1u);
    queue.push(key(kZ, true, kModCtrl));
    queue.push(key(kCtrl, false, 0));
    queue.push(key(kZ, false, 0));
    const std::vector<InputEvent> first = queue.takeFrame();
    ASSERT_EQ(first.size(), 1u);
    EXPECT_TRUE(sameEvent(first[0], key(kZ, true, kModCtrl)));
    const std::vector<InputEvent> second = queue.takeFrame();
    ASSERT_EQ(second.size(), 2u);
    EXPECT_EQ(second[0].code, kCtrl);
    EXPECT_EQ(second[1].code, kZ);
}

TEST(InputQueue, ADoubleClickIsTwoPressesInFourFrames) {
    InputQueue queue;
    queue.push(cursor(100, 50));
    for (int i = 0; i < 2; ++i) {
        queue.push(button(0, true));
        queue.push(button(0, false));
    }
    const auto frames = allFrames(queue);
    ASSERT_EQ(frames.size(), 4u);
    EXPECT_EQ(frames[0].size(), 2u); // the move, then the first press
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const InputEvent& last = frames[f].back();
        EXPECT_EQ(last.kind, Kind::Button);
        EXPECT_EQ(last.down, f % 2 == 0) << f;
    }
}

TEST(InputQueue, AClickLandsWhereItWasAndTextWaitsForTheFocus) {
    // A click on a field, a move away, and typing, all between two frames.
    InputQueue queue;
    queue.push(cursor(10, 10));
    queue.push(button(0, true));
    queue.push(cursor(300, 300));
    queue.push(button(0, false));
    queue.push(key(kA, true, 0));
    queue.push(character('a'));
    queue.push(key(kA, false, 0));
    const auto frames = allFrames(queue);
    ASSERT_GE(frames.size(), 3u);
    EXPECT_EQ(frames[0].back().kind, Kind::Button); // the press, at (10, 10) ...
    EXPECT_EQ(frames[0].front().value, glm::vec2(10, 10));
    EXPECT_EQ(frames[1].front().kind, Kind::Cursor); // ... and the move only after it
    int charFrame = -1;
    for (std::size_t f = 0; f < frames.size(); ++f)
        for (const InputEvent& e : frames[f])
            if (e.kind == Kind::Char) charFrame = int(f);
    // Not in the frame of the press nor in the next one: the field is focused by then.
    EXPECT_GE(charFrame, 2);
}

TEST(InputQueue, TextAfterTabWaitsAFrameButTypingDoesNot) {
    InputQueue queue;
    for (char c : std::string("ab")) {
        const int code = c == 'a' ? kA : kB;
        queue.push(key(code, true, 0));
        queue.push(character(c));
        queue.push(key(code, false, 0));
    }
    auto frames = allFrames(queue);
    ASSERT_FALSE(frames.empty());
    // 'a' goes with its key's press: typing takes no extra frame.
    ASSERT_GE(frames[0].size(), 2u);
    EXPECT_EQ(frames[0][1].kind, Kind::Char);
    EXPECT_LE(frames.size(), 3u);

    queue.push(key(kTab, true, 0));
    queue.push(key(kTab, false, 0));
    queue.push(key(kX, true, 0));
    queue.push(character('x'));
    frames = allFrames(queue);
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(frames[0].size(), 1u);               // Tab down
    EXPECT_EQ(frames[1].size(), 2u);               // Tab up, X down
    EXPECT_EQ(frames[2].front().kind, Kind::Char); // 'x' once the focus has moved
}

TEST(InputQueue, AMarkerEndsItsFrame) {
    InputQueue queue;
    queue.push(key(kA, true, 0));
    queue.push({Kind::Marker, 7});
    queue.push(key(kB, true, 0));
    const auto frames = allFrames(queue);
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0].back().kind, Kind::Marker);
    EXPECT_EQ(frames[0].back().code, 7);
}

TEST(InputQueue, DroppedFilesComeInOrderWithoutTouchingTheModifiers) {
    // Two files dropped (GLFW's drop callback queues them with no modifiers) between a Ctrl+Z
    // and its release: the drops ride along in the Ctrl+Z's frame, in order, and do not split it.
    InputQueue queue;
    InputEvent first;
    first.kind = Kind::Drop;
    first.path = "/a/model.glb";
    InputEvent second = first;
    second.path = "/a/scene.json";
    queue.push(key(kCtrl, true, kModCtrl));
    queue.push(key(kZ, true, kModCtrl));
    queue.push(first);
    queue.push(second);
    queue.push(key(kZ, false, kModCtrl));
    const auto frames = allFrames(queue);
    ASSERT_EQ(frames.size(), 2u) << "Z's release waits for the next frame, the drops do not";
    ASSERT_EQ(frames[0].size(), 4u);
    EXPECT_EQ(frames[0][2].path, "/a/model.glb");
    EXPECT_EQ(frames[0][3].path, "/a/scene.json");
    EXPECT_EQ(pressFrames(frames, kZ, kModCtrl), std::vector<int>{0}) << "still a Ctrl+Z";
}

TEST(InputQueue, RandomBurstsComeOutWholeInOrderOneTransitionPerKeyAFrame) {
    std::mt19937 random(21);
    for (int round = 0; round < 200; ++round) {
        InputQueue queue;
        std::vector<InputEvent> pushed;
        std::vector<bool> down(4, false);
        int mods = 0;
        const int count = 1 + int(random() % 60);
        for (int i = 0; i < count; ++i) {
            InputEvent e;
            switch (random() % 6) {
            case 0: { // a modifier
                const bool d = !(mods & kModShift);
                mods = d ? mods | kModShift : mods & ~kModShift;
                e = key(kShift, d, mods);
                break;
            }
            case 1:
            case 2: { // one of four keys
                const int k = int(random() % 4);
                down[std::size_t(k)] = !down[std::size_t(k)];
                e = key(kA + k, down[std::size_t(k)], mods);
                break;
            }
            case 3:
                e = character(char('a' + random() % 26), mods);
                break;
            case 4:
                e = button(int(random() % 2), random() % 2 == 0, mods);
                break;
            default:
                e = {Kind::Cursor, 0, false, mods, {float(random() % 100), 0.0f}};
                break;
            }
            pushed.push_back(e);
            queue.push(e);
        }
        std::vector<InputEvent> all;
        bool lastEmpty = false;
        for (int f = 0; f < 1000 && !queue.empty(); ++f) {
            const std::vector<InputEvent> frame = queue.takeFrame();
            // (Text waits one frame after a click: never two.)
            ASSERT_FALSE(frame.empty() && lastEmpty) << "two frames took nothing while events wait";
            lastEmpty = frame.empty();
            std::vector<int> keys, buttons;
            int frameMods = -1;
            for (const InputEvent& e : frame) {
                if (e.kind == Kind::Key) {
                    EXPECT_EQ(std::count(keys.begin(), keys.end(), e.code), 0);
                    keys.push_back(e.code);
                }
                if (e.kind == Kind::Button) {
                    EXPECT_EQ(std::count(buttons.begin(), buttons.end(), e.code), 0);
                    buttons.push_back(e.code);
                }
                const bool reads = ((e.kind == Kind::Key || e.kind == Kind::Button) && e.down) ||
                                   e.kind == Kind::Char || e.kind == Kind::Scroll;
                if (frameMods >= 0) {
                    EXPECT_EQ(e.mods, frameMods);
                }
                if (reads) frameMods = e.mods;
                all.push_back(e);
            }
        }
        EXPECT_TRUE(queue.empty());
        // Nothing lost, merged or reordered.
        ASSERT_EQ(all.size(), pushed.size());
        for (std::size_t i = 0; i < all.size(); ++i)
            EXPECT_TRUE(sameEvent(all[i], pushed[i])) << i;
    }
}
