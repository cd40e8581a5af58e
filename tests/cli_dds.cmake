# End-to-end checks of voronav dds-echo / dds-selftest / dds-config (tests/cli_dds.py).
foreach(case IN ITEMS selftest_6 selftest_kill selftest_loss selftest_text echo_bad_args
                      echo_alone_times_out config)
  add_test(NAME cli.dds.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_dds.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.dds.${case} PROPERTIES LABELS "cli;dds" TIMEOUT 120)
endforeach()
