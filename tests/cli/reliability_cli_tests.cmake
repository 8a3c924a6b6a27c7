# Reliability tests of the command-line tools (issue 11). Included from cli_tests.cmake, after
# grass_cli_test() is defined.

# Saves survive a kill: 25 paint runs and 12 export runs SIGKILLed at random points, most of them
# mid-save (kill_save_test.sh prints the counts); about a minute on 2 cores. No GL.
add_test(NAME cli.kill_during_save
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/kill_save_test.sh ${GRASS_BIN}
                 ${GRASS_CLI_PROJECTS}/growth_tiny ${GRASS_CLI_TMP}/kill-save 25 12)
set_tests_properties(cli.kill_during_save PROPERTIES LABELS cli TIMEOUT 300
    PASS_REGULAR_EXPRESSION "^paint: 25 runs .*\nexport: 12 runs ")

# Ctrl+C during an export stops it at its next stage: exit 130 (143 for SIGTERM), one line, the
# folder as it was, no staged temporary; a second Ctrl+C ends it at once (interrupt_export_test.sh).
add_test(NAME cli.export_interrupted
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/interrupt_export_test.sh ${GRASS_BIN}
                 ${GRASS_CLI_PROJECTS}/growth_tiny ${GRASS_CLI_TMP}/export-interrupted)
set_tests_properties(cli.export_interrupted PROPERTIES LABELS cli TIMEOUT 120
    PASS_REGULAR_EXPRESSION "the next export writes and leaves no temporary")

# The editor's autosave survives a kill: 10 painting sessions SIGKILLed at random moments, each
# next one recovering the autosave (kill_autosave_test.sh); under Xvfb, about a minute.
if(TARGET grass-editor)
    add_test(NAME cli.kill_during_autosave
             COMMAND ${GRASS_XVFB_RUN} -a -s "-screen 0 1024x768x24"
                     ${GRASS_BASH} ${GRASS_CLI_DIR}/kill_autosave_test.sh
                     $<TARGET_FILE:grass-editor> ${GRASS_BIN} ${GRASS_CLI_TMP}/kill-autosave 10)
    set_tests_properties(cli.kill_during_autosave PROPERTIES LABELS "cli;gl" TIMEOUT 400
        PASS_REGULAR_EXPRESSION "autosave: 10 sessions killed"
        ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")
    # A real-window test: `script` under Xvfb with real X input (xdotool) at about one frame a
    # second, passing when its output holds `pass`; the editor and ARGN are its arguments.
    function(editor_window_test name script timeout pass)
        add_test(NAME cli.${name}
                 COMMAND ${GRASS_XVFB_RUN} -a -s "-screen 0 1024x768x24"
                         ${GRASS_BASH} ${GRASS_CLI_DIR}/${script} $<TARGET_FILE:grass-editor> ${ARGN})
        set_tests_properties(cli.${name} PROPERTIES LABELS "cli;gl" TIMEOUT ${timeout}
            PASS_REGULAR_EXPRESSION "${pass}"
            ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")
    endfunction()
    # Ctrl+C or SIGTERM: the unsaved changes go into the autosave, exit 130/143; about 20 s.
    editor_window_test(editor_real_terminate editor_real_terminate_test.sh 120
        "real terminate: SIGINT with nothing unsaved ends at once; SIGTERM keeps the typed name"
        ${GRASS_CLI_TMP}/editor-real-terminate)
    # Quick clicks, a double-click and typing all reach the project (issue 24); about 30 s.
    editor_window_test(editor_real_input editor_real_input_test.sh 120
        "real input: name typed, quick click, double-click" ${GRASS_CLI_TMP}/editor-real-input)
    # A gizmo drag inside one frame (press, motion and release by xdotool within milliseconds)
    # moves the ball as far as the same drag over frames; about 20 s.
    editor_window_test(editor_real_flick editor_real_flick_test.sh 120
        "real flick: the ball went down" ${GRASS_CLI_TMP}/editor-real-flick)
    # The artist's own mesh (issue 26): File › New from mesh…, a typed path in the file browser,
    # Save As by Ctrl+S, a refused typed value, Ctrl+O and the recent list; about 50 s.
    editor_window_test(editor_real_import editor_real_import_test.sh 150
        "real import: new from mesh, browser typing, save as"
        ${CMAKE_SOURCE_DIR}/tests/data/gltf/cube.glb ${GRASS_CLI_TMP}/editor-real-import)
    # Species painted with the map overlay (issue 27): a layer added, chosen for the brush, a
    # subtract stroke with "show map" on, Ctrl+S; about 55 s.
    editor_window_test(editor_real_species editor_real_species_test.sh 150
        "real species: a layer added, chosen for the brush" ${GRASS_CLI_TMP}/editor-real-species)
endif()

# Hostile files and careless paths (issue 22): one test per class of defect, each a list of
# commands a hostile or careless user could give (hostile_input_test.sh says what each checks).
# Several render headless, so all carry the GL label and environment.
foreach(class gnuplot paths disk_full output_is_input export_cleanup special_files bounds
              messages)
    add_test(NAME cli.hostile_${class}
             COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/hostile_input_test.sh ${GRASS_BIN}
                     ${GRASS_CLI_DATA} ${GRASS_CLI_TMP}/hostile-${class} ${class})
    set_tests_properties(cli.hostile_${class} PROPERTIES LABELS "cli;gl" TIMEOUT 300
        PASS_REGULAR_EXPRESSION "^${class}: [1-9][0-9]* cases, 0 failed"
        ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")
endforeach()
