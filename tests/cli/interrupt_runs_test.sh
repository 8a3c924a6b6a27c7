#!/usr/bin/env bash
# Ctrl+C during the long runs (core/util/interrupt_stop.h): `grass soak`'s run under way ends
# at its next step and what ran is judged, printed and saved (the report says "stopped": true),
# exit 130, and a "both" soak does not start its second backend; `grass sim` ends before its next
# step with the summary and report of the steps run.
#
#   interrupt_runs_test.sh GRASS_BIN PROJECT WORK_DIR
set -u
source "$(dirname "$0")/interrupt_lib.sh"
bin=$1
project=$2
work=$3

fail() { echo "FAIL: $*" >&2; cat "$work/err" "$work/out" >&2 2>/dev/null; exit 1; }
rm -rf -- "$work" && mkdir -p -- "$work" || fail "cannot make $work"
report=$work/soak.json
"$bin" soak "$project" --seconds 3600 --sample-every 1 --backend both --report "$report" \
    >"$work/out" 2>"$work/err" &
# Once a few samples are in: a line "soak cpu: t = 3.0/3600 s" or later.
interrupt_when "soak cpu: t = ([3-9]|[1-9][0-9]+)\.[0-9]/3600" "$work/err" $! INT
status=$interrupted_status
[[ $status == 130 ]] || fail "exit $status, not 130"
grep -q "soak: cpu: stopped after" "$work/err" || fail "no word of the stop"
grep -q "^soak stopped: passed so far" "$work/out" || fail "no verdict of what ran"
grep -q '"stopped": true' "$report" || fail "the report does not say it was stopped"
grep -q '"backend": "gpu"' "$report" && fail "the second backend ran after the stop"
echo "soak interrupted: exit 130, $(grep -c '"t":' "$report") samples judged and saved"

# grass sim: a day asked for (minutes even for a small field), stopped once the progress line
# shows steps run.
"$bin" sim "$project" --seconds 86400 --report "$work/sim.json" >"$work/out" 2>"$work/err" &
interrupt_when "sim: step [1-9][0-9]*/" "$work/err" $! INT
[[ $interrupted_status == 130 ]] || fail "sim: exit $interrupted_status, not 130"
grep -q "sim: stopped after [1-9][0-9]* steps" "$work/err" || fail "sim: no word of the stop"
grep -q "^  health " "$work/out" || fail "sim: no summary of the steps run"
grep -q '"stopped": true' "$work/sim.json" || fail "sim: the report does not say it was stopped"
echo "sim interrupted: exit 130, $(grep -o '"steps": [0-9]*' "$work/sim.json") summed up and saved"
