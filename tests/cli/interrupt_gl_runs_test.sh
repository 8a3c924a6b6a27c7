#!/usr/bin/env bash
# Ctrl+C during the runs that draw (core/util/interrupt_stop.h): `grass tradeoff`'s sweep ends
# after the knob under way, and the knobs measured are written (table, tradeoff.json, plots);
# `grass render --turntable`'s turn ends after the view under way, with the sheet of the views
# done; exit 130 both.
#
#   interrupt_gl_runs_test.sh GRASS_BIN PROJECT WORK_DIR
set -u
source "$(dirname "$0")/interrupt_lib.sh"
bin=$1
project=$2
work=$3

fail() { echo "FAIL: $*" >&2; cat "$work/err" >&2 2>/dev/null; exit 1; }
rm -rf -- "$work" && mkdir -p -- "$work/turn" || fail "cannot make $work"

# stopped WHAT PATTERN STOPPED COMMAND...: runs the command, sends SIGINT once its stderr has a
# line matching PATTERN, and fails unless it exits 130 with a line matching STOPPED.
stopped() {
    local what=$1 pattern=$2 said=$3
    shift 3
    "$@" >"$work/stdout" 2>"$work/err" &
    interrupt_when "$pattern" "$work/err" $! INT
    [[ $interrupted_status == 130 ]] || fail "$what: exit $interrupted_status, not 130"
    grep -Eq "$said" "$work/err" || fail "$what: no word of the stop"
}

# 30 frames a setting: seconds a knob on llvmpipe, so the signal lands while the second runs.
stopped tradeoff "knob 2/3" "stopped after 2 of 3 knob\(s\)" \
    "$bin" tradeoff "$project" --knobs lod_distance,geometry_detail,cull_distance --frames 30 \
    --out "$work/out"
[[ -f $work/out/tradeoff.json && -f $work/out/geometry_detail.png ]] ||
    fail "the knobs measured were not written"
[[ -e $work/out/cull_distance.png ]] && fail "the knob after the stop was measured"
echo "tradeoff interrupted: exit 130, 2 of 3 knobs written"

# A turntable of 24 views, stopped once the third is written.
stopped turntable "turntable frame 3/24" "render: stopped after ([3-9]|1[0-9]|2[0-3]) of 24 views" \
    "$bin" render "$project" --turntable 24 --width 160 --height 100 --out "$work/turn/t.png"
[[ -f $work/turn/t_0002.png && -f $work/turn/t_sheet.png ]] ||
    fail "turntable: the views done and their sheet were not written"
[[ -e $work/turn/t_0023.png ]] && fail "turntable: the last view was drawn after the stop"
echo "turntable interrupted: exit 130, the views done and their sheet written"
