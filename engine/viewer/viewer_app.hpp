// The viewer (`rmsc view`, started by runViewer in viewer/viewer.hpp). One class holds the
// window, the editor document and the UI state, with the GPU side in a ViewRenderer
// (view_renderer.hpp); its parts live in viewer_app.cpp (the frame loop, files),
// viewer_panels.cpp (the Dear ImGui panels) and viewer_controls.cpp (camera and viewport
// gestures).
#pragma once

#include "dialogs.hpp"
#include "display_pass.hpp"
#include "editor/adaptive_scale.hpp"
#include "editor/document.hpp"
#include "editor/editing_map.hpp"
#include "editor/file_watcher.hpp"
#include "editor/fly_camera.hpp"
#include "editor/transform_gesture.hpp"
#include "editor_session.hpp"
#include "imgui_platform.hpp"
#include "input_state.hpp"
#include "inspector.hpp"
#include "messages.hpp"
#include "panel_layout.hpp"
#include "replay_script.hpp"
#include "scene_files.hpp"
#include "view_renderer.hpp"
#include "view_settings.hpp"
#include "viewer/viewer.hpp"
#include "viewer_commands.hpp"
#include "window.hpp"

#include <array>
#include <chrono>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace rmsc::app {

class Viewer {
  public:
    Viewer(const ViewerOptions& options, std::unique_ptr<Window> window);
    ~Viewer();
    int run(); // the frame loop; returns the exit code

    // --- state shared by the parts ---
    ViewerOptions options;
    std::unique_ptr<Window> window;
    InputState input;
    std::optional<Script> script;
    int frameNumber = 0;
    float frameMilliseconds = 0.0f;

    EditorSession session; // the document and the view's camera
    ViewSettings view;
    ViewRenderer gpu; // after window: goes first
    Messages messages;
    SceneFiles files;
    Dialogs dialogs;
    editor::FileWatcher shaderWatcher;
    double lastPoll = 0.0; // when the files were last looked at

    // Gestures: move (G), rotate (R) and scale (S) of the selection with the mouse; the math
    // is editor/transform_gesture.hpp. X / Y / Z constrain, click / Enter keeps, Esc cancels.
    struct Gesture {
        bool active = false;
        editor::TransformGesture math; // the start; its axis and space change while it runs
        glm::vec2 lastMouse{0.0f};     // viewport pixels last applied
        bool needsApply = false;       // apply even if the mouse did not move (axis changed)
    } gesture;
    bool orbiting = false;
    bool looking = false;

    InspectorState inspector;

    // Layout (window pixels)
    PanelLayout layout;

    // --- parts ---
    double now() const;

    // viewer_app.cpp
    bool loadShaders(bool initial);
    ViewInput viewInput() const; // what the view shows this frame
    void renderView();
    void screenshotToDefaultFile();
    void pollFiles();

    void drawUi(); // the menus, panels, overlay and dialogs
    // Carries out the commands the part that just ran queued, and clears them.
    void carryOut(ViewerCommands& commands);

    // viewer_controls.cpp
    void handleShortcuts();
    void handleCamera(float seconds);
    void handleViewportMouse();
    void startGesture();  // G, R or S pressed with a movable selection
    void updateGesture(); // follows the mouse; keeps, cancels or changes the axis
    void frameSelection();

  private:
    std::chrono::steady_clock::time_point start_;
};

} // namespace rmsc::app
