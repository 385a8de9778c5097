#!/usr/bin/env bash
# Fuzzes the two loaders of untrusted files with libFuzzer (clang, ASan +
# UBSan): fuzz_preset (preset JSON) and fuzz_gltf (.gltf / .glb). Fails on
# any crash, leak, timeout or out-of-memory.
#
#   scripts/fuzz.sh            # each target for 60 s
#   scripts/fuzz.sh 600        # each target for 10 minutes
#   AERIAL_FUZZ_TARGETS=fuzz_preset scripts/fuzz.sh 30
#
# Build: build/fuzz (its own clang configuration; only the fuzz targets and
# what they link). Corpus: build/fuzz/corpus/<target> grows between runs and
# starts from the seeds in tests/fuzz/corpus/<target> and the real files
# (shipped presets, test fixtures). A crashing input is saved as
# build/fuzz/artifacts/<target>/crash-*; replay it with
#   build/fuzz/tests/fuzz/<target>_fuzzer FILE
# and add it to tests/fuzz/corpus/<target> once fixed, so every normal test
# run replays it (CTest: <target>_corpus).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
if ! [[ $seconds =~ ^[0-9]+$ ]] || (( seconds < 1 )); then
  echo "usage: scripts/fuzz.sh [SECONDS_PER_TARGET]" >&2; exit 2
fi
targets=${AERIAL_FUZZ_TARGETS:-"fuzz_preset fuzz_gltf"}
cxx=${AERIAL_FUZZ_CXX:-$(command -v clang++-14 || command -v clang++ || echo clang++)}
build=build/fuzz

sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=all -fsanitize=fuzzer-no-link"
echo "== fuzz: configure ($cxx, $build)"
cmake -S . -B "$build" -G Ninja \
  -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$sanitizers -fno-omit-frame-pointer" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DAERIAL_BUILD_FUZZERS=ON -DAERIAL_BUILD_APPS=OFF -DAERIAL_BUILD_BENCHMARKS=OFF \
  -DAERIAL_BUILD_EDITOR=OFF -DAERIAL_WERROR=OFF >/dev/null

build_targets=()
for t in $targets; do build_targets+=("${t}_fuzzer"); done
echo "== fuzz: build ${build_targets[*]}"
cmake --build "$build" -j "$(nproc)" --target "${build_targets[@]}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for t in $targets; do
  corpus=$build/corpus/$t
  artifacts=$build/artifacts/$t
  mkdir -p "$corpus" "$artifacts"
  case $t in
    fuzz_preset) seeds=(tests/fuzz/corpus/preset presets tests/data/presets tests/data/bad_inputs/presets) ;;
    fuzz_gltf) seeds=(tests/fuzz/corpus/gltf) ;;
    *) echo "fuzz: unknown target $t" >&2; exit 2 ;;
  esac
  existing=()
  for s in "${seeds[@]}"; do [[ -d $s ]] && existing+=("$s"); done
  dict=()
  [[ -f tests/fuzz/$t.dict ]] && dict=(-dict="tests/fuzz/$t.dict")
  echo "== fuzz: $t for ${seconds}s (corpus $corpus)"
  log=$build/$t.log
  # -rss_limit_mb: the limits of aerial/limits.hpp keep a load far below it.
  # -timeout: any single input slower than this is a hang.
  if "$build/tests/fuzz/${t}_fuzzer" "$corpus" "${existing[@]}" "${dict[@]}" \
       -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
       -print_final_stats=1 -artifact_prefix="$artifacts/" \
       >"$log" 2>&1; then
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+[[:space:]]+DONE)' "$log" || true
    echo "fuzz: $t: no crash; corpus $(find "$corpus" -type f | wc -l) files"
  else
    status=1
    echo "fuzz: $t FAILED; the last lines of $log:" >&2
    tail -n 40 "$log" >&2
    ls -1 "$artifacts" >&2 || true
  fi
done
exit $status
