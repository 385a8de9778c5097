#!/usr/bin/env bash
# Builds Aerial and runs every test: first the release build, then the whole
# suite again under AddressSanitizer + UndefinedBehaviorSanitizer, then each
# libFuzzer target for a bounded time (scripts/fuzz.sh; clang).
#   AERIAL_SKIP_ASAN=1 scripts/test.sh   # no sanitizer pass (quicker, local use)
#   AERIAL_SKIP_FUZZ=1 scripts/test.sh   # no fuzzing
#   AERIAL_FUZZ_SECONDS=300 scripts/test.sh   # fuzz longer (default 30 s per target)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh

jobs=$(nproc)
run_preset() {
  local preset=$1
  echo "== $preset: configure, build, test"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  ctest --preset "$preset" -j "$jobs"
}

run_preset release
if [[ ${AERIAL_SKIP_ASAN:-0} != 1 ]]; then
  run_preset asan
fi
if [[ ${AERIAL_SKIP_FUZZ:-0} != 1 ]]; then
  echo "== fuzz: each loader for ${AERIAL_FUZZ_SECONDS:-30} s"
  scripts/fuzz.sh "${AERIAL_FUZZ_SECONDS:-30}"
fi
