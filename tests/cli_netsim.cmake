# End-to-end checks of `voronav netsim` (tests/cli_netsim.py).
foreach(case IN ITEMS both_json one_method_plots errors scenario_file write_scenario)
  add_test(NAME cli.netsim.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_netsim.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.netsim.${case} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
