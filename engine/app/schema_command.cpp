// rmsc schema: prints the JSON Schema of scene files (docs/scene.schema.json is its output).
#include "commands.hpp"

#include "scene/scene_schema.hpp"

#include <cstdio>

namespace rmsc::app {

const CommandSpec kSchemaSpec = {
    "schema",
    "",
    "print the JSON Schema of scene files",
    "rmsc schema",
    "Prints the JSON Schema (draft 2020-12) of scene files, generated from the scene reader\n"
    "and the primitive catalogue. Refresh the shipped copy with\n"
    "  rmsc schema > docs/scene.schema.json",
    {},
    0};

int runSchema(const ParsedArgs&) {
    const SceneSchema schema = generateSceneSchema();
    for (const std::string& problem : schema.problems)
        std::fprintf(stderr, "rmsc schema: %s\n", problem.c_str());
    std::fputs(schema.text.c_str(), stdout);
    return schema.problems.empty() ? kExitOk : kExitSystem;
}

} // namespace rmsc::app
