#!/usr/bin/env python3
"""readability_test.py — every shipped preset, rendered as shipped (`aerial
render`, its own exposure, the default tone-mapped view), reads at every hour:
at each of the contact sheet's eight hours the displayed picture is neither
black nor blown out.

The band, on the 8-bit sRGB PNG (luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B'
of the encoded values, 0..1):
  * mean luma in [0.06, 0.60]: below 0.06 (~15/255 average) a picture reads as
    black on a normal monitor in a lit room, and 0.60 is above any exposed
    scene here (automatic exposure shows a sunny noon's median grey near
    0.45; the presets key a -1 to -1.5 EV night compensation, which lands
    near 0.12-0.2);
  * at most 2 % of the pixels clipped to white (every channel >= 250): the
    sun's disc and an emitter may clip, a blown-out sky or ground may not;
  * at most 50 % of the pixels near black (luma < 0.02): a night may be dark,
    not a black frame with stars.
A negative control renders two frames with --exposure pushed 8 stops down and
6 stops up and checks that the same band rejects them, so the check can fail.

Usage: readability_test.py --aerial build/release/app/aerial --source-dir . --work-dir DIR
"""
import argparse
import glob
import os
import subprocess
import sys

SIZE = "96x54"
MEAN_LUMA = (0.06, 0.60)
MAX_CLIPPED = 0.02
MAX_NEAR_BLACK = 0.50


def stats(png, read_png):
    w, h, rgb = read_png(png)
    n = w * h
    luma = [(0.2126 * rgb[3 * i] + 0.7152 * rgb[3 * i + 1] + 0.0722 * rgb[3 * i + 2]) / 255.0 for i in range(n)]
    clipped = sum(1 for i in range(n) if min(rgb[3 * i:3 * i + 3]) >= 250) / n
    black = sum(1 for y in luma if y < 0.02) / n
    return sum(luma) / n, clipped, black


def verdict(mean, clipped, black):
    """'' when readable, else why not."""
    why = []
    if mean < MEAN_LUMA[0]:
        why.append("black (mean luma %.3f < %.2f)" % (mean, MEAN_LUMA[0]))
    if mean > MEAN_LUMA[1]:
        why.append("blown out (mean luma %.3f > %.2f)" % (mean, MEAN_LUMA[1]))
    if clipped > MAX_CLIPPED:
        why.append("%.1f %% clipped to white (> %.0f %%)" % (100 * clipped, 100 * MAX_CLIPPED))
    if black > MAX_NEAR_BLACK:
        why.append("%.0f %% near black (> %.0f %%)" % (100 * black, 100 * MAX_NEAR_BLACK))
    return "; ".join(why)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--aerial", required=True)
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--work-dir", required=True)
    args = ap.parse_args()
    sys.path.insert(0, os.path.join(args.source_dir, "scripts"))
    from contact_sheet import HOURS, read_png  # the sheet's hours and PNG reader
    os.makedirs(args.work_dir, exist_ok=True)

    def render(preset, hour, extra=()):
        out = os.path.join(args.work_dir, "%s_%s.png" % (os.path.basename(preset)[:-5], hour.replace(":", "")))
        p = subprocess.run([args.aerial, "render", preset, "--time", hour, "--size", SIZE, "--out", out] + list(extra),
                           capture_output=True, text=True, timeout=300)
        if p.returncode != 0:
            sys.exit("FAIL: aerial render %s --time %s: exit %d: %s" % (preset, hour, p.returncode, p.stderr))
        return out

    presets = sorted(p for p in glob.glob(os.path.join(args.source_dir, "presets", "*.json"))
                     if not p.endswith(".schema.json"))
    if len(presets) < 5:
        sys.exit("FAIL: expected the shipped presets in %s/presets" % args.source_dir)
    failures = []
    print("%-22s %s" % ("preset", "  ".join("%-17s" % h for h in HOURS)))
    for preset in presets:
        cells = []
        for hour in HOURS:
            mean, clipped, black = stats(render(preset, hour), read_png)
            cells.append("m%.2f c%.2f b%.2f" % (mean, clipped, black))
            why = verdict(mean, clipped, black)
            if why:
                failures.append("%s at %s: %s" % (os.path.basename(preset), hour, why))
        print("%-22s %s" % (os.path.basename(preset)[:-5], "  ".join(cells)))

    # Negative controls: the band must reject a black and a blown-out frame.
    day = os.path.join(args.source_dir, "presets", "clear_summer_day.json")
    dark = verdict(*stats(render(day, "02:00", ["--exposure", "-8"]), read_png))
    bright = verdict(*stats(render(day, "12:00", ["--exposure", "6"]), read_png))
    print("control, 02:00 at -8 EV: %s" % (dark or "readable"))
    print("control, 12:00 at +6 EV: %s" % (bright or "readable"))
    if "black" not in dark:
        failures.append("the band did not reject a frame 8 stops too dark")
    if "blown out" not in bright and "clipped" not in bright:
        failures.append("the band did not reject a frame 6 stops too bright")
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1
    print("every shipped preset reads at every hour")
    return 0


if __name__ == "__main__":
    sys.exit(main())
