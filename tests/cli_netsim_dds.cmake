# End-to-end checks of netsim with one process per robot over Cyclone DDS (tests/cli_netsim_dds.py).
foreach(case IN ITEMS scenario1_equals_sim scenario3_json repair_ring_equals_sim
                      repair_sense_walk_equals_sim killed_relay world_restart loss
                      robot_errors lone_processes_time_out)
  add_test(NAME cli.netsim_dds.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_netsim_dds.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.netsim_dds.${case} PROPERTIES LABELS "cli;dds" TIMEOUT 600)
endforeach()
