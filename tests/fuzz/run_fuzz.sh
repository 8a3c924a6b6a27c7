#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz (see README.md there).
#   run_fuzz.sh [-j JOBS] BUILD_DIR SECONDS [TARGET...]
# First every input kept under regressions/<target>/ and every seed under corpus/<target>/ is
# run once (the regression mode; SECONDS = 0 stops there). Then each target is fuzzed for
# SECONDS, JOBS targets at a time, from a copy of its seed corpus, so that the repository stays
# unchanged. A crash, a leak, a hang (an input over 10 s), an input using over 2 GB, a sanitizer
# report or a failed check fails the run: it prints the log's report and the input libFuzzer
# kept, under BUILD_DIR/fuzz-run/artifacts/<target>/, and exits 1.
#
# GRASS_FUZZ_SEED (default 1) seeds libFuzzer's mutations. With a fixed seed the same build
# starts down the same path of inputs each run, so CI's short run retraces much of what a run here
# tried (not all: coverage feedback from the libraries' threads differs a little between runs,
# two runs of map_png's 20,000 inputs kept 57 and 59), instead of a fresh draw each time.
# GRASS_FUZZ_SEED=0 draws a new seed for each target, for exploring; the seed drawn is printed.
set -uo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
jobs=1
if [ "${1:-}" = -j ]; then
  jobs="$2"
  shift 2
fi
if [ $# -lt 2 ] || ! [[ "$2" =~ ^[0-9]+$ ]]; then
  echo "usage: $0 [-j JOBS] BUILD_DIR SECONDS [TARGET...]" >&2
  exit 2
fi
build="$(cd "$1" && pwd)" || exit 2
seconds="$2"
shift 2
fuzz_seed="${GRASS_FUZZ_SEED:-1}"
if ! [[ "$fuzz_seed" =~ ^[0-9]+$ ]] || ((${#fuzz_seed} > 9)); then
  echo "GRASS_FUZZ_SEED must be a number from 0 to 999999999 (0: a new seed each run), not '$fuzz_seed'" >&2
  exit 2
fi
fuzz_seed=$((10#$fuzz_seed)) # 010 is ten, not octal eight
targets=("$@")
if ((${#targets[@]} == 0)); then
  targets=(project gltf glb map_png map_tiff map_exr map_tga grass_texture packing_cache raw_export
    export_cleanup)
fi
for t in "${targets[@]}"; do
  if [ ! -x "$build/bin/fuzz_$t" ]; then
    echo "no fuzz target $build/bin/fuzz_$t (build $build first)" >&2
    exit 2
  fi
done

# Everything a run writes: logs and artifacts are kept for a look afterwards; the working
# corpora and the targets' TMPDIR (where a crashed target leaves its scratch folder) are not.
run="$build/fuzz-run"
rm -rf "$run"
mkdir -p "$run/logs" "$run/artifacts" "$run/work" "$run/tmp"
trap 'rm -rf "$run/work" "$run/tmp"' EXIT
export UBSAN_OPTIONS="print_stacktrace=1:${UBSAN_OPTIONS:-}"
# Known third-party leaks, each explained in the file.
export LSAN_OPTIONS="suppressions=$here/lsan.supp:${LSAN_OPTIONS:-}"
# Memory: one allocation over 2 GB is a failure (-malloc_limit_mb), so is a process that grows
# past 2 GB resident (-rss_limit_mb: libFuzzer reads the peak, so one input that allocated 2 GB
# in pieces counts; ASAN_OPTIONS=hard_rss_limit_mb=N names that input, tests/fuzz/README.md),
# and leaks are (LeakSanitizer).
common=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 -detect_leaks=1)

# What in a log means a failure even when the exit status says otherwise.
report_pattern='ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|grass fuzz check failed|SUMMARY: '

failed=0
fail() {
  local target="$1" log="$2" why="$3"
  failed=1
  echo "FAIL $target: $why"
  grep -E -m 20 "$report_pattern|#[0-9]+ 0x.* in (grass|LLVMFuzzerTestOneInput)" "$log" | sed 's/^/    /'
  echo "    log: $log"
}

echo "== fuzz regression inputs and seeds, each run once"
for t in "${targets[@]}"; do
  inputs=()
  for dir in "$here/regressions/$t" "$here/corpus/$t"; do
    [ -d "$dir" ] && while IFS= read -r -d '' f; do inputs+=("$f"); done \
      < <(find "$dir" -type f ! -name README.md -print0 | sort -z)
  done
  if ((${#inputs[@]} == 0)); then
    echo "     $t: no inputs"
    continue
  fi
  log="$run/logs/$t.regressions.log"
  mkdir -p "$run/tmp/$t"
  TMPDIR="$run/tmp/$t" "$build/bin/fuzz_$t" "${common[@]}" "${inputs[@]}" >"$log" 2>&1
  rc=$?
  if ((rc != 0)) || grep -Eq "$report_pattern" "$log"; then
    fail "$t" "$log" "exit status $rc on $(grep '^Running: ' "$log" | tail -1 | cut -c10-)"
  else
    echo "  ok $t: ${#inputs[@]} inputs"
  fi
done
if ((seconds == 0)); then
  exit "$failed"
fi

if ((fuzz_seed == 0)); then
  seed_note="a new seed each target (GRASS_FUZZ_SEED=0)"
else
  seed_note="seed $fuzz_seed (GRASS_FUZZ_SEED)"
fi
echo "== fuzzing ${#targets[@]} targets for ${seconds} s each, $jobs at a time, $seed_note"
fuzz_one() {
  local t="$1"
  mkdir -p "$run/work/$t" "$run/artifacts/$t" "$run/tmp/$t"
  [ -d "$here/corpus/$t" ] && cp -R "$here/corpus/$t/." "$run/work/$t/"
  local dict=()
  [ -f "$here/dict/$t.dict" ] && dict=(-dict="$here/dict/$t.dict")
  TMPDIR="$run/tmp/$t" "$build/bin/fuzz_$t" "${common[@]}" "${dict[@]}" \
    -seed="$fuzz_seed" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$run/artifacts/$t/" \
    "$run/work/$t" >"$run/logs/$t.log" 2>&1
  echo $? >"$run/logs/$t.rc"
}
# The seed libFuzzer used, when it drew one (GRASS_FUZZ_SEED=0): to replay the run.
drawn_seed() {
  ((fuzz_seed == 0)) || return 0
  local seed
  seed="$(sed -n 's/.*Seed: \([0-9]*\).*/\1/p' "$1" | head -1)"
  [ -n "$seed" ] && echo ", seed $seed"
}
running=0
for t in "${targets[@]}"; do
  if ((running >= jobs)); then
    wait -n
    ((running--))
  fi
  fuzz_one "$t" &
  ((running++))
done
wait

for t in "${targets[@]}"; do
  log="$run/logs/$t.log"
  rc="$(cat "$run/logs/$t.rc" 2>/dev/null || echo '?')"
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
  corpus="$(find "$run/work/$t" -type f | wc -l)"
  artifacts="$(find "$run/artifacts/$t" -type f)"
  if [ "$rc" != 0 ] || grep -Eq "$report_pattern" "$log"; then
    fail "$t" "$log" "exit status $rc after ${execs:-?} executions$(drawn_seed "$log")"
    for a in $artifacts; do echo "    input: $a"; done
  elif [ -z "$execs" ]; then
    fail "$t" "$log" "no final statistics: libFuzzer did not finish"
  else
    echo "  ok $t: $execs executions in ${seconds} s, corpus $corpus inputs$(drawn_seed "$log")"
  fi
done
exit "$failed"
