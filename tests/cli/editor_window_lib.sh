# Shared by the real-window tests (editor_real_*_test.sh), sourced after they set $editor and
# $work: checks for X and xdotool, the tiny project in $work/p, the editor started on it at about
# one frame a second, and `act` (an xdotool command, then time for two frames or more).
fail() { echo "FAIL: $*" >&2; [ -f "$work/log.txt" ] && sed 's/^/  editor: /' "$work/log.txt" >&2; exit 1; }
[ -n "${DISPLAY:-}" ] || fail "no X display: run this under xvfb-run -a"
command -v xdotool >/dev/null || fail "xdotool is missing (apt-get install xdotool)"
rm -rf -- "$work" && mkdir -p -- "$work/p" || fail "cannot make $work"
cat > "$work/p/project.json" <<'JSON'
{
  "format": "grass-project", "version": 2, "name": "tiny",
  "mesh": {"procedural": "plane", "size": 2, "resolution": 2},
  "layers": [{"name": "grass", "density": 20}],
  "render": {"width": 900, "height": 640, "geometry": "strips", "msaa": 0}
}
JSON

# Starts the editor on $work/p with every frame slowed to about a second, as on a software
# renderer; the caller's environment (XDG_CONFIG_HOME) passes through.
start_editor() {
  "$editor" "$work/p" --no-physics --frame-delay-ms 900 > "$work/log.txt" 2>&1 &
  pid=$!
  trap 'kill $pid 2>/dev/null' EXIT
  xdotool search --sync --name "grass" >/dev/null || fail "no editor window"
  sleep 4  # the first frames (the UI's fonts, the field) are slower still
}

stop_editor() {
  kill $pid 2>/dev/null; wait $pid 2>/dev/null
  trap - EXIT
}

act() { xdotool "$@"; sleep 2.5; }  # two frames or more between actions
