// rmsc view: the interactive viewer and scene editor (window, editor panels, live rendering).
#include "commands.hpp"
#include "core/limits.hpp"
#include "editor/ui_scale.hpp"
#include "viewer/viewer.hpp"

#include <cstdio>
#include <cstdlib>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

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
    {"--ui-scale", nullptr, "S",
     "scale of the panels' text and sizes, 0.5 to 4 (default: the display's content scale, "
     "2 on a display set to 200%)"},
    {"--embedded-shaders", nullptr, nullptr,
     "use the shaders built into the binary; do not watch the source shaders folder"},
    kSandboxOption,
};

} // namespace

const CommandSpec kViewSpec = {
    "view",
    "[SCENE]",
    "open the viewer and scene editor in a window",
    "rmsc view [SCENE] [--size WxH] [--target-ms MS] [--ui-scale S] [--script FILE] [--stats] "
    "[--sandbox DIR]",
    "Opens SCENE (a .json scene, or a .gltf/.glb model; without SCENE, the built-in demo) in a\n"
    "window with an editor: fly with right mouse + W/A/S/D, Q/E roll, Space / Left Shift up and\n"
    "down, the wheel sets the speed, Shift is fast; Alt + drag orbits the selection, F frames it.\n"
    "Click to select, G moves (then X/Y/Z for an axis), Ctrl+Z / Ctrl+Shift+Z undo and redo,\n"
    "Ctrl+S saves (atomically, keeping SCENE.bak), F12 writes a screenshot, Shift+A searches\n"
    "everything that can be added, F1 lists every shortcut. Drop a .gltf/.glb on the window to\n"
    "add it, a .json to open it. The scene file and the shaders are watched and reloaded when\n"
    "they change on disk.",
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
    if (args.has("--ui-scale")) {
        const std::string text = args.get("--ui-scale", "");
        char* end = nullptr;
        const double scale = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' ||
            !(scale >= editor::kMinUiScale && scale <= editor::kMaxUiScale)) {
            std::fprintf(stderr,
                         "rmsc view: --ui-scale: expected a scale from %g to %g, got '%s'\n",
                         double(editor::kMinUiScale), double(editor::kMaxUiScale), text.c_str());
            return kExitUsage;
        }
        options.uiScale = float(scale);
    }
    options.script = args.get("--script", "");
    options.watchShaders = !args.has("--embedded-shaders");
    options.stats = args.has("--stats");
    if (!args.positionals.empty()) options.scene = args.positionals[0];
#if defined(__GLIBC__)
    // The viewer's workers (cell pruning, shader warming, scene preparation) free large blocks
    // that other threads then allocate again. glibc gives each thread an arena of its own and
    // keeps what is freed there for that thread: such blocks took new memory. With two arenas,
    // on the 10,000-shape grid the viewer peaks at 387 MB instead of 413 (docs/performance.md,
    // "Memory"). One arena would save a few MB more, but the UI thread would then share its
    // lock with the pruning threads' millions of allocations.
    mallopt(M_ARENA_MAX, 2);
#endif
    return runViewer(options);
}

} // namespace rmsc::app
