# grass soak (issue 11): the bounded version of the hour-long soak, on the small windy project (400
# blades, a vortex and a ball on one-second paths that soak drives forth and back). Included from
# cli_tests.cmake, after grass_cli_test() and WINDY are defined. docs/soak.md has the full hour.

grass_cli_test(soak_help OK --no-stderr
    --stdout "^usage: grass soak" --stdout "^  --seconds S" --stdout "^  --backend"
    --stdout "^  --sample-every S" --stdout "^  --report FILE" --stdout "1e-4\\*h"
    -- ${GRASS_BIN} soak --help)

# 5 minutes of game time at 60 Hz on the CPU (18 000 steps, ~15 s on one idle core) and 10 minutes
# on the GPU (36 000 steps, ~12 s on llvmpipe), 10 samples each: every check passes and says so.
set(SOAK_REPORT ${GRASS_CLI_TMP}/soak-windy.json)
grass_cli_test(soak_windy_cpu OK
    --stdout "^soak of windy: 300\\.000 s at dt 0\\.01667 s \\(18000 steps\\), wind 2 source\\(s\\), 1 collider sphere\\(s\\), 2 path\\(s\\) driven forth and back \\(longest period 2 s\\)$"
    --stdout "^cpu \\(CPU reference, 1 thread\\): 400 blades, 18000 steps, 300\\.000 s simulated"
    --stdout "^  length .* ok$" --stdout "^  nonfinite  0  ok$" --stdout "^  RSS .* ok$"
    --stdout "^soak passed$" --stderr "^soak cpu: t = 300\\.0/300 s \\(100 %\\)"
    --file ${SOAK_REPORT} "\"passed\": true"
    --file ${SOAK_REPORT} "\"heap_in_use_end_bytes\": [0-9]+,"
    --stdout "^  RSS .*; heap in use [-+][0-9.]+ MiB\\)  ok$"
    -- ${GRASS_BIN} soak ${WINDY} --seconds 300 --sample-every 30 --backend cpu --threads 1
       --report ${SOAK_REPORT})
grass_cli_test(soak_windy_gpu GL OK
    --stdout "^gpu \\(.*\\): 400 blades, 36000 steps, 600\\.000 s simulated"
    --stdout "^  length .* ok$" --stdout "^  nonfinite  0  ok$" --stdout "^  RSS .* ok$"
    --stdout "^  GL +before set-up none; after set-up [1-9].* buffers.*; after tear-down none  ok$"
    --stdout "^soak passed$"
    -- ${GRASS_BIN} soak ${WINDY} --seconds 600 --sample-every 60 --backend gpu)

# Ctrl+C during an hour's soak: the run under way ends at its next step, what ran is judged,
# printed and saved ("stopped": true), exit 130, and a "both" soak does not start the GPU; an
# day's sim ends with the summary and report of the steps run (interrupt_runs_test.sh; a few
# seconds).
add_test(NAME cli.long_runs_interrupted
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/interrupt_runs_test.sh ${GRASS_BIN} ${WINDY}
                 ${GRASS_CLI_TMP}/runs-interrupted)
set_tests_properties(cli.long_runs_interrupted PROPERTIES LABELS cli TIMEOUT 120
    PASS_REGULAR_EXPRESSION "soak interrupted: exit 130, [1-9][0-9]* samples judged and saved\nsim interrupted: exit 130, \"steps\": [1-9][0-9]* summed up and saved")

# --density-scale thins the field (how projects/nature's hour fits a slow machine, docs/soak.md):
# windy at a quarter of its density grows fewer blades, and the report says the scale.
set(SOAK_THIN_REPORT ${GRASS_CLI_TMP}/soak-windy-thin.json)
grass_cli_test(soak_density_scale OK
    --stdout "^cpu \\(CPU reference, 1 thread\\): 100 blades, 60 steps"
    --stdout "^soak passed$" --file ${SOAK_THIN_REPORT} "\"density_scale\": 0\\.25"
    -- ${GRASS_BIN} soak ${WINDY} --seconds 1 --backend cpu --threads 1 --density-scale 0.25
       --report ${SOAK_THIN_REPORT})

# Bad command lines fail before anything runs.
grass_cli_test(soak_density_scale_zero ERROR "--density-scale" --also "expected"
    -- ${GRASS_BIN} soak ${WINDY} --density-scale 0)
grass_cli_test(soak_density_scale_above_one ERROR "--density-scale" --also "expected"
    -- ${GRASS_BIN} soak ${WINDY} --density-scale 2)
grass_cli_test(soak_seconds_nan ERROR "--seconds" -- ${GRASS_BIN} soak ${WINDY} --seconds nan)
grass_cli_test(soak_seconds_negative ERROR "--seconds" -- ${GRASS_BIN} soak ${WINDY} --seconds -60)
grass_cli_test(soak_dt_zero ERROR "--dt" -- ${GRASS_BIN} soak ${WINDY} --dt 0)
grass_cli_test(soak_sample_every_zero ERROR "--sample-every"
    -- ${GRASS_BIN} soak ${WINDY} --sample-every 0)
grass_cli_test(soak_backend_unknown ERROR "--backend" -- ${GRASS_BIN} soak ${WINDY} --backend tpu)
grass_cli_test(soak_no_project ERROR "project" -- ${GRASS_BIN} soak)
grass_cli_test(soak_report_folder_missing ERROR "no-such-folder"
    --absent ${GRASS_CLI_TMP}/no-such-folder
    -- ${GRASS_BIN} soak ${WINDY} --seconds 1 --report ${GRASS_CLI_TMP}/no-such-folder/s.json)

# Under AddressSanitizer the quarantine holds freed memory back from reuse (to catch use after
# free), and with the driver's allocations on every GPU dispatch it grew RSS by 4.7 GiB over the
# 36 000 steps, which the RSS check rightly fails; with no quarantine RSS stays flat (measured:
# 389 → 1449 MiB over 120 s of game time with it, 365 → 545 MiB, −6.7 after warm-up, without).
# The soaks measure memory, so in a sanitizer build they run without the quarantine.
if(GRASS_SANITIZE)
    set_property(TEST cli.soak_windy_cpu cli.soak_windy_gpu APPEND PROPERTY
        ENVIRONMENT_MODIFICATION "ASAN_OPTIONS=string_append:quarantine_size_mb=0:")
endif()
