#!/bin/sh
# install_gltf_validator.sh PREFIX — installs the Khronos glTF validator
# (npm package gltf-validator, pinned below) into PREFIX/node_modules for
# the layout.gltf tests (tests/CMakeLists.txt, fixture gltf_validator).
# PREFIX is in the build folder: nothing is installed globally and nothing
# is written to the source tree. Idempotent: when the pinned version is
# already there, it does nothing (no network).
#
# Reads: the npm registry (only when not yet installed). Writes: PREFIX.
# Exit 0 when the validator is ready, 1 (with the reason) otherwise.
set -eu
version=2.0.0-dev.3.10
[ $# -eq 1 ] || { echo "usage: install_gltf_validator.sh PREFIX" >&2; exit 2; }
prefix=$1
package=$prefix/node_modules/gltf-validator/package.json
if [ -f "$package" ] && grep -q "\"version\": *\"$version\"" "$package"; then
    echo "gltf-validator $version already in $prefix"
    exit 0
fi
for tool in node npm; do
    command -v "$tool" >/dev/null 2>&1 || {
        echo "install_gltf_validator.sh: $tool not found: install Node.js (Debian: nodejs npm)" >&2
        exit 1
    }
done
mkdir -p "$prefix"
npm install --prefix "$prefix" --no-audit --no-fund --no-save --loglevel=error "gltf-validator@$version" || {
    echo "install_gltf_validator.sh: npm install gltf-validator@$version into $prefix failed" >&2
    exit 1
}
[ -f "$package" ] || { echo "install_gltf_validator.sh: $package missing after npm install" >&2; exit 1; }
echo "gltf-validator $version installed into $prefix"
