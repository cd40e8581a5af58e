#include "voronav/bag/command_bags.hpp"

#include <algorithm>
#include <cmath>

#include "voronav/bag/collision_markers.hpp"

namespace voronav::bag {

std::map<std::string, std::size_t> write_plan_bag(const std::filesystem::path& file,
                                                  const OccupancyGrid& map, Vec2 start, Vec2 goal,
                                                  const std::vector<Vec2>& path,
                                                  const std::string& planner, double speed_mps,
                                                  const McapOptions& options) {
  report::Recording rec;
  rec.map = map;
  report::RobotTrack robot{0, "robot 0", 0.2, "", {}};
  if (path.empty()) {
    robot.poses.push_back({0.0, {start, 0.0}});
  } else {
    double t = 0.0, yaw = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i) {
      if (i > 0) t += distance(path[i - 1], path[i]) / std::max(1e-9, speed_mps);
      if (i + 1 < path.size() && distance(path[i], path[i + 1]) > 1e-12)
        yaw = std::atan2(path[i + 1].y - path[i].y, path[i + 1].x - path[i].x);
      robot.poses.push_back({t, {path[i], yaw}});
    }
    rec.paths.push_back({0, 0.0, planner, path});
  }
  rec.robots.push_back(std::move(robot));
  BagExtras extras;
  if (path.empty())
    extras.events.push_back({0.0, "no_path",
                             planner + " found no path from (" + std::to_string(start.x) + ", " +
                                 std::to_string(start.y) + ") to (" + std::to_string(goal.x) +
                                 ", " + std::to_string(goal.y) + ")"});
  return write_run_bag(rec, file, extras, options);
}

std::map<std::string, std::size_t> write_topology_bag(const std::filesystem::path& file,
                                                      const OccupancyGrid& map,
                                                      const topology::TopologicalMap& topo,
                                                      const McapOptions& options) {
  report::Recording rec;
  rec.map = map;
  report::RasterLayer voronoi{"Voronoi diagram", report::RasterStyle::kMask, "#d62728", true,
                              GridMap<std::int32_t>(topo.geometry, 0)};
  for (std::size_t i = 0; i < topo.diagram.size(); ++i)
    voronoi.cells[i] = topo.diagram[i] != 0 ? 1 : 0;
  report::RasterLayer regions{"Topological regions", report::RasterStyle::kLabels, "#1f77b4", true,
                              GridMap<std::int32_t>(topo.geometry, 0)};
  for (std::size_t i = 0; i < topo.region.size(); ++i)
    regions.cells[i] = topo.region[i] < 0 ? 0 : topo.region[i] + 1;
  rec.rasters = {std::move(voronoi), std::move(regions)};
  report::GraphLayer critical{"Voronoi critical points", "#ff7f0e", true, {}, {}};
  for (std::size_t i = 0; i < topo.critical_points.size(); ++i)
    critical.nodes.push_back(
        {static_cast<int>(i), topo.geometry.cell_center(topo.critical_points[i].cell), ""});
  report::GraphLayer graph{"Topological graph", "#1f77b4", true, {}, {}};
  for (const auto& r : topo.regions) {
    std::string label = "R";
    label += std::to_string(r.id);
    graph.nodes.push_back({r.id, r.centre_world, label});
  }
  for (const auto& e : topo.edges)
    graph.edges.push_back({e.a, e.b});
  rec.graphs = {std::move(critical), std::move(graph)};
  return write_run_bag(rec, file, {}, options);
}

std::map<std::string, std::size_t> write_coordination_bag(
    const std::filesystem::path& file, const OccupancyGrid& map,
    const std::vector<coordination::Agent>& agents, const coordination::CoordinationResult& r,
    const coordination::CollisionMapOptions& map_options, const McapOptions& options) {
  report::Recording rec;
  rec.map = map;
  BagExtras extras;
  constexpr double kDt = 0.2;
  double end = 0.0;
  for (std::size_t i = 0; i < agents.size(); ++i)
    end = std::max(end, (i < r.delays.size() ? r.delays[i] : 0.0) + agents[i].path.travel_time());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const auto& a = agents[i];
    const double delay = i < r.delays.size() ? r.delays[i] : 0.0;
    const double travel = a.path.travel_time();
    report::RobotTrack track{a.id, "", a.radius, "", {}};
    double yaw = 0.0;
    const auto steps = static_cast<int>(std::ceil(end / kDt));
    for (int k = 0; k <= steps; ++k) {
      const double t = std::min(end, k * kDt);
      const double local = std::clamp(t - delay, 0.0, travel);
      const Vec2 p = a.path.position(local);
      const Vec2 ahead = a.path.position(std::min(local + kDt, travel));
      if (distance(ahead, p) > 1e-9) yaw = std::atan2(ahead.y - p.y, ahead.x - p.x);
      track.poses.push_back({t, {p, yaw}});
    }
    rec.robots.push_back(std::move(track));
    rec.paths.push_back({a.id, 0.0, "planned path", a.path.nodes()});
    extras.events.push_back({delay, "depart", "robot " + std::to_string(a.id)});
    extras.events.push_back({delay + travel, "arrive", "robot " + std::to_string(a.id)});
  }
  extras.collision_boxes = collision_box_markers(agents, r, map_options);
  return write_run_bag(rec, file, extras, options);
}

}  // namespace voronav::bag
