#!/usr/bin/env bash
# The reference runtime's sample host (issue 28), as a developer runs it: a small project is
# exported raw, grass-runtime-sample draws it in a real X window (Xvfb) for a fixed number of
# frames and writes a screenshot; then, with the left button held by xdotool at the window's
# centre, the export's collider follows the mouse to where the centre ray meets its plane (the
# camera looks at (0, 0.3, 0) and the ball rides at y = 0.3, so it must end there).
#   runtime_sample_test.sh GRASS SAMPLE WORK_DIR
set -u
grass=$1 sample=$2 work=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -n "${DISPLAY:-}" ] || fail "no X display: run this under xvfb-run -a"
command -v xdotool >/dev/null || fail "xdotool is missing (apt-get install xdotool)"
rm -rf -- "$work" && mkdir -p -- "$work/p" || fail "cannot make $work"
cat > "$work/p/project.json" <<'JSON'
{
  "format": "grass-project", "version": 2, "name": "sample",
  "mesh": {"procedural": "plane", "size": 6, "resolution": 8},
  "layers": [{"name": "grass", "density": 120}],
  "cameras": [{"name": "view", "position": [0, 4, 6], "target": [0, 0.3, 0], "fov_y_deg": 45}],
  "render": {"width": 480, "height": 320, "geometry": "strips"},
  "wind": [{"name": "breeze", "kind": "directional", "direction": [1, 0, 0], "strength": 6}],
  "colliders": [{"name": "ball", "shape": "sphere", "position": [-2, 0.3, 1], "radius": 0.5,
                 "path": [{"time": 0, "position": [-2, 0.3, 1]}, {"time": 4, "position": [2, 0.3, 1]}]}]
}
JSON
"$grass" export "$work/p" --format raw --out "$work/export" > "$work/export.txt" 2>&1 ||
  { cat "$work/export.txt" >&2; fail "grass export --format raw"; }

"$sample" --help | grep -q "usage: grass-runtime-sample EXPORT" || fail "--help"

# Frames and a screenshot, no input: the ball is on its path.
"$sample" "$work/export" --frames 6 --screenshot "$work/shot.png" > "$work/run.txt" 2>&1 ||
  { cat "$work/run.txt" >&2; fail "the sample did not run"; }
cat "$work/run.txt"
grep -Eq "blades drawn [1-9][0-9]* of [1-9]" "$work/run.txt" || fail "no blades drawn"
grep -q "on its path" "$work/run.txt" || fail "the ball left its path without the mouse"
[ "$(head -c 4 "$work/shot.png" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "no PNG screenshot"

# The left button held at the window's centre moves the ball there.
"$sample" "$work/export" --frames 120 > "$work/mouse.txt" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null' EXIT
window=$(xdotool search --sync --name "grass runtime sample" | head -1)
[ -n "$window" ] || fail "no sample window"
sleep 1  # the first frame compiles the shaders
xdotool mousemove --window "$window" 240 160 mousedown 1
wait $pid || { cat "$work/mouse.txt" >&2; fail "the sample failed under the mouse"; }
trap - EXIT
xdotool mouseup 1
cat "$work/mouse.txt"
line=$(grep "moved by the mouse" "$work/mouse.txt") || fail "the mouse did not move the ball"
read -r x y z < <(echo "$line" | sed -E 's/.*at \(([^,]+), ([^,]+), ([^)]+)\).*/\1 \2 \3/')
awk -v x="$x" -v z="$z" 'BEGIN { exit !(x * x + z * z < 0.04) }' ||
  fail "the ball ended at ($x, $y, $z), not under the mouse at (0, 0.3, 0)"
echo "runtime sample: screenshot written, the ball followed the mouse to ($x, $y, $z)"
