// rmsc schema: prints the JSON Schema of scene files (docs/scene.schema.json is its output).
#include "commands.hpp"
#include "options.hpp"

#include "scene/scene_schema.hpp"

#include <cstdio>

namespace rmsc::app {
namespace {

const CommandSpec kSpec = {"schema",
                           "rmsc schema",
                           "Prints the JSON Schema (draft 2020-12) of scene files, generated from "
                           "the scene reader\nand the primitive catalogue. Refresh the shipped "
                           "copy with\n  rmsc schema > docs/scene.schema.json",
                           {},
                           0};

} // namespace

int runSchema(std::span<const std::string> args) {
    std::string error;
    std::optional<ParsedArgs> parsed = parseArgs(kSpec, args, error);
    if (!parsed) {
        std::fprintf(stderr, "rmsc schema: %s\n", error.c_str());
        return kExitUsage;
    }
    if (parsed->help) {
        std::fputs(formatHelp(kSpec).c_str(), stdout);
        return kExitOk;
    }
    const SceneSchema schema = generateSceneSchema();
    for (const std::string& problem : schema.problems)
        std::fprintf(stderr, "rmsc schema: %s\n", problem.c_str());
    std::fputs(schema.text.c_str(), stdout);
    return schema.problems.empty() ? kExitOk : kExitSystem;
}

} // namespace rmsc::app
