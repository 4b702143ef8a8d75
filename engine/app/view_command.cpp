// rmsc view: the interactive viewer and scene editor (window, editor panels, live rendering).
#include "commands.hpp"
#include "core/limits.hpp"
#include "viewer/viewer.hpp"

#include <cstdio>
#include <cstdlib>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--size", nullptr, "WxH", "window size in pixels (default 1280x720)"},
    {"--target-ms", nullptr, "MS",
     "frame time the adaptive resolution holds while the camera moves (default 33)"},
    {"--script", nullptr, "FILE",
     "replay input events from FILE instead of the keyboard and mouse (for tests)"},
    {"--stats", nullptr, nullptr,
     "log, for each change, the UI frame times until the view is refined and the time from the "
     "last input to the refined image; and all frames' times at exit"},
    {"--embedded-shaders", nullptr, nullptr,
     "use the shaders built into the binary; do not watch the source shaders folder"},
    kSandboxOption,
};

} // namespace

const CommandSpec kViewSpec = {
    "view",
    "[SCENE]",
    "open the viewer and scene editor in a window",
    "rmsc view [SCENE] [--size WxH] [--target-ms MS] [--script FILE] [--stats] [--sandbox DIR]",
    "Opens SCENE (a .json scene, or a .gltf/.glb model; without SCENE, the built-in demo) in a\n"
    "window with an editor: fly with right mouse + W/A/S/D, Q/E roll, Space / Left Shift up and\n"
    "down, the wheel sets the speed, Shift is fast; Alt + drag orbits the selection, F frames it.\n"
    "Click to select, G moves (then X/Y/Z for an axis), Ctrl+Z / Ctrl+Shift+Z undo and redo,\n"
    "Ctrl+S saves (atomically, keeping SCENE.bak), F12 writes a screenshot. The scene file and\n"
    "the shaders are watched and reloaded when they change on disk.",
    kOptions,
    1};

int runView(const ParsedArgs& args) {
    ViewerOptions options;
    if (args.has("--size") && !parseSize(args.get("--size", ""), options.width, options.height)) {
        std::fprintf(stderr, "rmsc view: --size: expected %s, got '%s'\n",
                     sizeExpectation().c_str(), args.get("--size", "").c_str());
        return kExitUsage;
    }
    if (args.has("--target-ms")) {
        const std::string text = args.get("--target-ms", "");
        char* end = nullptr;
        const double ms = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !(ms >= 1.0 && ms <= 10000.0)) {
            std::fprintf(
                stderr, "rmsc view: --target-ms: expected milliseconds from 1 to 10000, got '%s'\n",
                text.c_str());
            return kExitUsage;
        }
        options.targetMilliseconds = float(ms);
    }
    options.script = args.get("--script", "");
    options.watchShaders = !args.has("--embedded-shaders");
    options.stats = args.has("--stats");
    if (!args.positionals.empty()) options.scene = args.positionals[0];
    return runViewer(options);
}

} // namespace rmsc::app
