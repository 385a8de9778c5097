#!/bin/sh
# check_golden.sh AERIAL GOLDEN_COMPARE SOURCE_DIR WORK_DIR — renders every
# golden case (golden_common.sh) with the `aerial` CLI and compares it with
# tests/golden/NAME.png: fails when a frame's PSNR is below
# GOLDEN_MIN_PSNR_DB. Update the goldens with scripts/update_golden.sh.
set -eu
aerial=$1 compare=$2 source=$3 work=$4
. "$source/tests/golden/golden_common.sh"
mkdir -p "$work"
status=0
echo "$GOLDEN_CASES" | while read -r name preset time; do
    [ -n "$name" ] || continue
    golden_render "$aerial" "$source" "$preset" "$time" "$work/$name.png"
    if ! "$compare" "$source/tests/golden/$name.png" "$work/$name.png" "$GOLDEN_MIN_PSNR_DB" "$name"; then
        echo "golden $name differs: see $work/$name.png; if the change is intended, run scripts/update_golden.sh"
        exit 1
    fi
done || status=1
exit $status
