# End-to-end checks of voronav topo / map / plan --planner topo (tests/cli_topology.py).
foreach(case IN ITEMS topo_edt topo_ca topo_labels plan_topo map_sweep errors)
  add_test(NAME cli.topology.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_topology.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.topology.${case} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
