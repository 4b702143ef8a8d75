// Replay scripts for the viewer (`rmsc view --script FILE`): input events at frame numbers, so
// tests (and bug reports) can drive the real viewer. One event per line, '#' starts a comment:
//
//   FRAME key KEYS            press at FRAME, release at FRAME+1; KEYS like w, ctrl+z,
//                             ctrl+shift+z, f12, escape, enter, space, delete, left_shift,
//                             kp_7 (the numpad's digits; viewer/key_names.hpp)
//   FRAME hold KEY N          hold KEY down for N frames
//   FRAME move X Y            mouse to window pixel (X, Y), top-left origin
//   FRAME down BUTTON         BUTTON: left | right | middle
//   FRAME up BUTTON
//   FRAME click X Y           move there, press left at FRAME, release at FRAME+1
//   FRAME wheel DY
//   FRAME text STRING         typed characters (the rest of the line)
//   FRAME drop PATH           the file PATH dropped on the window (the event GLFW's drop
//                             callback queues)
//   FRAME screenshot PATH     the rendered view at full resolution, as PNG
//   FRAME window-shot PATH    the whole window with the editor panels, as PNG
//   FRAME wait-shaders        wait until the shaders being built in the background are built
//                             and in use (the view is drawn with them from this frame on)
//   FRAME wait-view           wait until the render thread has drawn this frame's view (with
//                             the best map ready now: nothing built is waited for)
//   FRAME wait-refined        hold the script until the view is fully refined (its frame
//                             count stops meanwhile; the viewer draws on)
//   FRAME wait-export         hold the script until the export running (File > Export) ends
//   FRAME quit                close the window (asks when there are unsaved changes)
//
// Frames count from 0. A frame's events join the viewer's input queue (editor/input_queue.hpp)
// in file order, as real input does, so one frame takes at most one transition of each key and
// button: `5 key ctrl+z` and `6 key ctrl+z` undo twice, the second in frames 7 and 8. The other
// actions run when the queue reaches them, after the input queued before them.
#pragma once

#include "input_state.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rmsc::app {

struct ScriptEvent {
    int frame = 0;
    enum class Kind {
        KeyDown,
        KeyUp,
        MouseMove,
        ButtonDown,
        ButtonUp,
        Wheel,
        Text,
        Drop,
        Screenshot,
        WindowShot,
        WaitShaders,
        WaitView,
        WaitRefined,
        WaitExport,
        Quit
    } kind = Kind::Quit;
    int code = 0; // key or button
    glm::vec2 value{0.0f};
    std::string text; // characters or a path
    int line = 0;
};

struct Script {
    std::vector<ScriptEvent> events; // sorted by frame, stable
    int lastFrame() const { return events.empty() ? 0 : events.back().frame; }
};

// Parses a script; on error returns nullopt with `error` naming the file and line.
std::optional<Script> parseScript(const std::string& text, const std::string& file,
                                  std::string& error);
std::optional<Script> loadScript(const std::filesystem::path& path, std::string& error);

// Actions a frame's events ask of the viewer beyond input.
struct ScriptActions {
    std::vector<std::string> screenshots;
    std::vector<std::string> windowShots;
    bool waitShaders = false;
    bool waitView = false;
    bool waitRefined = false;
    bool waitExport = false;
    bool quit = false;
};

// Queues the events of `frame`, stamped with `time`: input as events, the other actions as
// markers naming their index in script.events. `mods` carries the modifiers the script holds
// from one frame to the next.
void playScriptFrame(const Script& script, int frame, double time, editor::InputQueue& queue,
                     int& mods);
// The actions of the markers among `taken` (events the queue handed out).
ScriptActions scriptActions(const Script& script, const std::vector<editor::InputEvent>& taken);

} // namespace rmsc::app
