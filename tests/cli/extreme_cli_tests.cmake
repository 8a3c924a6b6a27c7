# Extreme values on the command line (issue 11). Included from cli_tests.cmake, after
# grass_cli_test() is defined.

# Every numeric option of every command × 0, -1, nan, inf, -inf, 1e300, abc, "": refused with one
# line naming the option and its range, or parsed when inside it (extreme_options_test.sh prints
# the count). Parsing only, but each run starts the binary (~0.5 s of dynamic linking): 296 runs,
# four at a time, about 3 minutes on 2 busy cores. No GL.
add_test(NAME cli.extreme_option_values
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/extreme_options_test.sh ${GRASS_BIN})
set_tests_properties(cli.extreme_option_values PROPERTIES LABELS cli TIMEOUT 600
    PASS_REGULAR_EXPRESSION "extreme options: [0-9]+ numeric options .*all refused")

# A frame buffer beyond the limit is refused before the scene is grown or a context is made,
# with the memory it would need.
grass_cli_test(render_framebuffer_too_big ERROR "--width/--height/--msaa" --also "GiB"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --width 16384 --height 16384 --msaa 8
       --out ${GRASS_CLI_TMP}/huge-frame.png)
set_tests_properties(cli.render_framebuffer_too_big PROPERTIES ENVIRONMENT GRASS_CLI_TIMEOUT=20)
