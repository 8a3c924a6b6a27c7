# Extreme values on the command line (issue 11). Included from cli_tests.cmake, after
# grass_cli_test() is defined.

# A frame buffer beyond the limit is refused before the scene is grown or a context is made,
# with the memory it would need.
grass_cli_test(render_framebuffer_too_big ERROR "--width/--height/--msaa" --also "GiB"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --width 16384 --height 16384 --msaa 8
       --out ${GRASS_CLI_TMP}/huge-frame.png)
set_tests_properties(cli.render_framebuffer_too_big PROPERTIES ENVIRONMENT GRASS_CLI_TIMEOUT=20)
