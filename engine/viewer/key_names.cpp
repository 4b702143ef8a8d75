// GLFW key codes by name (see key_names.hpp).
#include "key_names.hpp"

#include "input_state.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace rmsc::app {

int glfwKeyNamed(std::string_view name) {
    std::string key(name);
    std::transform(key.begin(), key.end(), key.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    struct Named {
        std::string_view name;
        int key;
    };
    static constexpr Named kNamed[] = {
        {"space", GLFW_KEY_SPACE},
        {"escape", GLFW_KEY_ESCAPE},
        {"esc", GLFW_KEY_ESCAPE},
        {"enter", GLFW_KEY_ENTER},
        {"tab", GLFW_KEY_TAB},
        {"backspace", GLFW_KEY_BACKSPACE},
        {"delete", GLFW_KEY_DELETE},
        {"left", GLFW_KEY_LEFT},
        {"right", GLFW_KEY_RIGHT},
        {"up", GLFW_KEY_UP},
        {"down", GLFW_KEY_DOWN},
        {"home", GLFW_KEY_HOME},
        {"end", GLFW_KEY_END},
        {"ctrl", GLFW_KEY_LEFT_CONTROL},
        {"left_ctrl", GLFW_KEY_LEFT_CONTROL},
        {"shift", GLFW_KEY_LEFT_SHIFT},
        {"left_shift", GLFW_KEY_LEFT_SHIFT},
        {"right_shift", GLFW_KEY_RIGHT_SHIFT},
        {"alt", GLFW_KEY_LEFT_ALT},
    };
    for (const Named& named : kNamed)
        if (named.name == key) return named.key;
    if (key.size() == 1) {
        const char c = key[0];
        if (c >= 'a' && c <= 'z') return GLFW_KEY_A + (c - 'a');
        if (c >= '0' && c <= '9') return GLFW_KEY_0 + (c - '0');
    }
    // The numpad's digits: "Numpad 1" (the shortcut table), "kp_1" (replay scripts).
    for (const std::string_view prefix : {"numpad ", "kp_"})
        if (key.size() == prefix.size() + 1 && key.compare(0, prefix.size(), prefix) == 0 &&
            key.back() >= '0' && key.back() <= '9')
            return GLFW_KEY_KP_0 + (key.back() - '0');
    if (key.size() >= 2 && key[0] == 'f' &&
        std::all_of(key.begin() + 1, key.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        const int n = std::stoi(key.substr(1));
        if (n >= 1 && n <= 12) return GLFW_KEY_F1 + (n - 1);
    }
    return -1;
}

} // namespace rmsc::app
