// Process exit codes of rmsc and of every program built on the engine: 0 success, 1 bad input
// (scene, model, texture), 2 bad usage, 3 no GL context or an I/O error.
#pragma once

namespace rmsc {

enum ExitCode { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitSystem = 3 };

} // namespace rmsc
