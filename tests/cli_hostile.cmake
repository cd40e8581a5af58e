# Hostile input against the CLI (issue 17; tests/cli_hostile.py): exit code, message naming the
# file/line/key or option, time and memory limits. "interrupt": a long run's heartbeat and SIGINT.
add_test(NAME cli.hostile.cases
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_hostile.py
                 $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR})
add_test(NAME cli.hostile.interrupt
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_hostile.py
                 $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} interrupt)
set_tests_properties(cli.hostile.cases cli.hostile.interrupt PROPERTIES LABELS cli TIMEOUT 120)
