#!/usr/bin/env bash
# Installs the Debian 12 packages Aerial builds and tests with. Idempotent:
# only missing packages are installed, and `apt-get update` runs only then.
# Nothing is downloaded from anywhere but Debian's archive.
set -euo pipefail

packages=(
  # toolchain
  cmake ninja-build g++ pkg-config
  # aerial_core
  libglm-dev nlohmann-json3-dev
  # the aerial CLI
  libcli11-dev
  # `aerial bake` writes EXR sky tables (linked into the CLI only, never core)
  libopenexr-dev
  # renderer: GL loader, headless EGL on Mesa (llvmpipe in CI), EXR/PNG
  # capture, OCIO display transform, glTF scenes (libopenexr-dev: above)
  libepoxy-dev libegl-dev libgl1-mesa-dri libegl-mesa0 libopencolorio-dev libtinygltf-dev libstb-dev
  # the editor: GLFW window, Dear ImGui 1.86 (needs libstb, above)
  libglfw3-dev libimgui-dev
  # tests and benchmarks; the editor's window tests run under Xvfb
  # (python3-ephem: the independent sun and moon ephemeris of tests/cli/ephemeris_test.py)
  libgtest-dev libbenchmark-dev python3 python3-jsonschema python3-ephem xvfb xauth openexr
  # fuzzing the loaders: clang with libFuzzer (tests/fuzz)
  clang libclang-rt-14-dev
)
# Node.js and npm: the Khronos glTF validator of tests/cli/layout_test.py
# (the test installs npm gltf-validator into the build folder). Left alone
# when some node and npm are already there (e.g. from NodeSource).
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  echo "deps: installing ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
