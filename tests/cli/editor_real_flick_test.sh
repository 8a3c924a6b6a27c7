#!/usr/bin/env bash
# A flick by real X input at about one frame a second: the gizmo (key g) and a click on the
# ball's marker within milliseconds (one frame: the click must go to the gizmo), then its up arrow pressed, dragged 50 px down and released by xdotool within a few
# milliseconds, all inside one frame, as a quick hand does on a software renderer; then Ctrl+S.
# The saved ball must have gone down as far as the same drag spread over frames takes it
# (tests/gl/slow_frame_input_gl_test.cpp: 0.8 m → 0.498 m). Before 2026-12-07 the viewport read
# only where the pointer was when the frame ended: the flick grabbed no handle and the ball stayed.
#
#   editor_real_flick_test.sh GRASS_EDITOR WORK_DIR     (under xvfb-run: needs X and xdotool)
set -u
editor=$1
work=$2

. "$(dirname "$0")/editor_window_lib.sh"
# The ball project of the GL tests (editor_runs.h writeBallProject): its marker at (615, 189).
cat > "$work/p/project.json" <<'JSON'
{
  "format": "grass-project", "version": 2, "name": "ball",
  "mesh": {"procedural": "plane", "size": 2, "resolution": 2},
  "layers": [{"name": "grass", "density": 20}],
  "colliders": [{"name": "ball", "shape": "sphere", "position": [0, 0.8, 0], "radius": 0.3}],
  "cameras": [{"name": "main", "position": [0.0, 1.6, 3.2], "target": [0, 0.4, 0]}],
  "render": {"width": 900, "height": 560, "geometry": "strips", "msaa": 0}
}
JSON
start_editor

act key g mousemove 615 189 click 1           # the gizmo and a click on the ball's marker, in one frame
act mousemove 615 150 mousedown 1 mousemove 615 175 mousemove 615 200 mouseup 1   # the flick
act key ctrl+s
sleep 2
stop_editor

saved=$work/p/project.json
y=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["colliders"][0]["position"][1])' "$saved") ||
    fail "cannot read the ball's position from $saved"
python3 -c 'import sys; sys.exit(0 if abs(float(sys.argv[1]) - 0.498) < 0.01 else 1)' "$y" ||
    fail "the flicked ball stands at y = $y m, not 0.498 m as after the same drag over frames"
echo "real flick: the ball went down to $y m in one frame"
