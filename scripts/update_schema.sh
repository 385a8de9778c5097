#!/bin/sh
# update_schema.sh [PRINT_SCHEMA] — regenerates presets/aerial-preset.schema.json
# from the parameter table and the caps of aerial/limits.hpp
# (aerial::presetJsonSchema(), printed by the aerial_print_schema test tool;
# default: build/release/tests/aerial_print_schema, or $AERIAL_PRINT_SCHEMA)
# and says whether it changed. test_preset fails until the file matches.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
tool=${1:-${AERIAL_PRINT_SCHEMA:-$root/build/release/tests/aerial_print_schema}}
if [ ! -x "$tool" ]; then
    echo "update_schema.sh: no schema printer at $tool" \
         "(cmake --build --preset release --target aerial_print_schema, or pass its path)" >&2
    exit 1
fi
schema="$root/presets/aerial-preset.schema.json"
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
"$tool" > "$tmp"
if [ -f "$schema" ] && cmp -s "$schema" "$tmp"; then
    echo "unchanged presets/aerial-preset.schema.json"
    exit 0
fi
cp "$tmp" "$schema"
echo "updated presets/aerial-preset.schema.json ($(wc -c < "$schema") bytes); review with git diff"
