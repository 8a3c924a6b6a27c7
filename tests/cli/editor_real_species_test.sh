#!/usr/bin/env bash
# Species, painted with the map overlay, by real X input at about one frame a second (issue 27):
# the brush (key b), the only layer's header folded, "add layer" clicked, the brush's layer set
# to the new one in its combo, "show map" ticked, subtract chosen, a drag across the field, and
# Ctrl+S. The saved project holds both layers and only the new one names a painted density map,
# whose texels under the stroke are below 1. Screenshots (the overlay with the red ring) are left
# in WORK_DIR for a person to look at.
#
#   editor_real_species_test.sh GRASS_EDITOR WORK_DIR   (under xvfb-run: X and xdotool)
set -u
editor=$1
work=$2

. "$(dirname "$0")/editor_window_lib.sh"
mkdir -p -- "$work/config" || fail "cannot make $work"
export XDG_CONFIG_HOME="$work/config"
start_editor

shot() { command -v import >/dev/null && import -window root "$work/$1" 2>/dev/null; }
# Where the widgets are at Xvfb's scale of 1 (re-measure from a screenshot if the layout changes).
act key b                                     # the brush: its settings open over the layers
act mousemove 62 359 click 1                  # fold layer "grass": "add layer" comes up
act mousemove 62 385 click 1                  # add layer
sleep 3                                       # the field re-grows with "grass 2"
act mousemove 80 131 click 1                  # the brush's layer combo
act mousemove 58 185 click 1                  # "grass 2"
act mousemove 31 183 click 1                  # show map
act mousemove 84 209 click 1                  # subtract
act mousemove 580 292
xdotool mousedown 1
for x in 590 600 610 620 630 640; do act mousemove $x 292; done
xdotool mouseup 1
sleep 3
act mousemove 614 300                         # the ring over the painted strip
shot overlay.png
act key ctrl+s
sleep 2
stop_editor

saved=$work/p/project.json
grep -q '"name": "grass 2"' "$saved" || fail "the added layer was not saved: $(grep '"name"' "$saved")"
[ "$(grep -c '"density_map": "maps/grass_2-density.png"' "$saved")" = 1 ] ||
    fail "the new layer does not name its painted map: $(grep density_map "$saved")"
grep -q '"density_map": "maps/grass-density.png"' "$saved" && fail "the first layer was painted"
map=$work/p/maps/grass_2-density.png
[ -f "$map" ] || fail "no painted map at $map"
# The painted map's darkest texel, read by a small PNG decoder (grey, 8 or 16 bit, as saved).
min=$(python3 - "$map" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
pos, idat, width, height, depth, colour = 8, b"", 0, 0, 0, 0
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR":
        width, height, depth, colour = struct.unpack(">IIBB", body[:10])
    elif kind == b"IDAT":
        idat += body
    pos += 12 + length
assert colour == 0 and depth in (8, 16), "not a grey PNG"
bpp = depth // 8
raw, stride, prev, low = zlib.decompress(idat), width * bpp, bytearray(width * bpp), 1.0
for y in range(height):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], (prev[i - bpp] if i >= bpp else 0)
        p = a + b - c
        pr = a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c
        line[i] = (line[i] + (0, a, b, (a + b) // 2, pr)[f]) & 255
    prev = line
    for x in range(width):
        v = line[x * bpp] if bpp == 1 else (line[2 * x] << 8) | line[2 * x + 1]
        low = min(low, v / (255.0 if bpp == 1 else 65535.0))
print(low)
PY
) || fail "cannot read $map"
awk -v m="$min" 'BEGIN { exit !(m < 0.9) }' || fail "the stroke did not lower the map (min $min)"
echo "real species: a layer added, chosen for the brush, painted with the overlay on and saved (map min $min)"
