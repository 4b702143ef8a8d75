#!/usr/bin/env bash
# Fuzzes the scene reader, the glTF importer and the importer's accessor and image paths under
# a small load budget (fuzz_gltf_accessors, a structured harness: its inputs are parameters,
# not files; tests/fuzz/make_accessor_seeds.py writes its seeds) with libFuzzer (clang, AddressSanitizer and UndefinedBehaviorSanitizer) for
# SECONDS each, starting from the samples, the seed inputs in tests/fuzz/seeds and the
# regression inputs in tests/fuzz/regressions. Fails when a fuzzer finds a crash, a sanitizer
# report, a leak, a hang (an input taking over 10 s) or a memory bomb (over 2 GiB resident, or
# one allocation over 2 GiB); the input that did it is left in build-asan/crashes/ (add it to
# tests/fuzz/regressions/<fuzzer>/ with the fix).
# Usage: tools/fuzz.sh [SECONDS, default 60]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build=build-asan # shared with tools/sanitize.sh
tools/sanitized-build.sh fuzz_scene fuzz_gltf fuzz_gltf_accessors
mkdir -p "$build/crashes"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
total=0
for name in scene gltf gltf_accessors; do
  case $name in
    scene) seeds=(samples/scenes) ;;
    gltf) seeds=(samples/assets) ;;
    gltf_accessors) seeds=() ;;
  esac
  for dir in "tests/fuzz/seeds/$name" "tests/fuzz/regressions/$name"; do
    [ -d "$dir" ] && seeds+=("$dir")
  done
  corpus="$build/corpus/$name" # grows between local runs; starts empty in CI
  mkdir -p "$corpus"
  log="$build/fuzz_$name.log"
  echo "fuzz_$name: ${seconds}s from ${seeds[*]:-nothing}"
  # Memory and time bombs are findings too: over 2 GiB resident or in one allocation, or 10 s.
  if ! "$build/bin/fuzz_$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -malloc_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/crashes/$name-" \
      "$corpus" ${seeds[@]+"${seeds[@]}"} >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz_$name FAILED: see $log and $build/crashes/" >&2
    exit 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  echo "fuzz_$name: $runs executions, no crash ($(ls "$corpus" | wc -l) inputs in $corpus)"
  total=$((total + runs))
done
echo "fuzz: $total executions in all, no crash"
