#!/usr/bin/env python3
"""Builds projects/nature/bunny.glb: the bunny collider of the nature scene (Jahrmann 2017, SPEC §14).

The paper packs the Stanford bunny into 1000 spheres. Its scan is not ours to ship and nothing
may be downloaded, so this script makes a stand-in: a bunny-like closed solid, generated from
scratch, deterministic (no randomness, no dependencies beyond the Python 3 standard library).

How it is made
  1. Shape. An implicit solid: the smooth union (polynomial smooth-min, blend radius BLEND) of
     ellipsoids, one each for the body, the haunches, the chest, the head, the cheeks and snout,
     two ears (long, thin, tilted back and apart), two front paws and a tail. Each ellipsoid
     contributes the approximate signed distance (|R^T (p - c) / r| - 1) * min(r). The bunny
     faces +X, stands on y = 0 (its origin is on the ground under its belly, the sole cut flat),
     and is about 1.3 m long, 1.4 m tall to the ear tips and 0.67 m wide (the nature project
     scales it by 1.5: big against the grass, as the paper's bunny is). 8,038 vertices,
     16,076 triangles, 0.29 MB.
  2. Polygonisation. Naive surface nets on a regular grid of CELL metres padded so the border
     is outside: one vertex per cell the surface crosses (the mean of the cell's edge
     crossings), one quad per grid edge the surface crosses (joining the four cells around the
     edge), each quad split along its shorter diagonal. A closed field on a grid whose border
     is outside gives a closed mesh: every edge is shared by exactly two triangles, used once
     in each direction. The script checks this (and that the signed volume is positive, i.e.
     the triangles face outwards) and stops if not.
  3. Normals from the gradient of the implicit function (central differences), outward.
  4. Binary glTF 2.0: one scene, one node, one mesh, one triangle primitive with POSITION,
     NORMAL (float32 VEC3) and indices (uint16, or uint32 past 65535 vertices); one buffer
     with three 4-byte-aligned buffer views; accessor min/max computed from the written
     float32 values; the JSON chunk padded with spaces and the BIN chunk with zeros to
     4 bytes.

Rerun (from the repository root; the output is byte-identical each time):
    python3 projects/nature/make_bunny.py            # writes projects/nature/bunny.glb
    python3 projects/nature/make_bunny.py OUT.glb    # elsewhere
The packing cache (projects/nature/.grass-cache/) notices a changed mesh file by itself.
Check the file with: grass mesh-info projects/nature/bunny.glb
"""

import json
import math
import os
import struct
import sys

CELL = 0.024  # grid cell in metres (16,076 triangles)
BLEND = 0.08  # smooth-union blend radius in metres


def rot_z(deg):
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    return ((c, -s, 0.0), (s, c, 0.0), (0.0, 0.0, 1.0))


def rot_x(deg):
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    return ((1.0, 0.0, 0.0), (0.0, c, -s), (0.0, s, c))


def mat_mul(a, b):
    return tuple(tuple(sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)) for i in range(3))


IDENTITY = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))

# (centre, radii, rotation R: ellipsoid axes in world = R · local axes).
# Bunny faces +X, up is +Y, left/right along Z.
PARTS = [
    # body: a big egg leaning forward
    ((-0.10, 0.40, 0.00), (0.46, 0.36, 0.33), rot_z(18)),
    # haunches (hind legs folded), one each side
    ((-0.22, 0.24, 0.17), (0.30, 0.24, 0.15), rot_z(5)),
    ((-0.22, 0.24, -0.17), (0.30, 0.24, 0.15), rot_z(5)),
    # hind feet, flat on the ground
    ((-0.10, 0.05, 0.20), (0.24, 0.06, 0.09), IDENTITY),
    ((-0.10, 0.05, -0.20), (0.24, 0.06, 0.09), IDENTITY),
    # chest
    ((0.22, 0.50, 0.00), (0.24, 0.28, 0.24), rot_z(-10)),
    # front paws
    ((0.36, 0.06, 0.10), (0.12, 0.06, 0.065), IDENTITY),
    ((0.36, 0.06, -0.10), (0.12, 0.06, 0.065), IDENTITY),
    # front legs
    ((0.30, 0.20, 0.10), (0.07, 0.17, 0.07), rot_z(-12)),
    ((0.30, 0.20, -0.10), (0.07, 0.17, 0.07), rot_z(-12)),
    # head and snout
    ((0.36, 0.80, 0.00), (0.23, 0.20, 0.19), rot_z(-20)),
    ((0.52, 0.74, 0.00), (0.12, 0.11, 0.12), rot_z(-20)),
    # cheeks
    ((0.40, 0.74, 0.09), (0.13, 0.11, 0.08), IDENTITY),
    ((0.40, 0.74, -0.09), (0.13, 0.11, 0.08), IDENTITY),
    # ears: long and flat, tilted back (about Z) and apart (about X)
    ((0.22, 1.08, 0.09), (0.065, 0.24, 0.035), mat_mul(rot_x(-14), rot_z(28))),
    ((0.22, 1.08, -0.09), (0.065, 0.24, 0.035), mat_mul(rot_x(14), rot_z(28))),
    # tail
    ((-0.55, 0.42, 0.00), (0.10, 0.10, 0.10), IDENTITY),
]


def ellipsoid_distance(p, centre, radii, rot):
    d = (p[0] - centre[0], p[1] - centre[1], p[2] - centre[2])
    # local = R^T d
    lx = rot[0][0] * d[0] + rot[1][0] * d[1] + rot[2][0] * d[2]
    ly = rot[0][1] * d[0] + rot[1][1] * d[1] + rot[2][1] * d[2]
    lz = rot[0][2] * d[0] + rot[1][2] * d[1] + rot[2][2] * d[2]
    q = math.sqrt((lx / radii[0]) ** 2 + (ly / radii[1]) ** 2 + (lz / radii[2]) ** 2)
    return (q - 1.0) * min(radii)


def smooth_min(a, b, k):
    h = max(k - abs(a - b), 0.0) / k
    return min(a, b) - h * h * k * 0.25


def field(p):
    """< 0 inside the bunny, > 0 outside."""
    value = None
    for centre, radii, rot in PARTS:
        d = ellipsoid_distance(p, centre, radii, rot)
        value = d if value is None else smooth_min(value, d, BLEND)
    # Flatten the sole: cut the solid at y = 0 so the bunny stands on the ground.
    return max(value, -p[1])


def gradient(p, eps=1e-4):
    gx = field((p[0] + eps, p[1], p[2])) - field((p[0] - eps, p[1], p[2]))
    gy = field((p[0], p[1] + eps, p[2])) - field((p[0], p[1] - eps, p[2]))
    gz = field((p[0], p[1], p[2] + eps)) - field((p[0], p[1], p[2] - eps))
    n = math.sqrt(gx * gx + gy * gy + gz * gz)
    if n == 0.0:
        return (0.0, 1.0, 0.0)
    return (gx / n, gy / n, gz / n)


def surface_nets():
    lo = (-0.80, -0.10, -0.50)
    hi = (0.80, 1.45, 0.50)
    n = [int(math.ceil((hi[a] - lo[a]) / CELL)) + 1 for a in range(3)]  # grid points per axis
    nx, ny, nz = n

    def point(i, j, k):
        return (lo[0] + i * CELL, lo[1] + j * CELL, lo[2] + k * CELL)

    values = [[[field(point(i, j, k)) for k in range(nz)] for j in range(ny)] for i in range(nx)]
    # The border must be outside so the surface closes.
    for i in range(nx):
        for j in range(ny):
            for k in range(nz):
                if i in (0, nx - 1) or j in (0, ny - 1) or k in (0, nz - 1):
                    assert values[i][j][k] > 0.0, "grid too small: the solid touches its border"

    corners = [(a, b, c) for a in (0, 1) for b in (0, 1) for c in (0, 1)]
    cube_edges = []
    for ci, a in enumerate(corners):
        for cj, b in enumerate(corners):
            if ci < cj and sum(abs(a[t] - b[t]) for t in range(3)) == 1:
                cube_edges.append((a, b))

    cell_vertex = {}
    positions = []
    for i in range(nx - 1):
        for j in range(ny - 1):
            for k in range(nz - 1):
                inside = [values[i + a][j + b][k + c] < 0.0 for a, b, c in corners]
                if all(inside) or not any(inside):
                    continue
                sx = sy = sz = 0.0
                count = 0
                for a, b in cube_edges:
                    va = values[i + a[0]][j + a[1]][k + a[2]]
                    vb = values[i + b[0]][j + b[1]][k + b[2]]
                    if (va < 0.0) == (vb < 0.0):
                        continue
                    t = va / (va - vb)
                    pa, pb = point(i + a[0], j + a[1], k + a[2]), point(i + b[0], j + b[1], k + b[2])
                    sx += pa[0] + t * (pb[0] - pa[0])
                    sy += pa[1] + t * (pb[1] - pa[1])
                    sz += pa[2] + t * (pb[2] - pa[2])
                    count += 1
                cell_vertex[(i, j, k)] = len(positions)
                positions.append((sx / count, sy / count, sz / count))

    triangles = []

    def dist2(u, v):
        return sum((positions[u][t] - positions[v][t]) ** 2 for t in range(3))

    def emit_quad(q):  # q: four vertex ids in counter-clockwise order seen from outside
        a, b, c, d = q
        if dist2(a, c) <= dist2(b, d):
            triangles.append((a, b, c))
            triangles.append((a, c, d))
        else:
            triangles.append((a, b, d))
            triangles.append((b, c, d))

    # For a grid edge along axis `ax` from grid point g to g + e_ax, the four cells around it
    # are offset by 0/-1 along the two other axes (u, v) with (ax, u, v) a right-handed cycle.
    for ax in range(3):
        u, v = (ax + 1) % 3, (ax + 2) % 3
        for i in range(nx):
            for j in range(ny):
                for k in range(nz):
                    g = [i, j, k]
                    if g[ax] + 1 >= n[ax] or g[u] == 0 or g[v] == 0:
                        continue
                    h = list(g)
                    h[ax] += 1
                    v0 = values[g[0]][g[1]][g[2]]
                    v1 = values[h[0]][h[1]][h[2]]
                    if (v0 < 0.0) == (v1 < 0.0):
                        continue
                    cells = []
                    for du, dv in ((-1, -1), (0, -1), (0, 0), (-1, 0)):
                        c = list(g)
                        c[u] += du
                        c[v] += dv
                        cells.append(cell_vertex[tuple(c)])
                    # The quad (−,−) (0,−) (0,0) (−,0) turns counter-clockwise about +ax. Its
                    # outward side is towards the outside end of the edge.
                    if v0 < 0.0:  # inside at g, outside at g + e_ax: face +ax
                        emit_quad(cells)
                    else:
                        emit_quad(cells[::-1])
    return positions, triangles


def check_closed(positions, triangles):
    directed = {}
    for t in triangles:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            assert a != b, "degenerate triangle"
            directed[(a, b)] = directed.get((a, b), 0) + 1
    for (a, b), count in directed.items():
        assert count == 1, "edge used twice in one direction (inconsistent winding)"
        assert directed.get((b, a), 0) == 1, "open or non-manifold edge"
    volume = 0.0
    for a, b, c in triangles:
        pa, pb, pc = positions[a], positions[b], positions[c]
        volume += (pa[0] * (pb[1] * pc[2] - pb[2] * pc[1]) - pa[1] * (pb[0] * pc[2] - pb[2] * pc[0])
                   + pa[2] * (pb[0] * pc[1] - pb[1] * pc[0])) / 6.0
    assert volume > 0.0, "triangles face inwards"
    return volume


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def write_glb(path, positions, normals, triangles):
    pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    nrm_bytes = b"".join(struct.pack("<3f", *v) for v in normals)
    big = len(positions) > 65535
    fmt, component = ("<3I", 5125) if big else ("<3H", 5123)
    idx_bytes = b"".join(struct.pack(fmt, *t) for t in triangles)

    def pad(data, byte=b"\x00"):
        return data + byte * ((4 - len(data) % 4) % 4)

    views = []
    blob = b""
    for data, target in ((pos_bytes, 34962), (nrm_bytes, 34962), (idx_bytes, 34963)):
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        blob = pad(blob + data)

    pmin = [min(f32(p[a]) for p in positions) for a in range(3)]
    pmax = [max(f32(p[a]) for p in positions) for a in range(3)]
    gltf = {
        "asset": {"version": "2.0", "generator": "grass projects/nature/make_bunny.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "bunny"}],
        "meshes": [{"name": "bunny", "primitives": [
            {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": pmin, "max": pmax},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": component, "count": 3 * len(triangles),
             "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob)}],
    }
    json_chunk = pad(json.dumps(gltf, separators=(",", ":"), sort_keys=True).encode("utf-8"), b" ")
    total = 12 + 8 + len(json_chunk) + 8 + len(blob)
    with open(path, "wb") as out:
        out.write(struct.pack("<4sII", b"glTF", 2, total))
        out.write(struct.pack("<I4s", len(json_chunk), b"JSON"))
        out.write(json_chunk)
        out.write(struct.pack("<I4s", len(blob), b"BIN\x00"))
        out.write(blob)
    return total


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "bunny.glb")
    positions, triangles = surface_nets()
    volume = check_closed(positions, triangles)
    normals = [gradient(p) for p in positions]
    size = write_glb(out, positions, normals, triangles)
    lo = [min(p[a] for p in positions) for a in range(3)]
    hi = [max(p[a] for p in positions) for a in range(3)]
    print(f"{out}: {len(positions)} vertices, {len(triangles)} triangles, closed, "
          f"volume {volume:.4f} m³, bounds {[round(x, 3) for x in lo]} .. "
          f"{[round(x, 3) for x in hi]}, {size} bytes")


if __name__ == "__main__":
    main()
