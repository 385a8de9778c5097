#!/usr/bin/env python3
"""Writes the malformed inputs of tests/hardening/test_bad_input.cpp:
presets/ (preset JSON) and gltf/ (.gltf, .glb). Each file is one defect on
an otherwise valid input; the expected error of each is in the test's table.

Usage: tests/data/bad_inputs/make_bad_inputs.py   (rewrites both folders)
"""
import copy
import json
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "fuzz"))
import make_gltf_seeds as g  # noqa: E402

VOLUME = {"id": "fog", "shape": "box", "position_m": [0, 0, 0], "rotation_xyzw": [0, 0, 0, 1],
          "half_extents_m": [10, 5, 10], "density_per_m": 0.02}
EMITTER = {"id": "lamp", "position_m": [0, 2, 0], "intensity_per_m": 1}


def preset(**extra):
    p = {"version": 1, "name": "bad"}
    p.update(extra)
    return p


def dump(obj):
    return (json.dumps(obj, indent=2) + "\n").encode()


def vol(**changes):
    v = copy.deepcopy(VOLUME)
    v.update(changes)
    return v


def track(keys, **target):
    t = dict(target)
    t.setdefault("param", "density_per_m")
    t["keys"] = keys
    return t


REGION = {"id": "ridge_storm", "shape": "ellipsoid", "position_m": [2500, 600, -6000],
          "half_extents_m": [3000, 2000, 1800], "blend_m": 800, "state": "storm"}


def weather(*regions, states=("storm",)):
    """A version-5 preset whose weather has `states` (no overrides) and `regions`."""
    return preset(version=5, weather={"states": [{"name": n, "overrides": []} for n in states],
                                      "regions": list(regions)})


def region(**changes):
    r = copy.deepcopy(REGION)
    r.update(changes)
    return r


def mesh_volume(mesh, **changes):
    v = vol(id="room", shape="mesh", mesh=mesh)
    v.update(changes)
    return v


PRESETS = {
    "empty.json": b"",
    "whitespace_only.json": b"  \n\t\n",
    "truncated_object.json": b'{\n  "version": 1,\n  "fog": {"density_per_m": 0.',
    "truncated_string.json": b'{"version": 1, "name": "unterminated',
    "trailing_comma.json": b'{"version": 1, "name": "x",}\n',
    "single_quotes.json": b"{'version': 1}\n",
    "comment.json": b'// a comment\n{"version": 1}\n',
    "trailing_garbage.json": b'{"version": 1}\nextra\n',
    "nan_literal.json": b'{"version": 1, "fog": {"density_per_m": NaN}}\n',
    "bom_only.json": b"\xef\xbb\xbf",
    "utf16_bom.json": b"\xff\xfe{\x00}\x00",
    "invalid_utf8_name.json": b'{"version": 1, "name": "caf\xe9"}\n',
    "nul_byte.json": b'{"version": 1,\x00 "name": "x"}\n',
    "binary_garbage.bin": bytes((i * 151 + 7) % 256 for i in range(256)),
    "root_array.json": b"[1, 2, 3]\n",
    "root_string.json": b'"version 1"\n',
    "version_missing.json": dump({"name": "no version"}),
    "version_string.json": dump({"version": "1"}),
    "version_newer.json": dump({"version": 7}),
    "version_zero.json": dump({"version": 0}),
    "version_fraction.json": dump({"version": 1.5}),
    "huge_number.json": b'{"version": 1, "fog": {"density_per_m": 1e400}}\n',
    "huge_negative_number.json": b'{"version": 1, "fog": {"base_height_m": -1e999}}\n',
    "huge_integer_seed.json": dump(preset(emitters=[dict(EMITTER, seed=99999999999999999999999)])),
    "fractional_seed.json": dump(preset(emitters=[dict(EMITTER, seed=1.5)])),
    "deep_nesting.json": b'{"version": 1, "description": ' + b"[" * 100 + b"]" * 100 + b"}\n",
    "negative_density.json": dump(preset(volumes=[vol(density_per_m=-0.5)])),
    "mesh_missing_file.json": dump(preset(volumes=[mesh_volume("../meshes/no_such_mesh.gltf")])),
    "mesh_without_file.json": dump(preset(volumes=[mesh_volume("")])),
    "mesh_open_edge.json": dump(preset(volumes=[mesh_volume("../meshes/open_edge.gltf")])),
    "mesh_flipped_triangle.json": dump(preset(volumes=[mesh_volume("../meshes/flipped_triangle.gltf")])),
    "mesh_inside_out.json": dump(preset(volumes=[mesh_volume("../meshes/inside_out.gltf")])),
    "mesh_non_manifold.json": dump(preset(volumes=[mesh_volume("../meshes/non_manifold.gltf")])),
    "mesh_degenerate_triangle.json": dump(preset(volumes=[mesh_volume("../meshes/degenerate_triangle.gltf")])),
    "mesh_lines.json": dump(preset(volumes=[mesh_volume("../meshes/lines.gltf")])),
    "mesh_not_gltf.json": dump(preset(volumes=[mesh_volume("../meshes/not_gltf.gltf")])),
    "mesh_index_count_overflow.json": dump(preset(volumes=[mesh_volume("../meshes/index_count_overflow.gltf")])),
    "mesh_zero_rotation.json": dump(preset(volumes=[mesh_volume("../meshes/zero_rotation.gltf")])),
    "mesh_unknown_blend.json": dump(preset(volumes=[vol(blend="multiply")])),
    "zero_half_extent.json": dump(preset(volumes=[vol(half_extents_m=[10, 0, 10])])),
    "negative_half_extent.json": dump(preset(volumes=[vol(half_extents_m=[10, 5, -3])])),
    "zero_quaternion.json": dump(preset(volumes=[vol(rotation_xyzw=[0, 0, 0, 0])])),
    "zero_gradient.json": dump(preset(volumes=[vol(gradient_direction=[0, 0, 0])])),
    "mie_extinction_below_scattering.json": dump(preset(atmosphere={"mie": {
        "scattering_per_m": [4e-6, 4e-6, 4e-6], "extinction_per_m": [4e-6, 1e-6, 4e-6]}})),
    "duplicate_volume_ids.json": dump(preset(volumes=[vol(), vol(position_m=[5, 0, 0])])),
    "duplicate_json_key.json": b'{"version": 1, "name": "a", "name": "b"}\n',
    "dangling_track_volume.json": dump(preset(volumes=[vol()], tracks=[
        track([{"time_h": 6, "value": 0.1}], volume="valley")])),
    "dangling_track_emitter.json": dump(preset(tracks=[
        track([{"time_h": 6, "value": 1}], emitter="lamp", param="intensity_per_m")])),
    "unknown_track_param.json": dump(preset(tracks=[
        track([{"time_h": 6, "value": 1}], param="fog.thickness")])),
    "not_animatable_track.json": dump(preset(tracks=[
        track([{"time_h": 6, "value": 40}], param="location.latitude_deg")])),
    "keys_not_increasing.json": dump(preset(tracks=[
        track([{"time_h": 8, "value": 0.1}, {"time_h": 6, "value": 0.2}], param="fog.density_per_m")])),
    "key_time_negative.json": dump(preset(tracks=[
        track([{"time_h": -1, "value": 0.1}], param="fog.density_per_m")])),
    "track_without_keys.json": dump(preset(tracks=[track([], param="fog.density_per_m")])),
    "colour_key_wrong_arity.json": dump(preset(tracks=[
        track([{"time_h": 6, "value": [1, 1]}], param="sun.colour_rgb")])),
    "volumes_not_array.json": dump(preset(volumes={"fog": VOLUME})),
    "volume_not_object.json": dump(preset(volumes=[42])),
    "colour_is_string.json": dump(preset(sun={"colour_rgb": "white"})),
    "position_two_numbers.json": dump(preset(volumes=[vol(position_m=[1, 2])])),
    "unknown_shape.json": dump(preset(volumes=[vol(shape="cylinder")])),
    "id_bad_characters.json": dump(preset(volumes=[vol(id="my fog/1")])),
    "id_too_long.json": dump(preset(volumes=[vol(id="v" * 65)])),
    "id_missing.json": dump(preset(volumes=[{k: v for k, v in VOLUME.items() if k != "id"}])),
    "name_too_long.json": dump(preset(name="n" * 4097)),
    "latitude_out_of_range.json": dump(preset(location={"latitude_deg": 91})),
    "region_unknown_state.json": dump(weather(region(state="hail"))),
    "region_bad_shape.json": dump(weather(region(shape="cone"))),
    "region_zero_size.json": dump(weather(region(half_extents_m=[3000, 0, 1800]))),
    "region_negative_size.json": dump(weather(region(half_extents_m=[-3000, 2000, 1800]))),
    "region_negative_blend.json": dump(weather(region(blend_m=-50))),
    "region_duplicate_id.json": dump(weather(region(), region(position_m=[0, 0, 0]))),
    "region_huge_number.json": b'{"version": 5, "weather": {"states": [], "regions": [\n'
                               b'  {"id": "r", "state": "none", "blend_m": 1e400}]}}\n',
    "region_fractional_priority.json": dump(weather(region(priority=0.5))),
    "region_missing_state.json": dump(weather({k: v for k, v in REGION.items() if k != "state"})),
    "view_not_object.json": dump(preset(version=5, view=[0, 40, 120])),
    "view_missing_target.json": dump(preset(version=5, view={"eye_m": [0, 40, 120]})),
    "view_eye_two_numbers.json": dump(preset(version=5, view={"eye_m": [0, 40], "target_m": [0, 10, -200]})),
    "view_same_point.json": dump(preset(version=5, view={"eye_m": [0, 40, 120], "target_m": [0, 40, 120]})),
    "view_fov_out_of_range.json": dump(preset(version=5, view={"eye_m": [0, 40, 120], "target_m": [0, 10, -200],
                                                               "fov_deg": 180})),
    "view_far_away.json": dump(preset(version=5, view={"eye_m": [0, 40, 2e7], "target_m": [0, 10, -200]})),
}


def write_glb(doc, length_delta=0, magic=b"glTF", version=2, truncate=None):
    data = doc.finish_glb()
    data = magic + struct.pack("<II", version, len(data) + length_delta) + data[12:]
    return data[:truncate] if truncate is not None else data


def mesh_gltf(positions, indices, mode=None, index_count=None, node=None):
    """A .gltf of one triangle mesh (a fog volume mesh), embedded buffer;
    index_count overrides the indices accessor's count, node adds to the node."""
    d = g.Doc()
    flat = [c for p in positions for c in p]
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    pos = d.accessor("f", flat, 5126, "VEC3", len(positions), (lo, hi))
    idx = d.accessor("H", indices, 5123, "SCALAR", len(indices) if index_count is None else index_count)
    prim = {"attributes": {"POSITION": pos}, "indices": idx}
    if mode is not None:
        prim["mode"] = mode
    d.json["meshes"] = [{"primitives": [prim]}]
    d.json["nodes"] = [dict({"mesh": 0}, **(node or {}))]
    d.json["scenes"] = [{"nodes": [0]}]
    return d.finish_embedded()


def cube():
    """The cube [-1, 1]^3: 8 vertices, 12 outward counter-clockwise triangles."""
    positions = [[1 if i & 1 else -1, 1 if i & 2 else -1, 1 if i & 4 else -1] for i in range(8)]
    quads = [[1, 3, 7, 5], [0, 4, 6, 2], [2, 6, 7, 3], [0, 1, 5, 4], [4, 5, 7, 6], [0, 2, 3, 1]]
    indices = []
    for q in quads:
        indices += [q[0], q[1], q[2], q[0], q[2], q[3]]
    return positions, indices


def mesh_variants():
    """Fog volume meshes (meshes/), each with one defect, and a good cube."""
    positions, indices = cube()
    out = {"cube.gltf": mesh_gltf(positions, indices)}
    out["open_edge.gltf"] = mesh_gltf(positions, indices[:-3])
    flipped = list(indices)
    flipped[0], flipped[1] = flipped[1], flipped[0]
    out["flipped_triangle.gltf"] = mesh_gltf(positions, flipped)
    inward = [indices[i + k] for i in range(0, len(indices), 3) for k in (0, 2, 1)]
    out["inside_out.gltf"] = mesh_gltf(positions, inward)
    # A fin: a third triangle on the cube's edge 1-3 (and its back face).
    fin_positions = positions + [[2, 0, -1]]
    out["non_manifold.gltf"] = mesh_gltf(fin_positions, indices + [1, 3, 8, 3, 1, 8])
    degenerate = indices + [0, 1, 1]
    out["degenerate_triangle.gltf"] = mesh_gltf(positions, degenerate)
    out["lines.gltf"] = mesh_gltf(positions, indices, mode=1)
    out["not_gltf.gltf"] = b"this is not JSON\n"
    # A count whose byte length overflows 64 bits (stride x count wraps round).
    out["index_count_overflow.gltf"] = mesh_gltf(positions, indices, index_count=2**62 + 1)
    out["zero_rotation.gltf"] = mesh_gltf(positions, indices, node={"rotation": [0, 0, 0, 0]})
    return out


def gltf_variants():
    out = {}

    def tri(index_type="u16"):
        return g.triangle(index_type)

    out["empty.gltf"] = b""
    out["not_json.gltf"] = b"this is not JSON\n"
    out["json_array.gltf"] = b"[1, 2, 3]\n"
    out["no_asset.gltf"] = json.dumps({"scenes": [{"nodes": []}]}).encode()
    d = tri()
    out["bad_magic.glb"] = write_glb(d, magic=b"gLTF")
    out["glb_version_1.glb"] = write_glb(tri(), version=1)
    out["glb_truncated.glb"] = write_glb(tri(), truncate=60)
    out["glb_length_mismatch.glb"] = write_glb(tri(), length_delta=8)
    out["glb_too_short.glb"] = b"glTF\x02\x00"
    d = tri()
    d.json["accessors"][0]["count"] = 1000
    out["accessor_past_buffer_view.gltf"] = d.finish_embedded()
    d = tri()
    d.json["accessors"][0]["bufferView"] = 9
    out["accessor_bad_buffer_view.gltf"] = d.finish_embedded()
    d = tri()
    d.json["bufferViews"][0]["byteLength"] = 4096
    out["buffer_view_past_buffer.gltf"] = d.finish_embedded()
    d = tri()
    d.json["bufferViews"][0]["byteStride"] = 4
    out["stride_too_small.gltf"] = d.finish_embedded()
    d = tri()
    d.bin = d.bin[:36] + struct.pack("<HHH", 0, 1, 7) + d.bin[42:]
    out["index_out_of_range.gltf"] = d.finish_embedded()
    d = tri()
    out["missing_external_buffer.gltf"] = d.finish_external("missing.bin")
    d = tri()
    raw = d.finish_embedded()
    js = json.loads(raw)
    js["buffers"][0]["uri"] = "data:application/octet-stream;base64,@@@not-base64@@@"
    out["bad_base64_buffer.gltf"] = json.dumps(js).encode()
    d = g.textured_quad()
    d.json["images"] = [{"uri": "missing_texture.png"}]
    out["missing_texture.gltf"] = d.finish_embedded()
    d = g.textured_quad()
    d.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 5
    out["texture_index_out_of_range.gltf"] = d.finish_embedded()
    d = tri()
    d.json["scenes"] = []
    out["no_scene.gltf"] = d.finish_embedded()
    d = tri()
    d.json["nodes"] = [{"mesh": 0, "children": [1]}, {"children": [0]}]
    out["node_cycle.gltf"] = d.finish_embedded()
    d = tri()
    d.json["scenes"] = [{"nodes": [4]}]
    out["scene_node_missing.gltf"] = d.finish_embedded()
    d = tri()
    d.json["accessors"][0]["type"] = "VEC2"
    out["position_vec2.gltf"] = d.finish_embedded()
    d = tri()
    d.json["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    d.json["extensionsUsed"] = ["KHR_draco_mesh_compression"]
    out["required_extension.gltf"] = d.finish_embedded()
    d = tri()
    d.json["meshes"][0]["primitives"][0]["indices"] = None
    del d.json["meshes"][0]["primitives"][0]["indices"]
    d.json["accessors"][0]["count"] = 2
    out["not_whole_triangles.gltf"] = d.finish_embedded()
    d = tri()
    d.json["nodes"] = [{"mesh": 0, "scale": [1, 2]}]
    out["scale_two_values.gltf"] = d.finish_embedded()
    d = tri()
    d.json["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 2]}}]
    d.json["meshes"][0]["primitives"][0]["material"] = 0
    out["base_colour_over_one.gltf"] = d.finish_embedded()
    # Caps (aerial/limits.hpp): node depth 256 loads, 257 does not; a
    # texture 16384 pixels wide loads, 16385 is refused from its header.
    for depth in (256, 257):
        d = tri()
        d.json["nodes"] = [{"children": [i + 1]} for i in range(depth - 1)] + [{"mesh": 0}]
        out[f"node_depth_{depth}.gltf"] = d.finish_embedded()
    for width in (16384, 16385):
        out[f"texture_{width}.png"] = g.png_rgba(width, 1, [200, 100, 50, 255] * width)
        d = g.textured_quad()
        d.json["images"] = [{"uri": f"texture_{width}.png"}]
        out[f"texture_{width}_wide.gltf"] = d.finish_embedded()
    # Two 16384 x 1 images: the image budget (GltfLoadOptions::maxImagePixels).
    d = g.textured_quad()
    d.json["images"] = [{"uri": "texture_16384.png"}, {"uri": "texture_16384.png"}]
    d.json["textures"].append({"source": 1})
    out["texture_16384_twice.gltf"] = d.finish_embedded()
    return out


def main():
    for sub, files in (("presets", PRESETS), ("gltf", gltf_variants()), ("meshes", mesh_variants())):
        folder = os.path.join(HERE, sub)
        os.makedirs(folder, exist_ok=True)
        for name, data in files.items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(data)
        print(f"{len(files)} files in {folder}")


if __name__ == "__main__":
    main()
