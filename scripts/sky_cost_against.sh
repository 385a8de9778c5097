#!/usr/bin/env bash
# sky_cost_against.sh [REVISION] [THREADS] [ROUNDS] — the sky solver's
# per-sun solve (the light moved, the atmosphere's tables kept) of this
# tree against another revision's, side by side in one process
# (bench/sky_against/): each round times both at every sun, so that a busy
# or throttled machine slows them alike; prints the best time per sun and
# the ratio to the revision's. REVISION defaults to 4dceb06, the solver as
# it stood when the multiple scattering was asked for (issue 14: "the full
# solve stays <= 1 ms, beside today's 0.7-0.8 ms"); THREADS 0 (all) and
# ROUNDS 30 by default. Builds the revision's aerial_core in a git worktree
# under build/against-REVISION and this tree's in build/release (run
# scripts/test.sh or cmake --build --preset release first). Nothing is
# downloaded: both are this repository.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rev=${1:-4dceb06}
threads=${2:-0}
rounds=${3:-30}
cd "$root"
work="$root/build/against-$rev"
if [ ! -d "$work/src" ]; then
    mkdir -p "$work"
    git worktree add --detach "$work/src" "$rev" >/dev/null
fi
if [ ! -f "$work/build/core/libaerial_core.a" ]; then
    cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DAERIAL_BUILD_TESTS=OFF \
        -DAERIAL_BUILD_BENCHMARKS=OFF -DAERIAL_BUILD_APPS=OFF -DAERIAL_BUILD_RENDERER=OFF \
        -DAERIAL_BUILD_EDITOR=OFF >/dev/null
    cmake --build "$work/build" --target aerial_core >/dev/null
fi
here="$root/build/release/core/libaerial_core.a"
if [ ! -f "$here" ]; then
    echo "sky_cost_against.sh: no $here (build the release preset first)" >&2
    exit 1
fi
# Each shim links its revision's library whole and keeps its symbols to
# itself, so that both load into one process.
shim() {  # shim OUT INCLUDE LIBRARY HAS_SINGLE
    c++ -O2 -std=c++20 -fPIC -shared -DAERIAL_SHIM_SINGLE="$4" -I"$2" bench/sky_against/solver_shim.cpp \
        -Wl,--whole-archive "$3" -Wl,--no-whole-archive -Wl,--exclude-libs,ALL -Wl,-Bsymbolic \
        $(pkg-config --libs tinygltf 2>/dev/null || echo -ltinygltf) -lpthread -o "$1"
}
single=0
grep -q singleScatteringOnly "$work/src/core/include/aerial/sky.hpp" && single=1
shim "$work/libsky_$rev.so" "$work/src/core/include" "$work/build/core/libaerial_core.a" "$single"
shim "$work/libsky_here.so" "$root/core/include" "$here" 1
c++ -O2 -std=c++20 bench/sky_against/sky_against.cpp -ldl -o "$work/sky_against"
"$work/sky_against" "$threads" "$rounds" "$work/libsky_$rev.so" 0 "$work/libsky_here.so" 0 "$work/libsky_here.so" 1
