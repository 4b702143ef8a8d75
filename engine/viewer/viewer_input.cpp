// Input state, GLFW callbacks and the Dear ImGui platform glue (see viewer_input.hpp).
#include "viewer/viewer_input.hpp"

#include <imgui.h>

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

void setupImGuiInput() {
    ImGuiIO& io = ImGui::GetIO();
    io.BackendPlatformName = "rmsc_input";
    const std::pair<ImGuiKey, int> map[] = {
        {ImGuiKey_Tab, GLFW_KEY_TAB},
        {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
        {ImGuiKey_RightArrow, GLFW_KEY_RIGHT},
        {ImGuiKey_UpArrow, GLFW_KEY_UP},
        {ImGuiKey_DownArrow, GLFW_KEY_DOWN},
        {ImGuiKey_PageUp, GLFW_KEY_PAGE_UP},
        {ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN},
        {ImGuiKey_Home, GLFW_KEY_HOME},
        {ImGuiKey_End, GLFW_KEY_END},
        {ImGuiKey_Insert, GLFW_KEY_INSERT},
        {ImGuiKey_Delete, GLFW_KEY_DELETE},
        {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
        {ImGuiKey_Space, GLFW_KEY_SPACE},
        {ImGuiKey_Enter, GLFW_KEY_ENTER},
        {ImGuiKey_Escape, GLFW_KEY_ESCAPE},
        {ImGuiKey_KeyPadEnter, GLFW_KEY_KP_ENTER},
        {ImGuiKey_A, GLFW_KEY_A},
        {ImGuiKey_C, GLFW_KEY_C},
        {ImGuiKey_V, GLFW_KEY_V},
        {ImGuiKey_X, GLFW_KEY_X},
        {ImGuiKey_Y, GLFW_KEY_Y},
        {ImGuiKey_Z, GLFW_KEY_Z},
    };
    for (const auto& [imguiKey, glfwKey] : map)
        io.KeyMap[imguiKey] = glfwKey;
}

void feedImGui(const InputState& input, int windowWidth, int windowHeight, int framebufferWidth,
               int framebufferHeight, float seconds) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(windowWidth), float(windowHeight));
    if (windowWidth > 0 && windowHeight > 0)
        io.DisplayFramebufferScale = ImVec2(float(framebufferWidth) / float(windowWidth),
                                            float(framebufferHeight) / float(windowHeight));
    io.DeltaTime = seconds > 0.0f ? seconds : 1.0f / 60.0f;
    io.MousePos = ImVec2(input.mouse.x, input.mouse.y);
    for (int b = 0; b < 3; ++b)
        io.MouseDown[b] = input.buttons[std::size_t(b)] || input.clicked[std::size_t(b)];
    io.MouseWheel += input.wheel;
    for (int k = 0; k < 512 && k <= GLFW_KEY_LAST; ++k)
        io.KeysDown[k] = input.keys[std::size_t(k)] || input.pressed(k);
    io.KeyCtrl = input.ctrl();
    io.KeyShift = input.shift();
    io.KeyAlt = input.alt();
    io.KeySuper = input.held(GLFW_KEY_LEFT_SUPER) || input.held(GLFW_KEY_RIGHT_SUPER);
    for (unsigned c : input.characters)
        io.AddInputCharacter(c);
}

} // namespace rmsc::app
