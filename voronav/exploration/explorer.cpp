#include "voronav/exploration/explorer.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "voronav/core/error.hpp"
#include "voronav/exploration/internal/team_run.hpp"

namespace voronav::exploration {
namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::string_view to_string(ExplorationMethod m) {
  switch (m) {
    case ExplorationMethod::kTree:
      return "tree";
    case ExplorationMethod::kFrontier:
      return "frontier";
    case ExplorationMethod::kCoordinated:
      return "coordinated";
    case ExplorationMethod::kTreeFrontier:
      return "tree-frontier";
  }
  return "?";
}

std::string_view to_string(TreeLegReplan r) {
  return r == TreeLegReplan::kNone ? "none" : "robots";
}

TreeLegReplan parse_tree_leg_replan(std::string_view name) {
  if (name == "none") return TreeLegReplan::kNone;
  if (name == "robots") return TreeLegReplan::kAroundRobots;
  throw Error("--tree-leg-replan", 0,
              "expected one of none, robots; got '" + std::string(name) + "'");
}

std::string_view to_string(FrontGuard r) {
  return r == FrontGuard::kCone ? "cone" : "corridor";
}

FrontGuard parse_front_guard(std::string_view name) {
  if (name == "cone") return FrontGuard::kCone;
  if (name == "corridor") return FrontGuard::kCorridor;
  throw Error("--guard", 0, "expected one of cone, corridor; got '" + std::string(name) + "'");
}

std::string_view to_string(TreeReplan r) {
  return r == TreeReplan::kNone ? "none" : "robots";
}

TreeReplan parse_tree_replan(std::string_view name) {
  if (name == "none") return TreeReplan::kNone;
  if (name == "robots") return TreeReplan::kFromRobots;
  throw Error("--tree-replan", 0, "expected one of none, robots; got '" + std::string(name) + "'");
}

ExplorationMethod parse_exploration_method(std::string_view name) {
  if (name == "tree") return ExplorationMethod::kTree;
  if (name == "frontier") return ExplorationMethod::kFrontier;
  if (name == "coordinated") return ExplorationMethod::kCoordinated;
  if (name == "tree-frontier") return ExplorationMethod::kTreeFrontier;
  throw Error("--method", 0,
              "expected one of tree, frontier, coordinated, tree-frontier; got '" +
                  std::string(name) + "'");
}

void ExplorationOptions::validate() const {
  const auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw Error(std::string("ExplorationOptions.") + name, 0,
                  "expected a positive finite number, got " + std::to_string(v));
  };
  if (robots < 1 || robots > 64)
    throw Error("ExplorationOptions.robots", 0, "expected 1..64, got " + std::to_string(robots));
  positive(time_limit, "time_limit");
  positive(dt, "dt");
  positive(start_spacing, "start_spacing");
  positive(map_period, "map_period");
  positive(record_period, "record_period");
  positive(replan_period, "replan_period");
  positive(goal_tolerance, "goal_tolerance");
  positive(min_cell_size, "min_cell_size");
  positive(gain_radius, "gain_radius");
  positive(stall_time, "stall_time");
  positive(stall_distance, "stall_distance");
  positive(disperse_range, "disperse_range");
  positive(unstick_retry_period, "unstick_retry_period");
  if (!(stall_reach_radius >= 0.0) || !std::isfinite(stall_reach_radius))
    throw Error("ExplorationOptions.stall_reach_radius", 0,
                "expected a finite number >= 0 (0 = the planning radius), got " +
                    std::to_string(stall_reach_radius));
  if (!(min_leaf_gain >= 0.0 && min_leaf_gain <= 1.0))
    throw Error("ExplorationOptions.min_leaf_gain", 0, "expected 0..1");
  if (!(hybrid_tree_start_time >= 0.0) || !std::isfinite(hybrid_tree_start_time))
    throw Error("ExplorationOptions.hybrid_tree_start_time", 0, "expected a finite number >= 0");
  positive(hybrid_tree_period, "hybrid_tree_period");
  if (!(tree_start_time >= 0.0) || !std::isfinite(tree_start_time))
    throw Error("ExplorationOptions.tree_start_time", 0, "expected a finite number >= 0");
  if (!(clearance >= 0.0)) throw Error("ExplorationOptions.clearance", 0, "expected >= 0");
  if (crowd_limit < 0 || crowd_limit > 64)
    throw Error("ExplorationOptions.crowd_limit", 0, "expected 0..64");
  if (map_beam_stride < 1) throw Error("ExplorationOptions.map_beam_stride", 0, "expected >= 1");
  if (start && !start->is_finite()) throw Error("--start", 0, "start must be finite");
  if (std::isnan(stop_at_coverage)) throw Error("ExplorationOptions.stop_at_coverage", 0, "NaN");
  // At most 1e9 steps (the rule both simulators share, core/stepper.hpp).
  (void)step_count(dt, time_limit, "ExplorationOptions.dt", "ExplorationOptions.time_limit");
  drive.validate();
  laser.validate();
  controller.validate();
  frontier_controller.validate();
  features.validate();
  tree.validate();
  frontier.validate();
}

// Coarser cells: a coarse cell is occupied if any of its cells is, else unknown if any is.
OccupancyGrid resample_world(const OccupancyGrid& in, double min_cell) {
  if (!(min_cell > 0.0) || !std::isfinite(min_cell))
    throw Error("resample_world", 0, "min_cell must be a positive finite size [m]");
  const double res = in.resolution();
  const int k = static_cast<int>(std::floor(min_cell / res + 1e-9));
  if (k < 2) return in;
  GridGeometry g = in.geometry();
  g.width = (g.width + k - 1) / k;
  g.height = (g.height + k - 1) / k;
  g.resolution = res * k;
  OccupancyGrid out(g, kFree);
  for (int y = 0; y < in.height(); ++y)
    for (int x = 0; x < in.width(); ++x) {
      const std::int8_t v = in[Cell{x, y}];
      std::int8_t& o = out[Cell{x / k, y / k}];
      if (v >= 50)
        o = kOccupied;
      else if (v < 0 && o != kOccupied)
        o = kUnknown;
    }
  return out;
}

ExplorationResult run_exploration(const OccupancyGrid& world_in, const ExplorationOptions& o) {
  o.validate();
  if (world_in.empty()) throw Error("run_exploration", 0, "the world map is empty");
  internal::TeamRun run(resample_world(world_in, o.min_cell_size), o);
  return run.run();
}

std::string to_json(const ExplorationOptions& o) {
  std::ostringstream os;
  const auto on = [](bool b) { return b ? "\"on\"" : "\"off\""; };
  const auto str = [](std::string_view v) {
    std::string q(1, '"');
    q.append(v);
    q.push_back('"');
    return q;
  };
  os << "{\"method\":" << str(to_string(o.method)) << ",\"robots\":" << o.robots
     << ",\"time_s\":" << num(o.time_limit) << ",\"dt\":" << num(o.dt) << ",\"seed\":" << o.seed;
  if (o.start) os << ",\"start\":[" << num(o.start->x) << "," << num(o.start->y) << "]";
  os << ",\"start_spacing\":" << num(o.start_spacing)
     << ",\"stop_at_coverage\":" << num(o.stop_at_coverage)
     << ",\"map_period\":" << num(o.map_period) << ",\"map_beam_stride\":" << o.map_beam_stride
     << ",\"record_period\":" << num(o.record_period)
     << ",\"tree_start_s\":" << num(o.tree_start_time)
     << ",\"tree_replan\":" << str(to_string(o.tree_replan))
     << ",\"tree_leg_replan\":" << str(to_string(o.tree_leg_replan))
     << ",\"hybrid_tree_start_time\":" << num(o.hybrid_tree_start_time)
     << ",\"hybrid_tree_period\":" << num(o.hybrid_tree_period)
     << ",\"min_leaf_gain\":" << num(o.min_leaf_gain) << ",\"gain_radius\":" << num(o.gain_radius)
     << ",\"gain_through_free\":" << on(o.gain_through_free)
     << ",\"stall_time\":" << num(o.stall_time) << ",\"stall_distance\":" << num(o.stall_distance)
     << ",\"stall_reach_radius\":" << num(o.stall_reach_radius) << ",\"unstick\":" << on(o.unstick)
     << ",\"disperse_neighbours\":" << on(o.disperse_neighbours)
     << ",\"disperse_range\":" << num(o.disperse_range)
     << ",\"clear_way_out\":" << on(o.clear_way_out) << ",\"unstick_retry\":" << on(o.unstick_retry)
     << ",\"unstick_retry_period\":" << num(o.unstick_retry_period)
     << ",\"unstick_right_of_way\":" << on(o.unstick_right_of_way)
     << ",\"frontier_unstick\":" << on(o.frontier_unstick)
     << ",\"idle_unstick\":" << on(o.idle_unstick) << ",\"yield_to_held\":" << on(o.yield_to_held)
     << ",\"retry_banned\":" << on(o.retry_banned) << ",\"share_bans\":" << on(o.share_bans)
     << ",\"crowd_limit\":" << o.crowd_limit
     << ",\"drop_goalless_routes\":" << on(o.drop_goalless_routes)
     << ",\"margin_escape\":" << on(o.margin_escape)
     << ",\"skip_known_leaves\":" << on(o.skip_known_leaves)
     << ",\"unknown_leaves_first\":" << on(o.unknown_leaves_first)
     << ",\"nearest_leaf_next\":" << on(o.nearest_leaf_next)
     << ",\"frontiers_after_leaves\":" << on(o.frontiers_after_leaves)
     << ",\"guard\":" << str(to_string(o.guard)) << ",\"replan_period\":" << num(o.replan_period)
     << ",\"goal_tolerance\":" << num(o.goal_tolerance) << ",\"clearance\":" << num(o.clearance)
     << ",\"min_cell_size\":" << num(o.min_cell_size)
     << ",\"random_turn_rate\":" << num(o.controller.random_turn_rate)
     << ",\"avoid_escape\":" << str(robot::to_string(o.controller.avoid_escape))
     << ",\"frontier_random_turn_rate\":" << num(o.frontier_controller.random_turn_rate)
     << ",\"frontier_avoid_escape\":" << str(robot::to_string(o.frontier_controller.avoid_escape))
     << "}";
  return os.str();
}

std::string to_json(const ExplorationResult& r, bool include_recording) {
  std::ostringstream os;
  const auto opt = [](const std::optional<double>& v) { return v ? num(*v) : std::string("null"); };
  os << "{\"method\":\"" << to_string(r.method) << "\",\"robots\":" << r.robots
     << ",\"coverage\":" << num(r.coverage) << ",\"t90_s\":" << opt(r.t90_s)
     << ",\"t99_s\":" << opt(r.t99_s) << ",\"sim_time_s\":" << num(r.sim_time_s)
     << ",\"distance_m\":" << num(r.distance_m) << ",\"collisions\":" << r.collisions
     << ",\"overlap\":" << num(r.overlap) << ",\"feature_points\":" << r.feature_points
     << ",\"leaves\":" << r.leaves << ",\"trees\":" << r.trees << ",\"dispatches\":" << r.dispatches
     << ",\"leaves_reached\":" << r.leaves_reached << ",\"frontier_goals\":" << r.frontier_goals
     << ",\"leaf_goals\":" << r.leaf_goals << ",\"stalled_robots\":" << r.stalled_robots
     << ",\"stalled_without_target\":" << r.stalled_without_target
     << ",\"idle_when_explored\":" << r.idle_when_explored
     << ",\"watchdog_events\":" << r.watchdog_events << ",\"leg_replans\":" << r.leg_replans
     << ",\"escapes\":" << r.escapes << ",\"unsticks\":" << r.unsticks
     << ",\"dispersals\":" << r.dispersals << ",\"way_clearances\":" << r.way_clearances
     << ",\"unstick_retries\":" << r.unstick_retries << ",\"unstick_yields\":" << r.unstick_yields
     << ",\"idle_unsticks\":" << r.idle_unsticks << ",\"yields\":" << r.yields
     << ",\"ban_resets\":" << r.ban_resets << ",\"shared_bans\":" << r.shared_bans
     << ",\"crowd_skips\":" << r.crowd_skips << ",\"route_drops\":" << r.route_drops
     << ",\"margin_escapes\":" << r.margin_escapes << ",\"leaves_skipped\":" << r.leaves_skipped
     << ",\"leaves_promoted\":" << r.leaves_promoted << ",\"leaves_pooled\":" << r.leaves_pooled
     << ",\"guard_wall_stops\":" << r.guard_wall_stops
     << ",\"guard_robot_stops\":" << r.guard_robot_stops
     << ",\"tree_time_s\":" << (r.recording.tree_time >= 0.0 ? num(r.recording.tree_time) : "null")
     << ",\"reachable_free_cells\":" << r.reachable_free_cells;
  if (include_recording) {
    const ExplorationRecording& rec = r.recording;
    const auto pt = [](Vec2 p) {
      std::string s = "[";
      s += num(p.x);
      s += ',';
      s += num(p.y);
      s += ']';
      return s;
    };
    os << ",\"recording\":{\"resolution\":" << num(rec.geometry.resolution)
       << ",\"width\":" << rec.geometry.width << ",\"height\":" << rec.geometry.height
       << ",\"origin\":" << pt(rec.geometry.origin.position) << ",\"frames\":[";
    for (std::size_t i = 0; i < rec.frames.size(); ++i) {
      const ExplorationFrame& f = rec.frames[i];
      os << (i ? "," : "") << "{\"t\":" << num(f.t) << ",\"coverage\":" << num(f.coverage)
         << ",\"poses\":[";
      for (std::size_t k = 0; k < f.poses.size(); ++k)
        os << (k ? "," : "") << "[" << num(f.poses[k].position.x) << ","
           << num(f.poses[k].position.y) << "," << num(f.poses[k].yaw) << "]";
      os << "]}";
    }
    os << "],\"feature_points\":[";
    for (std::size_t i = 0; i < rec.feature_points.size(); ++i)
      os << (i ? "," : "") << "{\"position\":" << pt(rec.feature_points[i].position)
         << ",\"kind\":\"" << to_string(rec.feature_points[i].kind)
         << "\",\"observations\":" << rec.feature_points[i].observations << "}";
    os << "],\"tree\":{\"root\":" << rec.tree.root << ",\"nodes\":[";
    for (std::size_t i = 0; i < rec.tree.nodes.size(); ++i) {
      const TreeNode& n = rec.tree.nodes[i];
      os << (i ? "," : "") << "{\"position\":" << pt(n.position) << ",\"parent\":" << n.parent
         << ",\"left\":" << n.left << ",\"right\":" << n.right << ",\"weight\":" << num(n.weight)
         << "}";
    }
    os << "]},\"routes\":[";
    for (std::size_t i = 0; i < rec.routes.size(); ++i) {
      os << (i ? "," : "") << "[";
      for (std::size_t k = 0; k < rec.routes[i].size(); ++k)
        os << (k ? "," : "") << pt(rec.routes[i][k]);
      os << "]";
    }
    os << "],\"dispatches\":[";
    for (std::size_t i = 0; i < rec.dispatches.size(); ++i) {
      const TreeDispatch& d = rec.dispatches[i];
      os << (i ? "," : "") << "{\"t\":" << num(d.t) << ",\"robot\":" << d.robot
         << ",\"first\":" << (d.first ? "true" : "false") << ",\"from\":" << pt(d.from)
         << ",\"root\":" << pt(d.root) << ",\"leaves\":[";
      for (std::size_t k = 0; k < d.leaves.size(); ++k)
        os << (k ? "," : "") << pt(d.leaves[k]);
      os << "]}";
    }
    os << "],\"tree_time\":" << num(rec.tree_time) << "}";
  }
  os << "}";
  return os.str();
}

}  // namespace voronav::exploration
