// The rmsc subcommands. Each takes its arguments (after the subcommand name) and returns the
// process exit code: 0 success, 1 bad input (scene, model), 2 bad usage, 3 no GL or I/O error.
#pragma once

#include "core/exit_code.hpp"

#include <span>
#include <string>

namespace rmsc::app {

int runRender(std::span<const std::string> args);
int runValidate(std::span<const std::string> args);
int runBench(std::span<const std::string> args);
int runPrimitives(std::span<const std::string> args);
int runView(std::span<const std::string> args);
int runSchema(std::span<const std::string> args);

} // namespace rmsc::app
