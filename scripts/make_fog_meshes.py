#!/usr/bin/env python3
"""Writes the fog volume meshes of the shipped presets (presets/meshes/):
closed, outward-facing triangle meshes as .gltf with an embedded buffer,
in metres, Y up (aerial/fog_mesh.hpp says what a fog mesh must be).

  river_mist.gltf  a bank of mist lying on the built-in scene's valley
                   floor, following the valley's bends north of the lake:
                   an elliptic tube (24 m wide, 8 m tall) swept along
                   x = 18 sin(z / 45) from z = 30 to z = -280, capped at
                   both ends. Concave in plan: a ray across it meets it
                   several times.

Usage: scripts/make_fog_meshes.py   (rewrites presets/meshes/)
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "presets", "meshes")


def write_gltf(path, positions, indices, name):
    pos = b"".join(struct.pack("<3f", *p) for p in positions)
    idx = b"".join(struct.pack("<I", i) for i in indices)
    buffer = pos + idx
    lo = [min(p[k] for p in positions) for k in range(3)]
    hi = [max(p[k] for p in positions) for k in range(3)]
    # Bounds as the float32 values stored (the validator compares them).
    lo = [struct.unpack("<f", struct.pack("<f", v))[0] for v in lo]
    hi = [struct.unpack("<f", struct.pack("<f", v))[0] for v in hi]
    doc = {
        "asset": {"version": "2.0", "generator": "Aerial scripts/make_fog_meshes.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": name, "mesh": 0}],
        "meshes": [{"name": name, "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "target": 34962},
            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx), "target": 34963},
        ],
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
    }
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def river_mist():
    half_width, half_height, centre_y = 12.0, 4.0, 1.5
    z0, z1, steps, around = 30.0, -280.0, 64, 16

    def centre(z):
        return 18.0 * math.sin(z / 45.0)

    positions, indices = [], []
    for s in range(steps + 1):
        z = z0 + (z1 - z0) * s / steps
        x = centre(z)
        # The cross-section lies in the plane across the path's direction.
        dx = 18.0 / 45.0 * math.cos(z / 45.0) * (z1 - z0) / abs(z1 - z0)
        tx, tz = dx, -1.0
        n = math.hypot(tx, tz)
        side = (-tz / n, tx / n)  # horizontal, to the path's right
        for k in range(around):
            a = 2.0 * math.pi * k / around
            u, v = math.cos(a), math.sin(a)
            positions.append((x + half_width * u * side[0], centre_y + half_height * v, z + half_width * u * side[1]))
    for s in range(steps):
        for k in range(around):
            a = s * around + k
            b = s * around + (k + 1) % around
            c = a + around
            d = b + around
            indices += [a, c, b, b, c, d]
    # Caps: a centre vertex at each end.
    start = len(positions)
    positions.append((centre(z0), centre_y, z0))
    end = len(positions)
    positions.append((centre(z1), centre_y, z1))
    last = steps * around
    for k in range(around):
        indices += [start, k, (k + 1) % around]
        indices += [end, last + (k + 1) % around, last + k]
    # Outward: the signed volume must be positive; flip every triangle if not.
    vol = 0.0
    for t in range(0, len(indices), 3):
        p, q, r = (positions[i] for i in indices[t:t + 3])
        vol += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                p[2] * (q[0] * r[1] - q[1] * r[0])) / 6.0
    if vol < 0.0:
        for t in range(0, len(indices), 3):
            indices[t + 1], indices[t + 2] = indices[t + 2], indices[t + 1]
    return positions, indices


def main():
    os.makedirs(OUT, exist_ok=True)
    positions, indices = river_mist()
    write_gltf(os.path.join(OUT, "river_mist.gltf"), positions, indices, "river_mist")
    print("presets/meshes/river_mist.gltf: %d vertices, %d triangles" % (len(positions), len(indices) // 3))


if __name__ == "__main__":
    main()
