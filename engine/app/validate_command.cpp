// rmsc validate: loads scenes (and every glTF they reference, and compiles their SDF trees)
// without rendering, and reports every problem found.
#include "commands.hpp"

#include "prepare/prepared_scene.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    kSandboxOption,
    {"--strict", nullptr, nullptr,
     "treat warnings (such as an unknown, misspelt key) as errors: a scene with any fails"},
};

int warningCount(const Diagnostics& diagnostics) {
    int n = 0;
    for (const Diagnostic& d : diagnostics.items)
        n += d.severity == Severity::Warning ? 1 : 0;
    return n;
}

std::string counted(int n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

} // namespace

const CommandSpec kValidateSpec = {
    "validate",
    "SCENE...",
    "load and check scenes, report every problem",
    "rmsc validate [--strict] SCENE... [--sandbox DIR]",
    "Loads each SCENE (.json scene or .gltf/.glb model), the glTF files it names, and compiles\n"
    "its SDF tree, without a GL context. Prints every problem as FILE: JSON-POINTER: MESSAGE\n"
    "and exits non-zero if any scene has an error (warnings alone exit 0, or fail as errors\n"
    "do with --strict).",
    kOptions,
    1 << 20};

int runValidate(const ParsedArgs& args) {
    if (args.positionals.empty()) {
        std::fprintf(stderr, "rmsc validate: no scene given\n");
        return kExitUsage;
    }
    const bool strict = args.has("--strict");
    int failed = 0;
    for (const std::string& path : args.positionals) {
        Diagnostics diagnostics;
        const std::optional<PreparedScene> prepared = openScene(path, diagnostics);
        const bool loaded = prepared.has_value();
        std::fputs(diagnostics.format().c_str(), stderr);
        const int warnings = strict ? warningCount(diagnostics) : 0;
        if (loaded && warnings == 0) {
            std::printf("%s: ok\n", path.c_str());
            if (!prepared->sdf.instructions.empty() || !prepared->shells.empty())
                std::printf(
                    "%s: %s\n", path.c_str(),
                    sdfCostSummary(prepared->sdfCost, prepared->scene.render.maxSteps).c_str());
            continue;
        }
        std::vector<std::string> counts;
        if (!loaded) counts.push_back(counted(diagnostics.errorCount(), "error"));
        if (warnings > 0)
            counts.push_back(counted(warnings, "warning") + " (errors with --strict)");
        std::printf("%s: %s\n", path.c_str(),
                    (counts[0] + (counts.size() > 1 ? ", " + counts[1] : "")).c_str());
        ++failed;
    }
    return failed ? kExitBadInput : kExitOk;
}

} // namespace rmsc::app
