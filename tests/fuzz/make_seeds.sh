#!/usr/bin/env bash
# Rebuilds tests/fuzz/corpus/ (the seed corpora; small valid files, each a few KB):
#   tests/fuzz/make_seeds.sh BUILD_FUZZ_DIR GRASS_BIN
# e.g. tests/fuzz/make_seeds.sh build-fuzz build/bin/grass. Sources of the seeds:
#   project        the projects/ and tests/data/projects/ files that load, and every field at
#                  its default (fuzz_make_seeds)
#   gltf, glb      tests/data/gltf/quad.gltf, skinned_morphed.gltf (a skin and a morph target),
#                  cube.glb and the Draco and meshopt boxes, and a `grass export` of
#                  tests/data/projects/tiny read back: its .gltf with the .bin after a NUL (the
#                  fuzz_gltf input format), and the same packed into one .glb, as is
#                  skinned_morphed.gltf
#   export_cleanup an export's .gltf and a raw export's manifest.json
#   map_*, grass_texture, packing_cache, raw_export   written by fuzz_make_seeds with the
#                  application's writers; raw_export also gets the export's patch table
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(cd "$1" && pwd)"
grass="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"
corpus="$root/tests/fuzz/corpus"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/grass-seeds.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
cd "$root"

rm -rf "$corpus"
mkdir -p "$corpus"/{project,gltf,glb,export_cleanup}
"$build/bin/fuzz_make_seeds" "$corpus"

for p in projects/*/project.json tests/data/projects/{tiny,windy,rock,growth_tiny}/project.json; do
  name="$(basename "$(dirname "$p")")"
  cp "$p" "$corpus/project/$name.json"
done

cp tests/data/gltf/quad.gltf tests/data/gltf/skinned_morphed.gltf "$corpus/gltf/"
cp tests/data/gltf/cube.glb tests/data/gltf/box_draco.glb tests/data/gltf/box_meshopt.glb "$corpus/glb/"
"$grass" export tests/data/projects/tiny --out "$scratch/export" --lod 3 >/dev/null 2>&1
"$grass" export tests/data/projects/tiny --out "$scratch/raw" --format raw >/dev/null 2>&1
cp "$scratch"/raw/grass.patches*.bin "$corpus/raw_export/export.patches.bin"
# export_cleanup: an export's .gltf, and a small raw-export manifest.json (the shape the
# clean-up reads: layers naming blade and map files; fuzz_export_cleanup.cpp).
cp "$scratch"/export/*.gltf "$corpus/export_cleanup/export.gltf"
printf '%s\n' '{"format":"grass-raw-export","version":1,"layers":[{"blades":{"file":"grass.blades-0123456789abcdef.bin"},"maps":[{"file":"grass-fedcba9876543210.bin"}]}]}' \
  >"$corpus/export_cleanup/manifest.json"
python3 - "$scratch/export" "$corpus" <<'PY'
import base64, glob, json, struct, sys
folder, corpus = sys.argv[1], sys.argv[2]

def write_glb(gltf, binary, path):
    """gltf (its one buffer without a uri) and binary as one GLB (glTF 2.0 §4.4): JSON and BIN
    chunks padded to 4 bytes."""
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = (struct.pack("<II", len(text), 0x4E4F534A) + text +
              struct.pack("<II", len(binary), 0x004E4942) + binary)
    open(path, "wb").write(struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks)

gltf = json.load(open(glob.glob(folder + "/*.gltf")[0]))
(buffer,) = gltf["buffers"]
binary = open(folder + "/" + buffer["uri"], "rb").read()
# fuzz_gltf writes what follows the first NUL as scene.bin.
buffer["uri"] = "scene.bin"
text = json.dumps(gltf, separators=(",", ":")).encode()
open(corpus + "/gltf/export.gltf", "wb").write(text + b"\0" + binary)
del buffer["uri"]
write_glb(gltf, binary, corpus + "/glb/export.glb")
# The skinned, morphed triangle too, its data: URI buffer moved into the BIN chunk.
gltf = json.load(open("tests/data/gltf/skinned_morphed.gltf"))
(buffer,) = gltf["buffers"]
binary = base64.b64decode(buffer.pop("uri").split(",", 1)[1])
write_glb(gltf, binary, corpus + "/glb/skinned_morphed.glb")
PY
du -sh "$corpus"
