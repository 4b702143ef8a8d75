// The viewer's input, in one place: the keys and buttons held, the modifiers, the mouse
// position, the wheel and typed characters of this frame. GLFW callbacks (a person driving the
// viewer) or a replay script (replay_script.hpp) queue every transition (editor/input_queue.hpp);
// each frame applies the events the queue hands out for it, then hands the state to Dear ImGui
// (imgui_platform.hpp) and to the camera and editor shortcuts, so scripted and real input take
// exactly the same path.
#pragma once

#define GLFW_INCLUDE_NONE // GL comes from glad (gl/gl.hpp), whichever header is included first
#include <GLFW/glfw3.h>
#include <glm/glm.hpp>

#include "editor/input_queue.hpp"

#include <array>
#include <string>
#include <vector>

namespace rmsc::app {

struct InputState {
    std::array<bool, GLFW_KEY_LAST + 1> keys{};
    std::array<bool, 3> buttons{}; // left, right, middle
    glm::vec2 mouse{0.0f};         // window pixels, top-left origin
    int mods = 0; // editor::InputModifier bits of this frame's events (held at the last one)
    // Per frame (cleared by beginFrame):
    float wheel = 0.0f;
    std::vector<unsigned> characters;
    std::vector<std::string> drops; // files dropped on the window this frame
    std::vector<int> pressedKeys;   // keys that went down this frame
    std::array<bool, 3> clicked{};  // buttons that went down this frame
    std::array<bool, 3> released{}; // buttons that went up this frame
    glm::vec2 mouseDelta{0.0f};     // movement since the last frame

    void beginFrame();   // before this frame's events: clears the per-frame fields
    void finishEvents(); // after them: computes mouseDelta
    void keyEvent(int key, bool down);
    void buttonEvent(int button, bool down);
    void moveMouse(glm::vec2 position);
    void apply(const editor::InputEvent& event); // one event the queue handed out (not a marker)

    bool held(int key) const { return key >= 0 && key <= GLFW_KEY_LAST && keys[std::size_t(key)]; }
    bool pressed(int key) const;
    bool ctrl() const { return (mods & editor::kModCtrl) != 0; }
    bool shift() const { return (mods & editor::kModShift) != 0; }
    bool alt() const { return (mods & editor::kModAlt) != 0; }
    bool super() const { return (mods & editor::kModSuper) != 0; }

  private:
    glm::vec2 lastMouse_{0.0f};
    bool haveLastMouse_ = false;
};

// The modifier bit of a GLFW modifier key (left or right Shift, Ctrl, Alt, Super), else 0.
int modifierBit(int key);
// `mods` after a key event: a modifier key's own bit set while it is down.
int modsAfterKey(int mods, int key, bool down);
// The event of a file dropped on the window (GLFW's drop callback and a script's `drop PATH`).
editor::InputEvent dropEvent(std::string path);

// Queues a window's GLFW input callbacks into `queue` (real input), stamped with glfwGetTime:
// keys, characters, buttons, the cursor, the wheel and files dropped on the window (one Drop
// event per file; replay scripts' `drop PATH` queues the same). Call once; the queue must
// outlive the window's callbacks. With `dropsOnly` (a replay script plays the rest), only the
// files dropped on the window are queued.
void attachGlfwInput(GLFWwindow* window, editor::InputQueue* queue, bool dropsOnly = false);

} // namespace rmsc::app
