// `rmsc view`: the interactive viewer and scene editor, as the rmsc command starts it. Everything
// else of the viewer is internal to engine/viewer/ (frame_loop.hpp is where it comes together).
#pragma once

#include <filesystem>

namespace rmsc::app {

struct ViewerOptions {
    std::filesystem::path scene;  // "" = the built-in demo
    std::filesystem::path script; // "" = interactive
    int width = 1280, height = 720;
    float targetMilliseconds = 33.0f;
    bool watchShaders = true; // read shaders from the source tree and reload them on change
    bool stats = false;       // log the UI frame times after each change and at exit
    float uiScale = 0.0f;     // the panels' scale (fonts, sizes); 0: the window's content scale
};

// Opens the window and runs the viewer until it closes; returns the process exit code.
int runViewer(const ViewerOptions& options);

} // namespace rmsc::app
