# CLI tests of `grass render --cull` and `--stats` (SPEC §6). Included from cli_tests.cmake,
# after grass_cli_test() is defined; tiny project, tiny image, one frame.

grass_cli_test(render_cull_stats GL OK
    --stdout "^  culling +[0-9]+ in, [0-9]+ drawn"
    --file ${GRASS_CLI_TMP}/cull-stats.json "\"blades_in\": [0-9]+"
    --file ${GRASS_CLI_TMP}/cull-stats.json "\"culled\": \\{\"patch\": [0-9]+, \"orientation\": [0-9]+, \"frustum\": [0-9]+, \"distance\": [0-9]+, \"occlusion\": [0-9]+, \"snow\": [0-9]+\\}"
    --file ${GRASS_CLI_TMP}/cull-stats.json "\"ms\": \\{\"physics\": "
    --file ${GRASS_CLI_TMP}/cull-stats.json "\"passes\": \\[\"opaque\", \"cull\", \"blades\"\\]"
    --file ${GRASS_CLI_TMP}/cull-stats.json "\"allocated\": \\[\\]"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/cull.png
       --width 64 --height 48 --frames 1 --cull frustum,distance --stats ${GRASS_CLI_TMP}/cull-stats.json)
grass_cli_test(render_cull_none_draws_all GL OK
    --stdout "^  culling +([0-9]+) in, [0-9]+ drawn \\(100\\.0 %\\)"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/cull-none.png
       --width 64 --height 48 --frames 1 --cull none)
grass_cli_test(render_cull_unknown_test ERROR "--cull" --also "orientation, frustum, distance, occlusion"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --cull orientation,sideways)
grass_cli_test(render_stats_folder_missing ERROR "no-such-folder"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --stats ${GRASS_CLI_TMP}/no-such-folder/s.json)
# Lighting per pixel everywhere (the far LODs are lit per vertex by default) renders; asking for
# both extremes at once is refused naming the option.
grass_cli_test(render_light_per_pixel GL OK
    --stdout "^wrote .*light-per-pixel.png"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/light-per-pixel.png
       --width 64 --height 48 --frames 1 --light-per-pixel)
grass_cli_test(render_light_per_pixel_and_vertex ERROR "--light-per-pixel" --also "--light-per-vertex"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --light-per-pixel --light-per-vertex)
# The snow surface's exposure per pixel (the default on a GPU) renders on software GL too; an
# unknown choice is refused naming the option and the choices.
grass_cli_test(render_snow_exposure_pixel GL OK
    --stdout "^wrote .*snow-exposure-pixel.png"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/snow-exposure-pixel.png
       --width 64 --height 48 --frames 1 --snow --snow-exposure pixel)
grass_cli_test(render_snow_exposure_unknown ERROR "--snow-exposure" --also "vertex"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --snow-exposure texel)
