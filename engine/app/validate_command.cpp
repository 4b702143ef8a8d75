// rmsc validate: loads scenes (and every glTF they reference, and compiles their SDF trees)
// without rendering, and reports every problem found.
#include "commands.hpp"

#include "prepare/prepared_scene.hpp"

#include <cstdio>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {kSandboxOption};

} // namespace

const CommandSpec kValidateSpec = {
    "validate",
    "SCENE...",
    "load and check scenes, report every problem",
    "rmsc validate SCENE... [--sandbox DIR]",
    "Loads each SCENE (.json scene or .gltf/.glb model), the glTF files it names, and compiles\n"
    "its SDF tree, without a GL context. Prints every problem as FILE: JSON-POINTER: MESSAGE\n"
    "and exits non-zero if any scene has an error (warnings alone exit 0).",
    kOptions,
    1 << 20};

int runValidate(const ParsedArgs& args) {
    if (args.positionals.empty()) {
        std::fprintf(stderr, "rmsc validate: no scene given\n");
        return kExitUsage;
    }
    int failed = 0;
    for (const std::string& path : args.positionals) {
        Diagnostics diagnostics;
        const bool ok = openScene(path, diagnostics).has_value();
        std::fputs(diagnostics.format().c_str(), stderr);
        if (ok) {
            std::printf("%s: ok\n", path.c_str());
        } else {
            std::printf("%s: %d error%s\n", path.c_str(), diagnostics.errorCount(),
                        diagnostics.errorCount() == 1 ? "" : "s");
            ++failed;
        }
    }
    return failed ? kExitBadInput : kExitOk;
}

} // namespace rmsc::app
