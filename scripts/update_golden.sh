#!/bin/sh
# update_golden.sh [AERIAL] — re-renders the golden images of
# tests/golden/ (the cases in tests/golden/golden_common.sh) with the
# `aerial` CLI (default: build/release/app/aerial, or $AERIAL) and says, for
# each, whether it changed and by how much (PSNR against the previous file,
# when the compare tool is built beside the CLI).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
aerial=${1:-${AERIAL:-$root/build/release/app/aerial}}
if [ ! -x "$aerial" ]; then
    echo "update_golden.sh: no aerial CLI at $aerial (build it, or pass its path)" >&2
    exit 1
fi
compare=$(dirname "$(dirname "$aerial")")/tests/aerial_golden_compare
. "$root/tests/golden/golden_common.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "$GOLDEN_CASES" | while read -r name preset time; do
    [ -n "$name" ] || continue
    golden="$root/tests/golden/$name.png"
    golden_render "$aerial" "$root" "$preset" "$time" "$tmp/$name.png"
    if [ -f "$golden" ] && cmp -s "$golden" "$tmp/$name.png"; then
        echo "unchanged tests/golden/$name.png"
        continue
    fi
    how="new"
    if [ -f "$golden" ]; then
        how="changed"
        if [ -x "$compare" ]; then
            psnr=$("$compare" "$golden" "$tmp/$name.png" 0 "$name" | sed -n 's/.*PSNR \([^ ]*\) dB.*/\1/p')
            how="changed, PSNR $psnr dB against the previous"
        fi
    fi
    cp "$tmp/$name.png" "$golden"
    echo "updated tests/golden/$name.png ($preset at $time; $how; $(wc -c < "$golden") bytes)"
done
