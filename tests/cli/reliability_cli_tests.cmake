# Reliability tests of the command-line tools (issue 11). Included from cli_tests.cmake, after
# grass_cli_test() is defined.

# Saves survive a kill: 25 paint runs and 12 export runs SIGKILLed at random points, most of them
# mid-save (kill_save_test.sh prints the counts); about a minute on 2 cores. No GL.
add_test(NAME cli.kill_during_save
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/kill_save_test.sh ${GRASS_BIN}
                 ${GRASS_CLI_PROJECTS}/growth_tiny ${GRASS_CLI_TMP}/kill-save 25 12)
set_tests_properties(cli.kill_during_save PROPERTIES LABELS cli TIMEOUT 300
    PASS_REGULAR_EXPRESSION "^paint: 25 runs .*\nexport: 12 runs ")

# The editor's autosave survives a kill: 10 painting sessions SIGKILLed at random moments, each
# next one recovering the autosave (kill_autosave_test.sh); under Xvfb, about a minute.
if(TARGET grass-editor)
    find_program(GRASS_XVFB_RUN xvfb-run)
    if(NOT GRASS_XVFB_RUN)
        set(GRASS_XVFB_RUN xvfb-run)  # fails with "not found": never a silent skip
    endif()
    add_test(NAME cli.kill_during_autosave
             COMMAND ${GRASS_XVFB_RUN} -a -s "-screen 0 1024x768x24"
                     ${GRASS_BASH} ${GRASS_CLI_DIR}/kill_autosave_test.sh
                     $<TARGET_FILE:grass-editor> ${GRASS_BIN} ${GRASS_CLI_TMP}/kill-autosave 10)
    set_tests_properties(cli.kill_during_autosave PROPERTIES LABELS "cli;gl" TIMEOUT 400
        PASS_REGULAR_EXPRESSION "autosave: 10 sessions killed"
        ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")
    # Real X input (xdotool) at about one frame a second (issue 24): quick clicks, a
    # double-click and typing all reach the project; about 30 s.
    add_test(NAME cli.editor_real_input
             COMMAND ${GRASS_XVFB_RUN} -a -s "-screen 0 1024x768x24"
                     ${GRASS_BASH} ${GRASS_CLI_DIR}/editor_real_input_test.sh
                     $<TARGET_FILE:grass-editor> ${GRASS_CLI_TMP}/editor-real-input)
    set_tests_properties(cli.editor_real_input PROPERTIES LABELS "cli;gl" TIMEOUT 120
        PASS_REGULAR_EXPRESSION "real input: name typed, quick click, double-click"
        ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")
    # The artist's own mesh by real X input at about one frame a second (issue 26): File › New
    # from mesh…, a typed path in the file browser, Save As by Ctrl+S, a refused typed value,
    # Ctrl+O and the recent list; about 50 s.
    add_test(NAME cli.editor_real_import
             COMMAND ${GRASS_XVFB_RUN} -a -s "-screen 0 1024x768x24"
                     ${GRASS_BASH} ${GRASS_CLI_DIR}/editor_real_import_test.sh
                     $<TARGET_FILE:grass-editor> ${CMAKE_SOURCE_DIR}/tests/data/gltf/cube.glb
                     ${GRASS_CLI_TMP}/editor-real-import)
    set_tests_properties(cli.editor_real_import PROPERTIES LABELS "cli;gl" TIMEOUT 150
        PASS_REGULAR_EXPRESSION "real import: new from mesh, browser typing, save as"
        ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")
    # Species painted with the map overlay by real X input at about one frame a second (issue
    # 27): a layer added, chosen for the brush, a subtract stroke with "show map" on, Ctrl+S;
    # about 45 s.
    add_test(NAME cli.editor_real_species
             COMMAND ${GRASS_XVFB_RUN} -a -s "-screen 0 1024x768x24"
                     ${GRASS_BASH} ${GRASS_CLI_DIR}/editor_real_species_test.sh
                     $<TARGET_FILE:grass-editor> ${GRASS_CLI_TMP}/editor-real-species)
    set_tests_properties(cli.editor_real_species PROPERTIES LABELS "cli;gl" TIMEOUT 150
        PASS_REGULAR_EXPRESSION "real species: a layer added, chosen for the brush"
        ENVIRONMENT_MODIFICATION "${GRASS_GL_TEST_ENV_MODIFICATION}")
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
