# golden_common.sh — the golden-image cases, sourced by
# tests/golden/check_golden.sh (the CTest) and scripts/update_golden.sh.
#
# Each case: NAME PRESET TIME. Every frame is the built-in scene from the
# preset's camera in `aerial render` (its "view", else the default camera),
# 320x180, at the preset's own exposure
# (its "exposure" block; no --exposure offset) through the "ACES 1.0 - SDR
# Video" view of Aerial's built-in OpenColorIO config ($OCIO is unset for
# these renders so a user's config cannot change them).
GOLDEN_CASES="
foggy_valley_0700 presets/foggy_valley_morning.json 07:00
clear_summer_1200 presets/clear_summer_day.json 12:00
hazy_sunset_1830 presets/hazy_sunset.json 18:30
hazy_sunset_1845 presets/hazy_sunset.json 18:45
stormy_night_0100 presets/stormy_night.json 01:00
"
GOLDEN_SIZE=320x180
GOLDEN_EXPOSURE=0
GOLDEN_VIEW="ACES 1.0 - SDR Video"
# Comparison: PSNR over the RGB channels of the 8-bit PNGs.
GOLDEN_MIN_PSNR_DB=40

# golden_render AERIAL SOURCE_DIR PRESET TIME OUT
golden_render() {
    env -u OCIO "$1" render "$2/$3" --time "$4" --size "$GOLDEN_SIZE" --exposure "$GOLDEN_EXPOSURE" \
        --view "$GOLDEN_VIEW" --out "$5" > /dev/null
}
