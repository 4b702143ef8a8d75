#!/usr/bin/env bash
# Builds rmsc with AddressSanitizer and UndefinedBehaviorSanitizer (gcc) in build-asan and runs
# the unit, GPU (on whatever headless GL is available, llvmpipe in CI) and CLI tests under them.
# Any sanitizer report fails the run: UBSan is built non-recovering, ASan and LeakSanitizer
# abort on their first report. Usage: tools/sanitize.sh [ctest -R pattern]
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j"$(nproc)"
# detect_leaks: on (the default on Linux), stated for the reader. No leak suppressions are
# used (docs/limits.md); if Mesa leaks, add a suppression file here naming the exact Mesa
# function, never a whole library, and say why.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" ${1:+-R "$1"}
