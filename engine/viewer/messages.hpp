// What the viewer tells the user: problems, shown over the view until they are solved or
// dismissed, and short notices that fade after a few seconds (and go to stderr as well).
#pragma once

#include <chrono>
#include <deque>
#include <string>

namespace rmsc::app {

struct Messages {
    std::string openError;   // the scene named on the command line could not be opened
    std::string sceneError;  // the current scene does not compile / a reload failed
    std::string shaderError; // the shaders on disk do not compile
    std::string fileError;   // the last save / open failed
    struct Notice {
        std::string text;
        std::chrono::steady_clock::time_point when;
    };
    std::deque<Notice> notices; // the newest last; at most 6

    void notice(const std::string& text);
};

} // namespace rmsc::app
