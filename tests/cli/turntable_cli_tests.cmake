# CLI tests of `grass render --turntable N` (issue 8: turntables for artists to share results).
# Included from cli_tests.cmake, after grass_cli_test().
#
# The tiny project (tests/data/projects/tiny) renders 64 × 48 views without MSAA: a turn of 4
# takes well under a second on llvmpipe. Its contact sheet is one row of 4 full-size cells with
# 2 px borders: (4·64 + 5·2) × (48 + 2·2) = 266 × 52 (tests/core/util/contact_sheet_test.cpp).

set(TURN_TMP ${GRASS_CLI_TMP}/turntable)
set(TURN_OUT ${TURN_TMP}/tiny.png)
# The --time turn writes elsewhere: the file check below expects the tiny turn's files alone,
# and the two may run in parallel.
set(TURN_TIME_TMP ${GRASS_CLI_TMP}/turntable_time)
add_test(NAME cli.turntable_setup
         COMMAND ${GRASS_BASH} -c
                 "rm -rf -- \"$0\" \"$1\" && mkdir -p -- \"$0\" \"$1\"" ${TURN_TMP} ${TURN_TIME_TMP})
set_tests_properties(cli.turntable_setup PROPERTIES LABELS cli TIMEOUT 30
                     FIXTURES_SETUP turntable_clean)

grass_cli_test(render_help_turntable OK --no-stderr --stdout "^  --turntable N"
    -- ${GRASS_BIN} render --help)

grass_cli_test(render_turntable_tiny GL OK --png ${TURN_TMP}/tiny_sheet.png 266 52
    --stdout "^wrote 4 frames .*tiny_0000\\.png \\.\\. .*tiny_0003\\.png \\(64x48\\)$"
    --stdout "^wrote .*tiny_sheet\\.png \\(266x52, 4 of 4 frames in 4 column\\(s\\)\\)$"
    --stderr "turntable frame 1/4 " --stderr "turntable frame 4/4 "
    -- ${GRASS_BIN} render ${TINY} --turntable 4 --out ${TURN_OUT})
set_tests_properties(cli.render_turntable_tiny PROPERTIES FIXTURES_REQUIRED turntable_clean
                     FIXTURES_SETUP turntable_rendered)

# Exactly the 4 views and the sheet (no --out image, no temporary file left behind), each view
# a 64 × 48 PNG: the width and height are the big-endian words at bytes 16 and 20 (IHDR).
set(TURN_CHECK [=[
cd -- "$0" || exit 1
expected="tiny_0000.png tiny_0001.png tiny_0002.png tiny_0003.png tiny_sheet.png"
actual=$(LC_ALL=C ls -A | tr '\n' ' ' | sed 's/ $//')
if [ "$actual" != "$expected" ]; then echo "files: '$actual', expected '$expected'"; exit 1; fi
for f in tiny_000?.png; do
    size=$(od -An -tu1 -j16 -N8 -- "$f" | tr -s ' ' | sed 's/^ //')
    if [ "$size" != "0 0 0 64 0 0 0 48" ]; then echo "$f: IHDR size bytes '$size'"; exit 1; fi
done
]=])
add_test(NAME cli.render_turntable_tiny_files COMMAND ${GRASS_BASH} -c "${TURN_CHECK}" ${TURN_TMP})
set_tests_properties(cli.render_turntable_tiny_files PROPERTIES LABELS "cli;gl" TIMEOUT 30
    FIXTURES_REQUIRED turntable_rendered)

# --time simulates once; every view shows that moment (the frames need not differ in wind).
grass_cli_test(render_turntable_time GL OK --png ${TURN_TIME_TMP}/windy_sheet.png 262 108
    --stdout "^simulated +0\\.200 s in 10 steps on the cpu" --stdout "^wrote 2 frames "
    -- ${GRASS_BIN} render ${WINDY} --time 0.2 --backend cpu --turntable 2
       --width 128 --height 104 --msaa 0 --out ${TURN_TIME_TMP}/windy.png)
set_tests_properties(cli.render_turntable_time PROPERTIES FIXTURES_REQUIRED turntable_clean)

# Bad counts: one line naming --turntable and its range, exit code 2 (a bad command line), and
# nothing written. They fail in the argument parser, before any GL context.
set(TURN_BAD_OUT ${GRASS_CLI_TMP}/turntable-never.png)
foreach(pair IN ITEMS zero:0 one:1 negative:-4 too_many:3601 not_a_number:abc fraction:2.5)
    string(REPLACE ":" ";" pair "${pair}")
    list(GET pair 0 badName)
    list(GET pair 1 bad)
    grass_cli_test(render_turntable_${badName} ERROR "--turntable" --also "from 2 to 3600"
        --also "'${bad}'" --absent ${TURN_BAD_OUT} --absent ${GRASS_CLI_TMP}/turntable-never_0000.png
        -- ${GRASS_BIN} render ${TINY} --turntable ${bad} --out ${TURN_BAD_OUT})
endforeach()
grass_cli_test(render_turntable_missing_value ERROR "--turntable" --absent ${TURN_BAD_OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${TURN_BAD_OUT} --turntable)
add_test(NAME cli.render_turntable_bad_exit_code
         COMMAND ${GRASS_BASH} -c
                 "for v in 0 -4 abc; do \"$0\" render \"$1\" --turntable $v --out \"$2\" 2>/dev/null; rc=$?; [ $rc -eq 2 ] || { echo \"--turntable $v: exit code $rc, expected 2\"; exit 1; }; done"
                 ${GRASS_BIN} ${TINY} ${TURN_BAD_OUT})
set_tests_properties(cli.render_turntable_bad_exit_code PROPERTIES LABELS cli TIMEOUT 30)
