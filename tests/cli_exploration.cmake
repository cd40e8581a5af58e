# End-to-end checks of `voronav explore` (tests/cli_exploration.py).
foreach(case IN ITEMS paper_json ros_map_coordinated out_folder errors)
  add_test(NAME cli.exploration.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_exploration.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.exploration.${case} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
