// rmsc: the Ray Marching Scene Creator command. Dispatches to the subcommands of one table,
// which also gives `rmsc --help` its list; parsing, --help and parse errors are handled here once.
#include "commands.hpp"

#include "core/crash_report.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rmsc::app {
namespace {

// Every subcommand, in the order `rmsc --help` lists them.
const Subcommand kSubcommands[] = {
    {kRenderSpec, runRender},         {kValidateSpec, runValidate}, {kBenchSpec, runBench},
    {kPrimitivesSpec, runPrimitives}, {kViewSpec, runView},         {kSchemaSpec, runSchema},
    {kLimitsSpec, runLimits},         {kExportSpec, runExport},
};

std::string usage() {
    std::string out = "usage: rmsc <command> [options]\n"
                      "\n"
                      "Renders and checks scenes that mix glTF meshes with signed-distance-field "
                      "objects.\n"
                      "\n"
                      "commands:\n";
    for (const Subcommand& command : kSubcommands) {
        std::string left = std::string("  ") + command.spec.name;
        if (*command.spec.arguments) left += std::string(" ") + command.spec.arguments;
        left.resize(std::max<std::size_t>(left.size() + 2, 30), ' ');
        out += left + command.spec.purpose + "\n";
    }
    out += "\n'rmsc <command> --help' describes each command.\n";
    return out;
}

int runSubcommand(const Subcommand& command, std::span<const std::string> args) {
    std::string error;
    const std::optional<ParsedArgs> parsed = parseArgs(command.spec, args, error);
    if (!parsed) {
        std::fprintf(stderr, "rmsc %s: %s\n", command.spec.name, error.c_str());
        return kExitUsage;
    }
    if (parsed->help) {
        std::fputs(formatHelp(command.spec).c_str(), stdout);
        return kExitOk;
    }
    if (!applySandboxOption(command.spec, *parsed)) return kExitUsage;
    return command.run(*parsed);
}

} // namespace
} // namespace rmsc::app

int main(int argc, char** argv) {
    using namespace rmsc;
    using namespace rmsc::app;
    installCrashReport();
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(usage().c_str(), args.empty() ? stderr : stdout);
        return args.empty() ? kExitUsage : kExitOk;
    }
    if (args[0] == "--version") {
        std::puts("rmsc 0.1.0");
        return kExitOk;
    }
    for (const Subcommand& command : kSubcommands)
        if (args[0] == command.spec.name)
            return runSubcommand(command, std::span<const std::string>(args).subspan(1));
    std::fprintf(stderr, "rmsc: unknown command '%s'\n\n%s", args[0].c_str(), usage().c_str());
    return kExitUsage;
}
