// rmsc: the Ray Marching Scene Creator command. Dispatches to the subcommands.
#include "commands.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace {

const char* kUsage =
    "usage: rmsc <command> [options]\n"
    "\n"
    "Renders and checks scenes that mix glTF meshes with signed-distance-field objects.\n"
    "\n"
    "commands:\n"
    "  render [SCENE] -o OUT.png   render a scene (or a .gltf/.glb, or the built-in demo) to PNG\n"
    "  validate SCENE...           load and check scenes, report every problem\n"
    "  bench [SCENE]               time frames of a scene (median, min, max per pass)\n"
    "  primitives                  list the SDF primitives and their parameters\n"
    "  view [SCENE]                open the viewer and scene editor in a window\n"
    "  schema                      print the JSON Schema of scene files\n"
    "\n"
    "'rmsc <command> --help' describes each command.\n";

} // namespace

int main(int argc, char** argv) {
    using namespace rmsc;
    using namespace rmsc::app;
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(kUsage, args.empty() ? stderr : stdout);
        return args.empty() ? kExitUsage : kExitOk;
    }
    if (args[0] == "--version") {
        std::puts("rmsc 0.1.0");
        return kExitOk;
    }
    const std::span<const std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "render") return runRender(rest);
    if (args[0] == "validate") return runValidate(rest);
    if (args[0] == "bench") return runBench(rest);
    if (args[0] == "primitives") return runPrimitives(rest);
    if (args[0] == "view") return runView(rest);
    if (args[0] == "schema") return runSchema(rest);
    std::fprintf(stderr, "rmsc: unknown command '%s'\n\n%s", args[0].c_str(), kUsage);
    return kExitUsage;
}
