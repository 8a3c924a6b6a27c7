#!/usr/bin/env python3
"""Builds projects/winter/rock-a.glb and rock-b.glb: the boulders of the winter scene.

Two lumpy, faceted rocks generated from scratch, deterministic (no randomness, no dependencies
beyond the Python 3 standard library), so the snow has flat tops to settle on, steep flanks it
slides off, and a lee side it never reaches.

How a rock is made
  1. A unit icosphere subdivided SUBDIVISIONS times (2,562 vertices, 5,120 triangles): a closed
     mesh whose triangles face outwards, every edge shared by exactly two of them.
  2. Each vertex direction d is pushed out to the surface of a star-shaped solid: the nearer of
     a rounded box (superellipsoid |x/a|^4 + |y/b|^4 + |z/c|^4 = 1) and a handful of cut planes
     (the facets of a split boulder: a near-flat top, slanted shoulders), then scaled by
     1 + LUMP * fractal value noise at the direction (three octaves, a hashed lattice). The
     solid is star-shaped around the origin, so the mesh stays closed and never folds.
  3. The rock is lowered so a third of its height is below y = 0: its origin is on the ground
     it is half buried in, as the project's `position` expects.
  4. Normals: area-weighted means of the adjacent face normals (smooth lumps, soft facet edges).
  5. Binary glTF 2.0 as projects/nature/make_bunny.py writes it: POSITION and NORMAL (float32
     VEC3), uint16 indices, three 4-byte-aligned buffer views, accessor min/max from the
     written float32 values. About 92 KB each.

Rerun (from the repository root; the output is byte-identical each time):
    python3 projects/winter/make_rocks.py
Check a file with: grass mesh-info projects/winter/rock-a.glb
"""

import json
import math
import os
import struct

SUBDIVISIONS = 4
LUMP = 0.14  # relative amplitude of the lumps
BURIED = 0.33  # share of the rock's height below the ground

# name: (superellipsoid half extents (a, b, c) in metres, cut planes (unit-ish normal, offset),
#        noise seed)
ROCKS = {
    "rock-a": ((1.0, 0.62, 0.8),
               [((0.05, 1.0, 0.1), 0.5), ((0.8, 0.6, 0.0), 0.78), ((-0.5, 0.5, 0.7), 0.72),
                ((0.2, 0.3, -0.95), 0.7), ((-0.95, 0.2, -0.2), 0.88)],
               11),
    "rock-b": ((0.8, 0.75, 0.9),
               [((-0.15, 1.0, 0.05), 0.6), ((0.6, 0.8, 0.3), 0.7), ((-0.7, 0.4, -0.6), 0.66),
                ((0.9, 0.1, -0.4), 0.74), ((0.1, 0.2, 1.0), 0.8)],
               29),
}


def normalize(v):
    n = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    return (v[0] / n, v[1] / n, v[2] / n)


def icosphere(levels):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [normalize(v) for v in (
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
        (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1))]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        midpoints = {}

        def mid(i, j):
            key = (min(i, j), max(i, j))
            if key not in midpoints:
                a, b = verts[i], verts[j]
                verts.append(normalize(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2)))
                midpoints[key] = len(verts) - 1
            return midpoints[key]

        next_faces = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            next_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = next_faces
    return verts, faces


def lattice(ix, iy, iz, seed):
    # A 32-bit integer hash of the lattice point, mapped to [-1, 1].
    h = (ix * 73856093) ^ (iy * 19349663) ^ (iz * 83492791) ^ (seed * 2654435761)
    h &= 0xFFFFFFFF
    h = ((h >> 16) ^ h) * 0x45D9F3B & 0xFFFFFFFF
    h = ((h >> 16) ^ h) * 0x45D9F3B & 0xFFFFFFFF
    h = (h >> 16) ^ h
    return (h & 0xFFFF) / 32767.5 - 1.0


def value_noise(p, seed):
    i = [math.floor(c) for c in p]
    f = [c - math.floor(c) for c in p]
    s = [x * x * (3.0 - 2.0 * x) for x in f]
    total = 0.0
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                w = ((s[0] if dx else 1 - s[0]) * (s[1] if dy else 1 - s[1]) *
                     (s[2] if dz else 1 - s[2]))
                total += w * lattice(i[0] + dx, i[1] + dy, i[2] + dz, seed)
    return total


def fractal(p, seed):
    total, amplitude, frequency, norm = 0.0, 1.0, 2.0, 0.0
    for octave in range(3):
        q = (p[0] * frequency, p[1] * frequency, p[2] * frequency)
        total += amplitude * value_noise(q, seed + octave)
        norm += amplitude
        amplitude *= 0.5
        frequency *= 2.1
    return total / norm


def surface_radius(d, extents, planes):
    a, b, c = extents
    box = ((d[0] / a) ** 4 + (d[1] / b) ** 4 + (d[2] / c) ** 4) ** -0.25
    t = box
    for normal, offset in planes:
        n = normalize(normal)
        along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2]
        if along > 1e-6:
            t = min(t, offset / along)
    return t


def make_rock(extents, planes, seed):
    dirs, faces = icosphere(SUBDIVISIONS)
    positions = []
    for d in dirs:
        r = surface_radius(d, extents, planes) * (1.0 + LUMP * fractal(d, seed))
        positions.append((d[0] * r, d[1] * r, d[2] * r))
    low = min(p[1] for p in positions)
    high = max(p[1] for p in positions)
    drop = low + BURIED * (high - low)
    positions = [(p[0], p[1] - drop, p[2]) for p in positions]
    normals = [[0.0, 0.0, 0.0] for _ in positions]
    for tri in faces:
        p0, p1, p2 = (positions[i] for i in tri)
        u = [p1[k] - p0[k] for k in range(3)]
        v = [p2[k] - p0[k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        for i in tri:
            for k in range(3):
                normals[i][k] += n[k]  # the cross product's length is twice the area
    return positions, [normalize(n) for n in normals], faces


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def pad(data, byte=b"\x00"):
    return data + byte * ((4 - len(data) % 4) % 4)


def write_glb(path, name, positions, normals, triangles):
    pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    nrm_bytes = b"".join(struct.pack("<3f", *v) for v in normals)
    idx_bytes = b"".join(struct.pack("<3H", *t) for t in triangles)
    views = []
    blob = b""
    for data, target in ((pos_bytes, 34962), (nrm_bytes, 34962), (idx_bytes, 34963)):
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                      "target": target})
        blob = pad(blob + data)
    pmin = [min(f32(p[a]) for p in positions) for a in range(3)]
    pmax = [max(f32(p[a]) for p in positions) for a in range(3)]
    gltf = {
        "asset": {"version": "2.0", "generator": "grass projects/winter/make_rocks.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": name}],
        "meshes": [{"name": name, "primitives": [
            {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": pmin, "max": pmax},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 3 * len(triangles),
             "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob)}],
    }
    json_chunk = pad(json.dumps(gltf, separators=(",", ":"), sort_keys=True).encode("utf-8"),
                     b" ")
    total = 12 + 8 + len(json_chunk) + 8 + len(blob)
    with open(path, "wb") as out:
        out.write(struct.pack("<4sII", b"glTF", 2, total))
        out.write(struct.pack("<I4s", len(json_chunk), b"JSON"))
        out.write(json_chunk)
        out.write(struct.pack("<I4s", len(blob), b"BIN\x00"))
        out.write(blob)
    return total, pmin, pmax


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for name, (extents, planes, seed) in ROCKS.items():
        positions, normals, triangles = make_rock(extents, planes, seed)
        size, pmin, pmax = write_glb(os.path.join(here, name + ".glb"), name, positions,
                                     normals, triangles)
        print("%s.glb: %d vertices, %d triangles, %d bytes, bounds [%s] .. [%s]" % (
            name, len(positions), len(triangles), size,
            ", ".join("%.2f" % v for v in pmin), ", ".join("%.2f" % v for v in pmax)))


if __name__ == "__main__":
    main()
