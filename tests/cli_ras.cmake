# End-to-end checks of `voronav plan --planner ras` (seed 001); included by tests/CMakeLists.txt.
foreach(case json_matches_bfs directions statuses bad_options pictures)
  add_test(NAME cli.ras.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_ras.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.ras.${case} PROPERTIES LABELS cli TIMEOUT 120)
endforeach()
