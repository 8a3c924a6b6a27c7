#!/usr/bin/env bash
# The CLI tests are only as honest as their drivers: this checks that expect_error.sh and
# expect_ok.sh fail on each kind of misbehaviour they are meant to catch (success, crash,
# hang, several lines, missing substring, a file left behind, no PNG, wrong size) and pass
# the well-behaved cases. Uses only sh, printf, kill, sleep and head.
set -u
here=$(cd -- "$(dirname -- "$0")" && pwd)
tmp=${1:?usage: driver_self_test.sh TMP_DIR}
mkdir -p -- "$tmp" || exit 2
failed=0

# check EXPECTED_RC DESCRIPTION DRIVER ARGS...: the driver's exit code must be EXPECTED_RC
# (0: the driver passes the command; 1: the driver fails it).
check() {
    local expected=$1 description=$2
    shift 2
    local output rc
    output=$("$@" 2>&1)
    rc=$?
    if [ "$rc" -ne "$expected" ]; then
        echo "FAIL: $description: driver exit code $rc, expected $expected"
        echo "$output" | head -n 20 | sed 's/^/    /'
        failed=1
    else
        echo "ok: $description"
    fi
}

err="$here/expect_error.sh"
ok="$here/expect_ok.sh"

check 0 "error: one line naming the option" \
    "$err" "--width" -- sh -c 'echo "tool: --width: bad" >&2; exit 2'
check 0 "error: notes are not counted" \
    "$err" "--width" -- sh -c 'echo "note: fyi" >&2; echo "tool: --width: bad" >&2; exit 1'
check 1 "error: exit code 0 is not an error" \
    "$err" "--width" -- sh -c 'echo "tool: --width: bad" >&2; exit 0'
check 1 "error: a crash (SIGSEGV) is not an error" \
    "$err" "--width" -- sh -c 'echo "tool: --width: bad" >&2; kill -SEGV $$'
check 1 "error: an abort (SIGABRT) is not an error" \
    "$err" "--width" -- sh -c 'echo "tool: --width: bad" >&2; kill -ABRT $$'
check 1 "error: a hang is not an error" \
    env GRASS_CLI_TIMEOUT=1 "$err" "--width" -- sh -c 'echo "tool: --width: bad" >&2; sleep 30'
check 1 "error: two lines are not one" \
    "$err" "--width" -- sh -c 'printf "tool: --width: bad\nmore\n" >&2; exit 2'
check 1 "error: no line at all" \
    "$err" "--width" -- sh -c 'exit 2'
check 1 "error: a blank line" \
    "$err" "--width" -- sh -c 'echo "  " >&2; exit 2'
check 1 "error: the line must name the option" \
    "$err" "--width" -- sh -c 'echo "tool: bad value" >&2; exit 2'
check 0 "error: every --also substring is there" \
    "$err" "--camera" --also "front" -- sh -c 'echo "tool: --camera: none (have: front)" >&2; exit 2'
check 1 "error: an --also substring is missing" \
    "$err" "--camera" --also "top" -- sh -c 'echo "tool: --camera: none (have: front)" >&2; exit 2'
check 1 "error: a missing command is not an error of the tool" \
    "$err" "x" -- "$tmp/no-such-program"
check 1 "error: a file left behind" \
    "$err" "bad" --absent "$tmp/left.png" -- sh -c "echo x > '$tmp/left.png'; echo bad >&2; exit 1"
check 0 "error: no file left behind" \
    "$err" "bad" --absent "$tmp/left.png" -- sh -c 'echo bad >&2; exit 1'

# A 3x2 PNG header (signature + IHDR); the drivers read no further.
# shellcheck disable=SC2317  # called through declare -f inside sh -c
png() {
    printf '\211PNG\r\n\032\n\000\000\000\rIHDR\000\000\000\003\000\000\000\002\010\006\000\000\000'
}
check 0 "ok: stdout pattern matches" \
    "$ok" --stdout '^wrote .* \(3x2\)$' -- sh -c 'echo "wrote x.png (3x2)"'
check 1 "ok: stdout pattern does not match" \
    "$ok" --stdout '^wrote' -- sh -c 'echo "nothing"'
check 1 "ok: a non-zero exit code" \
    "$ok" -- sh -c 'exit 1'
check 1 "ok: a crash" \
    "$ok" -- sh -c 'kill -SEGV $$'
check 1 "ok: stderr beyond notes with --no-stderr" \
    "$ok" --no-stderr -- sh -c 'echo "warning" >&2'
check 0 "ok: notes only with --no-stderr" \
    "$ok" --no-stderr -- sh -c 'echo "note: fine" >&2'
check 0 "ok: a 3x2 PNG" \
    "$ok" --png "$tmp/a.png" 3 2 -- sh -c "$(declare -f png); png > '$tmp/a.png'"
check 1 "ok: a PNG of the wrong size" \
    "$ok" --png "$tmp/a.png" 2 3 -- sh -c "$(declare -f png); png > '$tmp/a.png'"
check 1 "ok: not a PNG" \
    "$ok" --png "$tmp/a.png" 3 2 -- sh -c "echo 'not a png at all, no' > '$tmp/a.png'"
check 1 "ok: no file written (a stale one is removed first)" \
    "$ok" --png "$tmp/a.png" 3 2 -- sh -c 'exit 0'

exit "$failed"
