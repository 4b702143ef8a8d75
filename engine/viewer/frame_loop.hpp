// The viewer (`rmsc view`, started by runViewer in viewer/viewer.hpp): owns the window and the
// parts, and runs the frame loop. A frame takes its events from the input queue (real or
// replayed input, editor/input_queue.hpp), runs the shortcuts and the files dropped on the
// window, the gestures, the gizmo and the camera, draws the menus, panels, overlay, the add
// menu, the shortcut sheet, the gizmo, its toolbar and the dialogs (carrying out the commands
// each queues right after it), commits finished edits, looks at the files, hands the scene to
// the GPU side and draws the view; then writes the screenshots a replay script asks for.
#pragma once

#include "add_search_menu.hpp"
#include "camera_controls.hpp"
#include "dialogs.hpp"
#include "document_edits.hpp"
#include "editor/file_watcher.hpp"
#include "editor/input_queue.hpp"
#include "editor_session.hpp"
#include "export_dialog.hpp"
#include "frame_stats.hpp"
#include "gesture_controls.hpp"
#include "gizmo_controls.hpp"
#include "hierarchy_panel.hpp"
#include "input_state.hpp"
#include "inspector.hpp"
#include "messages.hpp"
#include "panel_layout.hpp"
#include "replay_script.hpp"
#include "scene_files.hpp"
#include "view_render_thread.hpp"
#include "view_settings.hpp"
#include "viewer/viewer.hpp"
#include "viewer_commands.hpp"
#include "window.hpp"

#include <chrono>
#include <memory>
#include <optional>

namespace rmsc::app {

class Viewer {
  public:
    // `script`: the replay script to play instead of the keyboard and mouse, if any.
    Viewer(const ViewerOptions& options, std::unique_ptr<Window> window,
           std::optional<Script> script);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    int run(); // the frame loop; returns the exit code

  private:
    ScriptActions readInput();       // this frame's events, and a script's other actions
    void handleInput(float seconds); // shortcuts, gestures, camera, click to select
    // Advances the glTF animation playing by the frame's seconds (editor/animation_playback.hpp)
    // and hands the inspector the newest compiled scene.
    void playAnimation(float seconds);
    void drawUi(); // the menus, panels, overlay and dialogs
    // Carries out the commands the part that just ran queued, and clears them.
    void carryOut(ViewerCommands& commands);
    void commitFinishedEdits(); // once no widget or gesture is changing the scene
    void pollFiles();           // recovery file, scene file and shaders, every second
    // The scene to the GPU, the SDF map, the view (the whole of it now with `refineAll`), on the
    // render thread: waited for with `waitForBuilds` (and the background builds), `waitForView`
    // or `refineAll`.
    void updateView(bool waitForBuilds, bool waitForView, bool refineAll);
    int writeScriptShots(const ScriptActions& actions); // returns how many failed
    bool loadShaders(bool initial);
    ViewInput viewInput() const;         // what the view shows this frame
    NewShapePlace newShapePlace() const; // where a shape added this frame goes
    void screenshotToDefaultFile();
    void dropFile(const std::filesystem::path& path); // a file dropped on the window
    glm::vec3 viewFocus() const; // where the view looks: its focus point straight ahead
    double now() const;          // seconds since the start

    const ViewerOptions options_;
    std::unique_ptr<Window> window_;
    std::optional<Script> script_;
    editor::InputQueue queue_; // every input event not yet taken by a frame
    InputState input_;
    double lastInput_ = 0.0; // when the newest input event taken arrived (glfwGetTime)
    int scriptFrame_ = 0;    // the replay script's frame: stops while it waits for refining
    int scriptMods_ = 0;     // the modifiers the script holds
    // When the script began to wait for refining or the export (glfwGetTime); -1: not waiting.
    // A wait longer than kScriptHoldSeconds ends the viewer with an error.
    double scriptHoldSince_ = -1.0;
    static constexpr double kScriptHoldSeconds = 300.0;
    bool scriptWaitsForExport_ = false; // the wait is for the export, not the refining
    int frameNumber_ = 0;
    float frameMilliseconds_ = 0.0f;
    FrameStats stats_;
    std::chrono::steady_clock::time_point start_;
    double lastPoll_ = 0.0; // when the files were last looked at

    EditorSession session_; // the document and the view's camera
    SceneFiles files_;
    editor::FileWatcher shaderWatcher_; // the source tree's shaders, when they are read from it
    Messages messages_;
    Dialogs dialogs_;
    ExportUi export_; // the export dialog and the export running on its thread
    PanelLayout layout_;
    HierarchyPanelState hierarchy_;
    InspectorState inspector_;
    ViewSettings view_;
    ViewportGesture gesture_;
    ViewportGizmo gizmo_;
    AddSearchMenu addSearch_;
    bool shortcutSheet_ = false; // the sheet of every shortcut is shown
    CameraDrags cameraDrags_;
    ViewRenderThread gpu_; // after window_: goes first, while its context exists
};

} // namespace rmsc::app
