# CLI tests of `grass render --technique`, `--animation`, `--lighting` and `--lod-distance`
# (SPEC §7, §8, §10; issue 5). Included from cli_tests.cmake, after grass_cli_test() is defined;
# tiny project, tiny image, one frame.

grass_cli_test(render_technique_billboards GL OK
    --stdout "^  technique  billboards; billboards drawn [1-9][0-9]* in 1 draw call"
    --file ${GRASS_CLI_TMP}/billboards-stats.json "\"billboards\": \\{\"drawn\": [1-9][0-9]*, \"draw_calls\": 1"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/billboards.png
       --width 64 --height 48 --frames 1 --technique billboards
       --stats ${GRASS_CLI_TMP}/billboards-stats.json)
grass_cli_test(render_technique_hybrid_per_cluster GL OK
    --stdout "^  technique  hybrid; billboards drawn [0-9]+ in [0-9]+ draw call"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/hybrid.png
       --width 64 --height 48 --frames 1 --technique hybrid --animation per-cluster)
grass_cli_test(render_lighting_simple_lod GL OK
    --stdout "^  detail     drawn per LOD [0-9]+ / 0 / 0 .*--lod-distance 0 m"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/simple.png
       --width 64 --height 48 --frames 1 --lighting simple --lod-distance 0)
grass_cli_test(render_technique_unknown ERROR "--technique" --also "hybrid"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --technique sprites)
grass_cli_test(render_lod_distance_negative ERROR "--lod-distance"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --lod-distance -1)
