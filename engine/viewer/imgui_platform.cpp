// Dear ImGui's platform side from an InputState (see imgui_platform.hpp).
#include "imgui_platform.hpp"

#include <imgui.h>

#include <utility>

namespace rmsc::app {

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
    io.KeySuper = input.super();
    for (unsigned c : input.characters)
        io.AddInputCharacter(c);
}

bool keyboardFree(const InputState& input) {
    const ImGuiIO& io = ImGui::GetIO();
    return !io.WantCaptureKeyboard && !io.WantTextInput && !input.ctrl();
}

} // namespace rmsc::app
