#!/usr/bin/env bash
# Runs a command that must fail the way the house rules say bad input fails (STYLE.md §4):
# a non-zero exit code below 128 (not a signal, not a hang), and exactly one line on stderr
# (lines starting "note: " aside) that contains SUBSTRING, which should name the file or
# option at fault; --also SUBSTRING (repeatable) names more text the line must hold. With
# --absent PATH (repeatable), PATH is removed before the run and must not exist after it: a
# failed command leaves no half-written file behind.
#
#   expect_error.sh SUBSTRING [--also SUBSTRING]... [--absent PATH]... -- COMMAND [ARG]...
#
# GRASS_CLI_TIMEOUT (seconds, default 120) bounds the run; a timeout fails the test.
set -u

usage() {
    echo "usage: expect_error.sh SUBSTRING [--also SUBSTRING]... [--absent PATH]... -- COMMAND..." >&2
    exit 2
}

[ $# -ge 1 ] || usage
expected=("$1")
shift
absent=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    case $1 in
        --also)
            [ $# -ge 2 ] || usage
            expected+=("$2")
            shift 2
            ;;
        --absent)
            [ $# -ge 2 ] || usage
            absent+=("$2")
            shift 2
            ;;
        *) echo "expect_error.sh: unknown option $1" >&2; usage ;;
    esac
done
if [ $# -lt 2 ] || [ "$1" != "--" ]; then usage; fi
shift
for text in "${expected[@]}"; do
    [ -n "$text" ] || { echo "expect_error.sh: SUBSTRING must not be empty" >&2; exit 2; }
done

for path in ${absent[@]+"${absent[@]}"}; do
    if [ -z "$path" ] || [ "$path" = "/" ]; then
        echo "expect_error.sh: bad --absent path" >&2
        exit 2
    fi
    rm -rf -- "$path"
done

work=$(mktemp -d) || exit 2
trap 'rm -rf -- "$work"' EXIT

timeout -k 10 "${GRASS_CLI_TIMEOUT:-120}" "$@" </dev/null >"$work/stdout" 2>"$work/stderr"
rc=$?

failures=()
if [ "$rc" -eq 0 ]; then
    failures+=("exit code 0, expected a failure")
elif [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    failures+=("timed out after ${GRASS_CLI_TIMEOUT:-120} s (exit code $rc): a hang, not an error")
elif [ "$rc" -ge 128 ]; then
    failures+=("killed by signal $((rc - 128)) (exit code $rc): a crash, not an error")
elif [ "$rc" -eq 125 ] || [ "$rc" -eq 126 ] || [ "$rc" -eq 127 ]; then
    failures+=("exit code $rc: the command could not be run at all")
fi

# The message lines: everything on stderr except notes.
lines=()
while IFS= read -r line || [ -n "$line" ]; do
    case $line in
        "note: "*) ;;
        *) lines+=("$line") ;;
    esac
done <"$work/stderr"

if [ "${#lines[@]}" -ne 1 ]; then
    failures+=("stderr has ${#lines[@]} lines (notes aside), expected exactly one")
elif [ -z "${lines[0]//[[:space:]]/}" ]; then
    failures+=("the error line on stderr is blank")
else
    for text in "${expected[@]}"; do
        [[ "${lines[0]}" == *"$text"* ]] || failures+=("the error line does not contain \"$text\"")
    done
fi

for path in ${absent[@]+"${absent[@]}"}; do
    [ -e "$path" ] && failures+=("left $path behind")
done

if [ "${#failures[@]}" -gt 0 ]; then
    echo "FAIL: $*"
    for failure in "${failures[@]}"; do echo "  - $failure"; done
    echo "--- exit code: $rc"
    echo "--- stderr:"
    cat "$work/stderr"
    echo "--- stdout (first 40 lines):"
    head -n 40 "$work/stdout"
    exit 1
fi
echo "ok (exit code $rc): ${lines[0]}"
