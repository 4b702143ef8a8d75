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
#include "messages.hpp"
#include "panel_layout.hpp"
#include "replay_script.hpp"
#include "scene_files.hpp"
#include "view_renderer.hpp"
#include "view_settings.hpp"
#include "viewer/viewer.hpp"
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
    // Inspector setting: positions shown in world coordinates, gesture axes are the world's
    // (otherwise the object's own).
    bool worldCoordinates = false;
    bool orbiting = false;
    bool looking = false;

    // Inspector: the file fields of the selected material's textures, one per slot
    // (editor/material_texture_edits.hpp); the file changes only when "apply" loads it.
    struct TextureFileField {
        int material = -1;     // the material the text belongs to
        std::string shownFile; // the slot's file when the text was last filled from it
        std::string text;      // the file name being typed
        std::string error;     // why the last apply failed ("" = it did not)
    };
    std::array<TextureFileField, 3> textureFileFields;

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

    // viewer_panels.cpp
    void drawUi();
    void drawMenuBar();
    void drawHierarchy();
    void drawInspector();
    void drawMaterialTextures(int material); // the texture slots of scene.materials[material]
    void drawOverlay();

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
