// runViewer (viewer/viewer.hpp): loads the replay script, opens the window, sets up Dear ImGui
// and runs the viewer.
#include "frame_loop.hpp"
#include "imgui_platform.hpp"
#include "viewer/viewer.hpp"

#include "core/exit_code.hpp"
#include "editor/ui_scale.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace rmsc::app {

int runViewer(const ViewerOptions& options) {
    std::string error;
    std::optional<Script> script;
    if (!options.script.empty()) {
        script = loadScript(options.script, error);
        if (!script) {
            std::fprintf(stderr, "rmsc view: %s\n", error.c_str());
            return kExitUsage;
        }
    }
    std::unique_ptr<Window> window = Window::open(options.width, options.height, "rmsc", error);
    if (!window) {
        std::fprintf(stderr, "rmsc view: %s\n", error.c_str());
        return kExitSystem;
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    // The panels' scale: --ui-scale, or the display's content scale (200% on a dense display).
    float contentX = 1.0f, contentY = 1.0f;
    glfwGetWindowContentScale(window->handle(), &contentX, &contentY);
    const float scale = editor::uiScale(options.uiScale, contentX, contentY);
    ImFontConfig font;
    font.SizePixels = std::round(13.0f * scale); // the default font's size at scale 1
    io.Fonts->AddFontDefault(&font);
    ImGui::GetStyle().ScaleAllSizes(scale);
    if (scale != 1.0f) std::fprintf(stderr, "rmsc view: panels at %.2fx\n", double(scale));
    setupImGuiInput();
    ImGui_ImplOpenGL3_Init("#version 450 core");
    int code = kExitOk;
    {
        Viewer viewer(options, std::move(window), std::move(script));
        code = viewer.run();
        ImGui_ImplOpenGL3_Shutdown();
    }
    ImGui::DestroyContext();
    return code;
}

} // namespace rmsc::app
