#!/usr/bin/env bash
# Builds rmsc with AddressSanitizer and UndefinedBehaviorSanitizer (clang, in build-asan, which
# tools/fuzz.sh shares: tools/sanitized-build.sh) and runs the unit, GPU (on whatever headless GL is available, llvmpipe in CI) and CLI tests under them.
# Any sanitizer report fails the run: UBSan is built non-recovering, ASan and LeakSanitizer
# abort on their first report. Usage: tools/sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan # shared with tools/fuzz.sh
# Only the programs the tests below run are built (not the Python module).
tools/sanitized-build.sh rmsc rmsc_unit_tests rmsc_gpu_tests rmsc_api_tests rmsc_prune_measure
# Unit tests run with LeakSanitizer on. Processes that create a GL context (GPU, CLI and viewer
# tests) end with two 56-byte blocks allocated inside Mesa's driver, which is unloaded before
# the leak check, so the report names no module or function and cannot be suppressed narrowly:
# those run with ASan and UBSan but without the leak check.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -L unit
# Not run here: gpu.python (an ASan-instrumented Python extension needs the ASan runtime loaded
# before the uninstrumented python3 starts) and cli.embed (it installs this build's
# instrumented librmsc.a and links an uninstrumented program against it); e2e.viewer_timing
# (UI frame times, figures only, which mean nothing under the sanitizers); e2e.viewer_burst (3.6
# minutes without the sanitizers; the input queue it drives runs here in its unit tests); and
# the three GPU agreement tests on the largest cell grids (3 minutes of the two cores here, their
# time the CPU's pruning and ray casts, which the CellPruning unit tests run under the
# sanitizers on random trees; the other cells agreement tests stay).
ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" \
  ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -LE unit \
    -E '^(gpu\.python|cli\.embed|e2e\.viewer_timing|e2e\.viewer_burst|gpu\.CpuGpuAgreement\.(CellsOnTheLargestSmoothTree|CellsOnTheLargestSmoothTreeAlongTheHorizon|CellsOnABoundedSceneEndRaysAtTheGrid))$'
