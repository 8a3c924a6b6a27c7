#!/usr/bin/env bash
# The editor's autosave survives a kill (issue 11). A painting session autosaves every 0.2 s of
# frames while GRASS_TEST_SAVE_DELAY_MS holds each finished temporary 150 ms before its rename,
# and is SIGKILLed at a random moment, many times over. Each next session starts with --recover,
# as a user would after a crash, and paints on. After every kill: project.json is untouched, an
# autosave that is there loads with its map (`grass sim --seconds 0`, which also clears the
# temporaries a kill left, as any start does) and no temporary survives that start. At the end a
# recovered session saves, and the saved project holds the painting and no autosave remains.
#
#   kill_autosave_test.sh GRASS_EDITOR GRASS WORK_DIR [KILLS]     (under xvfb-run: needs X)
set -u
editor=$1
grass=$2
work=$3
kills=${4:-10}

fail() { echo "FAIL: $*" >&2; exit 1; }
[ -n "${DISPLAY:-}" ] || fail "no X display: run this under xvfb-run -a"
rm -rf -- "$work" && mkdir -p -- "$work/p" || fail "cannot make $work"
p=$work/p
cat > "$p/project.json" <<'JSON'
{
  "format": "grass-project", "version": 1, "name": "autosave kill",
  "mesh": {"procedural": "plane", "size": 3, "resolution": 4},
  "layers": [{"name": "grass", "density": 300, "map_resolution": [96, 96]}],
  "cameras": [{"name": "above", "position": [0, 3.2, 2.2], "target": [0, 0, 0]}],
  "render": {"width": 900, "height": 560, "geometry": "strips", "msaa": 0}
}
JSON
cp "$p/project.json" "$work/original.json"

# A long session of brush strokes (ctrl: erase, so each stroke lowers the density): far longer
# than any kill delay, so the editor is always killed, never done.
{
    echo "key b"; echo "hold ctrl"
    for ((s = 0; s < 200; ++s)); do
        y=$(( 120 + (s * 37) % 320 ))
        echo "drag 430 $y 860 $(( y + 20 )) 6"; echo "wait 4"
    done
} > "$work/session.txt"

export GRASS_TEST_SAVE_DELAY_MS=150
now_ms() { date +%s%3N; }
temporaries() { find "$p" -name '.*.tmp-*' | wc -l; }
run_editor() {  # run_editor SCRIPT MS: the editor on the project, SIGKILLed after MS
    "$editor" "$p" --no-physics --recover --autosave-s 0.2 --script "$1" >"$work/editor.log" 2>&1 &
    local pid=$!
    sleep "$(printf '%d.%03d' $(($2 / 1000)) $(($2 % 1000)))"
    if kill -9 "$pid" 2>/dev/null; then wait "$pid" 2>/dev/null; echo killed
    else wait "$pid"; echo "finished $?"; fi
}

# The first autosave comes a little after the window opens: time a short session to aim kills.
printf 'key b\nhold ctrl\ndrag 430 260 860 280 6\nwait 20\n' > "$work/short.txt"
start=$(now_ms)
"$editor" "$p" --no-physics --autosave-s 0.2 --script "$work/short.txt" >"$work/editor.log" 2>&1 ||
    fail "a plain editor session fails: $(tail -3 "$work/editor.log")"
shortMs=$(( $(now_ms) - start ))
[ -f "$p/project.autosave.json" ] || fail "a short session left no autosave (see $work/editor.log)"

killed=0; midSave=0; recovered=0
for ((i = 1; i <= kills; ++i)); do
    # One to three times a short session: always past the window opening, often mid-save.
    delay=$(( shortMs + RANDOM % (2 * shortMs) ))
    result=$(run_editor "$work/session.txt" "$delay")
    [[ $result == killed ]] || fail "kill $i: the editor ended by itself ($result) before $delay ms"
    killed=$((killed + 1))
    (( $(temporaries) > 0 )) && midSave=$((midSave + 1))
    cmp -s "$p/project.json" "$work/original.json" || fail "kill $i: project.json changed"
    [ -f "$p/project.autosave.json" ] || fail "kill $i: the autosave is gone"
    "$grass" sim "$p/project.autosave.json" --seconds 0 >/dev/null 2>"$work/sim.err" ||
        fail "kill $i: the autosave does not load: $(cat "$work/sim.err")"
    recovered=$((recovered + 1))
    (( $(temporaries) == 0 )) || fail "kill $i: temporaries left after the next start: $(find "$p" -name '.*.tmp-*')"
done

# The last recovery: take the autosave back, save it, and find the painting in project.json.
printf 'wait 2\nkey ctrl+s\nwait 1\n' > "$work/save.txt"
"$editor" "$p" --no-physics --recover --script "$work/save.txt" >"$work/editor.log" 2>&1 ||
    fail "the recovering session fails: $(tail -3 "$work/editor.log")"
grep -q '"density_map"' "$p/project.json" || fail "the saved project names no density map"
[ ! -e "$p/project.autosave.json" ] || fail "the autosave is still there after a save"
[ -z "$(find "$p" -name '*.autosave.*' -o -name '.*.tmp-*')" ] || fail "autosave files left: $(ls -R "$p")"
"$grass" sim "$p" --seconds 0 >/dev/null 2>"$work/sim.err" || fail "the saved project does not load: $(cat "$work/sim.err")"
echo "autosave: $killed sessions killed ($shortMs ms for a short one), $midSave of them mid-save; every time project.json was untouched, the autosave loaded with its map and the next start left no temporary; the last recovery saved the painting"
