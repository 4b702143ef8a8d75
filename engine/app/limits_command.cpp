// rmsc limits: prints the limit catalogue (docs/limits.md's table is its --markdown output).
#include "commands.hpp"

#include "core/limit_catalogue.hpp"

#include <cstdio>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--markdown", nullptr, nullptr, "print the table used in docs/limits.md"},
};

} // namespace

const CommandSpec kLimitsSpec = {
    "limits",
    "",
    "list the size and count limits and what happens over them",
    "rmsc limits [--markdown]",
    "Lists every hard limit of rmsc: its value, what it applies to, and what happens over it\n"
    "(input over a limit is refused with an error naming it, never truncated).",
    kOptions,
    0};

int runLimits(const ParsedArgs& args) {
    if (args.has("--markdown")) {
        std::fputs(limitCatalogueMarkdown().c_str(), stdout);
        return kExitOk;
    }
    for (const Limit& limit : limitCatalogue())
        std::printf("%s: %s (limits::%s)\n    applies to:    %s\n    when exceeded: %s\n",
                    limit.name, limitValueText(limit).c_str(), limit.constant, limit.bounds,
                    limit.exceeded);
    return kExitOk;
}

} // namespace rmsc::app
