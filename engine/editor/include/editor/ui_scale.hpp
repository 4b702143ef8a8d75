// The scale of the viewer's panels (fonts and style sizes) on large or dense displays:
// `rmsc view --ui-scale S`, or else the window's content scale as the system reports it (GLFW's
// glfwGetWindowContentScale: 2 on a display set to 200%). GL-free.
#pragma once

namespace rmsc::editor {

inline constexpr float kMinUiScale = 0.5f;
inline constexpr float kMaxUiScale = 4.0f;

// `option` when it is > 0, else the larger of the content scales (1 when they are not finite
// and positive); kept within [kMinUiScale, kMaxUiScale].
float uiScale(float option, float contentScaleX, float contentScaleY);

} // namespace rmsc::editor
