# CLI tests of `grass render --shape` (SPEC §7 blade shapes, issue 5). Included from
# cli_tests.cmake, after grass_cli_test() is defined; tiny project, tiny image, one frame.

grass_cli_test(render_shape_dandelion GL OK --png ${GRASS_CLI_TMP}/shape-dandelion.png 64 48
    --stdout "^wrote .*shape-dandelion\\.png \\(64x48\\)$"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/shape-dandelion.png
       --width 64 --height 48 --frames 1 --shape dandelion)
grass_cli_test(render_shape_unknown ERROR "--shape" --also "dandelion"
    --absent ${GRASS_CLI_TMP}/shape-bogus.png
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/shape-bogus.png
       --shape bogus)
