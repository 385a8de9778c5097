#!/usr/bin/env bash
# Public headers pull in nothing heavy and nothing graphical: no JSON types,
# no iostream, no OpenGL/window/UI headers (../shared/STYLE.md 1 and 4).
set -euo pipefail
dir=$1
bad=$(grep -nE '#include *[<"](nlohmann/|iostream|GL/|epoxy|GLFW|imgui|EGL)' "$dir"/*.hpp || true)
if [[ -n $bad ]]; then
  echo "public headers include forbidden headers:"; echo "$bad"; exit 1
fi
echo "public headers: $(ls "$dir"/*.hpp | wc -l) checked, clean"
