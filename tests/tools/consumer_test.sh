#!/usr/bin/env bash
# Installs the build into a fresh prefix, then configures, builds and runs a
# consumer project that finds it with find_package(Aerial).
#   consumer_test.sh BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR CXX_FLAGS [EXECUTABLE [ARGS...]]
# EXECUTABLE is the consumer's target (default: app); ARGS are passed to it.
set -euo pipefail
build=$1 source=$2 work=$3 flags=${4:-} executable=${5:-app}
shift $(($# < 5 ? $# : 5))
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$source" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_CXX_FLAGS="$flags" >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/$executable" "$@"
