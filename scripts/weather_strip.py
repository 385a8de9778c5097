#!/usr/bin/env python3
"""weather_strip.py — a preset's weather changing, frame by frame: each row
is `aerial render PRESET --time T --transition FROM:TO:F` for F = 0, 0.25,
0.5, 0.75, 1 (aerial/weather.hpp: each category at its own speed, the fog
ahead of the clouds), labelled, in one PNG. Pure Python (zlib only).

Usage:
  scripts/weather_strip.py --aerial build/release/app/aerial --out docs/weather_strip.png
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact_sheet import Canvas, pool_map, read_png  # noqa: E402
from pngio import write_png  # noqa: E402

ROWS = [
    ("clear_summer_day", "14:00", "clear", "storm"),
    ("clear_summer_day", "19:15", "clear", "overcast"),
    ("foggy_valley_morning", "07:30", "fog", "clearing"),
]
FRACTIONS = ["0", "0.25", "0.5", "0.75", "1"]


def main():
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--aerial", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--cell", default="192x108")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    cw, ch = (int(v) for v in args.cell.lower().split("x"))
    with tempfile.TemporaryDirectory() as work:
        jobs = []
        for i, (preset, time, a, b) in enumerate(ROWS):
            for j, f in enumerate(FRACTIONS):
                out = os.path.join(work, "%d_%d.png" % (i, j))
                jobs.append([args.aerial, "render", os.path.join(source, "presets", preset + ".json"), "--time", time,
                             "--transition", "%s:%s:%s" % (a, b, f), "--size", args.cell, "--out", out])

        def render(cmd):
            p = subprocess.run(cmd, capture_output=True, text=True)
            if p.returncode != 0:
                sys.exit("weather_strip: %s failed: %s" % (" ".join(cmd), p.stderr.strip()))

        list(pool_map(render, jobs, args.jobs))
        gap, label_w, header_h = 4, 250, 24
        canvas = Canvas(label_w + len(FRACTIONS) * (cw + gap), header_h + len(ROWS) * (ch + gap))
        for j, f in enumerate(FRACTIONS):
            canvas.text(label_w + j * (cw + gap) + cw // 2 - len(f) * 6, 5, f)
        for i, (preset, time, a, b) in enumerate(ROWS):
            y0 = header_h + i * (ch + gap)
            for k, line in enumerate([preset.replace("_", " "), time, "%s to %s" % (a, b)]):
                canvas.text(6, y0 + ch // 2 - 27 + k * 18, line)
            for j in range(len(FRACTIONS)):
                w, h, rgb = read_png(os.path.join(work, "%d_%d.png" % (i, j)))
                canvas.blit(label_w + j * (cw + gap), y0, w, h, rgb)
    write_png(args.out, canvas.width, canvas.height, canvas.rgb)
    print("wrote %s (%dx%d)" % (args.out, canvas.width, canvas.height))


if __name__ == "__main__":
    main()
