#!/usr/bin/env python3
"""End-to-end tests of the real `aerial` binary (no pip packages).

    cli_test.py --aerial PATH --source-dir REPO_ROOT --work-dir DIR [unittest args]

Every command is run as a subprocess and judged by its exit code, stdout and
stderr. Known answers are recomputed here, independently of aerial_core:
the sun direction from the formulas in DESIGN.md ("Sun position"), and the
global-fog transmittance from the closed-form integral ("Global height
fog"). The sky table is compared with the library's brute-force reference
(`aerial sky` prints both). EXR files are checked by parsing their header
by hand (python3 has no OpenEXR module).
"""

import argparse
import re
import base64
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from pngio import decode_png  # noqa: E402  (the one PNG reader)

AERIAL = ""
ROOT = ""
WORK = ""
TEST_HOOKS = True  # aerial built with AERIAL_TEST_HOOKS (it honours AERIAL_TEST_FILE_FAULT)

SHIPPED = ["clear_summer_day", "desert_dusk", "foggy_valley_morning", "hazy_sunset", "stormy_night"]


def preset(name):
    return os.path.join(ROOT, "presets", name + ".json")


# A hang guard per aerial process, not a speed bound: the 96-step bake of
# test_pixels_lie_where_their_coordinates_say went past 120 s under
# AddressSanitizer on a loaded 2-core machine.
PROCESS_TIMEOUT = 600


def run(*args, timeout=PROCESS_TIMEOUT):
    """Runs aerial with args; returns (exit code, stdout, stderr)."""
    p = subprocess.run([AERIAL, *args], capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def run_json(testcase, *args):
    code, out, err = run(*args, "--json")
    testcase.assertEqual(code, 0, err)
    return json.loads(out)


# ---------------------------------------------------------------------------
# Independent references


def sun_direction(latitude_deg, day_of_year, north_offset_deg, t):
    """DESIGN.md "Sun position", with the azimuth formula from sun.hpp."""
    rad = math.radians
    decl = rad(-23.44) * math.cos(rad(360.0 / 365.0 * (day_of_year + 10.0)))
    hour_angle = rad(15.0 * (t - 12.0))
    lat = rad(latitude_deg)
    sin_el = math.sin(lat) * math.sin(decl) + math.cos(lat) * math.cos(decl) * math.cos(hour_angle)
    el = math.asin(max(-1.0, min(1.0, sin_el)))
    az = math.atan2(-math.cos(decl) * math.sin(hour_angle),
                    math.sin(decl) * math.cos(lat) - math.cos(decl) * math.cos(hour_angle) * math.sin(lat))
    az += rad(north_offset_deg)
    return (math.cos(el) * math.sin(az), math.sin(el), -math.cos(el) * math.cos(az))


def height_fog_optical_depth(b, c, h0, o, to):
    """DESIGN.md: b exp(-c (o.y - h0)) |d| (1 - exp(-c d.y)) / (c d.y)."""
    d = [to[i] - o[i] for i in range(3)]
    length = math.sqrt(sum(x * x for x in d))
    x = c * d[1]
    factor = 1.0 if x == 0.0 else -math.expm1(-x) / x
    return b * math.exp(-c * (o[1] - h0)) * length * factor


# ---------------------------------------------------------------------------
# A hand-written OpenEXR header reader: magic, version, then attributes
# (name \0 type \0 int32 size, value) until a null byte.


def read_exr_header(path):
    with open(path, "rb") as f:
        data = f.read()
    version, attributes, _ = parse_exr_header(data, path)
    return version, attributes


def parse_exr_header(data, path):
    """Returns (version, attributes, offset of the first byte after the header)."""
    if data[:4] != bytes([0x76, 0x2F, 0x31, 0x01]):
        raise ValueError(path + ": not an OpenEXR file (magic %s)" % data[:4].hex())
    version = struct.unpack("<i", data[4:8])[0]
    pos, attributes = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        pos = end + 1
        end = data.index(b"\0", pos)
        kind = data[pos:end].decode()
        pos = end + 1
        (size,) = struct.unpack("<i", data[pos:pos + 4])
        pos += 4
        attributes[name] = (kind, data[pos:pos + size])
        pos += size
    return version, attributes, pos + 1


def read_uncompressed_exr(path):
    """Pixels of a single-part, uncompressed, HALF or FLOAT scanline file: {channel: rows of values}."""
    with open(path, "rb") as f:
        data = f.read()
    _, attributes, pos = parse_exr_header(data, path)
    if attributes["compression"][1] != b"\0":
        raise ValueError(path + ": compressed")
    channels = read_chlist(attributes["channels"][1])  # stored in this (sorted) order
    x0, y0, x1, y1 = struct.unpack("<4i", attributes["dataWindow"][1])
    width, height = x1 - x0 + 1, y1 - y0 + 1
    offsets = struct.unpack("<%dQ" % height, data[pos:pos + 8 * height])
    pixels = {c: [None] * height for c in channels}
    formats = {1: "e", 2: "f"}  # HALF, FLOAT
    for offset in offsets:
        y, size = struct.unpack("<2i", data[offset:offset + 8])
        at = offset + 8
        for c, pixel_type in channels.items():
            fmt = "<%d%s" % (width, formats[pixel_type])
            pixels[c][y - y0] = struct.unpack(fmt, data[at:at + struct.calcsize(fmt)])
            at += struct.calcsize(fmt)
    return width, height, pixels


def read_chlist(value):
    """name \0, int32 pixel type, uint8 pLinear, 3 reserved, int32 xSampling, int32 ySampling; ends with \0."""
    channels, pos = {}, 0
    while value[pos] != 0:
        end = value.index(b"\0", pos)
        name = value[pos:end].decode()
        pos = end + 1
        (pixel_type,) = struct.unpack("<i", value[pos:pos + 4])
        pos += 16
        channels[name] = pixel_type
    return channels


def read_png(path):
    """(width, height, colour type, bit depth, rows of bytes) of an 8-bit RGB/RGBA PNG (scripts/pngio.py)."""
    return decode_png(path)


def has_render_command():
    code, out, _ = run("--help")
    return code == 0 and "render" in out


def leaf_paths(obj, prefix=""):
    if isinstance(obj, dict):
        out = set()
        for k, v in obj.items():
            out |= leaf_paths(v, prefix + "/" + k)
        return out
    return {prefix}


# ---------------------------------------------------------------------------


class Help(unittest.TestCase):
    def test_every_command_has_help_with_an_example_and_exit_codes(self):
        commands = [[], ["validate"], ["eval"], ["sky"], ["fog"], ["bake"], ["day"]]
        if has_render_command():
            commands.append(["render"])
        for command in commands:
            with self.subTest(command=command):
                code, out, err = run(*command, "--help")
                self.assertEqual(code, 0, err)
                self.assertIn("Example", out)
                self.assertIn("aerial " + (command[0] if command else ""), out)
                self.assertIn("Exit codes: 0", out)
                self.assertEqual(err, "")

    def test_version(self):
        code, out, _ = run("--version")
        self.assertEqual(code, 0)
        self.assertTrue(out.startswith("aerial "), out)


class Validate(unittest.TestCase):
    # Positions counted in the fixtures (as tests/core/test_preset.cpp).
    FIXTURES = [
        ("syntax_missing_comma.json", "", 4, 3, "unexpected string literal"),
        ("syntax_truncated.json", "/fog", 4, 1, "unexpected end of input"),
        ("syntax_bad_literal.json", "/fog/density_per_m", 3, 28, "invalid literal"),
        ("infinite.json", "/atmosphere/mie/scale_height_m", 4, 31, "overflow"),
        ("out_of_range.json", "/volumes/1/half_extents_m/1", 5, 40, "out of range: -3"),
        ("wrong_type.json", "/fog/density_per_m", 4, 22, "expected a number, got a string"),
        ("duplicate_ids.json", "/volumes/2/id", 6, 12, 'duplicate id "mist"'),
        ("unknown_target.json", "/tracks/1/volume", 6, 16, 'no volume with id "nope"'),
        ("unknown_param.json", "/tracks/0/param", 4, 15, 'unknown global parameter "fog.thickness"'),
        ("newer_version.json", "/version", 2, 14, "newer than this library reads"),
        ("missing_version.json", "/version", 1, 1, 'missing "version"'),
        ("bad_key_times.json", "/tracks/0/keys/1/time_h", 5, 54, "increase strictly"),
        ("key_time_24.json", "/tracks/0/keys/0/time_h", 4, 52, "[0, 24)"),
        ("not_animatable.json", "/tracks/0/param", 4, 15, "cannot be animated"),
        ("duplicate_json_key.json", "/fog/density_per_m", 3, 34, "duplicate key"),
        ("missing_id.json", "/emitters/1/id", 5, 5, 'missing required field "id"'),
        ("bad_enum.json", "/volumes/0/shape", 3, 36, 'unknown value "sphere"'),
        ("wrong_arity.json", "/sun/colour_rgb", 3, 25, "array of 3 numbers"),
        ("mie_extinction_below_scattering.json", "/atmosphere/mie/extinction_per_m/1", 6, 37, "must be >="),
        ("not_an_object.json", "", 1, 1, "expected an object"),
        ("bad_track_value.json", "/tracks/0/keys/0/value", 4, 65, "array of 3 numbers"),
        ("cloud_coverage_out_of_range.json", "/clouds/coverage", 3, 26, "out of range: 1.5 is not in 0..1"),
        ("cloud_thickness_zero.json", "/clouds/thickness_m", 4, 29, "out of range: 0 is not in 10..20000 m"),
        ("cloud_negative_density.json", "/clouds/density_per_m", 3, 31, "out of range: -0.01 is not in 0..1 1/m"),
        ("cloud_wind_arity.json", "/clouds/wind_m_per_s", 3, 30, "expected an array of 2 numbers, got an array of 3"),
        ("weather_unknown_param.json", "/weather/states/0/overrides/0/param", 4, 15, 'unknown global parameter "clouds.nope"'),
        ("weather_not_animatable.json", "/weather/states/0/overrides/0/param", 4, 15, 'does not change with the weather'),
        ("weather_two_modes.json", "/weather/states/0/overrides/0/scale", 4, 58, 'an override has one of "set", "add", "scale", not several'),
        ("weather_duplicate_name.json", "/weather/states/1/name", 5, 14, 'a second weather state named "storm"'),
        ("weather_out_of_range.json", "/weather/states/0/overrides/0/set", 4, 41, 'out of range: 1.5 is not in 0..1'),
        ("weather_unknown_volume.json", "/weather/states/0/overrides/0/volume", 4, 16, 'no volume with id "nope"'),
        ("weather_region_unknown_state.json", "/weather/regions/0/state", 4, 82, 'no weather state "fog" (the preset has none, storm)'),
        ("weather_region_bad_shape.json", "/weather/regions/0/shape", 4, 30, 'unknown value "cylinder"; expected one of box, ellipsoid'),
        ("cloud_volume_zero_extent.json", "/cloud_volumes/0/half_extents_m/1", 5, 61,
         "out of range: 0 is not in 1..1e+07 m"),
        ("cloud_volume_unknown_target.json", "/tracks/1/cloud_volume", 6, 22, 'no cloud volume with id "nope"'),
        ("cloud_volume_duplicate_ids.json", "/cloud_volumes/2/id", 6, 12, 'duplicate id "cell"'),
    ]

    def test_every_shipped_preset_is_valid(self):
        paths = [preset(name) for name in SHIPPED]
        code, out, err = run("validate", *paths)
        self.assertEqual(code, 0, out + err)
        self.assertEqual(out.splitlines(), [p + ": ok" for p in paths])
        self.assertEqual(err, "")

    def test_fixtures_fail_with_located_messages(self):
        for name, pointer, line, column, reason in self.FIXTURES:
            with self.subTest(fixture=name):
                path = os.path.join(ROOT, "tests", "data", "presets", name)
                code, out, err = run("validate", path)
                self.assertEqual(code, 1, out + err)
                prefix = "%s:%d:%d: %s" % (path, line, column, pointer + ": " if pointer else "")
                lines = [l for l in out.splitlines() if l.startswith(prefix)]
                self.assertTrue(lines, "no line starts with %r in:\n%s" % (prefix, out))
                self.assertIn(reason, lines[0][len(prefix):])
                self.assertEqual(len(err.splitlines()), 1, err)
                self.assertTrue(err.startswith("aerial validate: 1 of 1 preset invalid"), err)

    def test_exact_lines(self):
        path = os.path.join(ROOT, "tests", "data", "presets", "out_of_range.json")
        code, out, _ = run("validate", path)
        self.assertEqual(code, 1)
        self.assertIn(path + ":5:40: /volumes/1/half_extents_m/1: out of range: -3 is not in 0.001..1e+07 m",
                      out.splitlines())
        path = os.path.join(ROOT, "tests", "data", "presets", "wrong_type.json")
        code, out, _ = run("validate", path)
        self.assertEqual(out.splitlines(),
                         [path + ":4:22: /fog/density_per_m: expected a number, got a string"])

    def test_warnings_do_not_fail(self):
        path = os.path.join(ROOT, "tests", "data", "presets", "unknown_field.json")
        code, out, err = run("validate", path)
        self.assertEqual(code, 0, out + err)
        lines = out.splitlines()
        self.assertEqual(lines[0], path + ':3:34: warning: /fog/colour: unknown field "colour" (ignored)')
        self.assertTrue(lines[1].startswith(path + ":4:3: warning: /sky: "), lines[1])
        self.assertEqual(lines[2], path + ": ok (2 warnings)")

    def test_mixed_valid_and_invalid_and_json(self):
        bad = os.path.join(ROOT, "tests", "data", "presets", "bad_enum.json")
        code, out, err = run("validate", preset("hazy_sunset"), bad, "--json")
        self.assertEqual(code, 1, err)
        report = json.loads(out)
        self.assertFalse(report["valid"])
        self.assertEqual([p["valid"] for p in report["presets"]], [True, False])
        error = report["presets"][1]["errors"][0]
        self.assertEqual((error["line"], error["column"], error["pointer"]), (3, 36, "/volumes/0/shape"))


class Eval(unittest.TestCase):
    def test_sun_direction_matches_the_design_formula(self):
        for name in ("clear_summer_day", "foggy_valley_morning", "hazy_sunset"):
            with open(preset(name)) as f:
                location = json.load(f)["location"]
            for time_text, t in (("06:30", 6.5), ("12:00", 12.0), ("17.25", 17.25), ("23:45", 23.75)):
                with self.subTest(preset=name, time=time_text):
                    state = run_json(self, "eval", preset(name), "--time", time_text)
                    self.assertEqual(state["time_h"], t)
                    expected = sun_direction(location["latitude_deg"], location["day_of_year"],
                                             location.get("north_offset_deg", 0.0), t)
                    for got, want in zip(state["sun"]["direction"], expected):
                        self.assertAlmostEqual(got, want, delta=1e-9)
                    self.assertAlmostEqual(state["sun"]["elevation_deg"], math.degrees(math.asin(expected[1])),
                                           delta=1e-7)

    def test_light_in_lux(self):
        # The light as a meter reads it (aerial/photometry.hpp): a clear
        # noon's horizontal illuminance within 1.5x of the published
        # 90-130 klx, the sources adding up; a moonless midnight (a new moon
        # dated, 45 N) of 1-2 mlx under a zenith of 1.7-2.5e-4 cd/m^2
        # (within 2x and as published); --no-light leaves the block out.
        with open(preset("clear_summer_day")) as f:
            document = json.load(f)
        document["location"]["date"] = "2025-06-25"
        document["clouds"]["coverage"] = 0
        document["tracks"] = [t for t in document["tracks"] if t.get("param") != "clouds.coverage"]
        path = os.path.join(WORK, "new_moon.json")
        with open(path, "w") as f:
            json.dump(document, f)
        noon = run_json(self, "eval", path, "--time", "12:00")["light"]
        e = noon["horizontal_illuminance_lux"]
        self.assertGreater(e["total"], 90000 / 1.5)
        self.assertLess(e["total"], 130000 * 1.5)
        self.assertAlmostEqual(e["total"], e["sun"] + e["sky"] + e["moon"] + e["night"], delta=1e-9 * e["total"])
        night = run_json(self, "eval", path, "--time", "00:00")["light"]
        self.assertGreater(night["horizontal_illuminance_lux"]["total"], 0.5e-3)
        self.assertLess(night["horizontal_illuminance_lux"]["total"], 3e-3)
        self.assertGreater(night["zenith_luminance_cd_m2"], 1.7e-4)
        self.assertLess(night["zenith_luminance_cd_m2"], 2.5e-4)
        self.assertNotIn("light", run_json(self, "eval", path, "--time", "00:00", "--no-light"))

    def test_every_parameter_is_in_the_output(self):
        with open(preset("foggy_valley_morning")) as f:
            document = json.load(f)
        state = run_json(self, "eval", preset("foggy_valley_morning"), "--time", "06:00")
        globals_in_file = leaf_paths({k: document[k] for k in ("location", "atmosphere", "sun", "moon", "fog", "exposure", "clouds", "night")})
        self.assertEqual(leaf_paths(state["parameters"]), globals_in_file)
        self.assertEqual([v["id"] for v in state["volumes"]], [v["id"] for v in document["volumes"]])
        # A file leaves out "blend", "mesh" and "edge_softness" at their defaults; eval lists every parameter.
        optional = {"blend", "mesh", "edge_softness"}
        for volume, in_file in zip(state["volumes"], document["volumes"]):
            self.assertEqual(set(volume) - optional, set(in_file) - optional)
            self.assertEqual(volume["blend"], in_file.get("blend", "add"))
        for emitter, in_file in zip(state["emitters"], document["emitters"]):
            self.assertEqual(set(emitter) - {"flash"}, set(in_file))
            self.assertTrue(0.0 <= emitter["flash"] <= 1.0)
        for light in ("sun", "moon"):
            for key in ("direction", "illuminance_space_rgb", "transmittance_rgb", "illuminance_rgb"):
                self.assertEqual(len(state[light][key]), 3)

    def test_anchored_keys_follow_the_sun_to_a_new_date(self):
        # hazy_sunset's exposure keys follow the sun: each lies at its event
        # plus its offset as `sun_events` reports them, the keyed value holds
        # there, and the same file ten weeks later (day 295: the sunset ~1 h
        # earlier at 38 N) moves every one with its event. Against the
        # undated model's closed form for the sunset at -0.833 deg.
        with open(preset("hazy_sunset")) as f:
            document = json.load(f)
        def check(path, day):
            out = run_json(self, "eval", path, "--time", "12:00", "--no-light")
            lat, dec = math.radians(38.0), math.radians(-23.44 * math.cos(math.radians(360.0 / 365.0 * (day + 10))))
            cos_h = (math.sin(math.radians(-0.833)) - math.sin(lat) * math.sin(dec)) / (math.cos(lat) * math.cos(dec))
            self.assertAlmostEqual(out["sun_events"]["sunset"]["time_h"], 12.0 + math.degrees(math.acos(cos_h)) / 15.0,
                                   delta=1e-5)
            keys = out["anchored_keys"]
            self.assertEqual([k["anchor"] for k in keys], ["nautical_dawn", "sunrise", "sunset", "civil_dusk"])
            values = [k["value"] for k in document["tracks"][0]["keys"]]
            for key, value in zip(keys, values):
                event = out["sun_events"][key["anchor"]]["time_h"]
                self.assertAlmostEqual(key["time_h"], (event + key["offset_h"]) % 24.0, delta=1e-9)
                at = run_json(self, "eval", path, "--time", f"{key['time_h']:.9f}", "--no-light")
                self.assertAlmostEqual(at["parameters"]["exposure"]["compensation_ev"], value, delta=1e-6)
            return keys
        self.assertEqual(document["tracks"][0]["param"], "exposure.compensation_ev")
        august = check(preset("hazy_sunset"), 225)
        document["location"]["day_of_year"] = 295
        path = os.path.join(WORK, "hazy_sunset_october.json")
        with open(path, "w") as f:
            json.dump(document, f)
        october = check(path, 295)
        self.assertGreater(august[2]["time_h"] - october[2]["time_h"], 0.9)

    def test_a_key_20_minutes_after_sunset_peaks_there_in_june_and_october(self):
        # Issue 50's check: a fog density keyed {"anchor": "sunset", "offset_h": 0.333} between two lower
        # fixed keys peaks 20 min after the sunset `aerial eval` reports, on day 172 and on day 300 alike
        # (the sunset itself 1 h 40 min apart at 45 N). The peak is found on a 1-minute grid.
        for day in (172, 300):
            document = {"version": 4, "location": {"latitude_deg": 45.0, "day_of_year": day},
                        "tracks": [{"param": "fog.density_per_m", "interpolation": "smooth", "keys": [
                            {"time_h": 12.0, "value": 0.001},
                            {"anchor": "sunset", "offset_h": 0.333, "value": 0.01},
                            {"time_h": 23.5, "value": 0.001}]}]}
            path = os.path.join(WORK, "sunset_peak_%d.json" % day)
            with open(path, "w") as f:
                json.dump(document, f)
            out = run_json(self, "eval", path, "--time", "12:00", "--no-light")
            sunset = out["sun_events"]["sunset"]["time_h"]
            self.assertEqual(len(out["anchored_keys"]), 1)
            self.assertAlmostEqual(out["anchored_keys"][0]["time_h"], sunset + 0.333, delta=1e-9)
            best, best_t = -1.0, None
            for minute in range(-30, 31):
                t = sunset + 0.333 + minute / 60.0
                d = run_json(self, "eval", path, "--time", "%.9f" % t, "--no-light")["parameters"]["fog"]["density_per_m"]
                if d > best:
                    best, best_t = d, t
            self.assertAlmostEqual(best_t, sunset + 0.333, delta=0.5 / 60.0, msg="day %d" % day)
            self.assertAlmostEqual(best, 0.01, delta=1e-12)

    def test_time_forms_agree(self):
        a = run_json(self, "eval", preset("hazy_sunset"), "--time", "18:30")
        b = run_json(self, "eval", preset("hazy_sunset"), "--time", "18.5h")
        self.assertEqual(a, b)

    def test_readable_summary(self):
        code, out, err = run("eval", preset("stormy_night"), "--time", "02:00")
        self.assertEqual(code, 0, err)
        self.assertIn("Stormy night", out)
        self.assertIn("fog.density_per_m", out)
        self.assertRegex(out, r"(?m)^sun +elevation")


class EvalWeatherRegions(unittest.TestCase):
    """`aerial eval --camera`: the preset's weather regions applied at a point
    on top of --weather / --transition (aerial/weather.hpp, regionalWeather);
    clear_summer_day's storm ellipsoid over the ridge."""

    CATEGORIES = ("clouds", "fog", "wind", "haze", "light", "lightning", "other")

    def region(self):
        with open(preset("clear_summer_day")) as f:
            return json.load(f)["weather"]["regions"][0]

    def world(self, region, local):
        """position + rotation * local, the quaternion [x, y, z, w] applied by hand."""
        x, y, z, w = region["rotation_xyzw"]
        u = (x, y, z)
        cross = lambda a, b: (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        t = tuple(2 * c for c in cross(u, local))
        r = [local[i] + w * t[i] + cross(u, t)[i] for i in range(3)]
        return [region["position_m"][i] + r[i] for i in range(3)]

    def eval_at(self, camera, *weather):
        return run_json(self, "eval", preset("clear_summer_day"), "--time", "14:00", "--no-light", *weather,
                        "--camera=" + ",".join(repr(c) for c in camera))

    def test_render_applies_the_regions_at_the_eye(self):
        # From inside the storm ellipsoid every global weather renders as the
        # storm; from the valley, outside it, the global weather holds.
        if not has_render_command():
            self.skipTest("aerial built without the renderer")
        inside = ",".join(repr(c) for c in self.region()["position_m"])
        frames = {}
        for name, eye, weather in (("inside", inside, ()), ("inside_storm", inside, ("--weather", "storm")),
                                   ("inside_clear", inside, ("--weather", "clear")), ("valley", "0,100,120", ()),
                                   ("valley_storm", "0,100,120", ("--weather", "storm"))):
            out = os.path.join(WORK, "render_region_%s.exr" % name)
            code, _, err = run("render", preset("clear_summer_day"), "--time", "14:00", "--size", "32x18",
                               "--eye=" + eye, "--target=0,600,-20000", "--out", out, *weather)
            self.assertEqual(code, 0, err)
            with open(out, "rb") as f:
                frames[name] = f.read()
        self.assertEqual(frames["inside"], frames["inside_storm"])
        self.assertEqual(frames["inside_clear"], frames["inside_storm"])
        self.assertNotEqual(frames["valley"], frames["valley_storm"])

    def test_regions_are_listed_without_a_camera(self):
        r = run_json(self, "eval", preset("clear_summer_day"), "--time", "14:00", "--no-light")
        regions = r["weather"]["regions"]
        self.assertEqual([g["id"] for g in regions], ["ridge_storm"])
        self.assertEqual(regions[0], self.region())  # as the file spells it, no weight
        self.assertNotIn("camera", r["weather"])

    def test_inside_the_region_its_state_holds_exactly(self):
        region = self.region()
        inside = self.eval_at(region["position_m"], "--weather", "clear")
        storm = run_json(self, "eval", preset("clear_summer_day"), "--time", "14:00", "--no-light",
                         "--weather", "storm")
        self.assertEqual(inside["weather"]["regions"][0]["weight"], 1.0)
        weights = inside["weather"]["camera"]["weights"]
        for c in self.CATEGORIES:
            self.assertEqual((weights["clear"][c], weights["overcast"][c], weights["storm"][c]), (0.0, 0.0, 1.0))
        self.assertEqual(inside["parameters"], storm["parameters"])  # every number, exactly
        self.assertEqual(inside["weather"]["camera"]["position_m"], region["position_m"])

    def test_outside_the_global_weather_is_untouched(self):
        for weather in (("--weather", "clear"), ("--transition", "clear:overcast:0.4"), ()):
            with self.subTest(weather=weather):
                far = self.eval_at([0.0, 2.0, 0.0], *weather)
                plain = run_json(self, "eval", preset("clear_summer_day"), "--time", "14:00", "--no-light", *weather)
                self.assertEqual(far["weather"]["regions"][0]["weight"], 0.0)
                self.assertEqual(far["parameters"], plain["parameters"])
                if weather and weather[0] == "--transition":
                    self.assertEqual(far["weather"]["camera"]["weights"], plain["weather"]["applied"]["weights"])

    def test_half_way_through_the_blend_band(self):
        # On the region's local +X axis, half the blend inside the surface:
        # the depth is exactly 400 m (an axis of the ellipsoid), the weight
        # smoothstep(0.5) = 0.5, so clear and storm share every category.
        region = self.region()
        depth = region["blend_m"] / 2
        camera = self.world(region, (region["half_extents_m"][0] - depth, 0.0, 0.0))
        r = self.eval_at(camera, "--weather", "clear")
        self.assertAlmostEqual(r["weather"]["regions"][0]["weight"], 0.5, delta=1e-9)
        for c in self.CATEGORIES:
            self.assertAlmostEqual(r["weather"]["camera"]["weights"]["storm"][c], 0.5, delta=1e-9)
            self.assertAlmostEqual(r["weather"]["camera"]["weights"]["clear"][c], 0.5, delta=1e-9)
        # A cloud coverage half-way between the two states' (both "set").
        self.assertAlmostEqual(r["parameters"]["clouds"]["coverage"], 0.5 * 0.12 + 0.5 * 0.97, delta=1e-9)
        # 1 m either side the weight moves by at most 1.5 / blend per metre.
        for step in (-1.0, 1.0):
            moved = self.world(region, (region["half_extents_m"][0] - depth + step, 0.0, 0.0))
            w = self.eval_at(moved)["weather"]["regions"][0]["weight"]
            self.assertLessEqual(abs(w - 0.5), 1.5 / region["blend_m"] + 1e-9)
        code, out, err = run("eval", preset("clear_summer_day"), "--time", "14:00", "--no-light",
                             "--camera=" + ",".join(repr(c) for c in camera))
        self.assertEqual(code, 0, err)
        self.assertIn('region ridge_storm "Storm over the ridge": ellipsoid', out)
        self.assertIn("weight 0.5 at the camera", out)

    def test_a_bad_camera_is_a_usage_error(self):
        for text, why in (("1,2", "is not three finite numbers x,y,z"), ("0,0,2e7", "is out of range")):
            code, out, err = run("eval", preset("clear_summer_day"), "--time", "12", "--camera=" + text)
            self.assertEqual(code, 2, err)
            self.assertEqual(out, "")
            self.assertIn("--camera: \"%s\" %s" % (text, why), err)

    def test_the_bake_manifest_lists_the_regions(self):
        out_dir = os.path.join(WORK, "bake_regions")
        code, out, err = run("bake", preset("clear_summer_day"), "--out", out_dir, "--step", "12h",
                             "--size", "32x16", "--sky-view-size", "64x40", "--far-fog-size", "32x16")
        self.assertEqual(code, 0, err)
        with open(os.path.join(out_dir, "manifest.json")) as f:
            weather = json.load(f)["weather"]
        self.assertEqual(weather["regions"], [self.region()])
        self.assertIn("smoothstep(clamp(d / blend_m, 0, 1))", weather["regions_blend"])


class Sky(unittest.TestCase):
    def test_table_matches_the_exact_integral_above_the_horizon(self):
        directions = ["0,1,0", "1,0.2,0", "0,0.05,-1", "-0.8,0.45,0.3", "0.3,0.1,0.95", "0.6,0.02,-0.8"]
        for direction in directions:
            with self.subTest(direction=direction):
                r = run_json(self, "sky", preset("clear_summer_day"), "--time", "12:00", "--dir=" + direction)
                v = [float(x) for x in direction.split(",")]
                n = math.sqrt(sum(x * x for x in v))
                for got, want in zip(r["direction"], v):
                    self.assertAlmostEqual(got, want / n, delta=1e-12)
                for c in range(3):
                    table, exact = r["table"]["single_scattering_rgb"][c], r["reference"]["radiance_rgb"][c]
                    self.assertAlmostEqual(r["table"]["radiance_rgb"][c],
                                           table + r["table"]["multiple_scattering_rgb"][c], delta=1e-12 * exact)
                    self.assertGreater(exact, 0.0)
                    self.assertLess(abs(table / exact - 1.0), 0.03, r)
                self.assertLess(r["max_abs_relative_difference"], 0.03)

    def test_readable_output(self):
        code, out, err = run("sky", preset("hazy_sunset"), "--time", "18:30", "--dir", "0,0.1,-1")
        self.assertEqual(code, 0, err)
        self.assertIn("exact integral", out)
        self.assertIn("relative difference", out)
        self.assertIn("limiting magnitude", out)

    def dated_clear_summer_day(self, date):
        with open(preset("clear_summer_day")) as f:
            p = json.load(f)
        p["location"]["date"] = date
        path = os.path.join(WORK, "clear_summer_day_" + date + ".json")
        with open(path, "w") as f:
            json.dump(p, f)
        return path

    def evening_time(self, path, elevation_deg):
        """The time at which the sun sinks through elevation_deg (bisection on `aerial eval`)."""
        lo, hi = 12.0, 23.99
        for _ in range(24):
            mid = 0.5 * (lo + hi)
            e = run_json(self, "eval", path, "--time", "%.6f" % mid)["sun"]["elevation_deg"]
            lo, hi = (mid, hi) if e > elevation_deg else (lo, mid)
        return 0.5 * (lo + hi)

    def test_stars_limiting_magnitude(self):
        """Issue 48: the naked-eye limiting magnitude at the zenith, clear_summer_day dated
        2025-06-25 (new moon, 45 N): <= 1.5 with the sun at -6 deg, >= 5.5 at midnight (sun
        below -18 deg, the natural sky of 21.6-22 mag/arcsec^2); the background's surface
        brightness is its luminance in V mag/arcsec^2 (L = 10.8e4 10^(-0.4 S) cd/m^2); null
        below the horizon."""
        path = self.dated_clear_summer_day("2025-06-25")
        civil = run_json(self, "sky", path, "--time", "%.6f" % self.evening_time(path, -6.0), "--dir", "0,1,0")
        stars = civil["stars"]
        self.assertAlmostEqual(stars["background_mag_arcsec2"],
                               -2.5 * math.log10(stars["background_cd_m2"] / 1.08e5), delta=1e-9)
        self.assertLessEqual(stars["limiting_magnitude"], 1.5, stars)
        self.assertGreater(stars["limiting_magnitude_at_eye"], stars["limiting_magnitude"])  # extinction
        below = run_json(self, "sky", path, "--time", "00:00", "--dir", "0,-1,0")["stars"]
        self.assertIsNone(below["limiting_magnitude"])
        night = run_json(self, "sky", path, "--time", "00:00", "--dir", "0,1,0")["stars"]
        self.assertGreaterEqual(night["limiting_magnitude"], 5.5, night)

    def test_a_citys_glow_brightens_the_night_and_hides_stars(self):
        """Issue 48: night.light_pollution_cd_m2 adds a city's glow: the zenith's luminance grows by it
        (`aerial eval` light.zenith_luminance_cd_m2 and `aerial sky` stars.background_cd_m2 agree), the ground
        gets more light, and fewer stars show (a suburb's 2e-3 cd/m^2: 19.3 mag/arcsec^2 with the natural sky)."""
        path = self.dated_clear_summer_day("2025-06-25")
        with open(path) as f:
            p = json.load(f)
        p["night"] = {"light_pollution_cd_m2": 2e-3, "light_pollution_azimuth_deg": 90, "light_pollution_lamps": "led"}
        city = os.path.join(WORK, "clear_summer_day_city.json")
        with open(city, "w") as f:
            json.dump(p, f)
        dark = run_json(self, "eval", path, "--time", "00:00")["light"]
        lit = run_json(self, "eval", city, "--time", "00:00")["light"]
        self.assertAlmostEqual(lit["zenith_luminance_cd_m2"] - dark["zenith_luminance_cd_m2"], 2e-3, delta=2e-5)
        self.assertGreater(lit["horizontal_illuminance_lux"]["night"], 5 * dark["horizontal_illuminance_lux"]["night"])
        stars = run_json(self, "sky", city, "--time", "00:00", "--dir", "0,1,0")["stars"]
        self.assertAlmostEqual(stars["background_cd_m2"], lit["zenith_luminance_cd_m2"],
                               delta=0.02 * lit["zenith_luminance_cd_m2"])
        natural = run_json(self, "sky", path, "--time", "00:00", "--dir", "0,1,0")["stars"]
        self.assertLess(stars["limiting_magnitude"], natural["limiting_magnitude"] - 1.0)
        # Towards the city, low down, the glow is many times the zenith's.
        east = run_json(self, "sky", city, "--time", "00:00", "--dir", "1,0.05,0")["stars"]
        self.assertGreater(east["background_cd_m2"], 8 * stars["background_cd_m2"])

    def test_clouds_brighten_a_citys_night_and_darken_a_dark_one(self):
        """Issue 48: clouds over a city are lit from below by its light (night_sky.hpp,
        lightPollutionUplight). Measured outdoors: overcast skies ~3x brighter than clear at a light-polluted
        site 32 km from Berlin's centre, ~10x inside the city (Kyba et al. 2011, PLoS ONE 6(3) e17307); at
        unpolluted sites clouds darken the sky (Jechow et al. 2019). Rendered, moonless, looking up at ~70 deg:
        a suburban 3e-3 cd/m^2 glow overcast within 2-6x of clear, a dark site's overcast below its clear sky."""
        if not has_render_command() or not RGBA_PROBE:
            self.skipTest("no render command or no --rgba-probe")
        with open(self.dated_clear_summer_day("2025-06-25")) as f:
            p = json.load(f)
        p["tracks"] = [t for t in p["tracks"] if t.get("param") != "clouds.coverage"]
        luminance = {}
        for coverage in (0.0, 1.0):
            for glow in (0.0, 3e-3):
                p["clouds"]["coverage"] = coverage
                p["night"] = {"light_pollution_cd_m2": glow, "light_pollution_azimuth_deg": 90,
                              "light_pollution_lamps": "sodium"}
                path = os.path.join(WORK, "overcast_%g_%g.json" % (coverage, glow))
                with open(path, "w") as f:
                    json.dump(p, f)
                out = path[:-5] + ".exr"
                code, _, err = run("render", path, "--time", "00:30", "--size", "64x36", "--eye", "0,2,0",
                                   "--target", "0,1000,-200", "--out", out)
                self.assertEqual(code, 0, err)
                probe = subprocess.run([RGBA_PROBE, out] + ["%d,%d" % (x, y) for x in range(4, 64, 8)
                                                            for y in range(2, 18, 4)],
                                       capture_output=True, text=True)
                self.assertEqual(probe.returncode, 0, probe.stderr)
                rgb = [list(map(float, line.split()[2:5])) for line in probe.stdout.splitlines()[1:]]
                luminance[coverage, glow] = sum(0.2126 * r + 0.7152 * g + 0.0722 * b for r, g, b in rgb) / len(rgb)
        city = luminance[1.0, 3e-3] / luminance[0.0, 3e-3]
        dark = luminance[1.0, 0.0] / luminance[0.0, 0.0]
        self.assertGreater(city, 2.0)
        self.assertLess(city, 6.0)
        self.assertLess(dark, 1.0)


class Fog(unittest.TestCase):
    FIXTURE = None  # set in setUpClass

    @classmethod
    def setUpClass(cls):
        cls.FIXTURE = os.path.join(ROOT, "tests", "data", "cli", "global_fog_only.json")
        with open(cls.FIXTURE) as f:
            fog = json.load(f)["fog"]
        cls.fog = (fog["density_per_m"], fog["falloff_per_m"], fog["base_height_m"])

    def test_global_fog_transmittance_is_the_closed_form(self):
        segments = [((10, 2, 0), (-300, 80, -900)),  # rising
                    ((0, 150, 0), (400, 1, 250)),      # falling
                    ((0, 3, 0), (0, 3, -2000)),        # horizontal
                    ((5, 0, 5), (5, 500, 5)),          # vertical
                    ((1, 2, 3), (1, 2, 3))]            # empty
        for o, to in segments:
            with self.subTest(segment=(o, to)):
                r = run_json(self, "fog", self.FIXTURE, "--time", "09:00",
                             "--from=%g,%g,%g" % o, "--to=%g,%g,%g" % to)
                tau = height_fog_optical_depth(*self.fog, o, to)
                expected = math.exp(-tau)
                for t in r["transmittance_rgb"]:
                    self.assertLessEqual(abs(t - expected), 1e-9 * expected, (t, expected))
                self.assertLessEqual(abs(r["global_fog"]["optical_depth"] - tau), 1e-9 * max(tau, 1e-300))
                self.assertEqual(r["volumes"], [])
                self.assertEqual(r["emitter_in_scatter_rgb"], [0.0, 0.0, 0.0])
                for s in r["in_scatter_rgb"]:
                    self.assertTrue(math.isfinite(s) and s >= 0.0)

    def test_volumes_are_listed_and_composited(self):
        r = run_json(self, "fog", preset("foggy_valley_morning"), "--time", "07:00", "--from=-50,5,0",
                     "--to", "0,2,-300")
        ids = [v["id"] for v in r["volumes"]]
        self.assertIn("valley_floor", ids)
        total = r["global_fog"]["optical_depth"]
        for v in r["volumes"]:
            self.assertLess(v["entry_m"], v["exit_m"])
            self.assertGreater(v["optical_depth"], 0.0)
            self.assertLessEqual(v["exit_m"], r["length_m"] + 1e-9)
            total += v["optical_depth"]
        # Grey transmittances multiply: T = exp(-(global + every volume)).
        for t in r["transmittance_rgb"]:
            self.assertAlmostEqual(t / math.exp(-total), 1.0, delta=1e-9)
        # Back to front: entry distances do not increase.
        entries = [v["entry_m"] for v in r["volumes"]]
        self.assertEqual(entries, sorted(entries, reverse=True))
        self.assertEqual(set(r["lights"]), {"sun", "moon"})

    def test_twilight_valley_fog_is_lit_by_what_reaches_it(self):
        # Sun 11 deg below the horizon: the valley fog over 100 m is lit by
        # the sky dome (aerial/fog_light.hpp), not painted with the glowing
        # horizon towards the set sun (that made it 54x brighter towards the
        # sun's azimuth than away from it).
        def luminance(rgb):
            return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]

        def level(azimuth):
            return run_json(self, "fog", preset("foggy_valley_morning"), "--time", "05:30", "--from=0,2,0",
                            "--to=%.6f,2,%.6f" % (100 * math.sin(azimuth), -100 * math.cos(azimuth)))

        sun = level(0.0)["lights"]["sun"]["direction"]
        self.assertLess(sun[1], -0.17)
        towards_azimuth = math.atan2(sun[0], -sun[2])
        r = level(towards_azimuth)
        towards = luminance(r["in_scatter_rgb"])
        away = luminance(level(towards_azimuth + math.pi)["in_scatter_rgb"])
        self.assertGreater(away, 0.0)
        self.assertLessEqual(towards / away, 3.0, (towards, away))
        # 100 m is 0.04% of the way to the horizon's colour (w = 1 - exp(-(s / 5 km)^2)),
        # s the length of the segment as passed (its end rounded to 1e-6 m).
        end = [float("%.6f" % (100 * math.sin(towards_azimuth))), float("%.6f" % (-100 * math.cos(towards_azimuth)))]
        s = math.hypot(end[0], end[1])
        self.assertAlmostEqual(r["global_fog"]["horizon_weight"], -math.expm1(-(s / 5000.0) ** 2), delta=1e-15)


class BakeSkyView(unittest.TestCase):
    """The per-step sky-view map: a sky texture any engine reads."""

    @classmethod
    def setUpClass(cls):
        cls.out = os.path.join(WORK, "bake_sky_view")
        # The tables at the size `aerial sky` solves (128x64), so the two agree.
        code, _, err = run("bake", preset("hazy_sunset"), "--out", cls.out, "--step", "6h", "--sky-view-size",
                           "64x32", "--far-fog-size", "32x16", "--quiet")
        assert code == 0, err
        with open(os.path.join(cls.out, "manifest.json")) as f:
            cls.manifest = json.load(f)

    def test_manifest_names_the_files_and_the_mapping(self):
        self.assertEqual(self.manifest["format_version"], 3)
        self.assertEqual(self.manifest["sky_view"]["channels"], ["R", "G", "B"])
        self.assertIn("line y = 0 lies exactly on the horizon", self.manifest["sky_view"]["mapping"])
        self.assertEqual((self.manifest["sky_view"]["width"], self.manifest["sky_view"]["height"]), (64, 32))
        self.assertEqual((self.manifest["far_fog"]["width"], self.manifest["far_fog"]["height"]), (32, 16))
        for step in self.manifest["steps"]:
            for key in ("sky_view_file", "far_fog_file"):
                self.assertTrue(os.path.isfile(os.path.join(self.out, step[key])), step[key])
            self.assertEqual(step["fog"]["far_fog_file"], step["far_fog_file"])
            self.assertEqual(len(step["sky_irradiance_sh9"]), 9)

    def test_openexr_tools_read_the_header(self):
        exrheader = shutil.which("exrheader")
        self.assertIsNotNone(exrheader, "exrheader (Debian package openexr, installed by scripts/deps.sh)")
        step = self.manifest["steps"][3]  # 18:00
        p = subprocess.run([exrheader, os.path.join(self.out, step["sky_view_file"])], capture_output=True,
                           text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        for line in ("aerialTimeHours (type double)", "aerialMapping (type string)",
                     "dataWindow (type box2i): (0 0) - (63 31)"):
            self.assertIn(line, p.stdout)
        channels = re.findall(r"^\s+([A-Za-z.]+), 32-bit floating-point", p.stdout, re.M)
        self.assertEqual(sorted(channels), ["B", "G", "R"])
        # The tables carry the anisotropy and the light's illuminance.
        p = subprocess.run([exrheader, os.path.join(self.out, step["sun"]["table_file"])], capture_output=True,
                           text=True)
        self.assertIn("aerialLightIlluminance (type v3d)", p.stdout)
        self.assertIn("aerialMieAnisotropy (type double): 0.", p.stdout)

    def test_an_rgba_only_reader_sees_the_sky_the_renderer_shows(self):
        if not RGBA_PROBE:
            self.skipTest("no --rgba-probe given")
        step = self.manifest["steps"][3]  # 18:00, a low sun: colour varies across the sky
        w, h = 64, 32
        pixels = [(5, 2), (40, 9), (17, 14), (60, 31), (33, 0)]
        p = subprocess.run([RGBA_PROBE, os.path.join(self.out, step["sky_view_file"])] +
                           ["%d,%d" % xy for xy in pixels], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        lines = p.stdout.splitlines()
        self.assertEqual(lines[0], "%d %d" % (w, h))
        for (x, y), line in zip(pixels, lines[1:]):
            r, g, b, a = map(float, line.split()[2:])
            self.assertEqual(a, 1.0)  # no alpha channel: the reader fills 1
            phi = 2 * math.pi * (x + 0.5) / w
            el = math.pi / 2 * (y / (h - 1)) ** 2
            d = (math.cos(el) * math.sin(phi), math.sin(el), -math.cos(el) * math.cos(phi))
            if y == 0:
                d = (d[0], 1e-9, d[2])  # line 0: the sky's limit from above the horizon
            sky = run_json(self, "sky", preset("hazy_sunset"), "--time", "18:00", "--dir=%r,%r,%r" % d)
            for got, want in zip((r, g, b), sky["sky_rgb"]):
                # An RGBA reader converts to half float: 11 significant bits.
                self.assertAlmostEqual(got, max(want, 0.0), delta=2e-3 * abs(want) + 1e-7, msg=(x, y, got, want))


class Clouds(unittest.TestCase):
    RG = 6360000.0

    @classmethod
    def setUpClass(cls):
        cls.LAYER = os.path.join(ROOT, "tests", "data", "cli", "clouds_layer.json")

    def height(self, p):
        x, y, z = p
        return math.sqrt(x * x + z * z + (y + self.RG) ** 2) - self.RG

    def at_height(self, x, z, h):
        """The point at (x, z) standing h above the curved ground."""
        return (x, math.sqrt((self.RG + h) ** 2 - x * x - z * z) - self.RG, z)

    def test_points_in_order_with_every_answer(self):
        points = [(0, 0, 0), (2000, 0, -500), (-300, 2500, 40), (100, 9000, 100)]
        r = run_json(self, "clouds", self.LAYER, "--time", "14:00", *["--at=%g,%g,%g" % p for p in points])
        self.assertTrue(r["clouds_active"])
        self.assertEqual([tuple(p["at"]) for p in r["points"]], [tuple(map(float, p)) for p in points])
        for p, q in zip(points, r["points"]):
            self.assertAlmostEqual(q["height_m"], self.height(p), delta=1e-6)
            for key in ("sun_visibility", "transmittance"):
                self.assertTrue(0.0 <= q[key] <= 1.0, q)
            self.assertAlmostEqual(q["coverage"], 0.7)
        # Above the layer (9 km) nothing lies between the point and the sun or the sky.
        self.assertEqual(r["points"][3]["sun_visibility"], 1.0)
        self.assertEqual(r["points"][3]["transmittance"], 1.0)
        # A 0.7 cover over 2 km of cloud hides the sun somewhere among a few points.
        many = run_json(self, "clouds", self.LAYER, "--time", "14:00",
                        *["--at=%d,0,%d" % (400 * i, -300 * i) for i in range(40)])
        vis = [p["sun_visibility"] for p in many["points"]]
        self.assertLess(min(vis), 0.05)
        self.assertEqual(max(vis), 1.0)

    def test_overcast_from_the_origin(self):
        r = run_json(self, "clouds", self.LAYER, "--time", "14:00", "--at=0,0,0")
        o = r["overcast"]
        for key in ("sky_cover", "horizon_cover"):
            self.assertTrue(0.05 < o[key] <= 1.0, o)
        # The two-stream diffuse transmittance of its optical depth (g = 0.85).
        self.assertGreater(o["optical_depth"], 0.5)
        self.assertAlmostEqual(o["diffuse_transmittance"], 1.0 / (1.0 + 0.75 * 0.15 * o["optical_depth"]),
                               delta=1e-12)
        # No layer, no overcast.
        clear = run_json(self, "clouds", os.path.join(ROOT, "tests", "data", "cli", "global_fog_only.json"),
                         "--time", "14:00", "--at=0,0,0")
        self.assertEqual(clear["overcast"], {"sky_cover": 0.0, "horizon_cover": 0.0, "optical_depth": 0.0,
                                             "diffuse_transmittance": 1.0})

    def test_up_through_the_layer_equals_down_through_it(self):
        # The same segment marched from either end gives the same samples.
        for x, z in ((0, 0), (1234, -777), (-5000, 3000)):
            # Radially, so both ends see the same segment.
            ground = self.at_height(x, z, 0)
            k = (self.RG + 6000.0) / self.RG  # 6 km up the same radius
            above = (x * k, (ground[1] + self.RG) * k - self.RG, z * k)
            up = run_json(self, "clouds", self.LAYER, "--time", "10:00", "--at=%r,%r,%r" % ground,
                          "--dir", "%r,%r,%r" % (x, ground[1] + self.RG, z))
            down = run_json(self, "clouds", self.LAYER, "--time", "10:00", "--at=%g,%g,%g" % above,
                            "--dir", "%r,%r,%r" % (-x, -(above[1] + self.RG), -z))
            a, b = up["points"][0]["transmittance"], down["points"][0]["transmittance"]
            self.assertAlmostEqual(a, b, delta=1e-5 * a + 1e-12)  # rounding of the printed points

    def test_the_wind_carries_the_layer(self):
        # wind [10, 3] m/s: at 13:00 the cloud at p + wind * 3600 s is the cloud at p at 12:00.
        base = [self.at_height(1300.0 * i, -900.0 * i, 1900 + 25.0 * (i % 10)) for i in range(60)]
        later = [self.at_height(p[0] + 36000.0, p[2] + 10800.0, self.height(p)) for p in base]
        r0 = run_json(self, "clouds", self.LAYER, "--time", "12:00", *["--at=%r,%r,%r" % p for p in base])
        r1 = run_json(self, "clouds", self.LAYER, "--time", "13:00", *["--at=%r,%r,%r" % p for p in later])
        d0 = [p["density_per_m"] for p in r0["points"]]
        d1 = [p["density_per_m"] for p in r1["points"]]
        self.assertGreater(sum(1 for d in d0 if d > 0), 3)
        for a, b in zip(d0, d1):
            self.assertAlmostEqual(a, b, delta=1e-6 * a + 1e-12)

    def test_a_clear_preset_has_no_cloud(self):
        r = run_json(self, "clouds", os.path.join(ROOT, "tests", "data", "cli", "global_fog_only.json"), "--time",
                     "18:00", "--at", "0,0,0", "--at", "0,2000,0")
        self.assertFalse(r["clouds_active"])
        for p in r["points"]:
            self.assertEqual((p["sun_visibility"], p["transmittance"], p["density_per_m"]), (1.0, 1.0, 0.0))

    def test_bake_manifest_carries_the_clouds(self):
        out = os.path.join(WORK, "bake_clouds")
        code, _, err = run("bake", self.LAYER, "--out", out, "--step", "12h", "--size", "16x8", "--quiet")
        self.assertEqual(code, 0, err)
        with open(os.path.join(out, "manifest.json")) as f:
            m = json.load(f)
        self.assertEqual(m["clouds"]["seed"], 5)
        self.assertRegex(m["clouds"]["noise_fnv1a64"], r"^0x[0-9a-f]{16}$")
        self.assertEqual(m["steps"][0]["parameters"]["clouds"]["coverage"], 0.7)
        clear = os.path.join(WORK, "bake_clear")
        code, _, err = run("bake", os.path.join(ROOT, "tests", "data", "cli", "global_fog_only.json"), "--out",
                           clear, "--step", "12h", "--size", "16x8", "--quiet")
        self.assertEqual(code, 0, err)
        with open(os.path.join(clear, "manifest.json")) as f:
            clear_manifest = json.load(f)
        self.assertNotIn("noise_fnv1a64", clear_manifest["clouds"])
        # The fog's authored render mode, for the game (analytic unless the preset says so).
        self.assertEqual(clear_manifest["fog"]["render_mode"], "analytic")
        shafts = os.path.join(WORK, "bake_volumetric")
        code, _, err = run("bake", preset("foggy_valley_morning"), "--out", shafts, "--step", "12h", "--size",
                           "16x8", "--quiet")
        self.assertEqual(code, 0, err)
        with open(os.path.join(shafts, "manifest.json")) as f:
            self.assertEqual(json.load(f)["fog"]["render_mode"], "volumetric")

    def test_cloud_volumes_set_the_coverage_inside(self):
        volumes = os.path.join(ROOT, "tests", "data", "cli", "clouds_volumes.json")
        # The storm cell is keyed from x = 0 (06:00) to x = 24 km (18:00): at noon it is at x = 12 km.
        points = [(12000, 2500, 0), (-20000, 2500, 10000), (0, 2500, 0), (12000 + 4000 * 0.85, 2500, 0)]
        r = run_json(self, "clouds", volumes, "--time", "12:00", *["--at=%g,%g,%g" % p for p in points])
        self.assertTrue(r["clouds_active"])
        coverage = [p["coverage"] for p in r["points"]]
        self.assertAlmostEqual(coverage[0], 1.0, delta=1e-12)  # inside the storm cell
        self.assertEqual(coverage[1], 0.0)  # inside the clear hole
        self.assertAlmostEqual(coverage[2], 0.3, delta=1e-12)  # outside both: the layer's
        self.assertTrue(0.3 < coverage[3] < 1.0, coverage)  # in the storm's soft edge
        # The layer without its volumes has the layer's coverage everywhere.
        plain = run_json(self, "clouds", self.LAYER, "--time", "12:00", "--at=%g,%g,%g" % points[0])
        self.assertAlmostEqual(plain["points"][0]["coverage"], 0.7)

    def test_eval_and_bake_list_the_cloud_volumes(self):
        volumes = os.path.join(ROOT, "tests", "data", "cli", "clouds_volumes.json")
        with open(volumes) as f:
            document = json.load(f)
        r = run_json(self, "eval", volumes, "--time", "12:00")
        self.assertEqual([v["id"] for v in r["cloud_volumes"]], ["storm", "hole"])
        self.assertEqual(set(r["cloud_volumes"][0]),
                         {"id", "name", "shape", "position_m", "rotation_xyzw", "half_extents_m", "coverage",
                          "edge_softness"})
        self.assertEqual(r["cloud_volumes"][0]["position_m"], [12000.0, 2500.0, 0.0])  # keyed
        self.assertEqual(r["cloud_volumes"][1]["shape"], "box")
        self.assertEqual(r["cloud_volumes"][1]["position_m"], document["cloud_volumes"][1]["position_m"])
        # Every preset lists them, if only as an empty array.
        self.assertEqual(run_json(self, "eval", self.LAYER, "--time", "12:00")["cloud_volumes"], [])
        code, out, err = run("eval", volumes, "--time", "12:00")
        self.assertEqual(code, 0, err)
        self.assertIn('cloud volume storm "Storm cell"', out)
        self.assertIn("edge_softness", out)
        # The bake manifest reuses the same state.
        bake = os.path.join(WORK, "bake_cloud_volumes")
        code, _, err = run("bake", volumes, "--out", bake, "--step", "12h", "--size", "16x8", "--quiet")
        self.assertEqual(code, 0, err)
        with open(os.path.join(bake, "manifest.json")) as f:
            manifest = json.load(f)
        self.assertEqual(manifest["steps"][1]["time_h"], 12.0)
        self.assertEqual(manifest["steps"][1]["cloud_volumes"], r["cloud_volumes"])

    def test_eval_shows_the_clouds_block(self):
        r = run_json(self, "eval", self.LAYER, "--time", "12:00")
        self.assertEqual(r["parameters"]["clouds"]["coverage"], 0.7)
        self.assertEqual(r["parameters"]["clouds"]["wind_m_per_s"], [10.0, 3.0])
        self.assertEqual(r["parameters"]["clouds"]["seed"], 5)


class Bake(unittest.TestCase):
    CHANNELS = {"rayleigh.R", "rayleigh.G", "rayleigh.B", "mie.R", "mie.G", "mie.B", "multiple.R", "multiple.G",
                "multiple.B", "elevation", "azimuth"}

    def test_bake_writes_exr_tables_and_a_manifest(self):
        out_dir = os.path.join(WORK, "bake_hazy_sunset")
        shutil.rmtree(out_dir, ignore_errors=True)
        code, out, err = run("bake", preset("hazy_sunset"), "--out", out_dir, "--step", "6h")
        self.assertEqual(code, 0, err)
        self.assertIn("baked 4 steps", out)
        files = sorted(os.listdir(out_dir))
        self.assertEqual(len([f for f in files if f.endswith("_sun.exr") or f.endswith("_moon.exr")]), 8, files)
        self.assertEqual(len([f for f in files if f.endswith("_skyview.exr")]), 4, files)
        self.assertEqual(len([f for f in files if f.endswith("_farfog.exr")]), 4, files)
        self.assertIn("manifest.json", files)
        self.assertFalse([f for f in files if f.startswith(".")], "temporary files left behind")

        with open(os.path.join(out_dir, "manifest.json")) as f:
            manifest = json.load(f)
        self.assertEqual(manifest["format"], "aerial-bake")
        self.assertEqual(manifest["step_count"], 4)
        table = manifest["table"]
        self.assertEqual((table["azimuth_count"], table["elevation_count"]), (128, 64))
        self.assertEqual(set(table["channels"]), self.CHANNELS)
        self.assertIn("elevation_j <= el < elevation_j+1", table["sampling"])
        self.assertEqual([s["time_h"] for s in manifest["steps"]], [0.0, 6.0, 12.0, 18.0])

        referenced = set()
        for step in manifest["steps"]:
            for light in ("sun", "moon"):
                name = step[light]["table_file"]
                referenced.add(name)
                version, attributes = read_exr_header(os.path.join(out_dir, name))
                self.assertEqual(version & 0xFF, 2)
                kind, value = attributes["channels"]
                self.assertEqual(kind, "chlist")
                channels = read_chlist(value)
                self.assertEqual(set(channels), self.CHANNELS)
                self.assertEqual({v for c, v in channels.items() if c not in ("elevation", "azimuth")}, {1},
                                 "HALF pixels")
                self.assertEqual((channels["elevation"], channels["azimuth"]), (2, 2), "FLOAT coordinates")
                kind, value = attributes["dataWindow"]
                self.assertEqual(kind, "box2i")
                x0, y0, x1, y1 = struct.unpack("<4i", value)
                self.assertEqual((x1 - x0 + 1, y1 - y0 + 1), (128, 64))
                kind, value = attributes["aerialLight"]
                self.assertEqual(value.decode(), light)
                self.assertEqual(len(step[light]["horizon_rayleigh"]), 3)
                self.assertEqual(len(step[light]["horizon_multiple"]), 3)
        referenced |= {step["sky_view_file"] for step in manifest["steps"]}
        referenced |= {step["far_fog_file"] for step in manifest["steps"]}
        self.assertEqual(referenced, {f for f in files if f.endswith(".exr")})
        # A sunlit sky has higher orders at the horizon; the exposure says how to expose it.
        self.assertTrue(all(v > 0.0 for v in manifest["steps"][2]["sun"]["horizon_multiple"]))
        self.assertIn("+ multiple", table["radiance"])
        self.assertEqual(manifest["exposure"]["nits_per_radiance_unit"], 5000.0)

        # The manifest's parameters are exactly what `aerial eval` gives.
        noon = run_json(self, "eval", preset("hazy_sunset"), "--time", "12:00")
        step = manifest["steps"][2]
        for key in ("parameters", "volumes", "emitters", "cloud_volumes"):
            self.assertEqual(step[key], noon[key], key)
        self.assertEqual(step["sun"]["direction"], noon["sun"]["direction"])

        # Baking again over the same directory works and stays complete.
        code, _, err = run("bake", preset("hazy_sunset"), "--out", out_dir, "--step", "12h", "--size", "32x16",
                           "--quiet")
        self.assertEqual(code, 0, err)
        self.assertEqual(err, "")
        with open(os.path.join(out_dir, "manifest.json")) as f:
            self.assertEqual(json.load(f)["step_count"], 2)

    def test_pixels_lie_where_their_coordinates_say(self):
        # Texel (i, j) of a baked file holds the table value in the direction
        # its own coordinate channels give (elevation, azimuth from the
        # light); `aerial sky` samples the same table. At 06:00 the sun is low
        # (the sky varies strongly with azimuth, the rows crowd at the horizon)
        # and at 19:45 it has just set (the columns crowd around the earth's
        # shadow opposite it).
        out_dir = os.path.join(WORK, "bake_pixels")
        code, _, err = run("bake", preset("clear_summer_day"), "--out", out_dir, "--step", "0.25h", "--size",
                           "16x8", "--sky-view-size", "8x4", "--far-fog-size", "8x4", "--compression", "none",
                           "--quiet")
        self.assertEqual(code, 0, err)
        with open(os.path.join(out_dir, "manifest.json")) as f:
            manifest = json.load(f)
        steps = {s["time"]: s for s in manifest["steps"]}
        for time, texels in (("06:00", ((0, 0), (3, 2), (8, 5), (13, 6), (5, 1))),
                             ("19:45", ((8, 0), (7, 1), (9, 2), (6, 3), (12, 1)))):
            step = steps[time]
            width, height, pixels = read_uncompressed_exr(os.path.join(out_dir, step["sun"]["table_file"]))
            self.assertEqual((width, height), (16, 8))
            light_azimuth = step["sun"]["light_azimuth_rad"]
            # Rows rise from the horizon to the zenith; azimuths rise along a row.
            rows = [pixels["elevation"][j][0] for j in range(height)]
            self.assertEqual(rows[0], 0.0)
            self.assertAlmostEqual(rows[-1], math.pi / 2, delta=1e-6)
            self.assertEqual(rows, sorted(rows), time)
            for j in range(height):
                self.assertEqual(list(pixels["azimuth"][j]), sorted(pixels["azimuth"][j]), (time, j))
            for i, j in texels:
                with self.subTest(time=time, texel=(i, j)):
                    el = pixels["elevation"][j][i]
                    az = light_azimuth + pixels["azimuth"][j][i]
                    v = (math.cos(el) * math.sin(az), math.sin(el), -math.cos(el) * math.cos(az))
                    sky = run_json(self, "sky", preset("clear_summer_day"), "--time", time, "--size", "16x8",
                                   "--dir=%.17g,%.17g,%.17g" % v)
                    for layer in ("rayleigh", "mie"):
                        for c, name in enumerate("RGB"):
                            baked = pixels[layer + "." + name][j][i]
                            # A reddened light just set is out of Rec.709's gamut (a
                            # little below 0 in blue): the file keeps no negative value.
                            table = max(sky["table"]["sun"][layer][c], 0.0)
                            self.assertAlmostEqual(baked, table, delta=2e-3 * abs(table) + 1e-7)

    def test_plain_progress_lines_when_not_a_terminal(self):
        out_dir = os.path.join(WORK, "bake_progress")
        # Small maps: the progress lines are what is judged (the default map
        # sizes are baked above; here they were a third of the time under
        # AddressSanitizer).
        code, _, err = run("bake", preset("clear_summer_day"), "--out", out_dir, "--step", "8h", "--size", "16x8",
                           "--sky-view-size", "8x4", "--far-fog-size", "8x4")
        self.assertEqual(code, 0, err)
        self.assertNotIn("\r", err)
        self.assertEqual(len(err.splitlines()), 3, err)


class DefaultPreset(unittest.TestCase):
    """Every command that takes a preset takes `default`: the built-in
    aerial::defaultPreset() (one place: loadPresetOrFail)."""

    def test_every_command_takes_default(self):
        evaluated = run_json(self, "eval", "default", "--time", "10:00")
        self.assertEqual(evaluated["preset"]["file"], "default")
        self.assertIn("apparent_elevation_deg", evaluated["sun"])
        self.assertIsNone(evaluated["julian_day_ut"])  # the default preset is undated
        self.assertGreater(evaluated["sun"]["apparent_elevation_deg"], evaluated["sun"]["elevation_deg"])
        run_json(self, "sky", "default", "--time", "10:00", "--dir", "0,1,0")
        run_json(self, "fog", "default", "--time", "10:00", "--from=0,2,0", "--to=0,2,-100")
        run_json(self, "clouds", "default", "--time", "10:00", "--at", "0,1000,0")
        run_json(self, "day", "default", "--step", "6")
        out_dir = os.path.join(WORK, "bake_default")
        shutil.rmtree(out_dir, ignore_errors=True)
        code, out, err = run("bake", "default", "--out", out_dir, "--step", "12h", "--size", "16x8")
        self.assertEqual(code, 0, err)
        self.assertTrue(os.path.isfile(os.path.join(out_dir, "manifest.json")))
        # The text form of eval shows the date parameters too.
        code, out, err = run("eval", "default", "--time", "10:00")
        self.assertEqual(code, 0, err)
        self.assertIn("location.date", out)

    def test_a_file_named_default_is_dot_slash_default(self):
        code, out, err = run("eval", "./default", "--time", "10:00")
        self.assertNotEqual(code, 0)
        self.assertIn("./default", err)


class CommandLineErrors(unittest.TestCase):
    def test_bad_input_gives_one_line_and_the_right_exit_code(self):
        good = preset("hazy_sunset")
        invalid = os.path.join(ROOT, "tests", "data", "presets", "out_of_range.json")
        missing = os.path.join(WORK, "no_such_preset.json")
        out_dir = os.path.join(WORK, "bake_never")
        cases = [
            (["eval", good, "--time", "25:00"], 2, "--time"),
            (["eval", good, "--time", "24:00"], 2, "--time"),
            (["eval", good, "--time", "12:75"], 2, "--time"),
            (["eval", good, "--time", "-1"], 2, "--time"),
            (["eval", good, "--time", "nan"], 2, "--time"),
            (["eval", good, "--frobnicate"], 2, "--frobnicate"),
            (["eval"], 2, "preset"),
            (["sky", good, "--dir", "0,0,0"], 2, "--dir"),
            (["sky", good, "--dir", "nan,1,0"], 2, "--dir"),
            (["sky", good, "--dir", "0,inf,0"], 2, "--dir"),
            (["sky", good, "--dir", "1,2"], 2, "--dir"),
            (["sky", good], 2, "--dir"),
            (["fog", good, "--from", "0,1,0", "--to", "0,1"], 2, "--to"),
            (["clouds", good, "--at", "0,1"], 2, "--at"),
            (["clouds", good, "--at", "0,nan,0"], 2, "--at"),
            (["clouds", good, "--at", "0,0,0", "--dir", "0,0,0"], 2, "--dir"),
            (["clouds", good], 2, "--at"),
            (["bake", good, "--out", out_dir, "--size", "0x5"], 2, "--size"),
            (["bake", good, "--out", out_dir, "--size", "128"], 2, "--size"),
            (["bake", good, "--out", out_dir, "--step", "0"], 2, "--step"),
            (["bake", good, "--out", out_dir, "--step", "1s"], 2, "--step"),
            (["bake", good, "--out", out_dir, "--compression", "lzw"], 2, "--compression"),
            (["bake", good], 2, "--out"),
            (["day", "--latitude", "91"], 2, "--latitude"),
            (["day", "--step", "nan"], 2, "--step"),
            (["frobnicate"], 2, "frobnicate"),
            ([], 2, "subcommand"),
            (["eval", missing], 1, missing),
            (["sky", missing, "--dir", "0,1,0"], 1, missing),
            (["fog", missing, "--from", "0,1,0", "--to", "0,1,-5"], 1, missing),
            (["clouds", missing, "--at", "0,0,0"], 1, missing),
            (["clouds", invalid, "--at", "0,0,0"], 1, invalid + ":5:40:"),
            (["bake", missing, "--out", out_dir], 1, missing),
            (["day", missing], 1, missing),
            (["validate", missing], 1, missing),
            (["eval", invalid], 1, invalid + ":5:40: /volumes/1/half_extents_m/1: out of range"),
            (["bake", invalid, "--out", out_dir], 1, invalid + ":5:40:"),
        ]
        for args, expected_code, mention in cases:
            with self.subTest(args=args):
                code, out, err = run(*args)
                self.assertEqual(code, expected_code, err)
                self.assertEqual(len(err.splitlines()), 1, err)
                self.assertTrue(err.startswith("aerial"), err)
                if args and args[0] == "validate":
                    self.assertIn(mention, out)  # validate reports on stdout, sums up on stderr
                else:
                    self.assertIn(mention, err)
                    self.assertEqual(out, "")
        self.assertFalse(os.path.exists(os.path.join(out_dir, "manifest.json")))


class Render(unittest.TestCase):
    """`aerial render` (only in a build with the renderer): one headless frame, EXR or PNG."""

    def setUp(self):
        if not has_render_command():
            self.skipTest("aerial was built without the renderer (AERIAL_BUILD_RENDERER=OFF)")
        self.dir = os.path.join(WORK, "render")
        os.makedirs(self.dir, exist_ok=True)

    def assertNoTemporaries(self):
        self.assertEqual([f for f in os.listdir(self.dir) if f.startswith(".")], [], "a temporary was left")

    def test_exr_is_half_float_with_the_requested_data_window(self):
        out = os.path.join(self.dir, "morning.exr")
        r = run_json(self, "render", preset("foggy_valley_morning"), "--time", "07:00", "--size", "64x36",
                     "--out", out)
        self.assertEqual((r["file"], r["format"], r["width"], r["height"]), (out, "exr", 64, 36))
        self.assertEqual(r["time"], "07:00")
        self.assertIsNone(r["exposure"]["exposure_ev"])  # the EXR holds radiance
        self.assertIsNone(r["exposure"]["display_ev"])
        self.assertEqual(r["exposure"]["mode"], "automatic")
        # Automatic: the metered EV100 of the frame, inside the preset's range.
        with open(preset("foggy_valley_morning")) as f:
            limits = json.load(f)["exposure"]
        meter = math.log2(r["exposure"]["average_luminance"] * 5000.0 * 100.0 / 12.5)
        self.assertAlmostEqual(r["exposure"]["ev100"], min(max(meter, limits["min_ev100"]), limits["max_ev100"]),
                               delta=1e-9)
        for key in ("solve_ms", "render_ms"):
            self.assertGreaterEqual(r[key], 0.0)
        with open(out, "rb") as f:
            self.assertEqual(f.read(4), bytes([0x76, 0x2F, 0x31, 0x01]))
        _, attributes = read_exr_header(out)
        x0, y0, x1, y1 = struct.unpack("<4i", attributes["dataWindow"][1])
        self.assertEqual((x0, y0, x1 - x0 + 1, y1 - y0 + 1), (0, 0, 64, 36))
        channels = read_chlist(attributes["channels"][1])
        self.assertEqual(set(channels), {"R", "G", "B", "A"})
        self.assertEqual(set(channels.values()), {1}, "HALF pixels")
        self.assertNoTemporaries()

    def test_the_fog_mode_follows_the_preset_unless_given(self):
        out = os.path.join(self.dir, "mode.exr")
        for name, authored in (("foggy_valley_morning", "volumetric"), ("clear_summer_day", "analytic")):
            with open(preset(name)) as f:
                self.assertEqual(json.load(f)["fog"]["render_mode"], authored)
            r = run_json(self, "render", preset(name), "--time", "08:00", "--size", "32x18", "--out", out)
            self.assertEqual(r["fog"], authored)
            for given in ("analytic", "volumetric"):
                r = run_json(self, "render", preset(name), "--time", "08:00", "--size", "32x18", "--fog", given,
                             "--out", out)
                self.assertEqual(r["fog"], given)
        code, _, err = run("render", preset("foggy_valley_morning"), "--fog", "froxels", "--out", out)
        self.assertEqual(code, 2)
        self.assertIn("--fog", err)

    def test_png_has_the_requested_size_and_a_sky(self):
        out = os.path.join(self.dir, "morning.png")
        for attempt in range(2):  # the second replaces the first
            code, stdout, err = run("render", preset("foggy_valley_morning"), "--time", "07:00", "--size",
                                    "64x36", "--out", out)
            self.assertEqual(code, 0, err)
            self.assertEqual(len(stdout.splitlines()), 1, stdout)
            self.assertIn(out, stdout)
            self.assertIn("64x36", stdout)
            self.assertIn("ms", stdout)
        width, height, colour, depth, rows = read_png(out)
        self.assertEqual((width, height, colour, depth), (64, 36, 2, 8))
        self.assertTrue(any(rows[0]), "the top row (sky) is black")
        self.assertGreater(len(set(b"".join(rows))), 16, "a flat image")
        self.assertNoTemporaries()

    def test_desert_campfire_keeps_the_moonlit_sky_blue(self):
        """desert_dusk's campfire (~100 cd) by moonlight: the sky above 20 deg reads blue (B >= R in the
        displayed image) and the exposure stays within 1.5 EV of the same night without the fire (issue 48:
        a campfire does not out-light the moon on air hundreds of metres away)."""
        with open(preset("desert_dusk")) as f:
            doc = json.load(f)
        doc["emitters"] = []
        doc["tracks"] = [t for t in doc["tracks"] if "emitter" not in t]
        no_fire = os.path.join(self.dir, "desert_no_fire.json")
        with open(no_fire, "w") as f:
            json.dump(doc, f)
        for time in ("23:00", "02:00"):  # the moon 25 and 55 deg up, 87 % lit
            ev = {}
            for label, path in (("fire", preset("desert_dusk")), ("no fire", no_fire)):
                out = os.path.join(self.dir, "desert.png")
                r = run_json(self, "render", path, "--time", time, "--size", "64x36", "--out", out)
                ev[label] = r["exposure"]["ev100"]
                width, height, colour, _, rows = read_png(out)
                channels = 3 if colour == 2 else 4
                eye, target = r["camera"]["eye"], r["camera"]["target"]
                forward = [t - e for t, e in zip(target, eye)]
                n = math.sqrt(sum(c * c for c in forward))
                forward = [c / n for c in forward]
                right = [-forward[2], 0.0, forward[0]]
                n = math.sqrt(sum(c * c for c in right))
                right = [c / n for c in right]
                up = [right[1] * forward[2] - right[2] * forward[1], right[2] * forward[0] - right[0] * forward[2],
                      right[0] * forward[1] - right[1] * forward[0]]
                half = math.tan(math.radians(r["camera"]["fov_deg"]) / 2)
                blue, sky = 0, 0
                for y in range(height):
                    for x in range(width):
                        sx = (2 * (x + 0.5) / width - 1) * half * width / height
                        sy = (1 - 2 * (y + 0.5) / height) * half
                        d = [f + sx * rr + sy * u for f, rr, u in zip(forward, right, up)]
                        if math.degrees(math.asin(d[1] / math.sqrt(sum(c * c for c in d)))) < 20:
                            continue
                        px = rows[y][x * channels:x * channels + 3]
                        sky += 1
                        blue += px[2] >= px[0]
                with self.subTest(time=time, frame=label):
                    self.assertGreater(sky, 0, "no sky above 20 degrees in the default view")
                    self.assertEqual(blue, sky, "%d of %d sky pixels above 20 deg have B < R" % (sky - blue, sky))
            with self.subTest(time=time):
                self.assertLessEqual(abs(ev["fire"] - ev["no fire"]), 1.5, ev)

    def test_night_vision_shows_the_night_blue_and_leaves_the_day(self):
        """The displayed PNG passes through aerial::nightVision (the rods' blue, colourless sight below
        5 cd/m^2): a moonless night, whose light is physically warm (the airglow, B-V ~0.9), reads blue;
        --photopic shows the measured colours; noon is the same either way."""
        def mean_rgb(path, rows):
            width, height, colour, _, data = read_png(path)
            channels = 3 if colour == 2 else 4
            sums, n = [0, 0, 0], 0
            for y in range(rows):
                for x in range(width):
                    for c in range(3):
                        sums[c] += data[y][x * channels + c]
                    n += 1
            return [v / n for v in sums]
        night = os.path.join(self.dir, "night.png")
        r = run_json(self, "render", preset("clear_summer_day"), "--time", "02:00", "--size", "64x36", "--out", night)
        self.assertTrue(r["night_vision"])
        seen = mean_rgb(night, 8)
        r = run_json(self, "render", preset("clear_summer_day"), "--time", "02:00", "--size", "64x36", "--photopic",
                     "--out", night)
        self.assertFalse(r["night_vision"])
        measured = mean_rgb(night, 8)
        self.assertGreater(seen[2], seen[0], "the night sky seen: B > R (%s)" % seen)
        self.assertGreater(measured[0], measured[2], "the night sky measured is warm: R > B (%s)" % measured)
        noon, noon_photopic = os.path.join(self.dir, "noon.png"), os.path.join(self.dir, "noon_photopic.png")
        run_json(self, "render", preset("clear_summer_day"), "--time", "12:00", "--size", "32x18", "--out", noon)
        run_json(self, "render", preset("clear_summer_day"), "--time", "12:00", "--size", "32x18", "--photopic",
                 "--out", noon_photopic)
        a, b = read_png(noon)[4], read_png(noon_photopic)[4]
        self.assertLessEqual(max(abs(p - q) for ra, rb in zip(a, b) for p, q in zip(ra, rb)), 1)

    def test_built_in_default_preset(self):
        out = os.path.join(self.dir, "default.png")
        r = run_json(self, "render", "default", "--size", "16x9", "--exposure", "-1", "--out", out)
        self.assertEqual(r["preset"]["file"], "<built-in default>")
        self.assertEqual((r["time"], r["exposure"]["exposure_ev"]), ("12:00", -1.0))
        self.assertEqual(read_png(out)[:2], (16, 9))

    def test_png_views_through_opencolorio(self):
        plain = os.path.join(self.dir, "plain.png")
        aces = os.path.join(self.dir, "aces.png")
        r = run_json(self, "render", "default", "--size", "16x9", "--view", "Un-tone-mapped", "--out", plain)
        self.assertEqual(r["view"], "Un-tone-mapped")
        r = run_json(self, "render", "default", "--size", "16x9", "--out", aces)
        self.assertEqual((r["display"], r["view"], r["ocio_config"]),
                         ("sRGB - Display", "ACES 1.0 - SDR Video", "built-in"))
        self.assertNotEqual(read_png(plain)[4], read_png(aces)[4], "the tone-mapped view changed nothing")
        # A broken $OCIO: a warning, and the built-in config.
        env = dict(os.environ, OCIO=os.path.join(WORK, "no_such_config.ocio"))
        p = subprocess.run([AERIAL, "render", "default", "--size", "16x9", "--out", plain, "--json"],
                           capture_output=True, text=True, timeout=PROCESS_TIMEOUT, env=env)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("warning", p.stderr)
        self.assertIn("no_such_config.ocio", p.stderr)
        self.assertEqual(json.loads(p.stdout)["ocio_config"], "built-in")
        self.assertNoTemporaries()

    def test_bad_input(self):
        good = preset("hazy_sunset")
        missing = os.path.join(WORK, "no_such_preset.json")
        png = os.path.join(self.dir, "never.png")
        cases = [
            (["render", good, "--out", os.path.join(self.dir, "never.tif")], 2, ".tif"),
            (["render", good, "--out", png, "--size", "0x10"], 2, "--size"),
            (["render", good, "--out", png, "--size", "8193x10"], 2, "--size"),
            (["render", good, "--out", png, "--fov", "179"], 2, "--fov"),
            (["render", good, "--out", png, "--eye", "1,2,3", "--target", "1,2,3"], 2, "--eye"),
            (["render", good, "--out", png, "--eye", "nan,2,3"], 2, "--eye"),
            (["render", good, "--out", os.path.join(self.dir, "never.exr"), "--exposure", "1"], 2, "--exposure"),
            (["render", good], 2, "--out"),
            (["render", good, "--out", png, "--view", "Filmic"], 2, "ACES 1.0 - SDR Video"),
            (["render", good, "--out", png, "--display", "Nope"], 2, "sRGB - Display"),
            (["render", good, "--out", os.path.join(self.dir, "never.exr"), "--view", "Raw"], 2, "--view"),
            (["render", missing, "--out", png], 1, missing),
            (["render", good, "--out", os.path.join(WORK, "no_such_dir", "x.png")], 1, "no_such_dir"),
        ]
        for args, expected_code, mention in cases:
            with self.subTest(args=args):
                code, out, err = run(*args)
                self.assertEqual(code, expected_code, err)
                self.assertEqual(len(err.splitlines()), 1, err)
                self.assertTrue(err.startswith("aerial render: "), err)
                self.assertIn(mention, err)
                self.assertEqual(out, "")
        self.assertEqual(sorted(f for f in os.listdir(self.dir) if "never" in f), [])

    def test_gltf_scene(self):
        """--scene: a glTF cube (a data-URI buffer) renders; bad files are exit 1 with one line."""
        corners = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
        faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
        indices = [q[k] for q in faces for k in (0, 1, 2, 0, 2, 3)]
        data = b"".join(struct.pack("<3f", *c) for c in corners) + struct.pack("<36H", *indices)
        uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
        doc = {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
               "nodes": [{"mesh": 0, "translation": [0, 5, -20], "scale": [3, 3, 3]}],
               "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
               "buffers": [{"byteLength": len(data), "uri": uri}],
               "bufferViews": [{"buffer": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
               "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3"},
                             {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}]}
        good = os.path.join(self.dir, "cube.gltf")
        with open(good, "w") as f:
            json.dump(doc, f)
        out = os.path.join(self.dir, "cube.png")
        code, stdout, err = run("render", "default", "--scene", good, "--eye", "0,5,0", "--target", "0,5,-20",
                                "--size", "16x9", "--out", out)
        self.assertEqual(code, 0, err)
        self.assertEqual(read_png(out)[:2], (16, 9))
        bad = os.path.join(self.dir, "bad.gltf")
        doc["nodes"][0]["children"] = [0]
        with open(bad, "w") as f:
            json.dump(doc, f)
        truncated = os.path.join(self.dir, "truncated.glb")
        with open(truncated, "wb") as f:
            f.write(b"glTF\x02\x00\x00\x00")
        png = os.path.join(self.dir, "never.png")
        for path, mention in ((bad, "its own ancestor"), (truncated, "GLB header"),
                              (os.path.join(WORK, "no_such.glb"), "no such file")):
            with self.subTest(path=path):
                code, stdout, err = run("render", "default", "--scene", path, "--out", png)
                self.assertEqual(code, 1, err)
                self.assertEqual(len(err.splitlines()), 1, err)
                self.assertTrue(err.startswith("aerial render: --scene: " + path + ": "), err)
                self.assertIn(mention, err)
                self.assertEqual(stdout, "")
        self.assertFalse(os.path.exists(png))


def rgb_bytes(path):
    """(width, height, RGB bytes) of an 8-bit PNG that aerial wrote."""
    width, height, colour, depth, rows = read_png(path)
    channels = {2: 3, 6: 4}[colour]
    rgb = bytearray()
    for row in rows:
        for x in range(width):
            rgb += row[x * channels:x * channels + 3]
    return width, height, bytes(rgb)


def display_median(path):
    """The median grey level of an 8-bit PNG, 0..1: the luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' of
    the encoded values of each pixel, the middle one (the mean of the two middle ones)."""
    width, height, rgb = rgb_bytes(path)
    luma = sorted(0.2126 * rgb[i] + 0.7152 * rgb[i + 1] + 0.0722 * rgb[i + 2] for i in range(0, len(rgb), 3))
    n = len(luma)
    return (luma[(n - 1) // 2] + luma[n // 2]) / 2.0 / 255.0


class PresetView(unittest.TestCase):
    """A preset's "view" (aerial/preset.hpp, PresetView): `aerial render`'s camera when the options leave
    it open, the built-in default for a preset without one."""

    def setUp(self):
        if not has_render_command():
            self.skipTest("aerial was built without the renderer (AERIAL_BUILD_RENDERER=OFF)")
        self.dir = os.path.join(WORK, "preset_view")
        os.makedirs(self.dir, exist_ok=True)

    def render(self, path, *args):
        out = os.path.join(self.dir, "view.png")
        return run_json(self, "render", path, "--time", "12:00", "--size", "32x18", "--out", out, *args)["camera"]

    def test_the_view_is_the_camera_unless_an_option_says_otherwise(self):
        with open(preset("clear_summer_day")) as f:
            doc = json.load(f)
        self.assertNotIn("view", doc)
        plain = self.render(preset("clear_summer_day"))
        self.assertFalse(plain["preset_view"])
        self.assertEqual((plain["eye"][0], plain["eye"][2], plain["target"][2], plain["fov_deg"]),
                         (0.0, 120.0, -200.0, 60.0))  # the built-in default
        doc["view"] = {"eye_m": [-40.5, 55.25, 90.0], "target_m": [10.0, 12.0, -150.0], "fov_deg": 42.0}
        framed = os.path.join(self.dir, "framed.json")
        with open(framed, "w") as f:
            json.dump(doc, f)
        camera = self.render(framed)
        self.assertTrue(camera["preset_view"])
        self.assertEqual((camera["eye"], camera["target"], camera["fov_deg"]),
                         ([-40.5, 55.25, 90.0], [10.0, 12.0, -150.0], 42.0))
        # Each option replaces its own part; the rest stays the view's.
        camera = self.render(framed, "--eye", "1,50,100")
        self.assertEqual((camera["eye"], camera["target"], camera["fov_deg"], camera["preset_view"]),
                         ([1.0, 50.0, 100.0], [10.0, 12.0, -150.0], 42.0, True))
        camera = self.render(framed, "--fov", "30")
        self.assertEqual((camera["eye"], camera["fov_deg"]), ([-40.5, 55.25, 90.0], 30.0))
        camera = self.render(framed, "--eye", "1,50,100", "--target", "0,0,0", "--fov", "30")
        self.assertFalse(camera["preset_view"])
        # An eye given on the command line at the view's target: no direction.
        code, _, err = run("render", framed, "--eye", "10,12,-150", "--out", os.path.join(self.dir, "never.png"))
        self.assertEqual(code, 2)
        self.assertIn("--eye is the preset view's other point", err)

    def test_a_bad_view_names_the_file_and_the_field(self):
        with open(preset("clear_summer_day")) as f:
            doc = json.load(f)
        bad = os.path.join(self.dir, "bad_view.json")
        for view, pointer, reason in (
                ({"eye_m": [0, 40, 120]}, "/view/target_m", 'missing required field "target_m"'),
                ({"eye_m": [0, 40, 120], "target_m": [0, 10, -200], "fov_deg": 0.5}, "/view/fov_deg",
                 "out of range: 0.5 is not in 1..179 deg")):
            doc["view"] = view
            with open(bad, "w") as f:
                json.dump(doc, f)
            code, _, err = run("render", bad, "--out", os.path.join(self.dir, "never.png"))
            self.assertEqual(code, 1, err)
            self.assertIn(bad, err)
            self.assertIn(pointer + ": " + reason, err)

    def test_misty_river_farm_shows_its_river_and_yard_not_the_foggy_valley(self):
        """The two presets share their sky, fog and day (misty_river_farm adds the river's mist and the
        yard's clear volume), so from one camera their contact-sheet rows were the same picture (mean
        difference <= 0.08/255 at these hours). misty_river_farm's view frames the river and the farm yard:
        at every hour of the sheet where both read, the pictures differ by a mean of at least 10/255 per
        channel (a difference seen at a glance; two renders of one preset differ by 0)."""
        with open(preset("misty_river_farm")) as f:
            self.assertIn("view", json.load(f))
        for hour in ("02:00", "05:30", "12:00", "18:45"):
            images = []
            for name in ("foggy_valley_morning", "misty_river_farm"):
                out = os.path.join(self.dir, "%s_%s.png" % (name, hour.replace(":", "")))
                code, _, err = run("render", preset(name), "--time", hour, "--size", "160x90", "--out", out)
                self.assertEqual(code, 0, err)
                images.append(rgb_bytes(out)[2])
            a, b = images
            mean = sum(abs(x - y) for x, y in zip(a, b)) / len(a)
            with self.subTest(hour=hour):
                self.assertGreaterEqual(mean, 10.0, "mean |difference| %.2f/255 at %s" % (mean, hour))


class NoonExposure(unittest.TestCase):
    """The automatic exposure meters as a photographer's camera does (aerial/exposure.hpp): a sunny noon
    in every clear preset, from the preset's own camera, lands at a display median (the grey level of
    the 8-bit picture) of 0.35-0.55: neither the dull grey nor the washed-out white of a miscalibrated
    meter (issue 47.4)."""

    CLEAR = ["clear_summer_day", "desert_dusk", "hazy_sunset"]

    def setUp(self):
        if not has_render_command():
            self.skipTest("aerial was built without the renderer (AERIAL_BUILD_RENDERER=OFF)")
        self.dir = os.path.join(WORK, "noon_exposure")
        os.makedirs(self.dir, exist_ok=True)

    def test_a_sunny_noon_reads_as_a_sunny_noon(self):
        for name in self.CLEAR:
            out = os.path.join(self.dir, name + ".png")
            r = run_json(self, "render", preset(name), "--time", "12:00", "--size", "160x90", "--out", out)
            self.assertEqual(r["exposure"]["mode"], "automatic")
            self.assertEqual(r["exposure"]["compensation_ev"], 0.0)  # the meter alone
            median = display_median(out)
            with self.subTest(preset=name):
                self.assertGreaterEqual(median, 0.35, "%s at noon: display median %.3f" % (name, median))
                self.assertLessEqual(median, 0.55, "%s at noon: display median %.3f" % (name, median))


class WriteFaults(unittest.TestCase):
    """Every file aerial writes goes through core's atomic writer: faults injected
    through its seam (AERIAL_TEST_FILE_FAULT, aerial/detail/file_system.hpp) and a
    real file-size limit give exit 1 and one line naming the file and the reason;
    the previous file is intact and no temporary is left (a killed process leaves
    one, which the next write of that file removes)."""

    OLD = b"old bake, must survive"
    FIRST = "sky_000_0000_sun.exr"

    def requireHooks(self):
        if not TEST_HOOKS:
            self.skipTest("aerial was built without AERIAL_TEST_HOOKS (no AERIAL_TEST_FILE_FAULT)")

    def run_with(self, args, fault=None, preexec_fn=None):
        env = dict(os.environ)
        env.pop("AERIAL_TEST_FILE_FAULT", None)
        if fault:
            env["AERIAL_TEST_FILE_FAULT"] = fault
        p = subprocess.run([AERIAL, *args], capture_output=True, text=True, timeout=PROCESS_TIMEOUT, env=env,
                           preexec_fn=preexec_fn)
        return p.returncode, p.stdout, p.stderr

    def fresh_dir(self, name):
        d = os.path.join(WORK, "faults", name)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        with open(os.path.join(d, self.FIRST), "wb") as f:
            f.write(self.OLD)
        return d

    def assertOldIntact(self, d):
        with open(os.path.join(d, self.FIRST), "rb") as f:
            self.assertEqual(f.read(), self.OLD)

    def bake(self, d, fault=None, preexec_fn=None):
        return self.run_with(["bake", preset("hazy_sunset"), "--out", d, "--step", "12h", "--size", "16x8",
                              "--quiet"], fault, preexec_fn)

    def test_bake_faults(self):
        self.requireHooks()
        cases = [
            ("missing-directory", "cannot create a temporary file in {d}: No such file or directory"),
            ("not-writable", "cannot create a temporary file in {d}: Permission denied"),
            ("disk-full", "cannot write {d}/.sky_000_0000_sun.exr.tmp-"),
            ("sync", "cannot flush {d}/.sky_000_0000_sun.exr.tmp-"),
            ("rename", "cannot rename {d}/.sky_000_0000_sun.exr.tmp-"),
        ]
        reasons = {"disk-full": ": No space left on device", "sync": " to disk (fsync): Input/output error",
                   "rename": " over {d}/sky_000_0000_sun.exr: Input/output error"}
        for fault, start in cases:
            with self.subTest(fault=fault):
                d = self.fresh_dir(fault)
                code, out, err = self.bake(d, fault)
                self.assertEqual(code, 1, err)
                self.assertEqual(len(err.splitlines()), 1, err)
                self.assertTrue(err.startswith("aerial bake: " + start.format(d=d)), err)
                if fault in reasons:
                    self.assertTrue(err.rstrip("\n").endswith(reasons[fault].format(d=d)), err)
                self.assertOldIntact(d)
                self.assertEqual(sorted(os.listdir(d)), [self.FIRST], "a temporary was left")

    def test_bake_past_a_file_size_limit(self):
        import resource
        import signal

        def limit():
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (200, 200))

        d = self.fresh_dir("fsize")
        code, out, err = self.bake(d, preexec_fn=limit)
        self.assertEqual(code, 1, err)
        self.assertEqual(len(err.splitlines()), 1, err)
        self.assertTrue(err.startswith("aerial bake: cannot write " + d + "/.sky_000_0000_sun.exr.tmp-"), err)
        self.assertTrue(err.rstrip("\n").endswith(": File too large"), err)
        self.assertOldIntact(d)
        self.assertEqual(sorted(os.listdir(d)), [self.FIRST])

    def test_bake_killed_mid_write(self):
        self.requireHooks()
        d = self.fresh_dir("crash")
        code, out, err = self.bake(d, "crash")
        self.assertEqual(code, -9, err)  # SIGKILL
        self.assertOldIntact(d)
        left = sorted(os.listdir(d))
        self.assertEqual(len(left), 2, left)
        self.assertTrue(left[0].startswith(".sky_000_0000_sun.exr.tmp-"), left)
        # The next bake replaces the file and removes the dead process's temporary.
        code, out, err = self.bake(d)
        self.assertEqual(code, 0, err)
        self.assertFalse([f for f in os.listdir(d) if f.startswith(".")], os.listdir(d))
        self.assertIn("manifest.json", os.listdir(d))

    def test_render_faults(self):
        self.requireHooks()
        if not has_render_command():
            self.skipTest("aerial was built without the renderer")
        d = os.path.join(WORK, "faults", "render")
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        out_file = os.path.join(d, "frame.png")
        with open(out_file, "wb") as f:
            f.write(self.OLD)
        cases = [("not-writable", "cannot create a temporary file in " + d + ": Permission denied"),
                 ("sync", "cannot flush " + d + "/.frame.png.tmp-"),
                 ("rename", "cannot rename " + d + "/.frame.png.tmp-")]
        for fault, start in cases:
            with self.subTest(fault=fault):
                code, out, err = self.run_with(["render", "default", "--out", out_file, "--size", "16x8"], fault)
                self.assertEqual(code, 1, err)
                self.assertEqual(len(err.splitlines()), 1, err)
                self.assertTrue(err.startswith("aerial render: " + start), err)
                with open(out_file, "rb") as f:
                    self.assertEqual(f.read(), self.OLD)
                self.assertEqual(os.listdir(d), ["frame.png"])
        # Killed before the rename (the image writer writes by name; the fault
        # fires at the fsync that follows): the old frame survives, and the next
        # render removes the dead process's temporary.
        code, out, err = self.run_with(["render", "default", "--out", out_file, "--size", "16x8"], "crash")
        self.assertEqual(code, -9, err)
        with open(out_file, "rb") as f:
            self.assertEqual(f.read(), self.OLD)
        self.assertEqual(len(os.listdir(d)), 2, os.listdir(d))
        code, out, err = self.run_with(["render", "default", "--out", out_file, "--size", "16x8"])
        self.assertEqual(code, 0, err)
        self.assertEqual(os.listdir(d), ["frame.png"])
        with open(out_file, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")

    def test_unknown_fault_is_a_usage_error(self):
        self.requireHooks()
        code, out, err = self.run_with(["day"], "meteor")
        self.assertEqual(code, 2)
        self.assertEqual(err, "aerial: AERIAL_TEST_FILE_FAULT=meteor is not a known fault\n")

    def test_fault_variable_ignored_without_test_hooks(self):
        if TEST_HOOKS:
            self.skipTest("aerial was built with AERIAL_TEST_HOOKS")
        code, out, err = self.run_with(["day"], "meteor")
        self.assertEqual(code, 0, err)
        self.assertEqual(err, "")
        d = self.fresh_dir("no_hooks")
        code, out, err = self.bake(d, "disk-full")
        self.assertEqual(code, 0, err)
        self.assertIn("manifest.json", os.listdir(d))


class Limits(unittest.TestCase):
    """The caps of aerial/limits.hpp on the command line: one over is refused."""

    def test_table_and_image_sizes(self):
        out_dir = os.path.join(WORK, "limits_bake")
        for size in ("4097x64", "128x2049"):
            with self.subTest(size=size):
                code, out, err = run("bake", preset("hazy_sunset"), "--out", out_dir, "--size", size)
                self.assertEqual(code, 2, err)
                self.assertIn("azimuth columns 4..4096 x elevation rows 2..2048", err)
                self.assertFalse(os.path.exists(out_dir))

    def test_huge_preset_file(self):
        big = os.path.join(WORK, "huge_preset.json")
        with open(big, "wb") as f:
            f.write(b'{"version": 1}')
            f.truncate(16 * 1024 * 1024 + 1)
        code, out, err = run("validate", big)
        self.assertEqual(code, 1, err)
        self.assertEqual(out, big + ": the file is 16777217 bytes, over the limit of 16777216 bytes (16 MiB) for a "
                              "preset\n")


class Day(unittest.TestCase):
    def test_day_on_the_built_in_default(self):
        code, out, err = run("day")
        self.assertEqual(code, 0, err)
        lines = out.splitlines()
        self.assertEqual(len(lines), 2 + 24, out)  # title, header, 24 hours
        self.assertTrue(lines[2].startswith("00:00"))
        r = run_json(self, "day", "--step", "6")
        self.assertEqual(len(r["steps"]), 4)
        for step in r["steps"]:
            for t in step["fog_1km_north"]["transmittance_rgb"]:
                self.assertTrue(0.0 <= t <= 1.0)

    def test_day_on_a_preset(self):
        code, out, err = run("day", preset("stormy_night"), "--step", "12")
        self.assertEqual(code, 0, err)
        self.assertIn("Stormy night", out)


def main():
    global AERIAL, ROOT, WORK, TEST_HOOKS, RGBA_PROBE
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--aerial", required=True, help="the aerial binary")
    parser.add_argument("--source-dir", required=True, help="the repository root")
    parser.add_argument("--work-dir", required=True, help="a scratch directory (emptied first)")
    parser.add_argument("--test-hooks", choices=["on", "off"], default="on",
                        help="whether aerial was built with AERIAL_TEST_HOOKS (default on)")
    parser.add_argument("--rgba-probe", default="", help="tests/tools/exr_rgba_probe (RGBA-only EXR reader)")
    args, rest = parser.parse_known_args()
    RGBA_PROBE = os.path.abspath(args.rgba_probe) if args.rgba_probe else ""
    AERIAL, ROOT, WORK = os.path.abspath(args.aerial), os.path.abspath(args.source_dir), os.path.abspath(
        args.work_dir)
    TEST_HOOKS = args.test_hooks == "on"
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    unittest.main(argv=[sys.argv[0], *rest], verbosity=2)


if __name__ == "__main__":
    main()
