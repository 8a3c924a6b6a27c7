#!/usr/bin/env bash
# Runs a command that must succeed: exit code 0 within the time limit, then optional checks.
#
#   expect_ok.sh [--stdout REGEX]... [--no-stderr] [--png FILE WIDTH HEIGHT] -- COMMAND [ARG]...
#
#   --stdout REGEX         some line of stdout matches the extended regular expression
#                          (grep -E); repeatable, each must match
#   --stderr REGEX         some line of stderr matches (grep -E); repeatable
#   --no-stderr            stderr holds nothing but "note: " lines
#   --png FILE W H         FILE is removed before the run; afterwards it must exist, be a PNG
#                          (signature and IHDR chunk) and be W x H pixels
#   --file FILE REGEX      FILE is removed before the run; afterwards some line of it matches
#                          REGEX (grep -E); repeatable
#   --absent FILE          FILE is removed before the run and must not exist afterwards (what
#                          the command must leave alone); repeatable
#
# GRASS_CLI_TIMEOUT (seconds, default 120) bounds the run; a timeout fails the test.
# Only bash and coreutils are used (no python, no `file`): CI has nothing else.
set -u

usage() {
    echo "usage: expect_ok.sh [--stdout REGEX]... [--no-stderr] [--png FILE W H]" \
        "[--file FILE REGEX]... [--absent FILE]... -- COMMAND..." >&2
    exit 2
}

patterns=()
stderrPatterns=()
noStderr=0
pngFile=""
pngWidth=0
pngHeight=0
fileChecks=()
absentFiles=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    case $1 in
        --stdout)
            [ $# -ge 2 ] || usage
            patterns+=("$2")
            shift 2
            ;;
        --stderr)
            [ $# -ge 2 ] || usage
            stderrPatterns+=("$2")
            shift 2
            ;;
        --no-stderr)
            noStderr=1
            shift
            ;;
        --png)
            [ $# -ge 4 ] || usage
            pngFile=$2
            pngWidth=$3
            pngHeight=$4
            shift 4
            ;;
        --file)
            [ $# -ge 3 ] || usage
            fileChecks+=("$2" "$3")
            shift 3
            ;;
        --absent)
            [ $# -ge 2 ] || usage
            absentFiles+=("$2")
            shift 2
            ;;
        *) echo "expect_ok.sh: unknown option $1" >&2; usage ;;
    esac
done
if [ $# -lt 2 ] || [ "$1" != "--" ]; then usage; fi
shift

if [ -n "$pngFile" ]; then
    rm -f -- "$pngFile"
    mkdir -p -- "$(dirname -- "$pngFile")" || exit 2
fi

for ((i = 0; i < ${#fileChecks[@]}; i += 2)); do rm -f -- "${fileChecks[i]}"; done
for absent in ${absentFiles[@]+"${absentFiles[@]}"}; do rm -f -- "$absent"; done

work=$(mktemp -d) || exit 2
trap 'rm -rf -- "$work"' EXIT

timeout -k 10 "${GRASS_CLI_TIMEOUT:-120}" "$@" </dev/null >"$work/stdout" 2>"$work/stderr"
rc=$?

failures=()
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    failures+=("timed out after ${GRASS_CLI_TIMEOUT:-120} s (exit code $rc)")
elif [ "$rc" -ge 128 ]; then
    failures+=("killed by signal $((rc - 128)) (exit code $rc): a crash")
elif [ "$rc" -ne 0 ]; then
    failures+=("exit code $rc, expected 0")
fi

for pattern in ${patterns[@]+"${patterns[@]}"}; do
    grep -Eq -- "$pattern" "$work/stdout" || failures+=("no line of stdout matches /$pattern/")
done

for pattern in ${stderrPatterns[@]+"${stderrPatterns[@]}"}; do
    grep -Eq -- "$pattern" "$work/stderr" || failures+=("no line of stderr matches /$pattern/")
done

for ((i = 0; i < ${#fileChecks[@]}; i += 2)); do
    checked=${fileChecks[i]}
    if [ ! -f "$checked" ]; then
        failures+=("$checked was not written")
    elif ! grep -Eq -- "${fileChecks[i + 1]}" "$checked"; then
        failures+=("no line of $checked matches /${fileChecks[i + 1]}/")
    fi
done

for absent in ${absentFiles[@]+"${absentFiles[@]}"}; do
    [ -e "$absent" ] && failures+=("$absent was written: the command must leave it alone")
done

if [ "$noStderr" -eq 1 ] && grep -qv '^note: ' "$work/stderr"; then
    failures+=("stderr holds more than notes")
fi

# Unsigned big-endian 32-bit integer at byte OFFSET of FILE.
be32() {
    local bytes value=0 b
    bytes=$(od -An -v -tu1 -j "$2" -N 4 -- "$1") || return 1
    for b in $bytes; do value=$((value * 256 + b)); done
    echo "$value"
}

if [ -n "$pngFile" ]; then
    if [ ! -f "$pngFile" ]; then
        failures+=("$pngFile was not written")
    else
        # PNG signature, then the IHDR chunk: length 13, "IHDR", width, height (big-endian).
        signature=$(od -An -v -tx1 -N 16 -- "$pngFile" | tr -d ' \n')
        if [ "$signature" != "89504e470d0a1a0a0000000d49484452" ]; then
            failures+=("$pngFile is not a PNG (first 16 bytes: $signature)")
        else
            width=$(be32 "$pngFile" 16)
            height=$(be32 "$pngFile" 20)
            if [ "$width" != "$pngWidth" ] || [ "$height" != "$pngHeight" ]; then
                failures+=("$pngFile is ${width}x${height}, expected ${pngWidth}x${pngHeight}")
            fi
        fi
    fi
fi

if [ "${#failures[@]}" -gt 0 ]; then
    echo "FAIL: $*"
    for failure in "${failures[@]}"; do echo "  - $failure"; done
    echo "--- exit code: $rc"
    echo "--- stderr:"
    cat "$work/stderr"
    echo "--- stdout (first 60 lines):"
    head -n 60 "$work/stdout"
    exit 1
fi
echo "ok: $*"
cat "$work/stdout"
