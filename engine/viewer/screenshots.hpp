// Screenshots: the view at full resolution (F12, File > Screenshot, a script's `screenshot`) and
// the whole window with the panels (a script's `window-shot`), as PNG files.
#pragma once

#include "panel_layout.hpp"
#include "view_render_thread.hpp"
#include "window.hpp"

#include <filesystem>
#include <string>

namespace rmsc::app {

// The view in `viewport` (window pixels) at the framebuffer's resolution. False with `error`
// when nothing is rendered or the file cannot be written.
bool writeViewShot(ViewRenderThread& renderer, const ViewInput& view, const Rect& viewport,
                   const Window& window, const std::string& path, std::string& error);
// The window's back buffer as it is before the swap: the view with the panels drawn over it.
bool writeWindowShot(const Window& window, const std::string& path, std::string& error);
// rmsc-screenshot-DATE-TIME.png next to the scene file (in the working folder for a scene
// never saved).
std::filesystem::path defaultScreenshotPath(const std::filesystem::path& sceneFile);

} // namespace rmsc::app
