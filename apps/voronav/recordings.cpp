#include "recordings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace voronav::cli {
namespace {
std::string format_seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}
}  // namespace

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
    if (!a.path.nodes().empty())
      rec.markers.push_back(
          {"goal", a.path.nodes().back(), a.id, "goal of robot " + std::to_string(a.id)});
    if (delay > 0.0)
      rec.events.push_back(
          {delay, "start",
           "robot " + std::to_string(a.id) + " starts after waiting " + format_seconds(delay),
           a.id});
    rec.events.push_back({delay + a.path.travel_time(), "arrival",
                          "robot " + std::to_string(a.id) + " reaches its goal", a.id});
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

report::Recording netsim_recording(const sim::NetSimScenario& sc, const sim::NetSimResult& result,
                                   double radio_range_m) {
  const sim::Recording& in = result.recording;
  const sim::NetSimMetrics& m = result.metrics;
  report::Recording rec;
  rec.title = "Networked robots (seed 000): route search by Voronoi points";
  rec.description = std::to_string(sc.robots.size()) + " robots with 3 m sensing and a " +
                    std::to_string(static_cast<int>(radio_range_m)) + " m radio; robot " +
                    std::to_string(sc.source) +
                    " (the source) needs a route to the destination (the star). Lines between "
                    "robots are messages.";
  if (m.route_time_s >= 0)
    rec.description += " The route was found after " + format_seconds(m.route_time_s) + ".";
  else
    rec.description += " No route was found.";
  if (!sc.changes.empty() && m.route_time_s >= 0)
    rec.description += " " + std::to_string(sc.changes.size()) + " obstacle change" +
                       (sc.changes.size() == 1 ? "" : "s") + " (orange); " +
                       std::to_string(m.repairs) + " route break" + (m.repairs == 1 ? "" : "s") +
                       " handled, " + std::to_string(m.repairs_executed) + " Repair" +
                       (m.repairs_executed == 1 ? "" : "s") + " executed (purple marks).";
  if (m.arrival_time_s >= 0)
    rec.description += " The source arrives at " + format_seconds(m.arrival_time_s) + ".";
  rec.map = sc.world;
  rec.message_display_s = 0.6;
  for (std::size_t r = 0; r < sc.robots.size(); ++r) {
    report::RobotTrack t;
    t.id = static_cast<int>(r);
    t.name = r == sc.source ? "source" : "robot " + std::to_string(r);
    t.radius = 0.25;
    double yaw = 0.0;
    for (std::size_t k = 0; k < in.steps.size(); ++k) {
      const Vec2 p = in.steps[k].positions[r];
      if (k > 0) {
        const Vec2 d = p - in.steps[k - 1].positions[r];
        if (d.norm() > 1e-9) yaw = std::atan2(d.y, d.x);
      }
      if (k + 1 < in.steps.size() && k > 0 && in.steps[k + 1].positions[r] == p &&
          in.steps[k - 1].positions[r] == p)
        continue;  // standing still: the interpolation needs only the ends of the pause
      t.poses.push_back({in.steps[k].t_s, {p, yaw}});
    }
    if (t.poses.empty()) t.poses.push_back({0.0, {sc.robots[r], 0.0}});
    rec.robots.push_back(std::move(t));
  }
  auto position = [&](std::size_t robot, double t) {
    return report::pose_at(rec.robots[robot], t).position;
  };
  for (const auto& msg : in.messages) {
    const std::string type(network::to_string(msg.type));
    if (msg.type == network::MessageType::kLinkAck) continue;  // transport chatter
    if (msg.to != network::kBroadcast.value) {
      if (msg.to < sc.robots.size())
        rec.messages.push_back({msg.t_s, static_cast<int>(msg.from), static_cast<int>(msg.to), type,
                                static_cast<std::int64_t>(msg.bytes)});
      continue;
    }
    for (std::size_t r = 0; r < sc.robots.size(); ++r)
      if (r != msg.from &&
          distance(position(msg.from, msg.t_s), position(r, msg.t_s)) <= radio_range_m)
        rec.messages.push_back({msg.t_s, static_cast<int>(msg.from), static_cast<int>(r), type,
                                static_cast<std::int64_t>(msg.bytes)});
  }
  if (!in.route.empty())
    rec.paths.push_back(
        {static_cast<int>(sc.source), std::max(0.0, m.route_time_s), "route", in.route});
  for (const auto& c : sc.changes)
    if (c.at_s >= 0.0) {  // at a simulated time (the paper runs), else after the first route
      if (c.at_s <= m.simulated_s) rec.obstacle_changes.push_back({c.at_s, c.cells, c.value});
    } else if (m.route_time_s >= 0) {
      rec.obstacle_changes.push_back({m.route_time_s + c.after_route_s, c.cells, c.value});
    }
  const int source_id = static_cast<int>(sc.source);
  rec.markers.push_back({"destination", sc.destination, -1, "destination of the source"});
  rec.markers.push_back({"start", sc.robots[sc.source], source_id, "start of the source"});
  if (m.route_time_s >= 0)
    rec.events.push_back({m.route_time_s, "route", "the source has a route", source_id});
  for (const auto& c : rec.obstacle_changes)
    rec.events.push_back({c.t, "change",
                          std::to_string(c.cells.size()) + " cells become " +
                              (c.value == kOccupied ? "blocked" : "free"),
                          -1});
  // Every route break handled, from the run itself: "repair" where a detour was found (a Repair
  // executed), "blocked" where the robot had to ask for help.
  for (const auto& rp : in.repairs) {
    const bool is_source = rp.robot == sc.source;
    rec.events.push_back(
        {rp.t_s, rp.executed ? "repair" : "blocked",
         (is_source ? std::string("the source") : "robot " + std::to_string(rp.robot)) + " " +
             rp.what,
         static_cast<int>(rp.robot)});
  }
  if (m.arrival_time_s >= 0)
    rec.events.push_back(
        {m.arrival_time_s, "arrival", "the source reaches the destination", source_id});
  std::stable_sort(
      rec.events.begin(), rec.events.end(),
      [](const report::EventRecord& a, const report::EventRecord& b) { return a.t < b.t; });
  report::Plot traffic{
      "Radio traffic by message type", "", "bytes", report::PlotKind::kBar, false, {}, {}};
  report::Series bytes{"bytes on the air", "#1f77b4", {}, {}};
  for (const auto& [name, counter] : m.by_type) {
    traffic.categories.push_back(name);
    bytes.y.push_back(static_cast<double>(counter.bytes));
  }
  traffic.series.push_back(bytes);
  if (!traffic.categories.empty()) rec.plots.push_back(std::move(traffic));
  return rec;
}

report::Recording exploration_recording(const exploration::ExplorationResult& result) {
  const exploration::ExplorationRecording& in = result.recording;
  report::Recording rec;
  rec.title = "Swarm exploration (seed 004): " + std::string(exploration::to_string(result.method));
  char summary[400];
  std::snprintf(summary, sizeof summary,
                "%d robots explore an unknown world; final coverage %.1f %% after %.0f s, %.0f m "
                "driven, %d collisions. The team map grows as the robots explore (cells appear "
                "when first seen: free light orange, obstacles orange).",
                result.robots, 100.0 * result.coverage, result.sim_time_s, result.distance_m,
                result.collisions);
  rec.description = summary;
  rec.map = in.team_map;
  if (in.reveal_time.size() == in.team_map.size()) {
    // The known map over time: start unknown, reveal every cell at its first-seen time.
    rec.map = OccupancyGrid(in.team_map.geometry(), kUnknown);
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < in.reveal_time.size(); ++i)
      if (in.reveal_time[i] >= 0.0F && in.team_map[in.team_map.cell_at(i)] != kUnknown)
        order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return in.reveal_time[a] < in.reveal_time[b];
    });
    for (std::size_t k = 0; k < order.size();) {
      const float t = in.reveal_time[order[k]];
      report::ObstacleChange free_cells{t, {}, kFree}, occupied{t, {}, kOccupied};
      for (; k < order.size() && in.reveal_time[order[k]] == t; ++k) {
        const Cell c = in.team_map.cell_at(order[k]);
        (in.team_map[c] == kOccupied ? occupied : free_cells).cells.push_back(c);
      }
      for (auto* ch : {&free_cells, &occupied})
        if (!ch->cells.empty()) rec.obstacle_changes.push_back(std::move(*ch));
    }
  }
  const std::size_t n = in.frames.empty() ? 0 : in.frames.front().poses.size();
  for (std::size_t r = 0; r < n; ++r) {
    report::RobotTrack t;
    t.id = static_cast<int>(r);
    t.radius = 0.12;
    for (const auto& f : in.frames)
      if (r < f.poses.size()) t.poses.push_back({f.t, f.poses[r]});
    rec.robots.push_back(std::move(t));
  }
  if (!in.tree.empty()) {
    report::GraphLayer tree{"Voronoi tree", "#9467bd", true, {}, {}};
    for (std::size_t i = 0; i < in.tree.nodes.size(); ++i) {
      const auto& node = in.tree.nodes[i];
      tree.nodes.push_back({static_cast<int>(i), node.position,
                            static_cast<int>(i) == in.tree.root ? "root"
                            : node.is_leaf()                    ? "leaf"
                                                                : ""});
      if (node.parent >= 0) tree.edges.push_back({node.parent, static_cast<int>(i)});
    }
    rec.graphs.push_back(std::move(tree));
    // The page draws the tree from the time it was first built, not from t = 0.
    if (in.tree_time >= 0.0) rec.graph_appearances.push_back({rec.graphs.size() - 1, in.tree_time});
  }
  if (!in.feature_points.empty()) {
    report::GraphLayer fp{"Feature points", "#ff7f0e", true, {}, {}};
    for (std::size_t i = 0; i < in.feature_points.size(); ++i)
      fp.nodes.push_back({static_cast<int>(i), in.feature_points[i].position, ""});
    rec.graphs.push_back(std::move(fp));
  }
  const double tree_time = in.tree_time >= 0.0 ? in.tree_time
                           : in.frames.empty() ? 0.0
                                               : in.frames.front().t;
  for (std::size_t r = 0; r < in.routes.size() && r < n; ++r)
    if (in.routes[r].size() >= 2)
      rec.paths.push_back({static_cast<int>(r), tree_time, "tree route", in.routes[r]});
  // Events from the run itself: the first tree, every re-plan along a new tree, every leaf
  // reached, every goal the progress watchdog gave up, every stalled or idle robot.
  if (in.tree_time >= 0.0)
    rec.events.push_back({in.tree_time, "tree",
                          "the first Voronoi tree is built (" +
                              std::to_string(in.tree.leaves_by_distance().size()) + " leaves)",
                          -1});
  for (const auto& d : in.dispatches)
    if (!d.first)
      rec.events.push_back({d.t, "tree",
                            "robot " + std::to_string(d.robot) + " re-plans along a new tree",
                            d.robot});
  for (const auto& e : in.events) {
    const std::string who = "robot " + std::to_string(e.robot);
    const std::string text =
        e.kind == "leaf"           ? who + " reaches a tree leaf"
        : e.kind == "watchdog"     ? who + " gives up its goal (no progress)"
        : e.kind == "stalled"      ? who + " is stalled"
        : e.kind == "idle"         ? who + " is idle: no reachable unknown space is left"
        : e.kind == "leaf_skipped" ? who + " skips a tree leaf the team already knows"
        : e.kind == "leaf_promoted"
            ? who + " drives first to a dealt tree leaf that still faces unknown space"
        : e.kind == "frontier_goal" ? who + " is done with its leaves and takes a frontier goal"
                                    : who + " " + e.kind;
    rec.events.push_back({e.t, e.kind, text, e.robot});
  }
  std::stable_sort(
      rec.events.begin(), rec.events.end(),
      [](const report::EventRecord& a, const report::EventRecord& b) { return a.t < b.t; });
  report::Plot cov{"Coverage", "time [s]", "coverage [%]", report::PlotKind::kLine, true, {}, {}};
  report::Series s{"team", "#2ca02c", {}, {}};
  for (const auto& f : in.frames) {
    s.x.push_back(f.t);
    s.y.push_back(100.0 * f.coverage);
  }
  cov.series.push_back(std::move(s));
  rec.plots.push_back(std::move(cov));
  return rec;
}

}  // namespace voronav::cli
