// The viewer's input, in one place: the keys and buttons held, the mouse position, the wheel
// and typed characters of this frame. Filled from GLFW callbacks when a person drives the
// viewer, or from a replay script (replay_script.hpp); then handed to Dear ImGui
// (imgui_platform.hpp) and to the camera and editor shortcuts, so scripted and real input take
// exactly the same path.
#pragma once

#define GLFW_INCLUDE_NONE // GL comes from glad (gl/gl.hpp), whichever header is included first
#include <GLFW/glfw3.h>
#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace rmsc::app {

struct InputState {
    std::array<bool, GLFW_KEY_LAST + 1> keys{};
    std::array<bool, 3> buttons{}; // left, right, middle
    glm::vec2 mouse{0.0f};         // window pixels, top-left origin
    // Per frame (cleared by beginFrame):
    float wheel = 0.0f;
    std::vector<unsigned> characters;
    std::vector<int> pressedKeys;   // keys that went down this frame
    std::array<bool, 3> clicked{};  // buttons that went down this frame
    std::array<bool, 3> released{}; // buttons that went up this frame
    glm::vec2 mouseDelta{0.0f};     // movement since the last frame

    void beginFrame();   // before this frame's events: clears the per-frame fields
    void finishEvents(); // after them: computes mouseDelta
    void keyEvent(int key, bool down);
    void buttonEvent(int button, bool down);
    void moveMouse(glm::vec2 position);

    bool held(int key) const { return key >= 0 && key <= GLFW_KEY_LAST && keys[std::size_t(key)]; }
    bool pressed(int key) const;
    bool ctrl() const { return held(GLFW_KEY_LEFT_CONTROL) || held(GLFW_KEY_RIGHT_CONTROL); }
    bool shift() const { return held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT); }
    bool alt() const { return held(GLFW_KEY_LEFT_ALT) || held(GLFW_KEY_RIGHT_ALT); }

  private:
    glm::vec2 lastMouse_{0.0f};
    bool haveLastMouse_ = false;
};

// Routes a window's GLFW input callbacks into `state` (real input).
void attachGlfwInput(GLFWwindow* window, InputState* state);

} // namespace rmsc::app
