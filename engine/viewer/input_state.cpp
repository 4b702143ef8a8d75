// Input state and the GLFW callbacks that fill it (see input_state.hpp).
#include "input_state.hpp"

#include <algorithm>

namespace rmsc::app {

void InputState::beginFrame() {
    wheel = 0.0f;
    characters.clear();
    pressedKeys.clear();
    clicked = {};
    released = {};
}

void InputState::finishEvents() {
    mouseDelta = haveLastMouse_ ? mouse - lastMouse_ : glm::vec2(0.0f);
    lastMouse_ = mouse;
    haveLastMouse_ = true;
}

void InputState::keyEvent(int key, bool down) {
    if (key < 0 || key > GLFW_KEY_LAST) return;
    if (down && !keys[std::size_t(key)]) pressedKeys.push_back(key);
    keys[std::size_t(key)] = down;
}

void InputState::buttonEvent(int button, bool down) {
    if (button < 0 || button > 2) return;
    if (down && !buttons[std::size_t(button)]) clicked[std::size_t(button)] = true;
    if (!down && buttons[std::size_t(button)]) released[std::size_t(button)] = true;
    buttons[std::size_t(button)] = down;
}

void InputState::moveMouse(glm::vec2 position) {
    mouse = position;
}

bool InputState::pressed(int key) const {
    return std::find(pressedKeys.begin(), pressedKeys.end(), key) != pressedKeys.end();
}

namespace {

InputState* stateOf(GLFWwindow* window) {
    return static_cast<InputState*>(glfwGetWindowUserPointer(window));
}

} // namespace

void attachGlfwInput(GLFWwindow* window, InputState* state) {
    glfwSetWindowUserPointer(window, state);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_PRESS) stateOf(w)->keyEvent(key, true);
        if (action == GLFW_RELEASE) stateOf(w)->keyEvent(key, false);
    });
    glfwSetCharCallback(window,
                        [](GLFWwindow* w, unsigned c) { stateOf(w)->characters.push_back(c); });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
        stateOf(w)->buttonEvent(button, action == GLFW_PRESS);
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        stateOf(w)->moveMouse(glm::vec2(float(x), float(y)));
    });
    glfwSetScrollCallback(window,
                          [](GLFWwindow* w, double, double dy) { stateOf(w)->wheel += float(dy); });
}

} // namespace rmsc::app
