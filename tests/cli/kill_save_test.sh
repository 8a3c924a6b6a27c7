#!/usr/bin/env bash
# Saves survive a kill (issue 11): `grass paint` (map + project save) and `grass export` are
# SIGKILLed at random points, concentrated on the end of the run where the files are written,
# many times. GRASS_TEST_SAVE_DELAY_MS (core/util/atomic_file.cpp) holds each finished temporary
# 150 ms before its rename, so that many kills land mid-save (the run prints how many did). After every kill the previous files must be whole (the project loads and its map
# reads: `grass sim --seconds 0`, which is also "the next start") and no temporary may be left
# once that next start has run.
#
#   kill_save_test.sh GRASS_BIN SOURCE_PROJECT WORK_DIR [PAINT_KILLS] [EXPORT_KILLS]
set -u
bin=$1
source=$2
work=$3
paintKills=${4:-30}
exportKills=${5:-15}

fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf -- "$work" && mkdir -p -- "$work" && cp -R -- "$source/." "$work/p" || fail "cannot copy $source"
project=$work/p
out=$work/export
export GRASS_TEST_SAVE_DELAY_MS=150

# Milliseconds a full run takes, to aim the kills.
now_ms() { date +%s%3N; }
paint() {
    "$bin" paint "$project" --map density --mode set --value "$1" --radius 0.4 \
        --stroke "-0.8,0,-0.8; 0.5,0,0.6" >/dev/null 2>&1
}
# The first paint also names the new map in project.json; time a later one, like those killed.
paint 0.5 || fail "a plain paint run fails"
start=$(now_ms); paint 0.6 || fail "a plain paint run fails"; paintMs=$(( $(now_ms) - start ))

temporaries() { find "$1" -name '.*.tmp-*' | wc -l; }
# A random delay in ms: 55 %..100 % of the run most of the time, anywhere in it otherwise.
delay_ms() {
    local full=$1
    if (( RANDOM % 4 != 0 )); then echo $(( full * 55 / 100 + RANDOM % (full * 45 / 100 + 1) ))
    else echo $(( RANDOM % (full + 1) )); fi
}
kill_after() {  # kill_after MS COMMAND...: run it, SIGKILL it after MS; prints killed|finished
    local ms=$1; shift
    "$@" >/dev/null 2>&1 &
    local pid=$!
    sleep "$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))"
    if kill -9 "$pid" 2>/dev/null; then echo killed; else echo finished; fi
    wait "$pid" 2>/dev/null
}

killed=0; finished=0; leftBehind=0
for ((i = 1; i <= paintKills; ++i)); do
    value="0.$(( RANDOM % 9 + 1 ))"
    result=$(kill_after "$(delay_ms "$paintMs")" "$bin" paint "$project" --map density \
        --mode set --value "$value" --radius 0.4 --stroke "-0.8,0,-0.8; 0.5,0,0.6")
    [[ $result == killed ]] && killed=$((killed + 1)) || finished=$((finished + 1))
    (( $(temporaries "$project") > 0 )) && leftBehind=$((leftBehind + 1))
    # The next start: the project loads, its map reads, and the temporaries are gone.
    "$bin" sim "$project" --seconds 0 >/dev/null 2>"$work/sim.err" ||
        fail "paint kill $i: the project no longer loads: $(cat "$work/sim.err")"
    (( $(temporaries "$project") == 0 )) || fail "paint kill $i: temporaries left after the next start"
done
echo "paint: $paintKills runs ($paintMs ms each): $killed killed, $finished finished first, $leftBehind left a temporary; every time the project and map loaded and the next start removed the temporaries"

# Every export run changes the field against the one before (LOD 0 and 1 alternate), so a
# mixed set of files would not load: the buffer and maps are named by their content and renamed
# first, the .gltf last (core/export/content_names.h), so the .gltf in place always names files
# that are there and whole.
start=$(now_ms); "$bin" export "$project" --out "$out" >/dev/null 2>&1 || fail "a plain export fails"
exportMs=$(( $(now_ms) - start ))
killed=0; finished=0; leftBehind=0
for ((i = 1; i <= exportKills; ++i)); do
    result=$(kill_after "$(delay_ms "$exportMs")" "$bin" export "$project" --out "$out" --lod $((i % 2)))
    [[ $result == killed ]] && killed=$((killed + 1)) || finished=$((finished + 1))
    (( $(temporaries "$out") > 0 )) && leftBehind=$((leftBehind + 1))
    # Whatever the kill left, the files in place are whole and belong together.
    [[ -s $out/grass.gltf ]] || fail "export kill $i: the previous export is gone"
    "$bin" mesh-info "$out/grass.gltf" >/dev/null 2>"$work/info.err" ||
        fail "export kill $i: the export in place does not load: $(cat "$work/info.err")"
    # The next export into the folder clears what the killed one left: its temporaries and the
    # files no .gltf names any more (one .gltf plus the files it names remain).
    "$bin" export "$project" --out "$out" --lod $(((i + 1) % 2)) >/dev/null 2>&1 ||
        fail "export kill $i: the next export fails"
    (( $(temporaries "$out") == 0 )) || fail "export kill $i: temporaries left after the next export"
    named=$(grep -c '"uri"' "$out/grass.gltf")
    present=$(find "$out" -maxdepth 1 -type f | wc -l)
    (( present == named + 1 )) ||
        fail "export kill $i: $present files after the next export, the .gltf names $named: $(ls "$out")"
done
echo "export: $exportKills runs ($exportMs ms each): $killed killed, $finished finished first, $leftBehind left a temporary; every time the export in place loaded and the next export removed the temporaries"
