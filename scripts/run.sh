#!/usr/bin/env bash
# Builds Aerial (release) and starts the editor, aerial-editor, on the
# built-in default preset and scene. Extra arguments go to the editor
# (scripts/run.sh presets/hazy_sunset.json --size 1600x900; see
# aerial-editor --help). Without a display (no DISPLAY / WAYLAND_DISPLAY) the
# editor says so, names the headless `aerial` commands to use instead and
# exits with status 2; `xvfb-run -a scripts/run.sh` runs it on a virtual one.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target aerial-editor aerial
exec build/release/app/aerial-editor "$@"
