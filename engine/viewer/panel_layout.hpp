// Where the viewer's parts sit in the window: the Scene panel on the left, the Inspector on the
// right, the view between them under the menu bar; and the view's rectangle in framebuffer
// pixels, for GL.
#pragma once

#include <glm/glm.hpp>

namespace rmsc::app {

// A rectangle of the window in window pixels (top-left origin).
struct Rect {
    float x = 0, y = 0, width = 0, height = 0;
    bool contains(glm::vec2 p) const {
        return p.x >= x && p.y >= y && p.x < x + width && p.y < y + height;
    }
};

struct PanelLayout {
    Rect viewport; // the view
    float leftPanelWidth = 270.0f, rightPanelWidth = 340.0f;
};

// The layout of a window of `windowWidth` x `windowHeight` pixels under a menu bar `menuHeight`
// high, with the panels' sizes scaled by `uiScale` (--ui-scale): panels take at most about half
// of a small window.
PanelLayout layoutPanels(int windowWidth, int windowHeight, float menuHeight, float uiScale = 1.0f);

// The view's rectangle in framebuffer pixels (y from the bottom, as GL counts), with the size
// of the whole framebuffer.
struct ViewportPixels {
    int x = 0, y = 0, width = 1, height = 1;
    int framebufferWidth = 1, framebufferHeight = 1;
};
ViewportPixels viewportPixels(const Rect& viewport, int windowWidth, int windowHeight,
                              int framebufferWidth, int framebufferHeight);

} // namespace rmsc::app
