// GLFW key codes by name, for the replay scripts ("ctrl+z", "f12", "delete") and the shortcut
// table (editor/shortcut_table.hpp: "Ctrl+Z", "F12", "Delete", "Numpad 1"): letters, digits,
// F1..F12, the numpad's digits ("Numpad 1", or "kp_1" in scripts) and the named keys, without
// regard to case.
#pragma once

#include <string_view>

namespace rmsc::app {

// The GLFW key named `name`, or -1.
int glfwKeyNamed(std::string_view name);

} // namespace rmsc::app
