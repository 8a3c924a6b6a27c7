#!/usr/bin/env bash
# The editor ended by a signal (util/interrupt_stop.h): Ctrl+C in its terminal or SIGTERM (a
# logout, a shutdown) puts the unsaved changes into the autosave, says so and exits 128 + the
# signal; project.json stays as it was, and the next start offers the autosave back. With nothing
# unsaved it just ends. Before, the process died at once and the changes since the last autosave
# (one every 3 minutes by default) were lost.
#
#   editor_real_terminate_test.sh GRASS_EDITOR WORK_DIR     (under xvfb-run: needs X and xdotool)
set -u
editor=$1
work=$2

. "$(dirname "$0")/editor_window_lib.sh"
cp "$work/p/project.json" "$work/original.json"

# Nothing unsaved: SIGINT ends it, no autosave.
start_editor
kill -INT $pid; wait $pid; status=$?; trap - EXIT
[ "$status" -eq 130 ] || fail "SIGINT with nothing unsaved: exit $status, not 130"
grep -q "interrupted: nothing was unsaved" "$work/log.txt" || fail "SIGINT: no word of it"
[ -e "$work/p/project.autosave.json" ] && fail "an autosave was written with nothing unsaved"

# A typed name, unsaved (the autosave is 3 minutes away): SIGTERM keeps it in the autosave.
start_editor
act mousemove 150 43 click 1                  # the name field, after its text
act type x
act key Return
kill -TERM $pid; wait $pid; status=$?; trap - EXIT
[ "$status" -eq 143 ] || fail "SIGTERM: exit $status, not 143"
grep -q "terminated: the unsaved changes: autosaved to .*project.autosave.json; the next start offers them back" \
    "$work/log.txt" || fail "SIGTERM: no word of the autosave"
grep -q '"name": "tinyx"' "$work/p/project.autosave.json" 2>/dev/null ||
    fail "the typed name is not in the autosave"
cmp -s "$work/p/project.json" "$work/original.json" || fail "project.json changed"
echo "real terminate: SIGINT with nothing unsaved ends at once; SIGTERM keeps the typed name in the autosave"
