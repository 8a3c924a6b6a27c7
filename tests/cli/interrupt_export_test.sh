#!/usr/bin/env bash
# Ctrl+C during `grass export` (core/util/interrupt_stop.h): the first SIGINT stops the export
# at its next stage: exit 130, one line saying nothing was written, the export already in the
# folder byte for byte as it was and no staged temporary left; SIGTERM the same with 143; a
# second SIGINT ends the process at once (the export in place still whole: its entry point is
# renamed last).
# GRASS_TEST_SAVE_DELAY_MS holds each staged file 400 ms, so the signal lands while it writes.
#
#   interrupt_export_test.sh GRASS_BIN SOURCE_PROJECT WORK_DIR
set -u
source "$(dirname "$0")/interrupt_lib.sh"
bin=$1
source=$2
work=$3

fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf -- "$work" && mkdir -p -- "$work" && cp -R -- "$source/." "$work/p" || fail "cannot copy $source"
project=$work/p
out=$work/export
"$bin" export "$project" --out "$out" >/dev/null 2>&1 || fail "a plain export fails"
before=$(cd "$out" && find . -type f | sort | xargs md5sum)
cp "$out/grass.gltf" "$work/grass.gltf.before" || fail "the export wrote no grass.gltf"
temporaries() { find "$1" -name '.*.tmp-*' | wc -l; }

# interrupt SIGNALS...: an export at LOD 1 (other files than those in place), each signal sent
# once it is writing (300 ms apart); prints its exit status. Its stderr is in $work/err.
interrupt() {
    GRASS_TEST_SAVE_DELAY_MS=400 "$bin" export "$project" --out "$out" --lod 1 \
        >/dev/null 2>"$work/err" &
    interrupt_when "writing" "$work/err" $! "$@"
    echo "$interrupted_status"
}
unchanged() {
    [[ $(cd "$out" && find . -type f | sort | xargs md5sum) == "$before" ]] ||
        fail "$1: the export in place changed"
}

status=$(interrupt INT)
[[ $status == 130 ]] || fail "SIGINT: exit $status, not 130: $(cat "$work/err")"
grep -q "the export was stopped: nothing was written" "$work/err" ||
    fail "SIGINT: no word of the stop: $(cat "$work/err")"
(( $(temporaries "$out") == 0 )) || fail "SIGINT: staged temporaries left"
unchanged SIGINT
echo "SIGINT: exit 130, folder unchanged, no temporary: $(tail -n 1 "$work/err")"

status=$(interrupt TERM)
[[ $status == 143 ]] || fail "SIGTERM: exit $status, not 143: $(cat "$work/err")"
(( $(temporaries "$out") == 0 )) || fail "SIGTERM: staged temporaries left"
unchanged SIGTERM
echo "SIGTERM: exit 143, folder unchanged, no temporary"

start=$(date +%s%3N)
status=$(interrupt INT INT)
ms=$(( $(date +%s%3N) - start ))
[[ $status == 130 ]] || fail "two SIGINTs: exit $status, not 130: $(cat "$work/err")"
# Ended at once, it may leave new content-named files beside the old ones (core/export/
# content_names.h: the entry point is renamed last), but the export in place is the old one.
cmp -s "$out/grass.gltf" "$work/grass.gltf.before" || fail "two SIGINTs: grass.gltf changed"
"$bin" mesh-info "$out/grass.gltf" >/dev/null 2>"$work/info.err" ||
    fail "two SIGINTs: the export in place does not load: $(cat "$work/info.err")"
echo "two SIGINTs: exit 130 in $ms ms, the export in place unchanged and loading"
# Whatever a second signal left, the next export clears it and writes.
"$bin" export "$project" --out "$out" --lod 1 >/dev/null 2>&1 || fail "the export after fails"
(( $(temporaries "$out") == 0 )) || fail "temporaries left after the next export"
echo "the next export writes and leaves no temporary"
