// The rmsc subcommands: one table (kSubcommands in main.cpp) of each command's spec and run
// function. main.cpp parses the arguments with the spec, answers --help and reports parse errors
// ("rmsc NAME: message", exit 2) for every command; `run` gets the parsed arguments and returns
// the process exit code: 0 success, 1 bad input (scene, model), 2 bad usage, 3 no GL or I/O error.
#pragma once

#include "core/exit_code.hpp"
#include "options.hpp"

namespace rmsc::app {

struct Subcommand {
    const CommandSpec& spec; // name, usage, help text and options
    int (*run)(const ParsedArgs& args);
};

extern const CommandSpec kRenderSpec;
int runRender(const ParsedArgs& args);
extern const CommandSpec kValidateSpec;
int runValidate(const ParsedArgs& args);
extern const CommandSpec kBenchSpec;
int runBench(const ParsedArgs& args);
extern const CommandSpec kPrimitivesSpec;
int runPrimitives(const ParsedArgs& args);
extern const CommandSpec kViewSpec;
int runView(const ParsedArgs& args);
extern const CommandSpec kSchemaSpec;
int runSchema(const ParsedArgs& args);
extern const CommandSpec kLimitsSpec;
int runLimits(const ParsedArgs& args);
extern const CommandSpec kExportSpec;
int runExport(const ParsedArgs& args);

} // namespace rmsc::app
