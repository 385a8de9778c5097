#!/usr/bin/env bash
# Builds Aerial and starts it on the built-in defaults. Until the editor
# lands this runs the `aerial` CLI: the sun, sky and fog through a whole day.
# Extra arguments go to `aerial` (try --help).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target aerial
if (($#)); then
  exec build/release/app/aerial "$@"
fi
exec build/release/app/aerial day
