#!/usr/bin/env python3
"""Writes the glTF seed corpus of fuzz_gltf (tests/fuzz/corpus/gltf/).

Each seed is one byte that picks the form (0: .gltf, 1: .glb; +2: smooth
computed normals) followed by the file. Small, valid scenes that reach
every part of the loader: embedded and external buffers, uint8/16/32 and
no indices, normals given and computed, TEXCOORD_0, materials with a
base-colour texture (a hand-made PNG), node hierarchies with matrices and
TRS, several scenes, and a GLB with a BIN chunk.

Usage: tests/fuzz/make_gltf_seeds.py [OUT_DIR]   (default: beside this file)
"""
import base64
import json
import os
import struct
import sys
import zlib


def png_rgba(width, height, pixels):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    raw = b"".join(b"\x00" + bytes(pixels[y * width * 4:(y + 1) * width * 4]) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def pad4(b, fill=b"\x00"):
    return b + fill * ((4 - len(b) % 4) % 4)


class Doc:
    def __init__(self):
        self.bin = b""
        self.json = {"asset": {"version": "2.0"}, "buffers": [], "bufferViews": [], "accessors": [],
                     "meshes": [], "nodes": [], "scenes": [], "scene": 0}

    def view(self, data, target=None):
        self.bin = pad4(self.bin)
        bv = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            bv["target"] = target
        self.bin += data
        self.json["bufferViews"].append(bv)
        return len(self.json["bufferViews"]) - 1

    def accessor(self, fmt, values, ctype, atype, count, minmax=None, normalized=False):
        data = struct.pack("<" + fmt * len(values), *values)
        acc = {"bufferView": self.view(data), "componentType": ctype, "count": count, "type": atype}
        if normalized:
            acc["normalized"] = True
        if minmax:
            acc["min"], acc["max"] = minmax
        self.json["accessors"].append(acc)
        return len(self.json["accessors"]) - 1

    def finish_embedded(self):
        self.json["buffers"] = [{"byteLength": len(self.bin),
                                 "uri": "data:application/octet-stream;base64," + base64.b64encode(self.bin).decode()}]
        return json.dumps(self.json, indent=1).encode()

    def finish_external(self, uri):
        self.json["buffers"] = [{"byteLength": len(self.bin), "uri": uri}]
        return json.dumps(self.json, indent=1).encode()

    def finish_glb(self):
        self.json["buffers"] = [{"byteLength": len(self.bin)}]
        js = pad4(json.dumps(self.json, separators=(",", ":")).encode(), b" ")
        bn = pad4(self.bin)
        total = 12 + 8 + len(js) + 8 + len(bn)
        return (b"glTF" + struct.pack("<II", 2, total) + struct.pack("<I", len(js)) + b"JSON" + js +
                struct.pack("<I", len(bn)) + b"BIN\x00" + bn)


def triangle(index_type=None):
    d = Doc()
    pos = d.accessor("f", [0, 0, 0, 1, 0, 0, 0, 1, 0], 5126, "VEC3", 3, ([0, 0, 0], [1, 1, 0]))
    prim = {"attributes": {"POSITION": pos}}
    if index_type:
        fmt, ctype = {"u8": ("B", 5121), "u16": ("H", 5123), "u32": ("I", 5125)}[index_type]
        prim["indices"] = d.accessor(fmt, [0, 1, 2], ctype, "SCALAR", 3)
    d.json["meshes"] = [{"primitives": [prim]}]
    d.json["nodes"] = [{"mesh": 0}]
    d.json["scenes"] = [{"nodes": [0]}]
    return d


def textured_quad():
    d = Doc()
    pos = d.accessor("f", [-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1], 5126, "VEC3", 4,
                     ([-1, 0, -1], [1, 0, 1]))
    nrm = d.accessor("f", [0, 1, 0] * 4, 5126, "VEC3", 4)
    uv = d.accessor("H", [0, 0, 65535, 0, 65535, 65535, 0, 65535], 5123, "VEC2", 4, normalized=True)
    idx = d.accessor("H", [0, 2, 1, 0, 3, 2], 5123, "SCALAR", 6)
    png = png_rgba(2, 2, [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128, 255, 255, 255, 0])
    d.json["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png).decode()}]
    d.json["textures"] = [{"source": 0}]
    d.json["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 0.8],
                                                     "baseColorTexture": {"index": 0},
                                                     "metallicFactor": 0.1, "roughnessFactor": 0.7},
                            "alphaMode": "BLEND"}]
    d.json["meshes"] = [{"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv},
                                         "indices": idx, "material": 0}]}]
    d.json["nodes"] = [{"mesh": 0, "translation": [0, 1, 0], "rotation": [0, 0.7071068, 0, 0.7071068],
                        "scale": [2, 1, 2]}]
    d.json["scenes"] = [{"nodes": [0]}]
    return d


def hierarchy():
    d = triangle("u16")
    d.json["nodes"] = [
        {"children": [1, 2], "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]},
        {"mesh": 0, "translation": [0, 2, 0]},
        {"mesh": 0, "children": [3], "scale": [1, 2, 1]},
        {"mesh": 0, "rotation": [0, 0, 0, 1]},
    ]
    d.json["scenes"] = [{"nodes": [1]}, {"nodes": [0]}]
    d.json["scene"] = 1
    d.json["meshes"][0]["primitives"].append({"attributes": {"POSITION": 0}, "mode": 1})
    d.json["materials"] = [{"alphaMode": "MASK", "alphaCutoff": 0.3}]
    d.json["meshes"][0]["primitives"][0]["material"] = 0
    return d


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                              "corpus", "gltf")
    os.makedirs(out, exist_ok=True)
    seeds = {
        "triangle_noindex.gltf": (0, triangle().finish_embedded()),
        "triangle_u8.gltf": (2, triangle("u8").finish_embedded()),
        "triangle_u32.glb": (1, triangle("u32").finish_glb()),
        "textured_quad.gltf": (0, textured_quad().finish_embedded()),
        "textured_quad.glb": (3, textured_quad().finish_glb()),
        "hierarchy.gltf": (2, hierarchy().finish_embedded()),
        "hierarchy.glb": (1, hierarchy().finish_glb()),
        "external_buffer.gltf": (0, triangle("u16").finish_external("missing.bin")),
    }
    for name, (prefix, data) in seeds.items():
        with open(os.path.join(out, name + ".seed"), "wb") as f:
            f.write(bytes([prefix]) + data)
    print(f"{len(seeds)} seeds in {out}")


if __name__ == "__main__":
    main()
