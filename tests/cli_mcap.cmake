# The ROS 2 bags (MCAP) of plan, topo, coordinate, netsim and explore, read back with @mcap/core
# and decoded with @foxglove/rosmsg2-serialization (tests/mcap/run.sh; npm packages pinned in
# tests/mcap/package-lock.json; label "mcap").
add_test(NAME mcap.ros2_bags
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/mcap/run.sh $<TARGET_FILE:voronav_cli>
                 ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(mcap.ros2_bags PROPERTIES LABELS mcap TIMEOUT 300)
