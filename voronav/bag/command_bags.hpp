// One call per voronav command that turns its result objects into a ROS 2 bag (MCAP) with the
// topics of run_bag.hpp: plan (a path on a map), topo (Voronoi diagram, regions and topological
// graph), coordinate (schedule tracks + collision boxes) — netsim and explore reuse their replay
// recordings through write_run_bag directly (docs/ros.md lists each command's topics).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "voronav/bag/run_bag.hpp"
#include "voronav/coordination/coordinator.hpp"
#include "voronav/topology/topological_map.hpp"

namespace voronav::bag {

/// A one-robot planning query. `path`: world points from start to goal (empty: no path). The
/// robot (id 0) drives the path at `speed_mps` so /tf moves in a player; /plan and
/// /robot_0/plan at t = 0; /events "route_found" or "no_path" naming `planner`.
std::map<std::string, std::size_t> write_plan_bag(const std::filesystem::path& file,
                                                  const OccupancyGrid& map, Vec2 start, Vec2 goal,
                                                  const std::vector<Vec2>& path,
                                                  const std::string& planner,
                                                  double speed_mps = 1.0,
                                                  const McapOptions& options = {});

/// A topological map: /map, /voronoi (diagram cells and critical points), /topology (regions as
/// coloured cells, region graph with labels R<id>, edges through the critical points).
std::map<std::string, std::size_t> write_topology_bag(const std::filesystem::path& file,
                                                      const OccupancyGrid& map,
                                                      const topology::TopologicalMap& topo,
                                                      const McapOptions& options = {});

/// A coordinated team as tracks (robots wait at the start for their delay, then drive their
/// timed path), each robot's path on /robot_<id>/plan, the collision boxes of the chosen order on
/// /collision_boxes and one /events entry per departure and arrival. `map` may be empty.
std::map<std::string, std::size_t> write_coordination_bag(
    const std::filesystem::path& file, const OccupancyGrid& map,
    const std::vector<coordination::Agent>& agents, const coordination::CoordinationResult& result,
    const coordination::CollisionMapOptions& map_options, const McapOptions& options = {});

}  // namespace voronav::bag
