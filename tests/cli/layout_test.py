#!/usr/bin/env python3
"""layout.gltf, the glTF scene `aerial bake` writes beside the manifest (no pip packages).

    layout_test.py --aerial PATH --source-dir REPO_ROOT --work-dir DIR
                   [--node NODE --validator-prefix DIR] [unittest args: Layout, KhronosValidator, ...]

Layout reads the file as JSON and checks it against `aerial eval --json` at the
bake's first time (00:00) and against the fixture's own numbers: one node per
fog volume, cloud volume and emitter named by its id, translation, rotation and
scale equal to the evaluated position, rotation and half extents (1e-6), every
parameter in extras, accessor min/max equal to the decoded buffer, closed
outward-facing meshes. KhronosValidator runs the Khronos glTF validator
(tests/tools/validate_gltf.js over npm gltf-validator, installed into the build
folder by tests/tools/install_gltf_validator.sh) on baked layouts and expects
no errors; KhronosValidatorCatchesErrors breaks a baked layout on purpose and
expects the validator to report it, so the clean verdict means something.
Reads tests/data/cli/layout.json, presets/; writes only under --work-dir.
"""

import argparse
import base64
import copy
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import unittest

AERIAL = ""
ROOT = ""
WORK = ""
NODE = ""
VALIDATOR_PREFIX = ""

FIXTURE = "tests/data/cli/layout.json"
FLOAT, UNSIGNED_INT = 5126, 5125
COMPONENTS = {"SCALAR": 1, "VEC3": 3}
TOLERANCE = 1e-6


def run(*args):
    p = subprocess.run([AERIAL, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def bake(preset_path, name):
    """Bakes a preset (two steps, small tables) into WORK/name; returns the directory."""
    out = os.path.join(WORK, name)
    shutil.rmtree(out, ignore_errors=True)
    code, _, err = run("bake", preset_path, "--out", out, "--step", "12h", "--size", "16x8", "--sky-view-size",
                       "8x4", "--far-fog-size", "8x4", "--quiet")
    if code != 0:
        raise AssertionError("aerial bake %s exited %d: %s" % (preset_path, code, err))
    return out


def load(path):
    with open(path) as f:
        return json.load(f)


def buffer_bytes(gltf):
    (buffer,) = gltf["buffers"]
    prefix = "data:application/octet-stream;base64,"
    assert buffer["uri"].startswith(prefix), buffer["uri"][:60]
    data = base64.b64decode(buffer["uri"][len(prefix):], validate=True)
    return buffer, data


def read_accessor(gltf, data, index):
    """The accessor's elements as tuples (float or int), little-endian, tightly packed."""
    accessor = gltf["accessors"][index]
    view = gltf["bufferViews"][accessor["bufferView"]]
    n = COMPONENTS[accessor["type"]]
    code = {FLOAT: "f", UNSIGNED_INT: "I"}[accessor["componentType"]]
    start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    values = struct.unpack_from("<%d%s" % (accessor["count"] * n, code), data, start)
    return [tuple(values[i:i + n]) for i in range(0, len(values), n)]


def rotate_smallest_first(triangle):
    """The same triangle (same winding) starting at its smallest index."""
    k = triangle.index(min(triangle))
    return tuple(triangle[k:]) + tuple(triangle[:k])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


# An octahedron stretched to 1 x 2 x 0.5: closed, outward, counter-clockwise.
OCTAHEDRON = [(1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 2.0, 0.0), (0.0, -2.0, 0.0), (0.0, 0.0, 0.5),
              (0.0, 0.0, -0.5)]


def octahedron_triangles():
    """One triangle per octant (a +-X, a +-Y and a +-Z vertex), turned to face outwards."""
    triangles = []
    for a in (0, 1):
        for b in (2, 3):
            for c in (4, 5):
                pa, pb, pc = OCTAHEDRON[a], OCTAHEDRON[b], OCTAHEDRON[c]
                outward = (pa[0], pb[1], pc[2])
                normal = cross(sub(pb, pa), sub(pc, pa))
                triangles.append((a, b, c) if dot(normal, outward) > 0 else (a, c, b))
    return triangles


def write_mesh_preset(directory):
    """A preset with two mesh volumes (add and subtract) over meshes/octahedron.gltf, and a
    subtract box; returns its path."""
    os.makedirs(os.path.join(directory, "meshes"), exist_ok=True)
    indices = [i for t in octahedron_triangles() for i in t]
    data = struct.pack("<%df" % (3 * len(OCTAHEDRON)), *[c for p in OCTAHEDRON for c in p])
    data += struct.pack("<%dI" % len(indices), *indices)
    mesh = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": FLOAT, "count": len(OCTAHEDRON), "type": "VEC3",
             "min": [min(p[c] for p in OCTAHEDRON) for c in range(3)],
             "max": [max(p[c] for p in OCTAHEDRON) for c in range(3)]},
            {"bufferView": 1, "componentType": UNSIGNED_INT, "count": len(indices), "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 12 * len(OCTAHEDRON)},
                        {"buffer": 0, "byteOffset": 12 * len(OCTAHEDRON), "byteLength": 4 * len(indices)}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }
    with open(os.path.join(directory, "meshes", "octahedron.gltf"), "w") as f:
        json.dump(mesh, f)
    preset = {
        "version": 1,
        "name": "Mesh layout (test)",
        "volumes": [
            {"id": "cave", "name": "Cave fog", "shape": "mesh", "mesh": "meshes/octahedron.gltf",
             "position_m": [10, 2, -30], "rotation_xyzw": [0, 0.6, 0, 0.8], "half_extents_m": [20, 5, 8],
             "density_per_m": 0.04},
            {"id": "hall", "name": "Dry hall", "shape": "mesh", "mesh": "meshes/octahedron.gltf", "blend": "subtract",
             "position_m": [12, 2, -30], "half_extents_m": [4, 2, 4]},
            {"id": "room", "name": "Dry room", "shape": "box", "blend": "subtract", "position_m": [0, 1, 0],
             "half_extents_m": [3, 1.5, 3]},
        ],
    }
    path = os.path.join(directory, "mesh_layout.json")
    with open(path, "w") as f:
        json.dump(preset, f, indent=1)
    return path


class Layout(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.preset = load(os.path.join(ROOT, FIXTURE))
        cls.out = bake(os.path.join(ROOT, FIXTURE), "layout")
        cls.gltf = load(os.path.join(cls.out, "layout.gltf"))
        code, out, err = run("eval", os.path.join(ROOT, FIXTURE), "--time", "00:00", "--json")
        assert code == 0, err
        cls.state = json.loads(out)

    def assertClose(self, got, want, what):
        self.assertEqual(len(got), len(want), what)
        for g, w in zip(got, want):
            self.assertLessEqual(abs(g - w), TOLERANCE, "%s: %r != %r" % (what, got, want))

    def node(self, name):
        matches = [n for n in self.gltf["nodes"] if n["name"] == name]
        self.assertEqual(len(matches), 1, name)
        return matches[0]

    def test_the_bake_lists_it_and_leaves_no_temporary(self):
        manifest = load(os.path.join(self.out, "manifest.json"))
        self.assertEqual(manifest["layout"]["file"], "layout.gltf")
        self.assertEqual(manifest["layout"]["time_h"], manifest["steps"][0]["time_h"])
        self.assertFalse([f for f in os.listdir(self.out) if f.startswith(".")], "temporary files left behind")

    def test_asset_and_scene(self):
        asset = self.gltf["asset"]
        self.assertEqual(asset["version"], "2.0")
        self.assertTrue(asset["generator"].startswith("Aerial "), asset["generator"])
        self.assertEqual(self.gltf["scene"], 0)
        (scene,) = self.gltf["scenes"]
        self.assertEqual(scene["name"], self.preset["name"])
        self.assertEqual(scene["extras"]["time_h"], 0.0)
        self.assertEqual(sorted(scene["nodes"]), list(range(len(self.gltf["nodes"]))))

    def test_one_node_per_object_named_by_its_id(self):
        ids = ([v["id"] for v in self.preset["volumes"]] + [v["id"] for v in self.preset["cloud_volumes"]] +
               [e["id"] for e in self.preset["emitters"]])
        self.assertEqual([n["name"] for n in self.gltf["nodes"]], ids)

    def test_volume_transforms_and_extras_at_the_first_time(self):
        for kind, key in (("fog_volume", "volumes"), ("cloud_volume", "cloud_volumes")):
            for v in self.state[key]:
                with self.subTest(id=v["id"]):
                    node = self.node(v["id"])
                    self.assertClose(node["translation"], v["position_m"], "translation")
                    self.assertClose(node["rotation"], v["rotation_xyzw"], "rotation")
                    self.assertClose(node["scale"], v["half_extents_m"], "scale")
                    self.assertAlmostEqual(math.sqrt(sum(q * q for q in node["rotation"])), 1.0, delta=1e-12)
                    extras = node["extras"]
                    self.assertEqual(extras["kind"], kind)
                    self.assertEqual(extras["name"], v["name"])
                    self.assertEqual(extras["shape"], v["shape"])
                    self.assertEqual(extras["parameters"], v)
                    if kind == "fog_volume":
                        self.assertEqual(extras["blend"], v.get("blend", "add"))
        # The keyed box at 00:00 is at its first keys, not at its static values.
        river = self.node("river_mist")
        tracks = {t["param"]: t["keys"][0]["value"] for t in self.preset["tracks"] if t.get("volume") == "river_mist"}
        self.assertClose(river["translation"], tracks["position_m"], "keyed position")
        self.assertClose(river["scale"], tracks["half_extents_m"], "keyed half extents")

    def test_emitters_are_punctual_lights(self):
        self.assertIn("KHR_lights_punctual", self.gltf["extensionsUsed"])
        lights = self.gltf["extensions"]["KHR_lights_punctual"]["lights"]
        for e in self.state["emitters"]:
            with self.subTest(id=e["id"]):
                node = self.node(e["id"])
                self.assertClose(node["translation"], e["position_m"], "translation")
                self.assertNotIn("mesh", node)
                light = lights[node["extensions"]["KHR_lights_punctual"]["light"]]
                self.assertEqual(light["type"], "point")
                self.assertTrue(all(0.0 <= c <= 1.0 for c in light["color"]), light)
                self.assertClose([c * light["intensity"] for c in light["color"]],
                                 [c * e["intensity_cd"] for c in e["colour_rgb"]], "colour x intensity [cd]")
                extras = node["extras"]
                self.assertEqual(extras["kind"], "emitter")
                self.assertEqual(extras["name"], e["name"])
                self.assertEqual(extras["flash"], e["flash"])
                self.assertEqual(extras["parameters"], {k: v for k, v in e.items() if k != "flash"})
        lamp = self.node("street_lamp")
        light = lights[lamp["extensions"]["KHR_lights_punctual"]["light"]]
        self.assertClose(light["color"], [1.0, 0.7, 0.38], "lamp colour over its largest component")
        # Candela times the largest component of the unit-luminance colour: the colour [2, 1.4, 0.76] over
        # its Rec.709 luminance, whose largest component is 2 / Y.
        state_lamp = next(e for e in self.state["emitters"] if e["id"] == "street_lamp")
        y = 0.2126 * 2 + 0.7152 * 1.4 + 0.0722 * 0.76
        self.assertAlmostEqual(light["intensity"] / (state_lamp["intensity_cd"] * 2 / y), 1.0, delta=1e-9)

    def checkedMesh(self, gltf, data, mesh):
        """The positions and indices of a glTF mesh, checked: one triangle primitive, float VEC3
        positions whose min/max are exactly the data's (the validator requires them), UNSIGNED_INT
        indices in range; closed (every edge run once each way) and counter-clockwise seen from
        outside (the shapes here are convex around the origin)."""
        (primitive,) = gltf["meshes"][mesh]["primitives"]
        self.assertEqual(primitive.get("mode", 4), 4)
        positions_index = primitive["attributes"]["POSITION"]
        accessor = gltf["accessors"][positions_index]
        self.assertEqual((accessor["componentType"], accessor["type"]), (FLOAT, "VEC3"))
        positions = read_accessor(gltf, data, positions_index)
        self.assertEqual(accessor["min"], [min(p[c] for p in positions) for c in range(3)])
        self.assertEqual(accessor["max"], [max(p[c] for p in positions) for c in range(3)])
        indices_accessor = gltf["accessors"][primitive["indices"]]
        self.assertEqual((indices_accessor["componentType"], indices_accessor["type"]), (UNSIGNED_INT, "SCALAR"))
        indices = [i for (i,) in read_accessor(gltf, data, primitive["indices"])]
        self.assertEqual(len(indices) % 3, 0)
        self.assertTrue(all(i < len(positions) for i in indices))
        edges = set()
        for t in range(0, len(indices), 3):
            a, b, c = (positions[i] for i in indices[t:t + 3])
            normal = cross(sub(b, a), sub(c, a))
            centroid = tuple((x + y + z) / 3 for x, y, z in zip(a, b, c))
            self.assertGreater(dot(normal, centroid), 0.0, "triangle %d of mesh %d faces inwards" % (t // 3, mesh))
            for u, v in ((0, 1), (1, 2), (2, 0)):
                edge = (indices[t + u], indices[t + v])
                self.assertNotIn(edge, edges)
                edges.add(edge)
        self.assertTrue(all((b, a) in edges for a, b in edges), "open edge in mesh %d" % mesh)
        return positions, indices, primitive.get("material")

    def test_buffer_accessors_and_meshes(self):
        buffer, data = buffer_bytes(self.gltf)
        self.assertEqual(buffer["byteLength"], len(data))
        for view in self.gltf["bufferViews"]:
            self.assertLessEqual(view.get("byteOffset", 0) + view["byteLength"], len(data))
        for material in self.gltf["materials"]:
            self.assertEqual(material["alphaMode"], "BLEND")
            self.assertLess(material["pbrMetallicRoughness"]["baseColorFactor"][3], 1.0)
        shapes = {n["extras"]["shape"]: n["mesh"] for n in self.gltf["nodes"] if "mesh" in n}
        self.assertEqual(set(shapes), {"box", "ellipsoid"})
        for shape, mesh in shapes.items():
            positions, indices, _ = self.checkedMesh(self.gltf, data, mesh)
            if shape == "box":
                self.assertEqual(sorted(positions),
                                 sorted((x, y, z) for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)))
                self.assertEqual(len(indices), 36)
            else:
                for p in positions:
                    self.assertAlmostEqual(math.sqrt(dot(p, p)), 1.0, delta=1e-6)

    def test_the_bake_carries_the_meshes(self):
        """meshes/<id>.gltf beside the manifest: the volume's own closed, outward triangles."""
        out = bake(write_mesh_preset(os.path.join(WORK, "mesh_preset")), "layout_mesh_files")
        manifest = load(os.path.join(out, "manifest.json"))
        volumes = manifest["meshes"]["volumes"]
        self.assertEqual(sorted(volumes), ["cave", "hall"])
        for volume_id, entry in volumes.items():
            with self.subTest(id=volume_id):
                self.assertEqual(entry["file"], "meshes/%s.gltf" % volume_id)
                self.assertEqual(entry["preset_mesh"], "meshes/octahedron.gltf")
                gltf = load(os.path.join(out, entry["file"]))
                _, data = buffer_bytes(gltf)
                positions, indices, _ = self.checkedMesh(gltf, data, 0)
                self.assertEqual(sorted(positions), sorted(OCTAHEDRON))
                self.assertEqual(len(indices) // 3, entry["triangles"])

    def test_mesh_volumes_carry_their_mesh(self):
        work = os.path.join(WORK, "mesh_preset")
        preset_path = write_mesh_preset(work)
        gltf = load(os.path.join(bake(preset_path, "layout_mesh"), "layout.gltf"))
        _, data = buffer_bytes(gltf)
        preset = load(preset_path)
        materials = [m["name"] for m in gltf["materials"]]
        want_triangles = sorted(tuple(OCTAHEDRON[i] for i in rotate_smallest_first(t)) for t in octahedron_triangles())
        for v in preset["volumes"]:
            with self.subTest(id=v["id"]):
                (node,) = [n for n in gltf["nodes"] if n["name"] == v["id"]]
                extras = node["extras"]
                self.assertEqual((extras["shape"], extras["blend"]), (v["shape"], v.get("blend", "add")))
                self.assertClose(node["translation"], v["position_m"], "translation")
                self.assertClose(node["scale"], v["half_extents_m"], "scale")
                self.assertClose(node["rotation"], v.get("rotation_xyzw", [0, 0, 0, 1]), "rotation")
                positions, indices, material = self.checkedMesh(gltf, data, node["mesh"])
                self.assertEqual(materials[material], "fog_volume_" + extras["blend"])
                if v["shape"] != "mesh":
                    self.assertNotIn("mesh", extras)
                    continue
                self.assertEqual(extras["mesh"], v["mesh"])
                # The mesh's own triangles in its own coordinates (the node scales them).
                self.assertEqual(sorted(positions), sorted(OCTAHEDRON))
                triangles = sorted(tuple(positions[i] for i in rotate_smallest_first(indices[t:t + 3]))
                                   for t in range(0, len(indices), 3))
                self.assertEqual(triangles, want_triangles)

    def test_a_preset_without_objects_gives_an_empty_scene(self):
        out = bake(os.path.join(ROOT, "tests", "data", "cli", "global_fog_only.json"), "layout_empty")
        gltf = load(os.path.join(out, "layout.gltf"))
        self.assertEqual(gltf["asset"]["version"], "2.0")
        self.assertNotIn("nodes", gltf)
        self.assertNotIn("buffers", gltf)
        self.assertNotIn("nodes", gltf["scenes"][0])


def validate(path):
    """(exit code, output) of tests/tools/validate_gltf.js on a file."""
    script = os.path.join(ROOT, "tests", "tools", "validate_gltf.js")
    p = subprocess.run([NODE, script, VALIDATOR_PREFIX, path], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout + p.stderr


class ValidatorCase(unittest.TestCase):
    def setUp(self):
        if not NODE or not VALIDATOR_PREFIX:
            self.fail("needs --node and --validator-prefix (the gltf_validator fixture of tests/CMakeLists.txt)")


class KhronosValidator(ValidatorCase):
    def test_baked_layouts_have_no_errors(self):
        presets = [os.path.join(ROOT, FIXTURE), os.path.join(ROOT, "tests", "data", "cli", "global_fog_only.json"),
                   os.path.join(ROOT, "presets", "stormy_night.json"),
                   os.path.join(ROOT, "presets", "foggy_valley_morning.json"),
                   write_mesh_preset(os.path.join(WORK, "mesh_preset"))]
        for preset_path in presets:
            with self.subTest(preset=os.path.basename(preset_path)):
                out = bake(preset_path, "validated_" + os.path.splitext(os.path.basename(preset_path))[0])
                files = [os.path.join(out, "layout.gltf")]
                meshes = os.path.join(out, "meshes")  # the mesh volumes' meshes the bake carries
                if os.path.isdir(meshes):
                    files += [os.path.join(meshes, f) for f in sorted(os.listdir(meshes))]
                for path in files:
                    code, output = validate(path)
                    self.assertEqual(code, 0, output)
                    self.assertIn(": 0 errors, 0 warnings", output)


class KhronosValidatorCatchesErrors(ValidatorCase):
    """The verdict above means something: a baked layout broken on purpose is refused."""

    def test_broken_layouts_are_reported(self):
        out = bake(os.path.join(ROOT, FIXTURE), "to_break")
        good = load(os.path.join(out, "layout.gltf"))

        def wrong_max(g):
            g["accessors"][0]["max"][0] += 0.5

        def non_unit_rotation(g):
            g["nodes"][0]["rotation"] = [0.0, 0.5, 0.0, 0.5]

        def missing_mesh(g):
            g["nodes"][0]["mesh"] = len(g["meshes"])

        def short_buffer(g):
            g["buffers"][0]["byteLength"] += 4

        cases = [(wrong_max, "ACCESSOR_MAX_MISMATCH"), (non_unit_rotation, "ROTATION_NON_UNIT"),
                 (missing_mesh, "UNRESOLVED_REFERENCE"), (short_buffer, "BUFFER_BYTE_LENGTH_MISMATCH")]
        for breaker, expected in cases:
            with self.subTest(broken=breaker.__name__):
                broken = copy.deepcopy(good)
                breaker(broken)
                path = os.path.join(WORK, breaker.__name__ + ".gltf")
                with open(path, "w") as f:
                    json.dump(broken, f)
                code, output = validate(path)
                self.assertEqual(code, 1, output)
                self.assertNotIn(": 0 errors", output)
                self.assertIn("error " + expected, output)
        # And the unbroken copy, written the same way, passes.
        path = os.path.join(WORK, "unbroken.gltf")
        with open(path, "w") as f:
            json.dump(good, f)
        code, output = validate(path)
        self.assertEqual(code, 0, output)


def main():
    global AERIAL, ROOT, WORK, NODE, VALIDATOR_PREFIX
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--aerial", required=True, help="the aerial binary")
    parser.add_argument("--source-dir", required=True, help="the repository root")
    parser.add_argument("--work-dir", required=True, help="a scratch directory (emptied first)")
    parser.add_argument("--node", default="", help="Node.js, for the Khronos validator")
    parser.add_argument("--validator-prefix", default="", help="where npm installed gltf-validator")
    args, rest = parser.parse_known_args()
    AERIAL, ROOT, WORK = (os.path.abspath(p) for p in (args.aerial, args.source_dir, args.work_dir))
    NODE = args.node
    VALIDATOR_PREFIX = os.path.abspath(args.validator_prefix) if args.validator_prefix else ""
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    unittest.main(argv=[sys.argv[0], *rest], verbosity=2)


if __name__ == "__main__":
    main()
