# The reference runtime (issue 28): its sample host in a real X window, its errors, and a
# program linking the runtime alone. Included from cli_tests.cmake.
if(NOT TARGET grass-runtime-sample)
    return()
endif()
set(GRASS_SAMPLE_BIN $<TARGET_FILE:grass-runtime-sample>)

# A small project exported raw, drawn for a few frames with a screenshot, then the ball moved by
# the left button held (xdotool) at the window's centre; about 25 s on llvmpipe.
add_test(NAME cli.runtime_sample
         COMMAND ${GRASS_XVFB_RUN} -a -s "-screen 0 1024x768x24"
                 ${GRASS_BASH} ${GRASS_CLI_DIR}/runtime_sample_test.sh ${GRASS_BIN}
                 ${GRASS_SAMPLE_BIN} ${GRASS_CLI_TMP}/runtime-sample)
set_tests_properties(cli.runtime_sample PROPERTIES LABELS "cli;gl" TIMEOUT 180
    PASS_REGULAR_EXPRESSION "runtime sample: screenshot written, the ball followed the mouse"
    ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")

grass_cli_test(runtime_sample_help OK --stdout "^usage: grass-runtime-sample EXPORT"
    --stdout "^  --frames N" -- ${GRASS_SAMPLE_BIN} --help)
# Bad input: one line naming the file or option, before any window opens (so no display here).
grass_cli_test(runtime_sample_no_export ERROR "manifest.json" --also "cannot be opened"
    -- ${GRASS_SAMPLE_BIN} ${GRASS_CLI_TMP}/runtime-no-such-export)
grass_cli_test(runtime_sample_not_raw ERROR "manifest.json" --also "not a raw grass export"
    -- ${GRASS_SAMPLE_BIN} ${GRASS_CLI_DATA}/runtime)
grass_cli_test(runtime_sample_bad_frames ERROR "--frames" --also "\"many\""
    -- ${GRASS_SAMPLE_BIN} ${GRASS_CLI_TMP} --frames many)
grass_cli_test(runtime_sample_bad_size ERROR "--size" --also "WxH"
    -- ${GRASS_SAMPLE_BIN} ${GRASS_CLI_TMP} --size 10)
grass_cli_test(runtime_sample_screenshot_without_frames ERROR "--screenshot: needs --frames"
    -- ${GRASS_SAMPLE_BIN} ${GRASS_CLI_TMP} --screenshot x.png)

# Links nothing but the runtime's stated dependencies (GL through epoxy, GLM, nlohmann-json).
add_executable(runtime_link_check ${CMAKE_SOURCE_DIR}/tests/runtime/runtime_link_check.cpp)
target_link_libraries(runtime_link_check PRIVATE grass_runtime)
add_test(NAME cli.runtime_link_only
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/runtime_link_test.sh ${GRASS_BIN}
                 $<TARGET_FILE:runtime_link_check> ${GRASS_CLI_PROJECTS}/tiny
                 ${GRASS_CLI_TMP}/runtime-link)
set_tests_properties(cli.runtime_link_only PROPERTIES LABELS cli TIMEOUT 120
    PASS_REGULAR_EXPRESSION "runtime export: 1 layers, [1-9][0-9]* blades")
