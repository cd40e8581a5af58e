// The collision boxes of a coordinated team (seed 002, Table 2) as markers for /collision_boxes:
// for every pair of robots in the chosen priority order, each box's path segment of the
// lower-priority robot (normalized length l_s..l_e) as a thick line strip, labelled with the two
// robot ids and the box's M = T3 - T1 and D = T4 - T2 [s].
#pragma once

#include <vector>

#include "voronav/bag/ros_msgs.hpp"
#include "voronav/coordination/coordinator.hpp"

namespace voronav::bag {

[[nodiscard]] std::vector<ros::Marker> collision_box_markers(
    const std::vector<coordination::Agent>& agents, const coordination::CoordinationResult& result,
    const coordination::CollisionMapOptions& options);

}  // namespace voronav::bag
