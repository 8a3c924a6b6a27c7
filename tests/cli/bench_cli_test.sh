#!/usr/bin/env bash
# `grass bench` end to end on the tiny case (issue 10, item 4), in one driver because the steps
# share a file: a run with --out writes JSON with every figure and sane values; a saved run
# compared with itself prints ratios of 1.00; a run at another image size refuses to compare
# with it, naming the file.
#
#   bench_cli_test.sh GRASS_BINARY WORK_DIR
#
# Only bash, grep and coreutils (as the other drivers). GRASS_CLI_TIMEOUT bounds each run.
set -u
source "$(dirname "$0")/interrupt_lib.sh"

[ $# -eq 2 ] || { echo "usage: bench_cli_test.sh GRASS_BINARY WORK_DIR" >&2; exit 2; }
grass=$1
work=$2
rm -rf -- "$work"
mkdir -p -- "$work" || exit 2
json=$work/tiny.json
failures=()

run() {
    timeout -k 10 "${GRASS_CLI_TIMEOUT:-120}" "$grass" "$@" </dev/null \
        >"$work/stdout" 2>"$work/stderr"
}

# The value of "key": number in the JSON file (the first occurrence; the tiny run has one case).
field() {
    grep -Eo "\"$1\": -?[0-9.eE+-]+" "$json" | head -n 1 | sed -E 's/.*: //'
}

# 1. A run that writes the results.
run bench --quick --frames 1 --cases tiny --out "$json"
rc=$?
[ "$rc" -eq 0 ] || failures+=("bench --out: exit code $rc, expected 0")
grep -Eq '^renderer +.+' "$work/stdout" || failures+=("bench: no renderer line on stdout")
grep -Eq '^tiny +1 ' "$work/stdout" || failures+=("bench: no table row for tiny")
if [ ! -f "$json" ]; then
    failures+=("bench --out did not write $json")
else
    grep -Eq '"format": "grass-bench"' "$json" || failures+=("no \"format\": \"grass-bench\"")
    grep -Eq '"renderer": ".+"' "$json" || failures+=("no renderer string in the JSON")
    # The work groups of the compute passes (GRASS_COMPUTE_GROUP, unset here: 32).
    [ "$(field compute_group)" = 32 ] ||
        failures+=("\"compute_group\" is '$(field compute_group)', expected 32")
    grep -Eq '^settings .*, compute groups of 32;' "$work/stdout" ||
        failures+=("bench: the settings line does not say the compute groups")
    for key in blades_in drawn culled_share frame_wall cull opaque grass snow ui ms_per_step \
        blade_steps_per_s; do
        value=$(field "$key")
        if [ -z "$value" ]; then
            failures+=("JSON has no number \"$key\"")
        elif [[ "$value" == -* ]]; then
            failures+=("\"$key\" is negative: $value")
        fi
    done
    # Times that must have been measured: more than 0 (snow is 0, the tiny project has none).
    for key in frame_wall ui ms_per_step blade_steps_per_s blades_in; do
        value=$(field "$key")
        [[ "$value" =~ ^0*(\.0*)?$ ]] && failures+=("\"$key\" is $value, expected > 0")
    done
    [[ "$(field snow)" =~ ^0*(\.0*)?$ ]] || failures+=("\"snow\" is $(field snow) without snow")
    bladesIn=$(field blades_in)
    drawn=$(field drawn)
    if [[ "$bladesIn" =~ ^[0-9]+$ && "$drawn" =~ ^[0-9]+$ ]]; then
        [ "$drawn" -le "$bladesIn" ] || failures+=("drawn $drawn > blades in $bladesIn")
        # tests/data/projects/tiny: density 20 on a 2 m x 2 m plane.
        [ "$bladesIn" -ge 40 ] && [ "$bladesIn" -le 160 ] ||
            failures+=("blades in $bladesIn, expected about 80")
        # Its camera is within the LOD distance: every drawn blade at full detail, 8 folded
        # segments, 32 triangles (core::drawnBladeTriangles).
        triangles=$(field blade_triangles)
        [ "$triangles" = "$((32 * drawn))" ] ||
            failures+=("blade_triangles '$triangles', expected 32 x drawn = $((32 * drawn))")
    else
        failures+=("blades_in '$bladesIn' or drawn '$drawn' is not an integer")
    fi
fi

# 2. The saved run against itself: every figure's ratio is 1.00 (or - where it is 0).
if [ -f "$json" ]; then
    run bench --results "$json" --compare "$json"
    rc=$?
    [ "$rc" -eq 0 ] || failures+=("bench --results --compare: exit code $rc, expected 0")
    grep -Eq '^settings .*, compute groups of 32;' "$work/stdout" ||
        failures+=("bench --results: the compute groups were not read back")
    row=$(grep -A 3 '^compared with' "$work/stdout" | grep -E '^tiny ')
    if [ -z "$row" ]; then
        failures+=("bench --compare: no ratio row for tiny")
    else
        ratios=(${row#tiny})
        ones=0
        for ratio in "${ratios[@]}"; do
            case $ratio in
                1.00) ones=$((ones + 1)) ;;
                -) ;;
                *) failures+=("bench --compare of a file with itself printed ratio $ratio") ;;
            esac
        done
        [ "$ones" -ge 8 ] || failures+=("bench --compare: only $ones ratios of 1.00 in: $row")
    fi

    # 3. Another image size: refused before measuring, with one line naming the file.
    run bench --cases tiny --frames 1 --width 64 --height 48 --compare "$json"
    rc=$?
    [ "$rc" -ge 1 ] && [ "$rc" -lt 125 ] || failures+=("bench --compare at 64x48: exit code $rc")
    lines=$(grep -cv '^note: ' "$work/stderr")
    [ "$lines" -eq 1 ] || failures+=("bench --compare at 64x48: $lines stderr lines, expected 1")
    grep -q -- "$json: measured at 1280x720" "$work/stderr" ||
        failures+=("bench --compare at 64x48: the error does not name $json and its size")
fi

# 4. Ctrl+C once the first case is measured: the run ends after the case under way (nature-100k,
#    seconds long, so that the signal lands in it: tiny-hybrid takes 0.1 s, and a signal that
#    came after it would find the last case under way), prints and saves the cases measured, and
#    exits 130 (core/util/interrupt_stop.h).
stopped=$work/stopped.json
timeout -k 10 "${GRASS_CLI_TIMEOUT:-120}" "$grass" bench --frames 1 \
    --cases tiny,nature-100k,tiny-hybrid --out "$stopped" </dev/null \
    >"$work/stdout" 2>"$work/stderr" &
interrupt_when "case took" "$work/stderr" $! INT
rc=$interrupted_status
[ "$rc" -eq 130 ] || failures+=("bench interrupted: exit code $rc, expected 130")
grep -q "bench: stopped after 2 of 3 case(s)" "$work/stderr" ||
    failures+=("bench interrupted: no word of the stop")
grep -Eq '^tiny +1 ' "$work/stdout" || failures+=("bench interrupted: no table row for tiny")
[ -f "$stopped" ] && grep -q '"name": "tiny"' "$stopped" ||
    failures+=("bench interrupted: the cases measured were not saved")

if [ "${#failures[@]}" -gt 0 ]; then
    echo "FAIL: grass bench"
    for failure in "${failures[@]}"; do echo "  - $failure"; done
    echo "--- last stderr:"
    cat "$work/stderr"
    echo "--- last stdout:"
    cat "$work/stdout"
    [ -f "$json" ] && { echo "--- $json:"; cat "$json"; }
    exit 1
fi
echo "ok: grass bench --out, --results --compare, size mismatch, Ctrl+C"
