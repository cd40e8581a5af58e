# End-to-end checks of voronav coordinate / validate-schedule (tests/cli_coordination.py).
foreach(case IN ITEMS crossing_delay mapf_searches out_and_validate no_delay_schedule errors sipp_mapf)
  add_test(NAME cli.coordination.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_coordination.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.coordination.${case} PROPERTIES LABELS cli TIMEOUT 120)
endforeach()
