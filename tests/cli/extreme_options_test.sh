#!/usr/bin/env bash
# Extreme values on the command line (issue 11): every option of every command that takes a
# number (read from the command's --help, which is generated from the table that parses) gets 0,
# -1, nan, inf, -inf, 1e300, abc and an empty string. Each run ends in the option parser: a
# sentinel unknown option follows the value, so nothing is grown or rendered. A value the
# option's stated range refuses must exit 2 with one stderr line naming the option and the range
# ("expected ..."); a value inside the range must reach the sentinel (parsed, nothing else said).
# Then the numbers inside --stroke, which are parsed after the options. Prints the case count.
#
#   extreme_options_test.sh GRASS_BINARY
set -u
grass=$1
GRASS_BASH_SELF=${BASH:-bash}
sentinel=--extreme-sentinel
values=(0 -1 nan inf -inf 1e300 abc "")
commands=(render sim mesh-info paint export bench tradeoff presets soak)
cases=0
failures=()

# Whether VALUE is accepted by the stated range of an option: KIND int MIN MAX | number MIN MAX |
# unsigned | choice A|B|C.
in_range() {
    local value=$1 kind=$2 a=${3:-} b=${4:-}
    case $kind in
        int) [[ $value =~ ^-?[0-9]+$ ]] && ((value >= a && value <= b)) ;;
        unsigned) [[ $value =~ ^[0-9]+$ ]] ;;
        number)
            [[ $value =~ ^-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$ ]] &&
                awk -v v="$value" -v lo="$a" -v hi="$b" 'BEGIN { exit !(v + 0 >= lo + 0 && v + 0 <= hi + 0) }'
            ;;
        choice) [[ "|$a|" == *"|$value|"* ]] ;;
        *) return 1 ;;
    esac
}

# One case: prints "FAIL: ..." when the command does not answer as the range says.
check() {
    local command=$1 option=$2 value=$3 kind=$4 a=${5:-} b=${6:-}
    local stderr rc lines
    stderr=$(timeout -k 5 20 "$grass" "$command" "$option" "$value" "$sentinel" 2>&1 >/dev/null)
    rc=$?
    lines=$(printf '%s\n' "$stderr" | grep -c .)
    local what="grass $command $option '$value'"
    if [ "$rc" -ne 2 ]; then
        echo "FAIL: $what: exit $rc, expected 2: $stderr"
    elif [ "$lines" -ne 1 ]; then
        echo "FAIL: $what: $lines stderr lines: $stderr"
    elif in_range "$value" "$kind" "$a" "$b"; then
        [[ $stderr == *"$sentinel"* ]] ||
            echo "FAIL: $what: inside the stated range but refused: $stderr"
    else
        [[ $stderr == *"$option"* && $stderr == *expected* ]] ||
            echo "FAIL: $what: refusal does not name the option and the range: $stderr"
    fi
}

# Each case is its own process (~0.5 s of start-up each), so they run four at a time.
if [ "${2:-}" = --case ]; then
    shift 2
    check "$@"
    exit 0
fi

cases_file=$(mktemp) || exit 2
trap 'rm -f -- "$cases_file"' EXIT
options=0
for command in "${commands[@]}"; do
    help=$("$grass" "$command" --help) || { failures+=("grass $command --help failed"); continue; }
    # "  --name METAVAR" then "      help text (range, default ...)".
    while IFS=$'\t' read -r option metavar text; do
        kind=""
        if [[ $text =~ \(a\ number\ from\ ([^ ]+)\ to\ ([^ ,]+), ]]; then
            kind=number a=${BASH_REMATCH[1]} b=${BASH_REMATCH[2]}
        elif [[ $metavar == N && $text =~ \((-?[0-9]+)\.\.(-?[0-9]+), ]]; then
            kind=int a=${BASH_REMATCH[1]} b=${BASH_REMATCH[2]}
        elif [[ $metavar == N ]]; then
            kind=unsigned a="" b=""
        elif [[ $metavar =~ ^([a-z]+\|)?[0-9]+(\|[0-9]+)+$ ]]; then
            kind=choice a=$metavar b=""
        fi
        [ -n "$kind" ] || continue
        options=$((options + 1))
        for value in "${values[@]}"; do
            printf '%s\0' "$command" "$option" "$value" "$kind" "$a" "$b" >>"$cases_file"
            cases=$((cases + 1))
        done
    done < <(printf '%s\n' "$help" | awk '
        /^  --/ { if (name != "") print name "\t" meta "\t" text; name = $1; meta = $2; text = ""; next }
        /^      / && name != "" { text = text " " $0; next }
        END { if (name != "") print name "\t" meta "\t" text }')
done

while IFS= read -r line; do
    failures+=("${line#FAIL: }")
done < <(xargs -0 -n 6 -P 4 "$GRASS_BASH_SELF" "$0" "$grass" --case <"$cases_file")

# The numbers of a stroke: refused before any file is read, naming --stroke.
for point in "nan,0,0" "0,inf,0" "0,0,-inf" "1e300,0,0" "abc,0,0" "0,0" "" "0,0,0;nan,1,1"; do
    cases=$((cases + 1))
    stderr=$(timeout -k 5 20 "$grass" paint no-such-project --map density --stroke "$point" 2>&1 >/dev/null)
    rc=$?
    if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$stderr" | grep -c .)" -ne 1 ] ||
        [[ $stderr != *--stroke* ]]; then
        failures+=("grass paint --stroke '$point': exit $rc: $stderr")
    fi
done

echo "extreme options: $options numeric options x ${#values[@]} values + 8 strokes = $cases cases"
if [ "$options" -lt 20 ]; then
    failures+=("only $options numeric options found in the commands' --help: parsing broke?")
fi
if [ ${#failures[@]} -gt 0 ]; then
    printf 'FAIL: %s\n' "${failures[@]}"
    exit 1
fi
echo "all refused with one line naming the option, or parsed within range"
