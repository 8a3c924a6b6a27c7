# Reliability tests of the command-line tools (issue 11). Included from cli_tests.cmake, after
# grass_cli_test() is defined.

# Saves survive a kill: 25 paint runs and 12 export runs SIGKILLed at random points, most of them
# mid-save (kill_save_test.sh prints the counts); about a minute on 2 cores. No GL.
add_test(NAME cli.kill_during_save
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/kill_save_test.sh ${GRASS_BIN}
                 ${GRASS_CLI_PROJECTS}/growth_tiny ${GRASS_CLI_TMP}/kill-save 25 12)
set_tests_properties(cli.kill_during_save PROPERTIES LABELS cli TIMEOUT 300
    PASS_REGULAR_EXPRESSION "^paint: 25 runs .*\nexport: 12 runs ")
