// The window's layout (see panel_layout.hpp).
#include "panel_layout.hpp"

#include <algorithm>

namespace rmsc::app {

PanelLayout layoutPanels(int windowWidth, int windowHeight, float menuHeight, float uiScale) {
    PanelLayout layout;
    const float w = float(windowWidth);
    layout.leftPanelWidth = std::min(std::clamp(w * 0.24f, 150.0f, 270.0f * uiScale), w * 0.35f);
    layout.rightPanelWidth = std::min(std::clamp(w * 0.28f, 200.0f, 340.0f * uiScale), w * 0.4f);
    layout.viewport = {
        layout.leftPanelWidth, menuHeight,
        std::max(1.0f, float(windowWidth) - layout.leftPanelWidth - layout.rightPanelWidth),
        std::max(1.0f, float(windowHeight) - menuHeight)};
    return layout;
}

ViewportPixels viewportPixels(const Rect& viewport, int windowWidth, int windowHeight,
                              int framebufferWidth, int framebufferHeight) {
    const float sx = windowWidth > 0 ? float(framebufferWidth) / float(windowWidth) : 1.0f;
    const float sy = windowHeight > 0 ? float(framebufferHeight) / float(windowHeight) : 1.0f;
    ViewportPixels pixels;
    pixels.x = int(viewport.x * sx);
    pixels.width = std::max(1, int(viewport.width * sx));
    pixels.height = std::max(1, int(viewport.height * sy));
    pixels.y = framebufferHeight - int((viewport.y + viewport.height) * sy);
    pixels.framebufferWidth = framebufferWidth;
    pixels.framebufferHeight = framebufferHeight;
    return pixels;
}

} // namespace rmsc::app
