#!/usr/bin/env python3
"""An engine's reader of a bake (examples/bake_reader, no Aerial code)
against `aerial sky` and `aerial fog` on the same preset and times.

For a few steps of a day's bake of three shipped presets (day, the low sun,
twilight, night): the sky-view map sampled by the reader in random
directions above the horizon against `aerial sky`'s sky_rgb, and the global
fog along segments of 50 m to 8 km against `aerial fog`'s global fog
(transmittance, the fog's colour) and, where the segment crosses no volume
and no emitter, its whole in-scatter: within 2 % per channel, floored at
2 % of the sample's brightest channel (a channel below that moves the colour
less than anyone sees).

python3 only (unittest); run by CTest as `bake_reader`.
"""
import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import unittest

ARGS = None


def run(*args):
    p = subprocess.run([ARGS.aerial] + list(args), capture_output=True, text=True)
    if p.returncode != 0:
        raise AssertionError("aerial %s: exit %d: %s" % (" ".join(args), p.returncode, p.stderr))
    return p.stdout


def run_json(*args):
    return json.loads(run(*args, "--json"))


def direction(azimuth, elevation):
    return (math.cos(elevation) * math.sin(azimuth), math.sin(elevation), -math.cos(elevation) * math.cos(azimuth))


def relative_error(got, want):
    floor = max(0.02 * max(max(want), 0.0), 1e-12)
    return max(abs(g - max(w, 0.0)) / max(max(w, 0.0), floor) for g, w in zip(got, want))


class BakeReader(unittest.TestCase):
    # preset -> steps (whole hours of a 1 h bake) to check
    PRESETS = {
        "hazy_sunset": [2, 7, 12, 18, 19, 20],
        "foggy_valley_morning": [5, 6, 9],
        "desert_dusk": [1, 17, 21],
    }

    @classmethod
    def setUpClass(cls):
        cls.bakes = {}
        for name in cls.PRESETS:
            out = os.path.join(ARGS.work_dir, name)
            shutil.rmtree(out, ignore_errors=True)
            run("bake", os.path.join(ARGS.source_dir, "presets", name + ".json"), "--out", out, "--step", "1h",
                "--quiet")
            with open(os.path.join(out, "manifest.json")) as f:
                cls.bakes[name] = (out, json.load(f))

    def reader(self, bake_dir, queries):
        p = subprocess.run([ARGS.reader, bake_dir], input="\n".join(queries) + "\n", capture_output=True,
                           text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        lines = p.stdout.splitlines()
        self.assertEqual(len(lines), len(queries))
        return [[float(x) for x in line.split()] for line in lines]

    def test_the_manifest_is_format_2(self):
        for name, (_, manifest) in self.bakes.items():
            self.assertEqual(manifest["format_version"], 3, name)
            step = manifest["steps"][0]
            for key in ("sky_view_file", "far_fog_file", "sky_irradiance_sh9", "fog"):
                self.assertIn(key, step, name)
            self.assertEqual(len(step["sky_irradiance_sh9"]), 9)
            self.assertIn("sky_view", manifest)
            self.assertIn("formula", manifest["fog"])

    def test_each_weather_state_is_baked(self):
        out, manifest = self.bakes["foggy_valley_morning"]
        self.assertEqual(manifest["weather"]["states"], ["fog", "clearing"])
        self.assertEqual(manifest["weather"]["category_share"]["clouds"], 1.0)
        for step in manifest["steps"]:
            for name in ("fog", "clearing"):
                entry = step["weather"][name]
                for key in ("sky_view_file", "far_fog_file"):
                    self.assertTrue(os.path.isfile(os.path.join(out, entry[key])), entry[key])
                self.assertEqual(len(entry["sky_irradiance_sh9"]), 9)
            # "fog" has no overrides: the keyed values; "clearing" scales the fog by 0.1.
            base = step["parameters"]["fog"]["density_per_m"]
            self.assertEqual(step["weather"]["fog"]["parameters"], step["parameters"])
            self.assertAlmostEqual(step["weather"]["clearing"]["parameters"]["fog"]["density_per_m"], 0.1 * base,
                                   delta=1e-15 + 1e-12 * base)
            self.assertAlmostEqual(step["weather"]["clearing"]["fog"]["density_per_m"], 0.1 * base,
                                   delta=1e-15 + 1e-12 * base)

    def test_the_sky_view_map_is_the_sky(self):
        rng = random.Random(49)
        worst = (0.0, None)
        for name, steps in self.PRESETS.items():
            out, manifest = self.bakes[name]
            preset = os.path.join(ARGS.source_dir, "presets", name + ".json")
            for index in steps:
                step = manifest["steps"][index]
                sun = step["sun"]
                # The map blurs the cap of the earth's shadow for a sun 0-0.3 deg down (manifest).
                self.assertFalse(-0.3 < sun["elevation_deg"] < 0.0, (name, index))
                dirs = []
                for _ in range(8):
                    v = direction(rng.uniform(0, 2 * math.pi), math.radians(rng.choice([0.3, 2.0, 8.0, 40.0]) * rng.random() ** 0.5 + 0.2))
                    dirs.append(v)
                got = self.reader(out, ["sky %d %r %r %r" % ((index,) + v) for v in dirs])
                for v, g in zip(dirs, got):
                    want = run_json("sky", preset, "--time", step["time"], "--dir=%r,%r,%r" % v)["sky_rgb"]
                    e = relative_error(g, want)
                    if e > worst[0]:
                        worst = (e, (name, step["time"], v, g, want))
                    self.assertLess(e, 0.02, (name, step["time"], v, g, want))
        print("sky-view map against `aerial sky`: worst %.4f at %r" % worst, file=sys.stderr)

    def test_the_fog_formula_is_the_fog(self):
        rng = random.Random(51)
        worst = (0.0, None)
        for name, steps in self.PRESETS.items():
            out, manifest = self.bakes[name]
            preset = os.path.join(ARGS.source_dir, "presets", name + ".json")
            for index in steps[:2] + steps[-1:]:
                step = manifest["steps"][index]
                segments = []
                for length in (50.0, 300.0, 2000.0, 8000.0):
                    az = rng.uniform(0, 2 * math.pi)
                    rise = rng.uniform(-0.02, 0.08) * length
                    segments.append(((0.0, 2.0, 0.0),
                                     (length * math.sin(az), 2.0 + rise, -length * math.cos(az))))
                queries = ["fog %d %r %r %r %r %r %r" % ((index,) + p + q) for p, q in segments]
                queries += ["fogcolour %d %r %r %r %r" % ((index,) + tuple(b - a for a, b in zip(p, q)) +
                                                          (math.dist(p, q),)) for p, q in segments]
                answers = self.reader(out, queries)
                for (p, q), fog, colour in zip(segments, answers[:len(segments)], answers[len(segments):]):
                    want = run_json("fog", preset, "--time", step["time"], "--from=%r,%r,%r" % p,
                                    "--to=%r,%r,%r" % q)
                    g = want["global_fog"]
                    self.assertAlmostEqual(fog[0], g["transmittance"], delta=1e-6 + 1e-6 * g["transmittance"],
                                           msg=(name, step["time"], p, q))
                    e = relative_error(colour, g["fog_colour_rgb"])
                    if e > worst[0]:
                        worst = (e, (name, step["time"], q, colour, g["fog_colour_rgb"]))
                    self.assertLess(e, 0.02, (name, step["time"], q, colour, g["fog_colour_rgb"]))
                    if not want["volumes"] and max(want["emitter_in_scatter_rgb"]) == 0.0:
                        self.assertLess(relative_error(fog[1:], want["in_scatter_rgb"]), 0.02,
                                        (name, step["time"], q, fog, want["in_scatter_rgb"]))
        print("fog formula against `aerial fog`: worst %.4f at %r" % worst, file=sys.stderr)

    def test_the_irradiance_lights_an_upward_surface_as_the_sky_does(self):
        # E(up) from the nine coefficients (Rec.709 luminance x the bake's
        # nits per radiance unit) against `aerial eval`'s horizontal
        # illuminance of the sky and the night sky (the sky under the
        # clouds, integrated by the library's own quadrature): 8 %. Nine
        # terms ring around a bright aureole low in the sky: 5.9 % with
        # hazy_sunset's g = 0.86 at 18:00 (Ramamoorthi and Hanrahan 2001
        # bound the nine-term irradiance at 9 % for any light); a wrong basis
        # constant or axis is off by tens of percent.
        for name, steps in self.PRESETS.items():
            out, manifest = self.bakes[name]
            nits = manifest["exposure"]["nits_per_radiance_unit"]
            preset = os.path.join(ARGS.source_dir, "presets", name + ".json")
            up = self.reader(out, ["irradiance %d 0 1 0" % i for i in steps])
            for index, e in zip(steps, up):
                lux = (0.2126 * e[0] + 0.7152 * e[1] + 0.0722 * e[2]) * nits
                light = run_json("eval", preset, "--time", manifest["steps"][index]["time"])["light"]
                want = light["horizontal_illuminance_lux"]["sky"] + light["horizontal_illuminance_lux"]["night"]
                print("%s %s: sky irradiance up %.6g lx from sh9, %.6g lx from aerial eval" %
                      (name, manifest["steps"][index]["time"], lux, want), file=sys.stderr)
                self.assertLess(abs(lux - want), 0.08 * want, (name, index, lux, want))


def main():
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument("--aerial", required=True)
    parser.add_argument("--reader", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--work-dir", required=True)
    ARGS, rest = parser.parse_known_args()
    os.makedirs(ARGS.work_dir, exist_ok=True)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
