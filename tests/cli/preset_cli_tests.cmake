# CLI tests of the quality presets (issue 10, item 2). Included from cli_tests.cmake, after
# grass_cli_test() is defined. The windy project steps 0.02 s: the reference preset's 1/960 s
# substep makes 20 substeps a step, draft's 1/30 s one.

grass_cli_test(presets_table OK --no-stderr
    --stdout "^\\| knob \\| draft \\| balanced \\| high \\| reference \\| measured on \\|$"
    --stdout "^\\| `physics_step` \\| \\*\\*1/"
    --stdout "^\\| `geometry_detail` \\| \\*\\*[0-9]+\\*\\*: "
    --stdout "^\\| `snow_map` \\| "
    --stdout "^Measured on: "
    -- ${GRASS_BIN} presets)
grass_cli_test(presets_help OK --no-stderr --stdout "^usage: grass presets"
    -- ${GRASS_BIN} presets --help)
# docs/presets.md shows exactly what `grass presets` prints (the table cannot drift).
add_test(NAME cli.presets_doc_matches
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/presets_doc_test.sh ${GRASS_BIN}
                 ${PROJECT_SOURCE_DIR}/docs/presets.md)
set_tests_properties(cli.presets_doc_matches PROPERTIES LABELS cli TIMEOUT 30)

grass_cli_test(sim_preset_reference OK
    --stdout "^simulated 0\\.100 s of windy: 5 steps of 0\\.02 s \\(20 substeps each\\)"
    -- ${GRASS_BIN} sim ${GRASS_CLI_PROJECTS}/windy --seconds 0.1 --preset reference)
grass_cli_test(sim_preset_draft OK
    --stdout "^simulated 0\\.100 s of windy: 5 steps of 0\\.02 s \\(1 substeps each\\)"
    -- ${GRASS_BIN} sim ${GRASS_CLI_PROJECTS}/windy --seconds 0.1 --preset draft)
# An explicit --lod-distance wins over the preset's (reference: LOD off).
grass_cli_test(render_preset_reference GL OK
    --stdout "--lod-distance 0 m\\)$"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --preset reference --frames 1
       --out ${GRASS_CLI_TMP}/preset-reference.png)
grass_cli_test(render_preset_flag_wins GL OK
    --stdout "--lod-distance 3 m\\)$"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --preset reference --lod-distance 3
       --frames 1 --out ${GRASS_CLI_TMP}/preset-flag.png)
grass_cli_test(export_preset OK
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --preset draft --format gltf
       --out ${GRASS_CLI_TMP}/preset-export)
grass_cli_test(render_unknown_preset ERROR "--preset" --also "draft"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --preset fast)
grass_cli_test(sim_unknown_preset ERROR "--preset"
    -- ${GRASS_BIN} sim ${GRASS_CLI_PROJECTS}/tiny --preset ultra)

# Ctrl+C during a sweep: it ends after the knob under way and the knobs measured are written;
# during a turntable, after the view under way with the sheet of the views done; exit 130
# (interrupt_gl_runs_test.sh; about 15 s on llvmpipe).
add_test(NAME cli.gl_runs_interrupted
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/interrupt_gl_runs_test.sh ${GRASS_BIN}
                 ${GRASS_CLI_PROJECTS}/tiny ${GRASS_CLI_TMP}/gl-runs-interrupted)
set_tests_properties(cli.gl_runs_interrupted PROPERTIES LABELS "cli;gl" TIMEOUT 180
    PASS_REGULAR_EXPRESSION "tradeoff interrupted: exit 130, 2 of 3 knobs written\nturntable interrupted: exit 130, the views done and their sheet written"
    ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")

# --replot: tables and plots again from a tradeoff.json, nothing measured (no GL needed). The
# presets column marks the settings the presets' rule picks from that run.
set(REPLOT ${GRASS_CLI_TMP}/replot)
add_test(NAME cli.tradeoff_replot_setup
         COMMAND ${CMAKE_COMMAND} -E copy ${PROJECT_SOURCE_DIR}/core/quality/measured/meadow_ao.json
                 ${REPLOT}/tradeoff.json)
set_tests_properties(cli.tradeoff_replot_setup PROPERTIES LABELS cli FIXTURES_SETUP replot_json)
grass_cli_test(tradeoff_replot OK
    --stdout "^\\| setting \\| .* \\| presets \\|$"
    --stdout "^\\| exact \\(ref\\) \\|.*\\| reference \\|$"
    --stdout "^wrote .*tradeoff\\.md and [0-9]+ plot files$"
    --file ${REPLOT}/ao_kernel.dat "\"reference\"$"
    -- ${GRASS_BIN} tradeoff --replot ${REPLOT})
set_tests_properties(cli.tradeoff_replot PROPERTIES FIXTURES_REQUIRED replot_json)
grass_cli_test(tradeoff_replot_missing ERROR "--replot" --also "no-such-dir/tradeoff.json"
    -- ${GRASS_BIN} tradeoff --replot ${GRASS_CLI_TMP}/no-such-dir)
add_test(NAME cli.tradeoff_replot_project_setup
         COMMAND ${CMAKE_COMMAND} -E copy ${GRASS_CLI_PROJECTS}/tiny/project.json
                 ${GRASS_CLI_TMP}/not-tradeoff/tradeoff.json)
set_tests_properties(cli.tradeoff_replot_project_setup PROPERTIES LABELS cli
    FIXTURES_SETUP replot_project)
grass_cli_test(tradeoff_replot_not_tradeoff ERROR "not-tradeoff/tradeoff.json" --also "knobs"
    -- ${GRASS_BIN} tradeoff --replot ${GRASS_CLI_TMP}/not-tradeoff)
set_tests_properties(cli.tradeoff_replot_not_tradeoff PROPERTIES FIXTURES_REQUIRED replot_project)
# --msaa takes the sample counts render and bench take; 3 is refused before anything is measured.
grass_cli_test(tradeoff_msaa_three ERROR "--msaa" --also "1|2|4|8"
    -- ${GRASS_BIN} tradeoff ${GRASS_CLI_PROJECTS}/tiny --msaa 3)
