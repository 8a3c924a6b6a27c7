#!/usr/bin/env python3
# One-off generator of the glTF inputs in tests/data (the CLI tests read the committed OUTPUT;
# python is not needed at test time). Run from the repository root:
#   python3 tests/data/make_data.py
# The expected numbers in tests/cli/cli_tests.cmake are worked out by hand from the geometry
# below, not from this script.
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def write(path, data):
    full = os.path.join(HERE, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "wb") as f:
        f.write(data)


def floats(values):
    return struct.pack("<%df" % len(values), *values)


def u16(values):
    return struct.pack("<%dH" % len(values), *values)


# quad.gltf: a 2x2 quad in the XZ plane facing +Y, with normals and UV0, placed by a node with
# translation [1, 0, 0] and scale 3: a 6x6 square, area 36, bounds [-2,0,-3]..[4,0,3].
QUAD_POS = [-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1]
QUAD_NRM = [0, 1, 0] * 4
QUAD_UV = [0, 0, 1, 0, 1, 1, 0, 1]
QUAD_IDX = [0, 2, 1, 0, 3, 2]


def quad_doc(index_values=QUAD_IDX, position_count=4, buffer_bytes=None, uri=None):
    blob = floats(QUAD_POS) + floats(QUAD_NRM) + floats(QUAD_UV) + u16(index_values)
    if buffer_bytes is not None:
        blob = blob[:buffer_bytes]
    doc = {
        "asset": {"version": "2.0", "generator": "grass tests/data/make_data.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "quad", "mesh": 0, "translation": [1, 0, 0], "scale": [3, 3, 3]}],
        "meshes": [{"primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
            "indices": 3, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": position_count, "type": "VEC3",
             "min": [-1, 0, -1], "max": [1, 0, 1]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48, "target": 34962},
            {"buffer": 0, "byteOffset": 48, "byteLength": 48, "target": 34962},
            {"buffer": 0, "byteOffset": 96, "byteLength": 32, "target": 34962},
            {"buffer": 0, "byteOffset": 128, "byteLength": 12, "target": 34963},
        ],
        "buffers": [{
            "byteLength": len(blob),
            "uri": uri if uri is not None else
            "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    }
    return doc


def dump(doc):
    return (json.dumps(doc, indent=2) + "\n").encode()


quad = dump(quad_doc())
write("gltf/quad.gltf", quad)
# The same quad placed at map coordinates (UTM-like: 512 km east, 5412 km north, 120 m up): as
# a project's ground, grass moves it next to its origin (core::GltfPlacement).
far_quad = quad_doc()
far_quad["nodes"][0]["translation"] = [512345, 120, 5412345]
write("gltf/far_quad.gltf", dump(far_quad))
# Cut in the middle of the JSON.
write("gltf/truncated.gltf", quad[: len(quad) // 2])
# Index 7 in a primitive with 4 vertices.
write("gltf/index_out_of_range.gltf", dump(quad_doc(index_values=[0, 2, 1, 0, 3, 7])))
# The POSITION accessor claims 40 vertices (480 bytes); its view and buffer hold 4 (48 bytes).
write("gltf/accessor_past_buffer.gltf", dump(quad_doc(position_count=40)))
# The buffer lives outside the glTF file's folder.
write("gltf/outside_uri.gltf", dump(quad_doc(uri="../outside.bin")))
write("outside.bin", floats(QUAD_POS) + floats(QUAD_NRM) + floats(QUAD_UV) + u16(QUAD_IDX))
# Requires Draco and names a Draco stream that is not one (the quad's own positions): grass
# decodes Draco, so the message must be the decoder's refusal, naming the extension.
draco = quad_doc()
draco["meshes"][0]["primitives"][0]["extensions"] = {
    "KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}
draco["extensionsUsed"] = ["KHR_draco_mesh_compression"]
draco["extensionsRequired"] = ["KHR_draco_mesh_compression"]
write("gltf/draco_required.gltf", dump(draco))

# cube.glb: a 2x2x2 cube centred on the origin without normals or UVs, 8 shared corners,
# 12 outward-facing triangles, placed by a node matrix (uniform scale 0.5, translation
# [0, 1, 0]): a unit cube, area 6, bounds [-0.5,0.5,-0.5]..[0.5,1.5,0.5].
CUBE_POS = []
for z in (-1, 1):
    for y in (-1, 1):
        for x in (-1, 1):
            CUBE_POS += [x, y, z]
# corner index = x + 2y + 4z (0/1 per axis); counter-clockwise seen from outside.
CUBE_IDX = [
    0, 2, 3, 0, 3, 1,  # -z
    4, 5, 7, 4, 7, 6,  # +z
    0, 4, 6, 0, 6, 2,  # -x
    1, 3, 7, 1, 7, 5,  # +x
    0, 1, 5, 0, 5, 4,  # -y
    2, 6, 7, 2, 7, 3,  # +y
]
cube_bin = floats(CUBE_POS) + u16(CUBE_IDX)  # 96 + 72 = 168 bytes, a multiple of 4
cube = {
    "asset": {"version": "2.0", "generator": "grass tests/data/make_data.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "cube", "mesh": 0,
               "matrix": [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 1, 0, 1]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
         "min": [-1, -1, -1], "max": [1, 1, 1]},
        {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"},
    ],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": 96},
        {"buffer": 0, "byteOffset": 96, "byteLength": 72},
    ],
    "buffers": [{"byteLength": len(cube_bin)}],
}
cube_json = json.dumps(cube, separators=(",", ":")).encode()
cube_json += b" " * (-len(cube_json) % 4)
glb = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(cube_json) + 8 + len(cube_bin))
glb += struct.pack("<I", len(cube_json)) + b"JSON" + cube_json
glb += struct.pack("<I", len(cube_bin)) + b"BIN\0" + cube_bin
write("gltf/cube.glb", glb)
