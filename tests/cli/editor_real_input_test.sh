#!/usr/bin/env bash
# Real X input at a low frame rate (issue 24): what scripted input hides. The editor runs with
# every frame slowed to about a second (--frame-delay-ms), as on a software renderer, and xdotool
# sends real X events, each quicker than a frame: a click in the name field and a typed "f" (text,
# not "frame the scene"), a quick click on a checkbox, a double-click on a number field and a
# typed value, a single click on another number field and a typed value, then Ctrl+S. The saved
# project.json must hold every one. Before issue 24 the quick click and the double-click were lost
# (press and release arrived in one frame); before 2026-12-06 a single click on a number field
# opened nothing and the typing after it was lost.
#
#   editor_real_input_test.sh GRASS_EDITOR WORK_DIR     (under xvfb-run: needs X and xdotool)
set -u
editor=$1
work=$2

. "$(dirname "$0")/editor_window_lib.sh"
start_editor

# Where the widgets are: the side panel's layout at Xvfb's scale of 1, top-left window
# (re-measure from a screenshot if the panel's layout changes).
act mousemove 150 43 click 1                  # the name field, after its text
act type f                                    # one letter: typed, not "frame the scene"
act key Return                                # done typing
act mousemove 49 414 click 1                  # "growth model": a click quicker than a frame
act mousemove 214 339 click --repeat 2 --delay 90 1   # the density field: double-click
act key ctrl+a
act type 35
act key Return
act mousemove 128 260 click 1                 # the height's upper end: one click, as in egui
act type 0.45                                 # typed over its selected value
act key Return
act key ctrl+s
sleep 2
stop_editor

saved=$work/p/project.json
grep -q '"name": "tinyf"' "$saved" || fail "the typed f did not reach the name field: $(grep '"name"' "$saved" | head -1)"
grep -q '"growth"' "$saved" && grep -A3 '"growth"' "$saved" | grep -q '"enabled": true' ||
    fail "the quick click on the growth checkbox was lost"
grep -q '"density": 35' "$saved" || fail "the double-click and typed density were lost: $(grep '"density"' "$saved")"
grep -q '0\.45' "$saved" || fail "the single click and typed height were lost: $(grep -A3 '"height' "$saved")"
echo "real input: name typed, quick click, double-click, single click and typing all saved"
