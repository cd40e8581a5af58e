#include "recordings.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace voronav::cli {

void add_topology_layers(report::Recording& rec, const topology::TopologicalMap& topo,
                         bool visible) {
  report::RasterLayer voronoi{"Voronoi diagram", report::RasterStyle::kMask, "#d62728", visible,
                              GridMap<std::int32_t>(topo.geometry, 0)};
  for (std::size_t i = 0; i < topo.diagram.size(); ++i)
    voronoi.cells[i] = topo.diagram[i] ? 1 : 0;
  report::RasterLayer regions{"Topological regions", report::RasterStyle::kLabels, "#1f77b4", false,
                              GridMap<std::int32_t>(topo.geometry, 0)};
  for (std::size_t i = 0; i < topo.region.size(); ++i)
    regions.cells[i] = topo.region[i] < 0 ? 0 : topo.region[i] + 1;
  report::GraphLayer graph{"Topological graph", "#1f77b4", visible, {}, {}};
  for (const auto& r : topo.regions) {
    std::string label = "R";  // appended, not "R" + ...: GCC 12 -O3 warns falsely (-Wrestrict)
    label += std::to_string(r.id);
    graph.nodes.push_back({r.id, r.centre_world, label});
  }
  for (const auto& e : topo.edges)
    graph.edges.push_back({e.a, e.b});
  rec.rasters.push_back(std::move(voronoi));
  rec.rasters.push_back(std::move(regions));
  rec.graphs.push_back(std::move(graph));
}

void add_schedule_tracks(report::Recording& rec, const std::vector<coordination::Agent>& agents,
                         const coordination::CoordinationResult& r, double dt) {
  double end = 0.0;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const double delay = i < r.delays.size() ? r.delays[i] : 0.0;
    end = std::max(end, delay + agents[i].path.travel_time());
  }
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const auto& a = agents[i];
    const double delay = i < r.delays.size() ? r.delays[i] : 0.0;
    report::RobotTrack track;
    track.id = a.id;
    track.radius = a.radius;
    double yaw = 0.0;
    for (double t = 0.0;; t += dt) {
      const double tt = std::min(t, end);
      const double local = std::clamp(tt - delay, 0.0, a.path.travel_time());
      const Vec2 p = a.path.position(local);
      const Vec2 ahead = a.path.position(std::min(local + dt, a.path.travel_time()));
      if ((ahead - p).norm() > 1e-9) yaw = std::atan2(ahead.y - p.y, ahead.x - p.x);
      track.poses.push_back({tt, {p, yaw}});
      if (tt >= end) break;
    }
    rec.paths.push_back({a.id, 0.0, "planned path", a.path.nodes()});
    rec.robots.push_back(std::move(track));
  }
}

report::Recording coordination_recording(const OccupancyGrid& map,
                                         const std::vector<coordination::Agent>& agents,
                                         const coordination::CoordinationResult& r) {
  report::Recording rec;
  rec.title = "Coordinated team (seed 002): start delays from collision maps";
  rec.description = std::to_string(agents.size()) + " robots on fixed paths; " + r.message +
                    ". Makespan " + std::to_string(r.makespan) + " s; the continuous-time check " +
                    (r.valid ? "passed" : "failed") + ".";
  rec.map = map;
  add_schedule_tracks(rec, agents, r);
  report::Plot delays{
      "Start delay and arrival per robot", "", "time [s]", report::PlotKind::kBar, false, {}, {}};
  report::Series d{"start delay", "#ff7f0e", {}, {}}, arr{"arrival", "#1f77b4", {}, {}};
  for (std::size_t i = 0; i < agents.size(); ++i) {
    delays.categories.push_back("robot " + std::to_string(agents[i].id));
    d.y.push_back(i < r.delays.size() ? r.delays[i] : 0.0);
    arr.y.push_back(i < r.arrivals.size() ? r.arrivals[i] : 0.0);
  }
  delays.series = {d, arr};
  rec.plots.push_back(std::move(delays));
  return rec;
}

}  // namespace voronav::cli
