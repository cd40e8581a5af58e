// write_run_bag: a run of any voronav command as a ROS 2 bag (MCAP). The run is given as the
// report::Recording its replay page shows (map, layers, robot tracks, paths, messages, obstacle
// changes) plus what only the bag carries (BagExtras). Topics (docs/ros.md):
//   /map              nav_msgs/OccupancyGrid   at the start and again after each obstacle change
//   /known_map        nav_msgs/OccupancyGrid   BagExtras::known_maps (exploration's merged map)
//   /robot_N/plan     nav_msgs/Path            every path of robot N, at the time it was planned
//   /plan             nav_msgs/Path            the same, for a one-robot run or a path labelled
//                                              "route" (the networked robots' source route)
//   /tf               tf2_msgs/TFMessage       map -> robot_N/base_link at every track sample
//   /robots           geometry_msgs/PoseArray  every robot's pose at the same times
//   /voronoi          MarkerArray              raster/graph layers whose name has "Voronoi"
//   /topology         MarkerArray              the other graph layers (nodes, edges, labels)
//   /messages         MarkerArray              radio messages as arrows sender -> receiver
//   /collision_boxes  MarkerArray              BagExtras::collision_boxes
//   /events           std_msgs/String          one JSON object per event {"t","event",...}
// Frame: "map" = the world frame of the map (REP-103, metres, yaw counter-clockwise from +x).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "voronav/bag/mcap_writer.hpp"
#include "voronav/bag/ros_msgs.hpp"
#include "voronav/report/recording.hpp"

namespace voronav::bag {

struct BagEvent {
  double t = 0.0;     ///< [s]
  std::string event;  ///< e.g. "route_found", "obstacle_change", "repair", "kill"
  std::string detail;
};

struct BagExtras {
  std::vector<std::pair<double, OccupancyGrid>> known_maps;  ///< (t [s], map) for /known_map
  std::vector<ros::Marker> collision_boxes;                  ///< published once at the start
  std::vector<BagEvent> events;                              ///< added to the derived ones
  /// /tf and /robots are published at every time a robot track has a sample, thinned evenly to
  /// at most this many messages.
  std::size_t max_tf_samples = 2000;
};

/// The robot's frame name: "robot_<id>/base_link".
[[nodiscard]] std::string base_link(int robot_id);

/// A map that grows over time, for /known_map (exploration): `final_map` with every cell unknown
/// until `reveal_time` (one entry per cell, [s]; < 0 never known) has passed, sampled every
/// `period_s` of simulated time from the first reveal on up to `end_s` (a snapshot only when
/// cells were revealed since the last one; the last sample is at `end_s`). At most
/// `max_snapshots` (the period is widened evenly). Throws voronav::Error when the sizes differ
/// or period_s is not > 0.
[[nodiscard]] std::vector<std::pair<double, OccupancyGrid>> known_map_series(
    const OccupancyGrid& final_map, const std::vector<float>& reveal_time, double end_s,
    double period_s, std::size_t max_snapshots = 200);

/// Writes `rec` (+ `extras`) to `file` as MCAP; returns the message count per topic. Throws
/// voronav::Error naming the file when it cannot be written.
std::map<std::string, std::size_t> write_run_bag(const report::Recording& rec,
                                                 const std::filesystem::path& file,
                                                 const BagExtras& extras = {},
                                                 const McapOptions& options = {});

}  // namespace voronav::bag
