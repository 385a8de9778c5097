#!/usr/bin/env bash
# Builds Aerial and runs every test: first the release build, then the whole
# suite again under AddressSanitizer + UndefinedBehaviorSanitizer.
#   AERIAL_SKIP_ASAN=1 scripts/test.sh   # release only (quicker, local use)
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
