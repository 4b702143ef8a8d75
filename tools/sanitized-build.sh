#!/usr/bin/env bash
# Configures and builds build-asan, the one instrumented build that tools/sanitize.sh and
# tools/fuzz.sh share: clang with AddressSanitizer and UndefinedBehaviorSanitizer (UBSan built
# non-recovering), and libFuzzer's coverage instrumentation (RMSC_FUZZ=ON), so the engine is
# compiled once for both. Usage: tools/sanitized-build.sh TARGET...
set -euo pipefail
cd "$(dirname "$0")/.."
# The instrumented code runs a few times slower: each tier's time limit (tests/CMakeLists.txt)
# is multiplied by 4. -O1 -g1 (line tables, enough for the reports' stacks) compiles in about
# 60% of the time -O2 -g takes with the sanitizers on, and clang compiles it in about 70% of
# gcc's time (a glTF test file: 13.3 s against 19.3 s).
CC=clang CXX=clang++ cmake -S . -B build-asan -DRMSC_FUZZ=ON -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="-O1 -g1" -DCMAKE_C_FLAGS="-O1 -g1" -DRMSC_TEST_TIMEOUT_FACTOR=4 >/dev/null
cmake --build build-asan -j"$(nproc)" --target "$@"
