# CLI tests of `grass bench` (issue 10, item 4). Included from cli_tests.cmake, after
# grass_cli_test() is defined. The measuring test runs the tiny case only (80 blades, one timed
# frame): about a second on llvmpipe. The error tests fail before any GL work.

grass_cli_test(bench_help OK --no-stderr
    --stdout "^usage: grass bench" --stdout "^  --cases LIST" --stdout "^  --quick"
    --stdout "^  --frames N" --stdout "^  --out FILE\\.json" --stdout "^  --compare OLD\\.json"
    --stdout "^  --results FILE\\.json" --stdout "^  --help"
    -- ${GRASS_BIN} bench --help)

# --out writes every figure with sane values; a saved run compared with itself gives 1.00; a run
# at another size refuses the comparison; Ctrl+C after the first case prints and saves the cases
# measured (bench_cli_test.sh).
add_test(NAME cli.bench_tiny_out_compare
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/bench_cli_test.sh ${GRASS_BIN}
                 ${GRASS_CLI_TMP}/bench)
set_tests_properties(cli.bench_tiny_out_compare PROPERTIES LABELS "cli;gl" TIMEOUT 150
    ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")

# The editor case (issue 24): the real editor window (under xvfb-run when there is no display)
# orbits, paints and plays the meadow at wall-clock time, and the run reports every figure of
# cases[].editor. Behaviour only: the figures are printed, not judged. About 40 s. The session
# opens a copy of the meadow that is deleted afterwards, which must not land in the user's
# recent projects (the test's own configuration folder stays without a recent.json).
if(TARGET grass-editor)
    grass_cli_test(bench_editor_case GL OK
        --absent ${GRASS_CLI_TMP}/bench-editor-config/grass/recent.json
        --stdout "^editor-meadow \\(the editor window, wall clock\\): orbit median [0-9.]+ ms, p95 [0-9.]+ ms \\([1-9][0-9]* frames\\); paint median"
        --stdout "full picture [0-9.]+ s after input stops; physics at [0-9.]+ of real time"
        --file ${GRASS_CLI_TMP}/bench-editor.json "\"realtime_factor\": [0-9.]+"
        --file ${GRASS_CLI_TMP}/bench-editor.json "\"p95_ms\": [0-9.]+"
        -- ${GRASS_BIN} bench --cases editor-meadow --out ${GRASS_CLI_TMP}/bench-editor.json)
    set_tests_properties(cli.bench_editor_case PROPERTIES TIMEOUT 300
        ENVIRONMENT "XDG_CONFIG_HOME=${GRASS_CLI_TMP}/bench-editor-config")
endif()

# A case with a technique of its own (nature-1m-hybrid's, on the tiny project): the project is
# grown and drawn as the hybrid technique, billboards and all, and measured like any case.
grass_cli_test(bench_technique_case GL OK
    --stderr "tiny-hybrid: technique hybrid instead of the project's"
    --stdout "^tiny-hybrid +1 +[1-9][0-9]* "
    -- ${GRASS_BIN} bench --cases tiny-hybrid --frames 1 --steps 1)

# --compare files that are not a bench run: named in one line, exit non-zero, nothing measured.
grass_cli_test(bench_compare_missing ERROR "no-such-run.json"
    -- ${GRASS_BIN} bench --cases tiny --compare ${GRASS_CLI_TMP}/no-such-run.json)
grass_cli_test(bench_compare_not_json ERROR "cube.glb" --also "not valid JSON"
    -- ${GRASS_BIN} bench --cases tiny --compare ${GRASS_CLI_GLTF}/cube.glb)
grass_cli_test(bench_compare_not_bench ERROR "tiny/project.json" --also "not a grass bench result"
    -- ${GRASS_BIN} bench --cases tiny --compare ${GRASS_CLI_PROJECTS}/tiny/project.json)
grass_cli_test(bench_unknown_case ERROR "--cases" --also "unknown case \"meadow-5k\""
    --also "nature-100k"
    -- ${GRASS_BIN} bench --cases tiny,meadow-5k)
grass_cli_test(bench_quick_leaves_none ERROR "--quick"
    -- ${GRASS_BIN} bench --quick --cases nature-1m)
grass_cli_test(bench_bad_frames ERROR "--frames"
    -- ${GRASS_BIN} bench --cases tiny --frames 0)
grass_cli_test(bench_results_with_cases ERROR "--cases" --also "--results"
    -- ${GRASS_BIN} bench --results ${GRASS_CLI_TMP}/any.json --cases tiny)
grass_cli_test(bench_out_folder_missing ERROR "no-such-folder"
    -- ${GRASS_BIN} bench --cases tiny --out ${GRASS_CLI_TMP}/no-such-folder/bench.json)
