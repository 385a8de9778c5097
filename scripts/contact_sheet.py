#!/usr/bin/env python3
"""contact_sheet.py — every shipped preset at eight hours of the day, labelled,
in one PNG: how an artist chooses a preset (by looking, not by reading JSON).

Each cell is `aerial render PRESET --time T` of the built-in scene from the
preset's camera (its "view", else the CLI's default), with the preset's own
exposure (its "exposure" block) and the
default (tone-mapped) view: exactly what `aerial render` shows. The last
column plots the preset's main parameters over the day (`aerial eval` every
half hour): sun and moon elevation, the global fog density (log scale) and
the exposure compensation. Pure Python (zlib only): reads the 8-bit PNGs
aerial writes, writes one 8-bit RGB PNG.

Usage:
  scripts/contact_sheet.py --aerial build/release/app/aerial --out docs/contact_sheet.png
  scripts/contact_sheet.py --aerial ... --cell 160x90 --hours 06:00,12:00 --presets clear_summer_day
"""
import argparse
import concurrent.futures
import glob
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngio import PngError, read_rgb, write_png  # noqa: E402

HOURS = ["02:00", "05:30", "07:00", "09:30", "12:00", "16:00", "18:45", "21:30"]

# A 5x7 bitmap font for the labels: each glyph is 7 rows of 5 bits.
FONT = {
    "a": "00000 00000 01110 00001 01111 10001 01111", "b": "10000 10000 11110 10001 10001 10001 11110",
    "c": "00000 00000 01110 10000 10000 10001 01110", "d": "00001 00001 01111 10001 10001 10001 01111",
    "e": "00000 00000 01110 10001 11111 10000 01110", "f": "00110 01001 01000 11100 01000 01000 01000",
    "g": "00000 01111 10001 10001 01111 00001 01110", "h": "10000 10000 10110 11001 10001 10001 10001",
    "i": "00100 00000 01100 00100 00100 00100 01110", "j": "00010 00000 00110 00010 00010 10010 01100",
    "k": "10000 10000 10010 10100 11000 10100 10010", "l": "01100 00100 00100 00100 00100 00100 01110",
    "m": "00000 00000 11010 10101 10101 10001 10001", "n": "00000 00000 10110 11001 10001 10001 10001",
    "o": "00000 00000 01110 10001 10001 10001 01110", "p": "00000 00000 11110 10001 11110 10000 10000",
    "q": "00000 00000 01111 10001 01111 00001 00001", "r": "00000 00000 10110 11001 10000 10000 10000",
    "s": "00000 00000 01111 10000 01110 00001 11110", "t": "01000 01000 11100 01000 01000 01001 00110",
    "u": "00000 00000 10001 10001 10001 10011 01101", "v": "00000 00000 10001 10001 10001 01010 00100",
    "w": "00000 00000 10001 10001 10101 10101 01010", "x": "00000 00000 10001 01010 00100 01010 10001",
    "y": "00000 00000 10001 10001 01111 00001 01110", "z": "00000 00000 11111 00010 00100 01000 11111",
    "0": "01110 10001 10011 10101 11001 10001 01110", "1": "00100 01100 00100 00100 00100 00100 01110",
    "2": "01110 10001 00001 00010 00100 01000 11111", "3": "11111 00010 00100 00010 00001 10001 01110",
    "4": "00010 00110 01010 10010 11111 00010 00010", "5": "11111 10000 11110 00001 00001 10001 01110",
    "6": "00110 01000 10000 11110 10001 10001 01110", "7": "11111 00001 00010 00100 01000 01000 01000",
    "8": "01110 10001 10001 01110 10001 10001 01110", "9": "01110 10001 10001 01111 00001 00010 01100",
    ":": "00000 01100 01100 00000 01100 01100 00000", ".": "00000 00000 00000 00000 00000 01100 01100",
    "-": "00000 00000 00000 11111 00000 00000 00000", "_": "00000 00000 00000 00000 00000 00000 11111",
    " ": "00000 00000 00000 00000 00000 00000 00000",
}


def read_png(path):
    """8-bit RGB or RGBA -> (w, h, rgb bytes); exits with the reason on anything else."""
    try:
        return read_rgb(path)
    except (OSError, PngError) as e:
        sys.exit("contact_sheet: %s" % e)


def pool_map(function, items, jobs=2):
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        return list(pool.map(function, items))


class Canvas:
    def __init__(self, width, height, colour=(24, 24, 28)):
        self.width, self.height = width, height
        self.rgb = bytearray(bytes(colour) * (width * height))

    def blit(self, x0, y0, w, h, rgb):
        for y in range(h):
            row = (y0 + y) * self.width + x0
            self.rgb[row * 3:(row + w) * 3] = rgb[y * w * 3:(y + 1) * w * 3]

    def point(self, x, y, colour):
        if 0 <= x < self.width and 0 <= y < self.height:
            self.rgb[(y * self.width + x) * 3:(y * self.width + x) * 3 + 3] = bytes(colour)

    def line(self, x0, y0, x1, y1, colour):
        n = max(abs(x1 - x0), abs(y1 - y0), 1)
        for k in range(n + 1):
            self.point(round(x0 + (x1 - x0) * k / n), round(y0 + (y1 - y0) * k / n), colour)

    def text(self, x0, y0, text, scale=2, colour=(230, 230, 230)):
        for n, ch in enumerate(text.lower()):
            glyph = FONT.get(ch, FONT[" "]).split()
            for gy, bits in enumerate(glyph):
                for gx, bit in enumerate(bits):
                    if bit != "1":
                        continue
                    for sy in range(scale):
                        for sx in range(scale):
                            self.point(x0 + (n * 6 + gx) * scale + sx, y0 + gy * scale + sy, colour)


# The plotted curves: (label, colour, value from `aerial eval --json`, range).
CURVES = [
    ("sun", (255, 200, 60), lambda e: e["sun"]["elevation_deg"], (-90.0, 90.0)),
    ("moon", (150, 190, 255), lambda e: e["moon"]["elevation_deg"], (-90.0, 90.0)),
    ("fog", (200, 200, 200), lambda e: math.log10(max(e["parameters"]["fog"]["density_per_m"], 1e-6)), (-6.0, -1.0)),
    ("ev comp", (240, 90, 200), lambda e: e["parameters"]["exposure"]["compensation_ev"], (-3.0, 3.0)),
]


def evaluate_day(aerial, preset):
    """`aerial eval --json` every half hour, 00:00 to 24:00."""
    rows = []
    for k in range(49):
        p = subprocess.run([aerial, "eval", preset, "--time", str(min(k * 0.5, 23.99)), "--json"],
                           capture_output=True, text=True)
        if p.returncode != 0:
            sys.exit("contact_sheet: aerial eval %s failed: %s" % (preset, p.stderr.strip()))
        rows.append((k * 0.5, json.loads(p.stdout)))
    return rows


def plot_day(canvas, x0, y0, w, h, rows):
    """The curves over 24 h in a w x h box: the horizon (elevation 0, EV 0) dotted, 6/12/18 h marked."""
    for gx in (6, 12, 18):
        for y in range(y0, y0 + h, 3):
            canvas.point(x0 + round(gx / 24.0 * (w - 1)), y, (70, 70, 78))
    for x in range(x0, x0 + w, 3):
        canvas.point(x, y0 + h // 2, (90, 90, 98))
    for _, colour, value, (lo, hi) in CURVES:
        last = None
        for t, e in rows:
            v = min(max((value(e) - lo) / (hi - lo), 0.0), 1.0)
            here = (x0 + round(t / 24.0 * (w - 1)), y0 + round((1.0 - v) * (h - 1)))
            if last:
                canvas.line(last[0], last[1], here[0], here[1], colour)
            last = here


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    source = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--aerial", required=True, help="the aerial CLI (build/release/app/aerial)")
    ap.add_argument("--out", required=True, help="the contact sheet, .png")
    ap.add_argument("--cell", default="192x108", help="each frame's size, WxH (default 192x108)")
    ap.add_argument("--hours", default=",".join(HOURS), help="comma-separated times (default eight hours)")
    ap.add_argument("--presets", default="", help="comma-separated preset names (default every shipped preset)")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    cw, ch = (int(v) for v in args.cell.lower().split("x"))
    hours = [h for h in args.hours.split(",") if h]
    if args.presets:
        presets = [os.path.join(source, "presets", p + ".json") for p in args.presets.split(",")]
    else:
        presets = sorted(p for p in glob.glob(os.path.join(source, "presets", "*.json"))
                         if not p.endswith(".schema.json"))
    with tempfile.TemporaryDirectory() as work:
        jobs = []
        for i, preset in enumerate(presets):
            for j, hour in enumerate(hours):
                out = os.path.join(work, "%d_%d.png" % (i, j))
                jobs.append((out, [args.aerial, "render", preset, "--time", hour, "--size", args.cell, "--out", out]))

        def render(job):
            p = subprocess.run(job[1], capture_output=True, text=True)
            if p.returncode != 0:
                sys.exit("contact_sheet: %s failed: %s" % (" ".join(job[1]), p.stderr.strip()))

        list(pool_map(render, jobs, args.jobs))
        days = list(pool_map(lambda p: evaluate_day(args.aerial, p), presets, args.jobs))
        gap, label_w, header_h = 4, 140, 24
        plot_w = 2 * cw
        frames_w = len(hours) * (cw + gap)
        canvas = Canvas(label_w + frames_w + plot_w + gap, header_h + len(presets) * (ch + gap))
        for j, hour in enumerate(hours):
            canvas.text(label_w + j * (cw + gap) + cw // 2 - len(hour) * 6, 5, hour)
        legend_x = label_w + frames_w
        for label, colour, _, _ in CURVES:
            canvas.text(legend_x, 5, label, colour=colour)
            legend_x += (len(label) + 1) * 12
        for i, preset in enumerate(presets):
            name = os.path.basename(preset)[:-5]
            y0 = header_h + i * (ch + gap)
            words = name.split("_")
            for k, word in enumerate(words):
                canvas.text(6, y0 + ch // 2 - len(words) * 9 + k * 18, word)
            for j in range(len(hours)):
                w, h, rgb = read_png(os.path.join(work, "%d_%d.png" % (i, j)))
                if (w, h) != (cw, ch):
                    sys.exit("contact_sheet: a frame is %dx%d, not %dx%d" % (w, h, cw, ch))
                canvas.blit(label_w + j * (cw + gap), y0, w, h, rgb)
            plot_day(canvas, label_w + frames_w, y0, plot_w, ch, days[i])
    write_png(args.out, canvas.width, canvas.height, canvas.rgb)
    print("wrote %s (%dx%d: %d presets x %d hours, and their day)" % (args.out, canvas.width, canvas.height,
                                                                       len(presets), len(hours)))


if __name__ == "__main__":
    main()
