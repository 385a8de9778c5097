#!/usr/bin/env python3
"""End-to-end tests of aerial-editor under Xvfb (xvfb-run -a), driven by its
automation mode (--script): the real window, ImGui, renderer, gizmo and
file code paths. Python standard library only.

    editor_e2e.py --editor PATH --source-dir DIR --work-dir DIR CASE

CASE: workflow | undo_redo | crash_recovery | screenshot | exposure | errors | prompts | session |
      cloud_volume | autokey | placement | curves | curves_mouse | sun_anchor | curve_edit | weather |
      small_things
(weather: e2e_weather.py)

Every case FAILS (never skips) when the editor cannot start under Xvfb.
"""
import argparse
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from pngio import PngError, decode_png  # noqa: E402  (the one PNG reader)
from e2e_weather import case_weather  # noqa: E402  (its own file: this one is long enough)

WINDOW = "640x360"


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


class Env:
    def __init__(self, args, case):
        self.editor = args.editor
        self.source = args.source_dir
        self.work = os.path.join(args.work_dir, case)
        shutil.rmtree(self.work, ignore_errors=True)
        os.makedirs(self.work)
        self.state = os.path.join(self.work, "state")
        self.config = os.path.join(self.work, "config")
        if shutil.which("xvfb-run") is None:
            fail("xvfb-run is not installed (apt-get install xvfb): the editor tests need it")

    def env(self):
        e = dict(os.environ)
        e["AERIAL_STATE_DIR"] = self.state
        e["AERIAL_CONFIG_DIR"] = self.config
        return e

    def path(self, name):
        return os.path.join(self.work, name)

    def script(self, name, text):
        p = self.path(name)
        with open(p, "w") as f:
            f.write(text)
        return p

    def command(self, script, extra=(), window=WINDOW):
        # -a picks a free display; starting the search at a per-process number keeps
        # tests run in parallel (ctest -j) from racing for the same one.
        first = str(100 + (os.getpid() * 7 + len(script)) % 800)
        # Our own auth file: xvfb-run then makes no temporary directory of its
        # own, whose removal sometimes failed ("problem while cleaning up
        # temporary directory", exit 5) and hid the editor's exit status.
        auth = self.path("Xauthority")
        open(auth, "a").close()
        return ["xvfb-run", "-a", "-n", first, "-f", auth, "-s", "-screen 0 1024x768x24", self.editor, "--size",
                window, "--script", script] + list(extra)

    def run(self, script, extra=(), expect_rc=0, timeout=240, window=WINDOW):
        cmd = self.command(script, extra, window)
        start = time.time()
        p = subprocess.run(cmd, env=self.env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           timeout=timeout)
        print("$ %s  (%.1f s, exit %d)" % (" ".join(cmd), time.time() - start, p.returncode))
        print(p.stdout)
        print(p.stderr, file=sys.stderr)
        if expect_rc is not None and p.returncode != expect_rc:
            fail("aerial-editor exited %d, expected %d (it must start under Xvfb)\n%s" %
                 (p.returncode, expect_rc, p.stderr[-3000:]))
        return p


def load_json(path):
    check(os.path.exists(path), "%s was not written" % path)
    with open(path) as f:
        return json.load(f)


def track(preset, param, object_id=None):
    for t in preset.get("tracks", []):
        if t.get("param") == param and (object_id is None or t.get("volume") == object_id
                                        or t.get("emitter") == object_id):
            return t
    return None


def key_at(t, hours):
    for k in t["keys"]:
        if abs(k["time_h"] - hours) < 1e-9:
            return k
    return None


def key_value(k):
    v = k["value"]
    return v[0] if isinstance(v, list) else v


# --- PNG reading (8-bit RGB/RGBA, non-interlaced, as stb writes) ------------

def read_png(path):
    """(width, height, bytes per pixel, rows) of the editor's 8-bit RGB/RGBA PNGs (scripts/pngio.py)."""
    check(os.path.exists(path), "%s was not written" % path)
    try:
        width, height, colour, depth, rows = decode_png(path)
    except PngError as e:
        fail(str(e))
    check(rows is not None, "%s: unsupported PNG format (colour %d, depth %d)" % (path, colour, depth))
    return width, height, 3 if colour == 2 else 4, rows


# --- cases -------------------------------------------------------------------

def case_workflow(env):
    """No file -> ellipsoid volume -> gizmo drag -> fog keys at 06:00 and 12:00 ->
    scrub -> save -> reopen -> the saved JSON holds the moved volume and the keys."""
    saved = env.path("workflow.json")
    script = env.script("workflow.txt", """
expect_clean
expect_volumes 1
add_volume ellipsoid
expect_selected volume 1
expect_dirty
gizmo_drag translate x 120 0 10
time 12
print volume[1].position_m
time 6
set fog.density_per_m 0.01
key fog.density_per_m
time 12
set fog.density_per_m 0.002
key fog.density_per_m
time 6
expect_param fog.density_per_m 0.01 1e-12
interp fog.density_per_m linear
select volume 1
time 8
key volume[1].density_per_m
copy_key volume[1].density_per_m
time 16
paste_key volume[1].density_per_m
move_key volume[1].density_per_m 16 17:30
expect_undo 8
expect_keys volume[1].density_per_m 2
gizmo_drag rotate y 0 40 6
scrub 0 24 30
save {saved}
expect_clean
new
expect_volumes 1
open {saved}
expect_volumes 2
expect_clean
time 12
expect_param fog.density_per_m 0.002 1e-12
quit
""".format(saved=saved))
    p = env.run(script)
    added = re.search(r"added volume 1 at (\S+) (\S+) (\S+)", p.stdout)
    check(added, "no 'added volume' line")
    start = [float(added.group(i)) for i in (1, 2, 3)]
    printed = re.search(r"volume\[1\]\.position_m = (\S+) (\S+) (\S+)", p.stdout)
    check(printed, "no position printed after the drag")
    moved = [float(printed.group(i)) for i in (1, 2, 3)]

    preset = load_json(saved)
    check(preset["name"] == "Workflow", "Save As did not give the unnamed preset the file's name: %r" % preset["name"])
    check(len(preset["volumes"]) == 2, "the saved preset has %d volumes" % len(preset["volumes"]))
    v = preset["volumes"][1]
    check(v["shape"] == "ellipsoid", "the new volume is a %s" % v["shape"])
    pos = v["position_m"]
    print("volume: added at %s, after the drag %s, saved %s" % (start, moved, pos))
    check(pos[0] - start[0] > 1.0, "the gizmo drag along +x did not move the volume along +x (%s -> %s)" % (start, pos))
    check(abs(pos[1] - start[1]) < 1e-9 and abs(pos[2] - start[2]) < 1e-9,
          "an x-axis drag changed y or z: %s -> %s" % (start, pos))
    check(all(abs(a - b) < 1e-9 for a, b in zip(pos, moved)), "saved position differs from the edited one")

    t = track(preset, "fog.density_per_m")
    check(t is not None, "no fog density track in the saved preset")
    k6, k12 = key_at(t, 6.0), key_at(t, 12.0)
    check(k6 is not None and k12 is not None, "keys at 06:00 and 12:00 missing: %s" % t["keys"])
    check(key_value(k6) == 0.01, "key at 06:00 = %s, want 0.01" % key_value(k6))
    check(key_value(k12) == 0.002, "key at 12:00 = %s, want 0.002" % key_value(k12))
    check(t["interpolation"] == "linear", "interpolation not saved: %s" % t["interpolation"])
    vt = track(preset, "density_per_m", v["id"])
    check(vt is not None and [k["time_h"] for k in vt["keys"]] == [8, 17.5],
          "copied/pasted/moved volume keys wrong: %s" % (vt and vt["keys"]))
    check(key_value(vt["keys"][1]) == key_value(vt["keys"][0]) == 0.02, "the pasted key has another value")
    check(v["rotation_xyzw"] != [0, 0, 0, 1], "the rotate drag did not rotate the volume")
    print("OK: workflow")


def case_undo_redo(env):
    """Every kind of change undoes and redoes; a gizmo drag is one step; export."""
    bake = env.path("bake")
    saved = env.path("undo.json")
    script = env.script("undo.txt", """
expect_undo 0
set fog.falloff_per_m 0.05
expect_undo 1
add_volume box
expect_undo 2
gizmo_drag translate y 0 -60 12
expect_undo 3
print volume[1].position_m
undo
expect_undo 2
print volume[1].position_m
redo
expect_undo 3
rename Mist
duplicate
expect_volumes 3
time 7
key volume[1].density_per_m
expect_keys volume[1].density_per_m 1
set volume[1].colour_rgb 0.5 0.25 0.125
expect_param volume[1].colour_rgb 0.5 0.25 0.125 0
select volume 1
gizmo_drag scale x 40 0 8
expect_undo 8
add_emitter point
expect_emitters 2
undo
expect_emitters 1
undo
undo
expect_param volume[1].colour_rgb 1 1 1 0
undo
expect_keys volume[1].density_per_m 0
undo
expect_volumes 2
undo
undo
expect_volumes 2
undo
expect_volumes 1
undo
expect_param fog.falloff_per_m 0.02 0
expect_undo 0
expect_clean
redo
redo
redo
redo
redo
redo
redo
redo
redo
expect_undo 9
expect_emitters 2
expect_volumes 3
expect_dirty
save {saved}
export {bake}
quit
""".format(saved=saved, bake=bake))
    p = env.run(script)
    positions = re.findall(r"volume\[1\]\.position_m = (\S+) (\S+) (\S+)", p.stdout)
    check(len(positions) == 2, "positions not printed")
    after, before = [float(x) for x in positions[0]], [float(x) for x in positions[1]]
    check(after[1] - before[1] > 0.5, "dragging the y arrow up did not raise the volume: %s -> %s" % (before, after))
    preset = load_json(saved)
    check(len(preset["volumes"]) == 3 and len(preset["emitters"]) == 2, "redo did not restore every object")
    check(preset["volumes"][1]["name"] == "Mist", "rename lost: %s" % preset["volumes"][1]["name"])
    check(preset["volumes"][1]["half_extents_m"][0] > 10.0, "the scale drag was lost")
    check(preset["fog"]["falloff_per_m"] == 0.05, "the first edit was lost")
    manifest = load_json(os.path.join(bake, "manifest.json"))
    check(manifest["step_count"] == 48, "the export is not a 0.5 h bake")
    check(os.path.exists(os.path.join(bake, "preset.json")), "the export has no preset.json")
    check(manifest["preset"]["file"] == "preset.json", "the manifest holds the path %r, not preset.json beside it"
          % manifest["preset"]["file"])
    # Export options (step, table size); an earlier export is replaced; a folder
    # holding other files is refused with the reason and left alone.
    other = env.path("not_an_export")
    os.makedirs(other, exist_ok=True)
    with open(os.path.join(other, "notes.txt"), "w") as f:
        f.write("mine")
    p = env.run(env.script("export_options.txt", "export {bake} 2 64x32\nprint_status\nquit\n".format(bake=bake)))
    status = re.search(r"^status (.*)$", p.stdout, re.M)
    check(status and "into %s " % bake in status.group(1) and "into . " not in status.group(1),
          "the export's status does not name its folder: %r" % (status.group(1) if status else p.stdout))
    manifest = load_json(os.path.join(bake, "manifest.json"))
    check(manifest["step_count"] == 12 and manifest["table"]["azimuth_count"] == 64,
          "the export options were not used: %d steps, %d columns" % (manifest["step_count"], manifest["table"]["azimuth_count"]))
    p = env.run(env.script("export_refused.txt", "export {other}\n".format(other=other)), expect_rc=1)
    check("holds other files" in p.stderr, "exporting into a folder of other files was not refused:\n" + p.stderr[-1500:])
    check(sorted(os.listdir(other)) == ["notes.txt"], "the refused export wrote into the folder: %s" % os.listdir(other))
    print("OK: undo_redo")


def run_until_autosave(env, script_text, name):
    script = env.script(name, script_text)
    cmd = env.command(script, ["--autosave-seconds", "0.5"])
    proc = subprocess.Popen(cmd, env=env.env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    pid, autosaved, lines = None, False, []
    deadline = time.time() + 180
    while time.time() < deadline:
        line = proc.stdout.readline()
        if not line:
            break
        lines.append(line)
        m = re.match(r"aerial-editor pid (\d+)", line)
        if m:
            pid = int(m.group(1))
        if line.startswith("autosaved "):
            autosaved = True
            break
    if not autosaved or pid is None:
        proc.kill()
        out, err = proc.communicate()
        fail("the editor did not autosave (it must start under Xvfb):\n%s%s\n%s" % ("".join(lines), out, err))
    os.kill(pid, signal.SIGKILL)  # the editor itself, not xvfb-run
    proc.communicate(timeout=60)
    print("".join(lines))
    print("killed aerial-editor (pid %d) with SIGKILL after the autosave" % pid)
    return pid


def case_crash_recovery(env):
    """kill -9 after an autosave; the next start recovers (--recover yes) or discards (no)."""
    pid = run_until_autosave(env, """
set fog.falloff_per_m 0.0456
add_volume box
wait_autosave
wait_frames 1000000
""", "crash1.txt")
    check(os.path.exists(os.path.join(env.state, "session-%d.json" % pid)), "no session marker left by the crash")
    check(os.path.exists(os.path.join(env.state, "recovery-%d.json" % pid)), "no recovery file left by the crash")
    recovered = env.path("recovered.json")
    env.run(env.script("recover.txt", """
expect_dirty
expect_volumes 2
expect_param fog.falloff_per_m 0.0456 0
save {out}
quit
""".format(out=recovered)), ["--recover", "yes"])
    preset = load_json(recovered)
    check(preset["fog"]["falloff_per_m"] == 0.0456, "the recovered preset lost the edit")
    check(len(preset["volumes"]) == 2 and preset["volumes"][1]["shape"] == "box", "the recovered preset lost the volume")
    check(os.listdir(env.state) == [], "state files left after a clean exit: %s" % os.listdir(env.state))

    run_until_autosave(env, """
set fog.falloff_per_m 0.09
wait_autosave
wait_frames 1000000
""", "crash2.txt")
    env.run(env.script("discard.txt", """
expect_clean
expect_param fog.falloff_per_m 0.02 0
quit
"""), ["--recover", "no"])
    check(os.listdir(env.state) == [], "declining recovery left files: %s" % os.listdir(env.state))
    print("OK: crash_recovery")


def case_screenshot(env):
    """A screenshot with a new volume differs from one without it, inside the
    volume's projected bounds (and much less elsewhere)."""
    before, after, exr = env.path("before.png"), env.path("after.png"), env.path("after.exr")
    p = env.run(env.script("shot.txt", """
time 10
screenshot {before}
add_volume ellipsoid
set volume[1].density_per_m 0.1
set volume[1].colour_mode custom
set volume[1].colour_rgb 3 0.2 0.1
screenshot {after}
screenshot {exr}
quit
""".format(before=before, after=after, exr=exr)))
    m = re.search(r"selection_bounds (\S+) (\S+) (\S+) (\S+)", p.stdout)
    check(m, "no selection bounds printed")
    x0, y0, x1, y1 = [float(m.group(i)) for i in (1, 2, 3, 4)]
    w0, h0, bpp, a = read_png(before)
    w1, h1, _, b = read_png(after)
    check((w0, h0) == (w1, h1), "screenshots of different sizes")
    with open(exr, "rb") as f:
        check(f.read(4) == b"\x76\x2f\x31\x01", "the .exr screenshot is not OpenEXR")
    # Shrink the box to its inner half: the ellipsoid covers it.
    cx, cy, hx, hy = (x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 4, (y1 - y0) / 4
    inside = outside = 0.0
    n_in = n_out = 0
    for y in range(h0):
        for x in range(w0):
            d = sum(abs(a[y][x * bpp + c] - b[y][x * bpp + c]) for c in range(3)) / 3.0
            if abs(x + 0.5 - cx) <= hx and abs(y + 0.5 - cy) <= hy:
                inside += d
                n_in += 1
            elif not (x0 - 4 <= x <= x1 + 4 and y0 - 4 <= y <= y1 + 4):
                outside += d
                n_out += 1
    check(n_in > 20, "the volume covers too few pixels (%d) to test: bounds %s" % (n_in, (x0, y0, x1, y1)))
    mean_in = inside / n_in
    mean_out = outside / max(n_out, 1)
    print("mean |difference| inside the volume %.2f, outside %.2f (8-bit levels, %d / %d px)" %
          (mean_in, mean_out, n_in, n_out))
    check(mean_in > 8.0, "the volume is not visible in the screenshot (mean difference %.2f)" % mean_in)
    check(mean_in > 4.0 * mean_out + 1.0, "the difference is not concentrated on the volume")
    print("OK: screenshot")


def case_exposure(env):
    """The preset's exposure reaches the picture: manual EV100 12 shows the
    same pixels as EV100 14 with the view's offset +2 and as EV100 14 with a
    compensation of +2 (the display multiplies by 2^-EV100 in each case), and
    two stops brighter than EV100 14 alone."""
    shots = {k: env.path(k + ".png") for k in ("ev12", "ev14_offset", "ev14_comp", "ev14")}
    env.run(env.script("exposure.txt", """
time 12
select exposure
set exposure.mode manual
set exposure.ev100 12
screenshot {ev12}
set exposure.ev100 14
exposure 2
screenshot {ev14_offset}
exposure 0
set exposure.compensation_ev 2
screenshot {ev14_comp}
set exposure.compensation_ev 0
screenshot {ev14}
expect_param exposure.ev100 14 0
quit
""".format(**shots)))
    images = {k: read_png(v) for k, v in shots.items()}

    def mean_level(image):
        w, h, bpp, rows = image
        return sum(sum(row[x * bpp + c] for c in range(3)) for row in rows for x in range(w)) / (3.0 * w * h)

    def max_difference(a, b):
        w, h, bpp, ra = a
        rb = b[3]
        return max(abs(ra[y][i] - rb[y][i]) for y in range(h) for i in range(w * bpp) if i % bpp < 3)

    for other in ("ev14_offset", "ev14_comp"):
        d = max_difference(images["ev12"], images[other])
        check(d <= 1, "EV100 12 and %s differ by up to %d levels; the same exposure must give the same picture"
              % (other, d))
    bright, dark = mean_level(images["ev12"]), mean_level(images["ev14"])
    print("mean 8-bit level: EV100 12 %.1f, EV100 14 %.1f" % (bright, dark))
    check(bright > dark + 20.0, "two stops more exposure did not brighten the picture (%.1f vs %.1f)" % (bright, dark))
    print("OK: exposure")


def case_cloud_volume(env):
    """A cloud ellipsoid added to a preset with a sparse cloud layer: it sits in
    the layer above the camera's pivot; moved 9 km ahead (in view of the
    default camera), coverage 1 inside it makes the sky cloudier than the
    layer's own coverage there; the gizmo moves it, F frames it, undo removes it."""
    with open(os.path.join(env.source, "presets", "clear_summer_day.json")) as f:
        preset = json.load(f)
    preset["clouds"]["coverage"] = 0.2
    preset["tracks"] = [t for t in preset.get("tracks", []) if not t.get("param", "").startswith("clouds.")]
    fixture = env.path("sparse_clouds.json")
    with open(fixture, "w") as f:
        json.dump(preset, f, indent=1)
    clear, before, after = env.path("clear.png"), env.path("before.png"), env.path("after.png")
    # Cloud marching on llvmpipe is slow: a quarter-resolution viewport and two screenshots.
    p = env.run(env.script("cloud_volume.txt", """
open {fixture}
resolution_scale 0.25
time 12
screenshot {clear}
add_cloud_volume ellipsoid
expect_cloud_volumes 1
expect_selected cloud_volume 0
expect_param cloud_volume[0].half_extents_m 3000 900 3000 0
set cloud_volume[0].position_m 0 2300 -9000
set cloud_volume[0].coverage 0.2
screenshot {before}
set cloud_volume[0].coverage 1
expect_param cloud_volume[0].coverage 1 0
screenshot {after}
gizmo_drag translate x 60 0 3
print cloud_volume[0].position_m
frame
print_camera
expect_undo 5
undo
undo
undo
undo
undo
expect_cloud_volumes 0
expect_clean
redo
expect_cloud_volumes 1
view clouds off
view clouds on
view shadows off
view shadows on
view fog volumetric
view fog analytic
view fog preset
quit
""".format(fixture=fixture, clear=clear, before=before, after=after)))
    added = re.search(r"added cloud volume 0 at (\S+) (\S+) (\S+)", p.stdout)
    check(added, "no 'added cloud volume' line")
    start = [float(added.group(i)) for i in (1, 2, 3)]
    # The layer at 12:00: bottom 1400 m, 1800 m thick (the fixture has no cloud tracks).
    check(abs(start[1] - (1400 + 900)) < 1e-9, "the cloud volume is not centred in the layer: %s" % start)
    moved = re.search(r"cloud_volume\[0\]\.position_m = (\S+) (\S+) (\S+)", p.stdout)
    check(moved, "no position printed after the gizmo drag")
    end = [float(moved.group(i)) for i in (1, 2, 3)]
    print("cloud volume: added at %s, after the drag %s" % (start, end))
    check(end[0] - start[0] > 10.0, "the gizmo drag along +x did not move the cloud volume along +x")
    check(abs(end[1] - start[1]) < 1e-9 and abs(end[2] + 9000) < 1e-9, "an x drag changed y or z")
    camera = re.search(r"camera (\{.*\})", p.stdout)
    check(camera, "no camera printed")
    target = json.loads(camera.group(1))["target_m"]
    check(all(abs(a - b) < 1e-6 for a, b in zip(target, end)), "F did not frame the cloud volume: %s" % target)

    m = re.search(r"selection_bounds (\S+) (\S+) (\S+) (\S+)", p.stdout)
    check(m, "no selection bounds printed for the cloud volume")
    x0, y0, x1, y1 = [float(m.group(i)) for i in (1, 2, 3, 4)]
    w0, h0, bpp, a = read_png(before)
    w1, h1, _, b = read_png(after)
    _, _, _, c = read_png(clear)
    check((w0, h0) == (w1, h1), "screenshots of different sizes")
    # Inside the volume the coverage is mix(layer, volume, w): the layer's own coverage changes nothing.
    same = max(abs(a[y][i] - c[y][i]) for y in range(h0) for i in range(w0 * bpp) if i % bpp < 3)
    check(same <= 1, "a cloud volume with the layer's coverage changed the picture (by up to %d levels)" % same)
    total = 0.0
    changed = 0
    for y in range(h0):
        for x in range(w0):
            d = sum(abs(a[y][x * bpp + c] - b[y][x * bpp + c]) for c in range(3)) / 3.0
            total += d
            changed += d > 8.0
    mean = total / (w0 * h0)
    print("mean |difference| %.2f (8-bit levels), %d of %d px changed by more than 8; volume bounds %s" %
          (mean, changed, w0 * h0, (x0, y0, x1, y1)))
    check(changed > w0 * h0 // 50, "coverage 1 in the cloud volume did not change the sky (%d px)" % changed)
    print("OK: cloud_volume")


def case_errors(env):
    """A bad preset shows the loader's errors and changes nothing; a script error
    names its line; without a display the editor says so and exits 2."""
    bad = os.path.join(env.source, "tests", "data", "presets", "out_of_range.json")
    p = env.run(env.script("bad.txt", """
set fog.falloff_per_m 0.07
open_expect_error {bad}
expect_dirty
expect_param fog.falloff_per_m 0.07 0
quit
""".format(bad=bad)))
    check(re.search(r"out_of_range\.json:\d+:\d+: /", p.stdout), "the load errors lack file:line:col: /pointer")
    # Dropping a broken preset over unsaved work says why at once, without
    # asking to save or discard first.
    p = env.run(env.script("drop_bad.txt", """
set fog.falloff_per_m 0.07
drop {bad}
wait_frames 2
expect_no_prompt
expect_dirty
expect_param fog.falloff_per_m 0.07 0
quit
""".format(bad=bad)))
    check("Cannot open" in p.stderr and "out_of_range.json" in p.stderr,
          "dropping a broken preset did not say why:\n" + p.stderr[-2000:])

    # The date: a real one is set and saved; an impossible one is refused with
    # the loader's reason and changes nothing.
    dated = env.path("dated.json")
    env.run(env.script("date.txt", """
new
set location.date 2026-03-21
place new york
save {dated}
quit
""".format(dated=dated)))
    with open(dated) as f:
        where = json.load(f)["location"]
    check(where["date"] == "2026-03-21", "the date was not saved")
    check((where["latitude_deg"], where["longitude_deg"], where["utc_offset_h"]) == (40.71, -74.01, -5),
          "the city list's New York was not set: %r" % where)
    p = env.run(env.script("bad_place.txt", "new\nplace Atlantis\n"), expect_rc=1)
    check('"Atlantis" is not in the city list' in p.stderr, "an unknown city is not refused:\n" + p.stderr[-2000:])
    p = env.run(env.script("bad_date.txt", "new\nset location.date 2026-02-30\n"), expect_rc=1)
    check("must be a calendar date" in p.stderr and "2026-02-30" in p.stderr,
          "an impossible date is not refused with the reason:\n" + p.stderr[-2000:])

    # Changing the resolution scale re-creates the viewport's textures without a GL error.
    p = env.run(env.script("resolution.txt", "wait_frames 2\nresolution_scale 0.75\nwait_frames 2\n"
                                             "resolution_scale 1\nwait_frames 2\nresolution_scale 0.5\nwait_frames 2\nquit\n"))
    check("GL error" not in p.stderr, "a resolution change raised a GL error:\n" + p.stderr[-1500:])

    script = env.script("broken.txt", "new\nset fog.density_per_m 0.01\nfrobnicate\n")
    p = env.run(script, expect_rc=1)
    check("broken.txt:3: unknown command" in p.stderr, "the script error does not name line 3")

    e = env.env()
    e.pop("DISPLAY", None)
    e.pop("WAYLAND_DISPLAY", None)
    p = subprocess.run([env.editor], env=e, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
    check(p.returncode == 2, "without a display the exit code is %d, not 2" % p.returncode)
    check("no display" in p.stderr and "aerial render" in p.stderr and "aerial day" in p.stderr,
          "the no-display message does not point to the CLI:\n" + p.stderr)
    print("OK: errors")


def case_prompts(env):
    """Unsaved changes are never lost silently: New, Open, a dropped preset and
    closing the window ask first (Save / Discard / Cancel; Save on an untitled
    preset goes through the Save As dialog, then carries on); the title shows
    the file and `*`."""
    saved = env.path("prompts.json")
    stormy = os.path.join(env.source, "presets", "stormy_night.json")
    env.run(env.script("prompts.txt", """
expect_title "Untitled - Aerial"
set fog.falloff_per_m 0.03
expect_title "Untitled* - Aerial"
request_new
wait_frames 1
expect_prompt
answer cancel
wait_frames 1
expect_no_prompt
expect_param fog.falloff_per_m 0.03 0
save {saved}
expect_title "prompts.json - Aerial"
request_new
expect_no_prompt
open {saved}
set fog.falloff_per_m 0.04
drop {stormy}
wait_frames 2
expect_prompt
answer save
wait_frames 2
expect_no_prompt
expect_clean
expect_title "stormy_night.json - Aerial"
new
expect_title "Untitled - Aerial"
set fog.falloff_per_m 0.06
request_open {stormy}
wait_frames 1
expect_prompt
answer save
wait_frames 1
dialog_submit {saved_as}
wait_frames 3
expect_no_prompt
expect_title "stormy_night.json - Aerial"
set fog.falloff_per_m 0.05
close_window
wait_frames 2
expect_prompt
answer discard
wait_frames 3
expect_param fog.falloff_per_m 999 0
""".format(saved=saved, stormy=stormy, saved_as=env.path("saved_as"))))
    preset = load_json(saved)
    check(preset["fog"]["falloff_per_m"] == 0.04, "Save in the prompt did not save before opening the dropped file")
    check(load_json(env.path("saved_as.json"))["fog"]["falloff_per_m"] == 0.06,
          "Save on an untitled preset did not go through Save As (.json appended) before opening")
    with open(stormy) as f:
        check(json.load(f)["fog"]["falloff_per_m"] == 0.006, "the shipped preset was modified")
    print("OK: prompts")


def case_session(env):
    """The viewport camera (a right-drag orbit) is kept in the session file and
    restored on the next start; it never goes into the preset."""
    saved = env.path("session_preset.json")
    p = env.run(env.script("orbit.txt", """
print_camera
orbit 120 -40 8
print_camera
save {saved}
quit
""".format(saved=saved)))
    cams = re.findall(r"^camera (\{.*\})$", p.stdout, re.M)
    check(len(cams) == 2, "cameras not printed")
    before, after = json.loads(cams[0]), json.loads(cams[1])
    check(abs(after["yaw_rad"] - before["yaw_rad"]) > 0.1, "the orbit did not turn the camera: %s -> %s" % (before, after))
    check(after["target_m"] == before["target_m"], "an orbit moved the pivot")
    session = load_json(os.path.join(env.config, "session.json"))
    check(session["camera"] == after, "session.json holds %s, not the camera %s" % (session.get("camera"), after))
    check("camera" not in load_json(saved), "the camera leaked into the preset")
    p = env.run(env.script("restore.txt", "print_camera\nquit\n"))
    restored = json.loads(re.findall(r"^camera (\{.*\})$", p.stdout, re.M)[0])
    check(restored == after, "the camera was not restored: %s, want %s" % (restored, after))
    # A preset's view: the preset opens there (over the session's camera); an orbit, then
    # preset_view (Home) goes back; set_preset_view makes the camera the view, and Save writes it.
    with open(os.path.join(env.source, "presets", "clear_summer_day.json")) as f:
        doc = json.load(f)
    doc["view"] = {"eye_m": [-60.0, 62.5, 70.0], "target_m": [5.0, 18.0, -90.0], "fov_deg": 45.0}
    framed, reframed = env.path("framed.json"), env.path("reframed.json")
    with open(framed, "w") as f:
        json.dump(doc, f)
    p = env.run(env.script("view.txt", """
open {framed}
print_camera
orbit 120 -40 8
preset_view
print_camera
orbit 120 -40 8
set_preset_view
print_camera
save {reframed}
quit
""".format(framed=framed, reframed=reframed)))
    cams = [json.loads(c) for c in re.findall(r"^camera (\{.*\})$", p.stdout, re.M)]
    check(len(cams) == 3, "cameras not printed: %s" % p.stdout)
    opened, back, moved = cams

    def eye_of(c):
        yaw, pitch, d = c["yaw_rad"], c["pitch_rad"], c["distance_m"]
        forward = [math.cos(pitch) * math.sin(yaw), math.sin(pitch), -math.cos(pitch) * math.cos(yaw)]
        return [t - d * f for t, f in zip(c["target_m"], forward)]

    for c, what in ((opened, "on opening"), (back, "after preset_view")):
        check(c["target_m"] == doc["view"]["target_m"] and c["vertical_fov_deg"] == 45.0 and
              max(abs(a - b) for a, b in zip(eye_of(c), doc["view"]["eye_m"])) < 1e-6,
              "the camera %s is %s, not the preset's view %s" % (what, c, doc["view"]))
    view = load_json(reframed)["view"]
    check(view["target_m"] == moved["target_m"] and max(abs(a - b) for a, b in zip(view["eye_m"], eye_of(moved))) < 1e-6,
          "the saved view %s is not the camera %s" % (view, moved))
    # Room for the picture: Maximize viewport gives it the window's width and
    # the timeline's height, Game view hides the helpers; both are kept.
    p = env.run(env.script("layout.txt", """
wait_frames 2
print_viewport
maximize_viewport on
game_view on
wait_frames 2
print_viewport
quit
"""))
    sizes = [tuple(map(int, m)) for m in re.findall(r"^viewport (\d+)x(\d+)$", p.stdout, re.M)]
    check(len(sizes) == 2, "print_viewport printed %s" % sizes)
    check(sizes[1][0] == 640 and sizes[1][0] > sizes[0][0] and sizes[1][1] > sizes[0][1],
          "maximizing did not give the viewport the window: %s -> %s" % (sizes[0], sizes[1]))
    layout = load_json(os.path.join(env.config, "session.json"))["layout"]
    check(layout["maximized"] and layout["game_view"], "the layout was not kept: %s" % layout)
    p = env.run(env.script("layout_back.txt", "wait_frames 2\nprint_viewport\nmaximize_viewport off\ngame_view off\nquit\n"))
    check(re.search(r"^viewport 640x", p.stdout, re.M), "the maximized layout was not restored:\n" + p.stdout)
    # Panels collapse in place: the viewport takes their room, and the
    # collapsed layout is kept for the next start.
    p = env.run(env.script("collapse.txt", """
wait_frames 2
print_viewport
collapse outliner on
collapse inspector on
collapse timeline on
wait_frames 3
print_viewport
quit
"""))
    sizes = [tuple(map(int, m)) for m in re.findall(r"^viewport (\d+)x(\d+)$", p.stdout, re.M)]
    check(len(sizes) == 2, "print_viewport printed %s" % sizes)
    check(560 <= sizes[1][0] < 640 and sizes[1][0] > sizes[0][0] + 100 and sizes[1][1] > sizes[0][1] + 40,
          "collapsing did not give the viewport the room: %s -> %s" % (sizes[0], sizes[1]))
    layout = load_json(os.path.join(env.config, "session.json"))["layout"]
    check(layout["outliner_collapsed"] and layout["inspector_collapsed"] and layout["timeline_collapsed"],
          "the collapsed layout was not kept: %s" % layout)
    check(layout["help_seen"] is False, "a scripted run marked the getting-started sheet as seen")
    p = env.run(env.script("collapse_back.txt", "wait_frames 2\nprint_viewport\nquit\n"))
    check(re.search(r"^viewport %dx%d$" % sizes[1], p.stdout, re.M), "the collapsed layout was not restored:\n" + p.stdout)
    print("OK: session")


def case_autokey(env):
    """Auto-key off (the default): an edit of an animated parameter away from its
    keys waits as an unkeyed change (shown, not saved) until key_pending or
    revert_pending; with auto-key on it keys at once; a value outside the valid
    range is clamped and the status bar says so."""
    first, second, third = env.path("autokey_1.json"), env.path("autokey_2.json"), env.path("autokey_3.json")
    env.run(env.script("autokey.txt", """
new
time 6
set fog.density_per_m 0.01
key fog.density_per_m
time 12
set fog.density_per_m 0.002
key fog.density_per_m
time 9
set fog.density_per_m 0.02
expect_pending 1
expect_param fog.density_per_m 0.02 1e-12
save {first}
expect_status unkeyed
key_pending fog.density_per_m
expect_pending 0
expect_param fog.density_per_m 0.02 1e-12
time 15
set fog.density_per_m 0.5
expect_pending 1
revert_pending
expect_pending 0
save {second}
autokey on
time 18
set fog.density_per_m 0.004
expect_pending 0
set fog.falloff_per_m -0.05
expect_status Fog height falloff clamped to 0 (valid 0..10 1/m)
expect_param fog.falloff_per_m 0 0
time 8
set fog.falloff_per_m 0.05
key fog.falloff_per_m
time 10
set fog.falloff_per_m 0.1
wrap fog.falloff_per_m off
time 3
expect_param fog.falloff_per_m 0.05 1e-12
time 23
expect_param fog.falloff_per_m 0.1 1e-12
save {third}
quit
""".format(first=first, second=second, third=third)))
    t1 = track(load_json(first), "fog.density_per_m")
    check(key_at(t1, 9.0) is None, "the unkeyed change was saved as a key: %s" % t1["keys"])
    t2 = track(load_json(second), "fog.density_per_m")
    check(key_at(t2, 9.0) is not None and key_value(key_at(t2, 9.0)) == 0.02, "key_pending did not key 0.02 at 09:00")
    check(key_at(t2, 15.0) is None, "the reverted change was keyed")
    t3 = track(load_json(third), "fog.density_per_m")
    check(key_at(t3, 18.0) is not None and key_value(key_at(t3, 18.0)) == 0.004, "auto-key on did not key at 18:00")
    falloff = track(load_json(third), "fog.falloff_per_m")
    check(falloff is not None and falloff.get("wrap") is False,
          "the held track was not saved with \"wrap\": false: %s" % falloff)
    print("OK: autokey")


def case_curves(env):
    """The timeline's curve view: two curves shown, a box selection of two keys
    moved in time and value (snapped, one undo step "Move 2 keys"), one key
    moved in time alone (snapped to the quarter hour) and made flat, zoom,
    pan and fit; the saved keys are what the moves made, and undo brings
    back the keys as they were."""
    before, after, undone = env.path("curves_before.json"), env.path("curves_after.json"), env.path("curves_undone.json")
    shot = env.path("curves_window.png")
    p = env.run(env.script("curves.txt", """
new
time 6
set fog.density_per_m 0.01
key fog.density_per_m
time 8
set fog.density_per_m 0.02
key fog.density_per_m
time 10
set fog.density_per_m 0
key fog.density_per_m
time 12
set fog.falloff_per_m 0.05
key fog.falloff_per_m
time 18
set fog.falloff_per_m 0.1
key fog.falloff_per_m
curve fog.density_per_m on
curve fog.falloff_per_m on
print_curves
save {before}
curve_box 5.5 8.5
curve_move 1 0.0833333333333333
curve_select none
curve_select fog.falloff_per_m 12
curve_move 0.3 0
curve_flat on
curve_zoom 2 6
print_curves
curve_pan 100
print_curves
timeline_fit
print_curves
window_screenshot {shot}
save {after}
undo
undo
undo
undo
save {undone}
quit
""".format(before=before, after=after, undone=undone, shot=shot)))
    out = p.stdout
    check("curves view 0 24 shown 2 selected 0" in out, "two curves were not shown on the whole day")
    check("curve_box: 2 points, 2 keys" in out, "the box did not select the 06:00 and 08:00 keys")
    check("curve_move: Move 2 keys by 1 h" in out, "the two keys did not move by an hour")
    check("curve_move: Move key by 0.25 h" in out, "12:18 did not snap to 12:15")
    check("curves view 3 15 " in out, "zooming in twice around 06:00 did not show 03:00-15:00")
    check("curves view 24 36 " in out, "panning did not stop at the view's margin")
    check(out.rstrip().count("curves view 0 24 ") >= 2, "timeline_fit did not show the whole day again")
    # The built-in preset has density keys of its own; the 06:00 and 08:00 keys moved by an
    # hour and up by a twelfth of the curve's height (its keys' range, 10 % padded each side).
    was = track(load_json(before), "fog.density_per_m")["keys"]
    span = 1.2 * (max(key_value(k) for k in was) - min(key_value(k) for k in was))
    want = [(k["time_h"] + 1.0, key_value(k) + span / 12.0) if k["time_h"] in (6.0, 8.0)
            else (k["time_h"], key_value(k)) for k in was]
    density = track(load_json(after), "fog.density_per_m")["keys"]
    got = [(k["time_h"], key_value(k)) for k in density]
    check(len(got) == len(want) and all(g[0] == w[0] and abs(g[1] - w[1]) < 1e-12 for g, w in zip(got, want)),
          "density keys %s, want %s" % (got, want))
    falloff = track(load_json(after), "fog.falloff_per_m")["keys"]
    moved = [k for k in falloff if k["time_h"] == 12.25]
    check(len(moved) == 1 and moved[0].get("flat") is True, "no flat key at 12:15: %s" % falloff)
    check(all("flat" not in k for k in falloff if k["time_h"] != 12.25), "other keys flat: %s" % falloff)
    check(not any(k["time_h"] == 12.0 for k in falloff), "the 12:00 key stayed: %s" % falloff)
    # Four undos: Save As renamed the preset after curves_after.json (a step), then the flat
    # tangent, the falloff key's move and the two density keys' move, one step each.
    check(load_json(undone)["tracks"] == load_json(before)["tracks"], "undo did not restore the keys")
    width, height, _, _ = read_png(shot)
    check(width > 0 and height > 0, "no window screenshot")
    # The curves shown are view state: not in the preset, remembered in the session.
    check("curves" not in json.dumps(load_json(after)), "the preset holds view state")
    session = load_json(os.path.join(env.config, "session.json"))
    check(session.get("curves") == ["fog.density_per_m", "fog.falloff_per_m"],
          "the session did not remember the curves shown: %s" % session.get("curves"))
    print("OK: curves")


def case_curves_mouse(env):
    """The curve view under ImGui's mouse (1280x720, where the curves have room):
    a vertical drag on a key changes its value and not its time; a horizontal
    drag moves it in time, snapped; a box drag on empty curve area selects the
    keys inside it and a drag on one of them moves them all (Shift: unsnapped),
    each drag one undo step; a click on empty curve area sets the time."""
    names = ["mouse_%d.json" % i for i in range(5)]
    paths = [env.path(n) for n in names]
    p = env.run(env.script("curves_mouse.txt", """
new
time 6
set fog.density_per_m 0.01
key fog.density_per_m
time 8
set fog.density_per_m 0.02
key fog.density_per_m
time 10
set fog.density_per_m 0.005
key fog.density_per_m
curve fog.density_per_m on
wait_frames 2
save {p0}
curve_drag fog.density_per_m 8 0 -20
save {p1}
curve_drag fog.density_per_m 6 40 0
save {p2}
curve_drag_box 5.5 -0.05 11 1.05
print_curves
curve_drag fog.density_per_m 10 30 0 shift
save {p3}
undo
undo
save {p4}
curve_drag_box 15 0.5 15 0.5
print_curves
curve_wheel 6 2
print_curves
curve_pan_drag 12 100
print_curves
quit
""".format(p0=paths[0], p1=paths[1], p2=paths[2], p3=paths[3], p4=paths[4])), window="1280x720")
    keys = [{k["time_h"]: key_value(k) for k in track(load_json(path), "fog.density_per_m")["keys"]} for path in paths]
    before, vertical, horizontal, boxed, undone = keys
    # Vertical: the 08:00 key went up, no key changed its time.
    check(sorted(vertical) == sorted(before), "a vertical drag moved keys in time: %s -> %s" % (before, vertical))
    check(vertical[8.0] > before[8.0], "a vertical drag up did not raise the 08:00 key: %s" % vertical)
    check(all(vertical[t] == before[t] for t in before if t != 8.0), "other keys changed: %s" % vertical)
    # Horizontal: the 06:00 key moved later onto a quarter hour (or another key's time), value kept.
    moved = sorted(set(horizontal) - set(vertical))
    check(len(moved) == 1 and 6.0 not in horizontal, "the 06:00 key did not move in time: %s" % horizontal)
    check(6.0 < moved[0] < 8.0 and horizontal[moved[0]] == vertical[6.0], "06:00 key now %s" % moved)
    all_keys = set()
    for t in load_json(paths[1])["tracks"]:
        all_keys.update(k["time_h"] for k in t["keys"])
    check(moved[0] * 4 == round(moved[0] * 4) or moved[0] in all_keys, "%s is not snapped" % moved[0])
    check("curves view 0 24 shown 1 selected 3" in p.stdout, "the box did not select the three keys")
    # The three boxed keys moved together, unsnapped (Shift), by the same time.
    shifted = sorted(set(boxed) - set(horizontal))
    check(len(shifted) == 3, "the box's keys did not all move: %s -> %s" % (horizontal, boxed))
    old = sorted(t for t in horizontal if 5.5 <= t <= 11.0)
    deltas = [b - a for a, b in zip(old, shifted)]
    check(max(deltas) - min(deltas) < 1e-9 and deltas[0] > 0.3, "uneven or no shift: %s" % deltas)
    # Two undos: the preset's name (it follows Save As to the next file, a step of its own),
    # then the whole box drag, one step: the keys are as the horizontal drag left them.
    check(undone == horizontal, "undo did not bring back the keys before the box drag: %s" % undone)
    views = [line.split() for line in p.stdout.splitlines() if line.startswith("curves view")]
    # Two wheel steps up at 06:00: 1.25^2 times in, 06:00 where it was (a quarter across).
    start, end = float(views[-2][2]), float(views[-2][3])
    check(abs((end - start) - 24.0 / 1.5625) < 0.01 and abs((6.0 - start) / (end - start) - 0.25) < 0.01,
          "the wheel did not zoom in around 06:00: %s" % views[-2])
    # A middle drag 100 px to the right shows earlier hours.
    check(float(views[-1][2]) < start - 0.5 and abs(float(views[-1][3]) - float(views[-1][2]) - (end - start)) < 1e-3,
          "the middle drag did not pan: %s" % views[-1])
    last = p.stdout.split("curves view")[-3]
    check(" selected 0 " in last, "a click on empty curve area kept the selection: %s" % last)
    clicked = float(last.split(" time ")[1].split()[0])
    check(abs(clicked - 15.0) < 0.05, "a click on empty curve area at 15:00 set the time to %s" % clicked)
    print("OK: curves_mouse")


def printed_blocks(stdout, command):
    """The lines each run of a printing script command wrote: one list per run, in order."""
    blocks, current = [], None
    for line in stdout.splitlines():
        if re.match(r"script:\d+: ", line):
            current = [] if line.split(": ", 1)[1] == command else None
            if current is not None:
                blocks.append(current)
        elif current is not None:
            current.append(line)
    return blocks


def sun_events(lines):
    """print_sun's lines as {event: hours}."""
    return {w[1]: float(w[2]) for w in (line.split() for line in lines) if len(w) == 3 and w[0] == "sun"}


def printed_keys(lines):
    """print_keys' lines as [(hours, text)]."""
    return [(float(w[2]), w[3]) for w in (line.split(" ", 3) for line in lines) if len(w) == 4 and w[0] == "key"]


def case_sun_anchor(env):
    """Keys that follow the sun: a shipped preset's fog key at 19:30 is anchored to
    sunset where it stands (the curve does not move), shifted by a typed +0:20
    (one undo step each), saved as {"anchor": "sunset", "offset_h": ...} with no
    time_h; a new date moves it with the sunset; a snapped drag of it lands on a
    whole 5 minutes after the sunset."""
    preset = os.path.join(env.source, "presets", "hazy_sunset.json")
    shifted, dated, snapped = env.path("anchor_shifted.json"), env.path("anchor_dated.json"), env.path(
        "anchor_snapped.json")
    stepped = env.path("anchor_stepped.json")
    shot = env.path("anchor_window.png")
    p = env.run(env.script("sun_anchor.txt", """
open {preset}
print_sun
curve fog.density_per_m on
curve_select fog.density_per_m 19:30
curve_anchor sunset
expect_undo 1
print_keys fog.density_per_m
curve_shift +0:20
expect_undo 2
print_keys fog.density_per_m
undo
print_keys fog.density_per_m
redo
wait_frames 2
window_screenshot {shot}
save {shifted}
set location.date 2026-12-21
print_sun
print_keys fog.density_per_m
save {dated}
curve_snap 5
curve_move 0.1 0
save {snapped}
curve_interp step
save {stepped}
quit
""".format(preset=preset, shifted=shifted, dated=dated, snapped=snapped, stepped=stepped, shot=shot)),
                window="1280x720")
    out = p.stdout
    suns = [sun_events(b) for b in printed_blocks(out, "print_sun")]
    keys = [printed_keys(b) for b in printed_blocks(out, "print_keys")]
    check(len(suns) == 2 and "sunset" in suns[0] and "sunset" in suns[1], "print_sun printed no sunset:\n" + out)
    check(len(keys) == 4, "print_keys ran %d times, not 4" % len(keys))
    sunset, winter_sunset = suns[0]["sunset"], suns[1]["sunset"]
    check(18.5 < sunset < 19.5, "the preset's sunset at %s h is not a mid-August one at 38 N" % sunset)
    check("curve_anchor: Anchor key to sunset (1 changed)" in out, "the key was not anchored:\n" + out)
    check("curve_shift: Shift key by 0.333333 h" in out, "the key was not shifted by 0:20:\n" + out)

    original = track(load_json(preset), "fog.density_per_m")["keys"]
    index = [i for i, k in enumerate(original) if abs(k.get("time_h", -1) - 19.5) < 1e-9]
    check(len(index) == 1, "the shipped preset has no fog key at 19:30: %s" % original)
    index = index[0]
    # Anchored where it stands: still 19:30, read as "sunset + H:MM (19:30)"; the other keys as they were.
    anchored, moved, undone = keys[0], keys[1], keys[2]
    check(abs(anchored[index][0] - 19.5) < 1e-9 and re.fullmatch(r"sunset \+ 0:\d\d(:\d\d)? \(19:30\)",
                                                                  anchored[index][1]) is not None,
          "the anchored key reads %s" % (anchored[index],))
    check([t for i, (t, _) in enumerate(anchored) if i != index] ==
          [k["time_h"] for i, k in enumerate(original) if i != index], "other keys moved: %s" % anchored)
    check(abs(moved[index][0] - (19.5 + 1.0 / 3.0)) < 1e-9 and moved[index][1].endswith("(19:50)"),
          "the shifted key reads %s" % (moved[index],))
    check(undone == anchored, "undo did not take back the shift alone: %s" % undone)

    # The file: anchor and offset in place of time_h, the offset from the sunset plus 0:20.
    key = track(load_json(shifted), "fog.density_per_m")["keys"][index]
    check(key.get("anchor") == "sunset" and "time_h" not in key, "saved as %s" % key)
    offset = 19.5 + 1.0 / 3.0 - sunset
    check(abs(key["offset_h"] - offset) < 1e-6, "offset_h %s, want %s" % (key["offset_h"], offset))
    check(key_value(key) == key_value(original[index]), "the value changed: %s" % key)
    fixed = [k for k in track(load_json(shifted), "fog.density_per_m")["keys"] if "anchor" not in k]
    check([k["time_h"] for k in fixed] == [k["time_h"] for i, k in enumerate(original) if i != index],
          "the other keys changed: %s" % fixed)

    # A winter date: the sunset is hours earlier and the key goes with it, its offset kept.
    check(winter_sunset < sunset - 1.5, "the December sunset %s is not earlier than %s" % (winter_sunset, sunset))
    winter = keys[3]
    anchored_now = [t for t, text in winter if text.startswith("sunset ")]
    check(len(anchored_now) == 1 and abs(anchored_now[0] - (winter_sunset + key["offset_h"])) < 1e-6,
          "the key did not follow the sunset to %s: %s" % (winter_sunset + key["offset_h"], winter))
    saved = load_json(dated)
    check(saved["location"]["date"] == "2026-12-21", "the date was not saved: %s" % saved["location"])
    winter_keys = [k for k in track(saved, "fog.density_per_m")["keys"] if "anchor" in k]
    check(len(winter_keys) == 1 and winter_keys[0]["anchor"] == "sunset" and "time_h" not in winter_keys[0]
          and abs(winter_keys[0]["offset_h"] - key["offset_h"]) < 1e-12,
          "the dated file's key: %s" % winter_keys)

    # Snap 5 min: a drag of the anchored key lands on a whole 5 minutes after the sunset.
    snapped_keys = [k for k in track(load_json(snapped), "fog.density_per_m")["keys"] if "anchor" in k]
    check(len(snapped_keys) == 1, "the anchored key was lost: %s" % snapped_keys)
    steps = snapped_keys[0]["offset_h"] * 12.0
    check(abs(steps - round(steps)) < 1e-9 and snapped_keys[0]["offset_h"] != key["offset_h"],
          "the dragged key's offset %s h is not a whole 5 minutes" % snapped_keys[0]["offset_h"])
    # The key's own interpolation (the key menu's Interpolation after > Step): saved on that key only.
    check("curve_interp: step (1 changed)" in out, "the key's interpolation was not set:\n" + out)
    stepped_keys = track(load_json(stepped), "fog.density_per_m")["keys"]
    marked = [k for k in stepped_keys if "interpolation" in k]
    check(len(marked) == 1 and marked[0].get("anchor") == "sunset" and marked[0]["interpolation"] == "step",
          "the saved keys' interpolations: %s" % stepped_keys)
    width, height, _, _ = read_png(shot)
    check(width == 1280 and height == 720, "window screenshot %dx%d" % (width, height))
    print("OK: sun_anchor")


def near_duplicate_keys(preset):
    """Pairs of keys of one track under a minute apart, as (param, t0, t1): the keys with a time_h."""
    found = []
    for t in preset.get("tracks", []):
        times = sorted(k["time_h"] for k in t["keys"] if "time_h" in k)
        found += [(t["param"], a, b) for a, b in zip(times, times[1:]) if b - a < 1.0 / 60.0]
    return found


def clock_hms(hours):
    """hours as HH:MM:SS, rounded to the second."""
    seconds = int(round(hours * 3600.0))
    return "%02d:%02d:%02d" % (seconds // 3600, seconds // 60 % 60, seconds % 60)


def case_curve_edit(env):
    """A precise curve editor (1280x720). Where Valley fog's density key lies 5 minutes
    (4 px) from the inspector's fog density key, a mouse drag pressed on Valley fog's
    key moves the fog density key and leaves Valley fog alone; the legend names the
    volume ("Valley fog density"), its colour stays when another curve is shown. The
    shipped preset's 19:30 fog key typed to 19:52:00 and 0.0031 (one undo step each)
    saves exactly that key changed, with no near-duplicate keys; the exposure key
    that follows the sunset typed a quarter hour later keeps its anchor, its offset
    changed."""
    source = load_json(os.path.join(env.source, "presets", "hazy_sunset.json"))
    overlap = json.loads(json.dumps(source))
    overlap["volumes"][0]["name"] = "Valley fog"
    volume_id = overlap["volumes"][0]["id"]
    # Both curves drawn from their keys' range: equal heights, the volume's middle key 5 min later.
    for t in overlap["tracks"]:
        if t["param"] == "fog.density_per_m" and "volume" not in t:
            t["keys"] = [{"time_h": 6.0, "value": 0.001}, {"time_h": 8.0, "value": 0.002},
                         {"time_h": 12.0, "value": 0.0015}]
        if t.get("volume") == volume_id and t["param"] == "density_per_m":
            t["keys"] = [{"time_h": 6.0, "value": 0.01}, {"time_h": 8.0 + 5.0 / 60.0, "value": 0.02},
                         {"time_h": 12.0, "value": 0.015}]
    opened = env.path("overlap.json")
    with open(opened, "w") as f:
        json.dump(overlap, f, indent=2)
    picked = env.path("picked.json")
    p = env.run(env.script("curve_pick.txt", """
open {opened}
inspect fog.density_per_m
curve volume[0].density_per_m on
wait_frames 2
print_legend
curve_drag volume[0].density_per_m 8:05 0 -30
save {picked}
curve clouds.coverage on
print_legend
print_sun
print_keys exposure.compensation_ev
quit
""".format(opened=opened, picked=picked)), window="1280x720")
    out = p.stdout
    legends = printed_blocks(out, "print_legend")
    check(len(legends) == 2, "print_legend ran %d times, not 2:\n%s" % (len(legends), out))
    names = [dict((line.split()[1], (int(line.split()[2]), " ".join(line.split()[3:]))) for line in block)
             for block in legends]
    volume_key = "volume:%s:density_per_m" % volume_id
    check(names[0].get(volume_key, (0, ""))[1] == "Valley fog density",
          "the legend does not name the volume: %s" % names[0])
    check(names[0].get("fog.density_per_m", (0, ""))[1] == "Fog density", "fog density's legend: %s" % names[0])
    check(all(names[1][k][0] == names[0][k][0] for k in names[0]),
          "showing another curve recoloured one: %s -> %s" % (names[0], names[1]))
    # The drag pressed on Valley fog's key: the inspector's key (4 px away) went up, Valley fog stayed.
    saved = load_json(picked)
    fog = [(k["time_h"], key_value(k)) for k in track(saved, "fog.density_per_m")["keys"]]
    valley = [(k["time_h"], key_value(k)) for k in track(saved, "density_per_m", volume_id)["keys"]]
    check(valley == [(6.0, 0.01), (8.0 + 5.0 / 60.0, 0.02), (12.0, 0.015)],
          "the overlaid curve's key moved: %s" % valley)
    check(len(fog) == 3 and fog[0] == (6.0, 0.001) and fog[2] == (12.0, 0.0015) and fog[1][0] == 8.0
          and fog[1][1] > 0.002, "the inspector's key was not the one dragged: %s" % fog)
    sunset = sun_events(printed_blocks(out, "print_sun")[0])["sunset"]
    sunset_keys = [t for t, text in printed_keys(printed_blocks(out, "print_keys")[0]) if text.startswith("sunset ")]
    check(len(sunset_keys) == 1, "hazy_sunset has no exposure key that follows the sunset: %s" % out)

    # Typed time and value on the shipped preset; then a key that follows the sunset.
    shipped = os.path.join(env.source, "presets", "hazy_sunset.json")
    typed, anchored = env.path("typed.json"), env.path("typed_anchored.json")
    anchored_to = clock_hms(sunset_keys[0] + 0.25)  # a quarter hour later, to the second
    p = env.run(env.script("curve_type.txt", """
open {shipped}
curve fog.density_per_m on
curve_select fog.density_per_m 19:30
print_curve_fields
curve_time 19:52:00
expect_undo 1
curve_value 0.0031
expect_undo 2
print_curve_fields
save {typed}
curve_select none
curve_select exposure.compensation_ev {sunset_key}
print_curve_fields
curve_time {anchored_to}
print_curve_fields
save {anchored}
quit
""".format(shipped=shipped, typed=typed, anchored=anchored, sunset_key="%.9f" % sunset_keys[0],
           anchored_to=anchored_to)), window="1280x720")
    out = p.stdout
    fields = [line for line in out.splitlines() if line.startswith("curve_fields ")]
    check(len(fields) == 4, "print_curve_fields ran %d times, not 4:\n%s" % (len(fields), out))
    check(fields[0] == "curve_fields 19:30:00 0.0018 1/m", "the fields before: %s" % fields[0])
    check(fields[1] == "curve_fields 19:52:00 0.0031 1/m", "the fields after typing: %s" % fields[1])
    check(fields[2].startswith("curve_fields %s " % clock_hms(sunset_keys[0])),
          "the sunset key's fields: %s" % fields[2])
    check(fields[3].startswith("curve_fields %s " % anchored_to), "the sunset key typed: %s" % fields[3])
    check("curve_time: Set key time, now 19:52:00" in out, "the time was not typed:\n" + out)
    check("curve_value: Set key value (1 changed)" in out, "the value was not typed:\n" + out)

    # Exactly that key changed: the same keys elsewhere, every other track as shipped.
    before, after = load_json(shipped), load_json(typed)
    was, now = track(before, "fog.density_per_m")["keys"], track(after, "fog.density_per_m")["keys"]
    check(len(now) == len(was), "fog density has %d keys, not %d: %s" % (len(now), len(was), now))
    changed = [(a, b) for a, b in zip(was, now) if a != b]
    check(len(changed) == 1 and changed[0][0]["time_h"] == 19.5, "keys changed: %s" % changed)
    key = changed[0][1]
    check(abs(key["time_h"] - (19.0 + 52.0 / 60.0)) < 1e-9 and key_value(key) == 0.0031,
          "the typed key was saved as %s" % key)
    others = lambda preset: [t for t in preset["tracks"] if t["param"] != "fog.density_per_m" or "volume" in t]
    check(others(after) == others(before), "other tracks changed")
    check(near_duplicate_keys(after) == [], "near-duplicate keys: %s" % near_duplicate_keys(after))

    # The sunset key typed to sunset + 0:15: still follows the sunset, its offset changed, no time_h.
    exposure = track(load_json(anchored), "exposure.compensation_ev")["keys"]
    was = track(before, "exposure.compensation_ev")["keys"]
    moved = [(a, b) for a, b in zip(was, exposure) if a != b]
    check(len(exposure) == len(was) and len(moved) == 1 and moved[0][0].get("anchor") == "sunset",
          "exposure keys changed: %s" % moved)
    key = moved[0][1]
    h, m, sec = map(int, anchored_to.split(":"))
    want = h + m / 60.0 + sec / 3600.0 - sunset
    check(key.get("anchor") == "sunset" and "time_h" not in key and abs(key["offset_h"] - want) < 1e-6
          and key["value"] == moved[0][0]["value"], "the sunset key was saved as %s (offset %s)" % (key, want))
    check(near_duplicate_keys(load_json(anchored)) == [], "near-duplicate keys after the anchored edit")
    print("OK: curve_edit")


def case_placement(env):
    """A new volume rests on the scene's surface under the viewport's centre;
    Drop to ground puts a volume's bottom on the surface under it, from above
    or from below the ground alike (undoable)."""
    p = env.run(env.script("placement.txt", """
new
add_volume box
print volume[1].position_m
set volume[1].position_m 40 300 -120
drop_to_ground
print volume[1].position_m
set volume[1].position_m 40 -50 -120
drop_to_ground
print volume[1].position_m
undo
print volume[1].position_m
quit
"""))
    positions = [list(map(float, m)) for m in re.findall(r"volume\[1\]\.position_m = (\S+) (\S+) (\S+)", p.stdout)]
    check(len(positions) == 4, "positions not printed:\n" + p.stdout)
    added, dropped_from_above, dropped_from_below, undone = positions
    check(abs(dropped_from_above[1] - dropped_from_below[1]) < 1e-9,
          "dropping from above and below disagree: %s vs %s" % (dropped_from_above, dropped_from_below))
    check(-50.0 < dropped_from_above[1] < 300.0 and dropped_from_above[0] == 40.0 and dropped_from_above[2] == -120.0,
          "the drop moved it elsewhere: %s" % dropped_from_above)
    check(undone[1] == -50.0, "undo did not restore the position: %s" % undone)
    print("placement: added at %s, dropped to %s" % (added, dropped_from_above))

    # Ids: edited in place, the tracks follow; a duplicate is refused with the reason.
    saved = env.path("ids.json")
    env.run(env.script("ids.txt", """
new
add_volume box
time 8
key volume[1].density_per_m
set_id volume 1 lake_mist
save {saved}
quit
""".format(saved=saved)))
    preset = load_json(saved)
    check(preset["volumes"][1]["id"] == "lake_mist", "the id was not changed: %s" % preset["volumes"][1]["id"])
    check(any(t.get("volume") == "lake_mist" for t in preset["tracks"]), "the track did not follow the id: %s" % preset["tracks"])
    p = env.run(env.script("ids_bad.txt", "new\nadd_volume box\nset_id volume 1 %s\n" % preset["volumes"][0]["id"]),
                expect_rc=1)
    check("already has the id" in p.stderr, "a duplicate id was not refused with the reason:\n" + p.stderr[-1500:])
    # Solo and mute leave objects out of the viewport only (the preset keeps them).
    saved = env.path("solo.json")
    p = env.run(env.script("solo.txt", """
new
add_volume box
add_emitter point
wait_frames 2
print_drawn
mute volume 0
wait_frames 2
print_drawn
solo emitter 1
wait_frames 2
print_drawn
solo off
wait_frames 2
print_drawn
expect_volumes 2
save {saved}
quit
""".format(saved=saved)))
    drawn = [tuple(map(int, m)) for m in re.findall(r"^drawn (\d+) volumes (\d+) emitters$", p.stdout, re.M)]
    check(len(drawn) == 4, "print_drawn printed %s" % drawn)
    everything, muted, solo, back = drawn
    check(everything[0] == 2 and everything[1] >= 1, "not everything was drawn: %s" % (everything,))
    check(muted == (1, everything[1]), "muting volume 0 drew %s" % (muted,))
    check(solo == (0, 1), "soloing emitter 1 drew %s" % (solo,))
    check(back == everything, "solo off did not bring everything back: %s" % (back,))
    check(len(load_json(saved)["volumes"]) == 2, "mute changed the preset")
    print("OK: placement")


def case_mesh_volume(env):
    """A mesh volume from a glTF file: added on the surface, made a subtract
    volume, saved with its path relative to the preset, kept right by Save As
    into another folder (crash recovery: test_autosave.cpp); a bad mesh is
    refused with the reason and changes nothing; undo removes it."""
    cube = os.path.join(env.source, "tests", "data", "bad_inputs", "meshes", "cube.gltf")
    bad = os.path.join(env.source, "tests", "data", "bad_inputs", "meshes", "open_edge.gltf")
    first = env.path("first.json")
    os.makedirs(env.path("elsewhere"), exist_ok=True)
    second = env.path(os.path.join("elsewhere", "second.json"))
    p = env.run(env.script("mesh.txt", """
new
save {first}
add_mesh_volume {cube}
set volume[1].blend subtract
set volume[1].half_extents_m 4 3 5
expect_volumes 2
wait_frames 2
print_drawn
save {first}
save {second}
quit
""".format(first=first, second=second, cube=cube)))
    m = re.search(r'added mesh volume 1 "([^"]+)" at (\S+) (\S+) (\S+)', p.stdout)
    check(m is not None, "add_mesh_volume printed nothing:\n" + p.stdout)
    saved = load_json(first)
    v = saved["volumes"][1]
    check(v["shape"] == "mesh" and v["blend"] == "subtract", "the volume was not saved as a subtract mesh: %s" % v)
    check(not os.path.isabs(v["mesh"]), "the mesh path is not relative to the preset: %s" % v["mesh"])
    check(os.path.samefile(os.path.join(env.work, v["mesh"]), cube), "the saved path names another file: %s" % v["mesh"])
    moved = load_json(second)["volumes"][1]["mesh"]
    check(os.path.samefile(os.path.join(env.work, "elsewhere", moved), cube),
          "Save As into another folder broke the mesh path: %s" % moved)
    # Export for game travels with its meshes: meshes/<id>.gltf beside
    # preset.json, which names it, and the bake's layout.gltf lists the volume.
    out = env.path("export")
    env.run(env.script("mesh_export.txt", "open %s\nexport %s 6 32x16\nquit\n" % (first, out)))
    exported = load_json(os.path.join(out, "preset.json"))["volumes"][1]
    check(exported["mesh"] == "meshes/%s.gltf" % exported["id"] and os.path.isfile(os.path.join(out, exported["mesh"])),
          "the export does not carry the mesh: %s" % exported)
    layout = load_json(os.path.join(out, "layout.gltf"))
    check(any(n.get("name") == exported["id"] for n in layout["nodes"]), "layout.gltf lacks the mesh volume")
    # Both files open again with their meshes (the loader resolves the paths).
    for path in (first, second):
        env.run(env.script("reopen.txt", "open %s\nexpect_volumes 2\nquit\n" % path))
    # A bad mesh: refused, named, nothing added.
    p = env.run(env.script("bad_mesh.txt", "new\nadd_mesh_volume %s\n" % bad), expect_rc=1)
    check("open edge" in p.stderr and "open_edge.gltf" in p.stderr,
          "the bad mesh was not refused with its reason:\n" + p.stderr[-1500:])
    # Shift+drop of a glTF adds it as a mesh volume (a plain drop loads it as the scene).
    p = env.run(env.script("mesh_drop.txt", """
new
drop {cube} shift
wait_frames 2
expect_volumes 2
print volume[1].shape
quit
""".format(cube=cube)))  # (enums print as their number: 2 = mesh)
    check(re.search(r"volume\[1\]\.shape = 2$", p.stdout, re.M), "Shift+drop did not add a mesh volume:\n" + p.stdout)
    # Undo removes the volume in one step.
    env.run(env.script("mesh_undo.txt", """
new
add_mesh_volume {cube}
expect_volumes 2
expect_undo 1
undo
expect_volumes 1
expect_undo 0
quit
""".format(cube=cube)))
    print("OK: mesh_volume")


def case_tangents(env):
    """Tangent handles (1280x720): the selected 08:00 key's out handle dragged up
    with the mouse gives it its own unified slope (both sides, one undo step),
    saved as "tangent_in"/"tangent_out"; broken, lifting the in handle lowers
    that side's slope only; a typed slope is saved exactly; Automatic takes them away."""
    paths = [env.path("tangents_%d.json" % i) for i in range(4)]
    p = env.run(env.script("tangents.txt", """
new
time 6
set fog.density_per_m 0.01
key fog.density_per_m
time 8
set fog.density_per_m 0.02
key fog.density_per_m
time 10
set fog.density_per_m 0.005
key fog.density_per_m
curve fog.density_per_m on
curve_select fog.density_per_m 8
wait_frames 2
curve_handle_drag out 0 -20
wait_frames 2
print_tangents fog.density_per_m
undo
print_tangents fog.density_per_m
redo
save {p0}
curve_tangent_mode broken
curve_handle_drag in 0 -30
wait_frames 2
save {p1}
curve_tangent out 0.004
save {p2}
curve_tangent_mode auto
save {p3}
quit
""".format(p0=paths[0], p1=paths[1], p2=paths[2], p3=paths[3])), window="1280x720")
    check("curve_handle_drag: press at" in p.stdout, "the handle drag did not start")
    # print_tangents: "tangent INDEX TIME_H MODE IN OUT"; the 08:00 key's mode after the drag and after undo.
    printed = [[w[3] for w in (line.split() for line in block) if len(w) == 6 and abs(float(w[2]) - 8.0) < 1e-9]
               for block in printed_blocks(p.stdout, "print_tangents")]
    check(printed == [["unified"], ["auto"]], "one undo did not take the whole handle drag back: %s" % printed)
    keys = [track(load_json(path), "fog.density_per_m")["keys"] for path in paths]
    unified, broken, typed, automatic = [key_at({"keys": k}, 8.0) for k in keys]
    check(len(set(len(k) for k in keys)) == 1, "a tangent edit added or removed keys: %s" % keys)
    check(unified.get("tangent_mode") == "unified" and unified["tangent_out"] > 0.0 and
          unified["tangent_in"] == unified["tangent_out"],
          "an upward drag of the out handle did not give one rising slope: %s" % unified)
    check(unified["time_h"] == 8 and unified["value"] == 0.02, "the tangent drag moved the key: %s" % unified)
    check(broken.get("tangent_mode") == "broken" and broken["tangent_out"] == unified["tangent_out"] and
          broken["tangent_in"] < unified["tangent_in"],
          "lifting the broken in handle (the curve comes down into the key) did not lower the in slope "
          "alone: %s -> %s" % (unified, broken))
    check(typed["tangent_out"] == 0.004 and typed["tangent_in"] == broken["tangent_in"],
          "the typed out slope was not saved exactly: %s" % typed)
    check("tangent_in" not in automatic and "tangent_mode" not in automatic,
          "Automatic tangent did not take the key's own tangents away: %s" % automatic)
    print("OK: tangents")


def case_paste_keys(env):
    """Copy and paste of keys across curves: the 06:00 fog base height key and the
    08:00 falloff key copied together (Ctrl+C on a curve selection) and pasted
    at 14:00 (Ctrl+V) land at 14:00 and 16:00 on their own curves, one undo
    step; pasted at 09:59:40 each lands 20 s before a key (10:00, 12:00) and
    replaces it at that key's time (no near-duplicates)."""
    paths = [env.path("paste_%d.json" % i) for i in range(2)]
    env.run(env.script("paste.txt", """
new
time 6
set fog.base_height_m 10
key fog.base_height_m
time 10
set fog.base_height_m 50
key fog.base_height_m
time 8
set fog.falloff_per_m 0.05
key fog.falloff_per_m
time 12
set fog.falloff_per_m 0.2
key fog.falloff_per_m
curve fog.base_height_m on
curve fog.falloff_per_m on
curve_select fog.base_height_m 6
curve_select fog.falloff_per_m 8
timeline_copy_key
time 14
timeline_paste_key
print_curves
undo
expect_keys fog.base_height_m 2
expect_keys fog.falloff_per_m 2
redo
save {p0}
time 9:59:40
timeline_paste_key
save {p1}
quit
""".format(p0=paths[0], p1=paths[1])))
    first, second = load_json(paths[0]), load_json(paths[1])
    height = {k["time_h"]: key_value(k) for k in track(first, "fog.base_height_m")["keys"]}
    falloff = {k["time_h"]: key_value(k) for k in track(first, "fog.falloff_per_m")["keys"]}
    check(height == {6: 10, 10: 50, 14: 10}, "base height after the paste at 14:00: %s" % height)
    check(falloff == {8: 0.05, 12: 0.2, 16: 0.05}, "falloff after the paste at 14:00: %s" % falloff)
    falloff2 = {k["time_h"]: key_value(k) for k in track(second, "fog.falloff_per_m")["keys"]}
    check(falloff2.get(12) == 0.05 and len(falloff2) == 3,
          "a pasted key 20 s from 12:00 did not replace the 12:00 key: %s" % falloff2)
    check(not near_duplicate_keys(second), "near-duplicate keys: %s" % near_duplicate_keys(second))
    height2 = {k["time_h"]: key_value(k) for k in track(second, "fog.base_height_m")["keys"]}
    check(height2 == {6: 10, 10: 10, 14: 10}, "a pasted key 20 s from 10:00 did not replace the 10:00 key: %s" % height2)
    print("OK: paste_keys")


def case_key_paths(env):
    """The gizmo and auto-key edit keys at their own time: a volume's position
    keyed at 12:00 and dragged with the gizmo at 12:00:20, and the fog base
    height keyed at 06:00 and set with auto-key on at 06:00:20; saved, reopened and
    saved again, each track keeps one key at its time with the new value, and
    no two keys of a track are under a minute apart."""
    saved, again = env.path("key_paths.json"), env.path("key_paths_again.json")
    p = env.run(env.script("key_paths.txt", """
new
add_volume ellipsoid
expect_selected volume 1
time 12
key volume[1].position_m
time 18
key volume[1].position_m
time 12:00:20
gizmo_drag translate x 120 0 10
time 12
print volume[1].position_m
time 6
set fog.base_height_m 10
key fog.base_height_m
time 10
set fog.base_height_m 50
key fog.base_height_m
autokey on
time 6:00:20
set fog.base_height_m 20
expect_pending 0
save {saved}
new
open {saved}
expect_keys volume[1].position_m 2
expect_keys fog.base_height_m 2
save {again}
quit
""".format(saved=saved, again=again)))
    printed = re.search(r"volume\[1\]\.position_m = (\S+) (\S+) (\S+)", p.stdout)
    check(printed, "no position printed after the gizmo drag")
    moved = [float(printed.group(i)) for i in (1, 2, 3)]
    for path in (saved, again):
        preset = load_json(path)
        check(not near_duplicate_keys(preset), "%s: near-duplicate keys %s" % (path, near_duplicate_keys(preset)))
        position = track(preset, "position_m", preset["volumes"][1]["id"])
        times = [k["time_h"] for k in position["keys"]]
        check(times == [12, 18], "%s: the gizmo drag at 12:00:20 did not edit the 12:00 key: %s" % (path, times))
        check(all(abs(a - b) < 1e-9 for a, b in zip(position["keys"][0]["value"], moved)),
              "%s: the 12:00 key is %s, the gizmo left %s" % (path, position["keys"][0]["value"], moved))
        check(position["keys"][1]["value"] != position["keys"][0]["value"], "the 18:00 key moved too")
        height = {k["time_h"]: key_value(k) for k in track(preset, "fog.base_height_m")["keys"]}
        check(height == {6: 20, 10: 50}, "%s: auto-key at 06:00:20 gave %s" % (path, height))
    print("OK: key_paths")


def case_small_things(env):
    """Small things the study met (issue 50, point 4): Drop to ground says the
    height the emitter now has; one edit that clamps two values of a colour
    names both; a parameter that cannot be animated (location.day_of_year)
    refuses keys. Window screenshots at 1280x720 and 1920x1080 with the
    day of year inspected and the fog's red (unkeyed) row, the atmosphere's
    Rayleigh row, and the side panels collapsed, to look at."""
    shots = {size: env.path("small_things_%s.png" % size) for size in ("1280x720", "1920x1080")}
    script = """
new
collapse outliner off
collapse inspector off
add_emitter point
set emitter[1].position_m 12 250 -40
drop_to_ground
print emitter[1].position_m
print_status
set atmosphere.ground_albedo_rgb 1.5 0.5 -0.25
print_status
time 6
set fog.base_height_m 10
key fog.base_height_m
time 9
set fog.base_height_m 40
inspect location.day_of_year
select fog
wait_frames 3
window_screenshot {shot}
wait_frames 2
select atmosphere
wait_frames 3
window_screenshot {atmosphere}
wait_frames 2
collapse outliner on
collapse inspector on
wait_frames 3
window_screenshot {collapsed}
wait_frames 2
quit
"""
    for size, shot in shots.items():
        collapsed, atmosphere = shot.replace(".png", "_collapsed.png"), shot.replace(".png", "_atmosphere.png")
        p = env.run(env.script("small_things_%s.txt" % size,
                               script.format(shot=shot, atmosphere=atmosphere, collapsed=collapsed)), window=size)
        check(all(os.path.isfile(f) for f in (shot, atmosphere, collapsed)), "no window screenshots at %s" % size)
    position = re.search(r"emitter\[1\]\.position_m = (\S+) (\S+) (\S+)", p.stdout)
    check(position, "the emitter's position was not printed:\n" + p.stdout)
    statuses = re.findall(r"^status (.*)$", p.stdout, re.M)
    check(len(statuses) == 2, "print_status printed %s" % statuses)
    dropped = re.search(r"at y = (-?[0-9.]+) m \(the ground at (-?[0-9.]+) m\)", statuses[0])
    check(dropped, "Drop to ground did not say the height: %r" % statuses[0])
    check(abs(float(dropped.group(1)) - float(position.group(2))) < 5e-4,
          "Drop to ground said y = %s, the emitter is at %s" % (dropped.group(1), position.group(2)))
    check(abs(float(dropped.group(1)) - float(dropped.group(2)) - 0.5) < 2e-3,
          "an emitter floats 0.5 m above the ground: %r" % statuses[0])
    check("2 values clamped" in statuses[1] and "r 1.5 to 1" in statuses[1] and "b -0.25 to 0" in statuses[1],
          "the clamp message does not name both clamped values: %r" % statuses[1])
    p = env.run(env.script("day_key.txt", "new\nkey location.day_of_year\n"), expect_rc=1)
    check("is not animatable" in p.stderr, "keying the day of year was not refused:\n" + p.stderr[-1500:])
    print("OK: small_things (look at %s)" % ", ".join(shots.values()))


CASES = {
    "session": case_session,
    "prompts": case_prompts,
    "workflow": case_workflow,
    "undo_redo": case_undo_redo,
    "crash_recovery": case_crash_recovery,
    "screenshot": case_screenshot,
    "exposure": case_exposure,
    "errors": case_errors,
    "cloud_volume": case_cloud_volume,
    "autokey": case_autokey,
    "placement": case_placement,
    "mesh_volume": case_mesh_volume,
    "curves": case_curves,
    "curves_mouse": case_curves_mouse,
    "sun_anchor": case_sun_anchor,
    "curve_edit": case_curve_edit,
    "weather": case_weather,
    "tangents": case_tangents,
    "paste_keys": case_paste_keys,
    "key_paths": case_key_paths,
    "small_things": case_small_things,
}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--editor", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--work-dir", required=True)
    parser.add_argument("case", choices=sorted(CASES))
    args = parser.parse_args()
    CASES[args.case](Env(args, args.case))


if __name__ == "__main__":
    main()
