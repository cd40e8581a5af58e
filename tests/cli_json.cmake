# Frames and units in the JSON outputs of plan, topo, coordinate, explore, netsim
# (tests/cli_json.py).
foreach(case IN ITEMS plan_ros plan_movingai errors_in_user_units topo coordinate explore netsim)
  add_test(NAME cli.json.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_json.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.json.${case} PROPERTIES LABELS cli TIMEOUT 120)
endforeach()
