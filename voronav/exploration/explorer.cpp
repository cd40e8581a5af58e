#include "voronav/exploration/explorer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <memory>
#include <random>
#include <sstream>

#include "voronav/core/error.hpp"
#include "voronav/core/stepper.hpp"
#include "voronav/exploration/internal/block_clock.hpp"
#include "voronav/exploration/internal/front_guard.hpp"
#include "voronav/exploration/internal/right_of_way.hpp"
#include "voronav/exploration/internal/team_bans.hpp"
#include "voronav/exploration/unstick.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/planning/bfs.hpp"
#include "voronav/planning/grid_planner.hpp"

namespace voronav::exploration {
namespace {

enum class AgentMode { kReactive, kFollow };

struct Agent {
  Agent(const ExplorationOptions& o, Pose2 start, std::uint64_t seed, const GridGeometry& g)
      : body(o.drive, start, seed),
        controller([&] {
          robot::ReactiveControllerOptions c =
              o.method == ExplorationMethod::kTree ? o.controller : o.frontier_controller;
          c.seed = seed;
          return c;
        }()),
        map(g) {}
  robot::DiffDriveRobot body;
  robot::ReactiveController controller;
  mapping::OccupancyMap map;
  AgentMode mode = AgentMode::kReactive;
  std::vector<Vec2> route;
  std::size_t next = 0;
  internal::BlockClock block;  // wanted to drive forward but took no forward step (3 s rule)
  double since_progress = 0.0;
  double reactive_until = 0.0;  // [s] a deadlocked robot searches reactively until then
  std::optional<Vec2> goal;     // frontier goal
  std::vector<Vec2> blacklist;  // unreachable frontier goals
  std::vector<Vec2> soft_bans;  // goals given up when blocked or without progress (retry_banned)
  double ban_reset_t = -1e9;    // [s] when soft_bans were last cleared (retry_banned)
  bool on_tree = false;         // following a leg of a tree dispatch
  std::deque<std::vector<Vec2>> legs;  // tree legs still to drive, each ending at a leaf
  bool tree_done = false;              // its dispatched leaves are done (or given up)
  bool goal_leaf = false;              // kTreeFrontier: the goal is a tree leaf
  double retry_at = 0.0;               // [s] TreeReplan::kFromRobots: next attempt
  Vec2 anchor;                         // stall watch: where it has stayed since anchor_t
  double anchor_t = 0.0;
  Vec2 wd_anchor;  // progress watchdog (give up a goal when stuck)
  double wd_t = 0.0;
  double back_off_until = 0.0;  // [s] yields to a robot with a lower index until then
  bool stalled = false;
  double leg_replan_t = -1e9;  // [s] last TreeLegReplan::kAroundRobots re-plan, and where
  Vec2 leg_replan_at;
  bool unsticking = false;     // following an unstick route (ExplorationOptions::unstick)
  bool guard_stopped = false;  // the front guard stopped it at its last route-following step
  bool escaping = false;       // its unstick route leaves the planning margin (margin_escape)
};

OccupancyGrid team_grid(const mapping::OccupancyMap& m) {
  OccupancyGrid out(m.geometry(), kUnknown);
  const auto l = m.log_odds().data();
  auto o = out.data();
  for (std::size_t i = 0; i < l.size(); ++i)
    o[i] = l[i] > 0.0F ? kOccupied : (l[i] < 0.0F ? kFree : kUnknown);
  return out;
}

// Known free cells, inflated by the body radius + clearance: 0 = a robot centre may go there.
BinaryGrid traversable_of(const OccupancyGrid& map, double radius) {
  return planning::make_planning_grid(binarize(map, {50, true}), radius);
}

std::optional<Cell> nearest_free(const BinaryGrid& g, Vec2 p, int search = 8) {
  const auto c = g.geometry().world_to_cell(p);
  if (!c) return std::nullopt;
  std::optional<Cell> best;
  double bd = std::numeric_limits<double>::infinity();
  for (int dy = -search; dy <= search; ++dy)
    for (int dx = -search; dx <= search; ++dx) {
      const Cell n{c->x + dx, c->y + dy};
      if (!g.contains(n) || g[n] != 0) continue;
      const double d = dx * dx + dy * dy;
      if (d < bd) {
        bd = d;
        best = n;
      }
    }
  return best;
}

// Line-of-sight simplification of a cell path on `g`.
std::vector<Vec2> simplify(const BinaryGrid& g, const std::vector<Vec2>& pts) {
  if (pts.size() <= 2) return pts;
  std::vector<Vec2> out{pts.front()};
  std::size_t i = 0;
  while (i + 1 < pts.size()) {
    std::size_t j = i + 1;
    for (std::size_t k = std::min(pts.size() - 1, i + 40); k > i + 1; --k)
      if (segment_free(g, pts[i], pts[k])) {
        j = k;
        break;
      }
    out.push_back(pts[j]);
    i = j;
  }
  return out;
}

// Path from the flood's start to `goal` by descending the BFS step counts (8-neighbours).
std::vector<Vec2> descend(const BinaryGrid& g, const planning::BfsFlood& flood, Cell goal) {
  std::vector<Vec2> rev;
  std::int32_t s = flood.steps(g, goal);
  if (s < 0) return {};
  Cell c = goal;
  rev.push_back(g.geometry().cell_center(c));
  while (s > 0) {
    bool moved = false;
    for (const Cell d : kNeighbours8) {
      const Cell n = c + d;
      if (g.contains(n) && flood.steps(g, n) == s - 1) {
        c = n;
        --s;
        moved = true;
        break;
      }
    }
    if (!moved) return {};
    rev.push_back(g.geometry().cell_center(c));
  }
  return {rev.rbegin(), rev.rend()};
}

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

// The world ends at the map's edge for the laser as for the body: the outermost ring of cells
// becomes a wall. The footprint check (robot::disc_collides) already refuses cells outside the
// map, but laser rays pass out of it unhit, so on a map whose free space runs to its edge a robot
// saw open space ahead, drove at the edge, was refused every step and stood there (issue 14:
// lab_intel seed 3, 8 robots tree and 2 robots coordinated, stalled at the edge).
namespace {
BinaryGrid closed_at_edge(BinaryGrid b) {
  const int w = b.geometry().width, h = b.geometry().height;
  for (int x = 0; x < w; ++x) {
    b[Cell{x, 0}] = 1;
    b[Cell{x, h - 1}] = 1;
  }
  for (int y = 0; y < h; ++y) {
    b[Cell{0, y}] = 1;
    b[Cell{w - 1, y}] = 1;
  }
  return b;
}
}  // namespace

ExplorationResult run_exploration(const OccupancyGrid& world_in, const ExplorationOptions& o) {
  o.validate();
  if (world_in.empty()) throw Error("run_exploration", 0, "the world map is empty");
  const OccupancyGrid world = resample_world(world_in, o.min_cell_size);
  const GridGeometry& g = world.geometry();
  const BinaryGrid blocked = closed_at_edge(binarize(world, {50, true}));
  const double body = o.drive.body_radius;

  // --- start positions ---
  std::mt19937_64 rng(o.seed);
  const auto place_team = [&](Vec2 centre) {
    std::vector<Vec2> starts;
    // Candidates on a square spiral of spacing start_spacing around the centre.
    for (int ring = 0; ring < 12 && static_cast<int>(starts.size()) < o.robots; ++ring) {
      for (int dy = -ring; dy <= ring && static_cast<int>(starts.size()) < o.robots; ++dy)
        for (int dx = -ring; dx <= ring && static_cast<int>(starts.size()) < o.robots; ++dx) {
          if (std::max(std::abs(dx), std::abs(dy)) != ring) continue;
          const Vec2 p = centre + Vec2{dx * o.start_spacing, dy * o.start_spacing};
          if (robot::disc_collides(blocked, p, body + 0.05)) continue;
          if (!segment_free(blocked, centre, p)) continue;
          starts.push_back(p);
        }
    }
    return starts;
  };
  std::vector<Vec2> starts;
  if (o.start) {
    if (robot::disc_collides(blocked, *o.start, body + 0.05))
      throw Error("--start", 0, "the start is not free for a robot of radius " + num(body) + " m");
    starts = place_team(*o.start);
  } else {
    const field::DistanceField df = field::distance_transform(blocked);
    // Spots with at least 0.8 m clearance (less in cramped worlds: 70 % of the largest).
    double most = 0.0;
    for (std::size_t i = 0; i < blocked.size(); ++i)
      if (blocked[i] == 0) most = std::max(most, df.distance_m(blocked.cell_at(i)));
    const double need = std::min(0.8, 0.7 * most);
    std::vector<Cell> roomy;
    for (std::size_t i = 0; i < blocked.size(); ++i) {
      const Cell c = blocked.cell_at(i);
      if (blocked[i] == 0 && df.distance_m(c) >= need && need > body) roomy.push_back(c);
    }
    if (roomy.empty()) throw Error("run_exploration", 0, "no free spot for a robot in the world");
    std::uniform_int_distribution<std::size_t> pick(0, roomy.size() - 1);
    for (int tries = 0; tries < 50; ++tries) {
      starts = place_team(g.cell_center(roomy[pick(rng)]));
      if (static_cast<int>(starts.size()) == o.robots) break;
    }
  }
  if (static_cast<int>(starts.size()) < o.robots)
    throw Error("--robots", 0,
                "no room for " + std::to_string(o.robots) +
                    " robots around the start; give fewer --robots or another --start");
  Vec2 centre;
  for (const Vec2& s : starts)
    centre += s;
  centre = centre / static_cast<double>(starts.size());

  // --- reachable free cells (ground truth), the denominator of coverage ---
  std::vector<char> reachable(blocked.size(), 0);
  std::size_t reachable_count = 0;
  {
    const auto sc = g.world_to_cell(starts.front());
    std::vector<Cell> stack{*sc};
    reachable[blocked.index(*sc)] = 1;
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      ++reachable_count;
      for (int k = 0; k < 4; ++k) {
        const Cell n = c + kNeighbours8[k];
        if (!blocked.contains(n) || blocked[n] != 0 || reachable[blocked.index(n)]) continue;
        reachable[blocked.index(n)] = 1;
        stack.push_back(n);
      }
    }
  }

  // --- team ---
  std::vector<std::unique_ptr<Agent>> agents;
  for (int i = 0; i < o.robots; ++i) {
    const double yaw = std::uniform_real_distribution<double>(-3.14159, 3.14159)(rng);
    agents.push_back(std::make_unique<Agent>(o, Pose2{starts[static_cast<std::size_t>(i)], yaw},
                                             o.seed * 1000003ULL + static_cast<std::uint64_t>(i),
                                             g));
  }
  mapping::OccupancyMap team(g);
  mapping::LaserModelOptions beam_model;
  beam_model.max_range = o.laser.range_max;
  robot::LaserOptions map_laser = o.laser;
  map_laser.beams = std::max(1, o.laser.beams / o.map_beam_stride);
  FeatureMap features(o.features);
  robot::LaserOptions guard_laser = o.laser;  // front check while following a path
  guard_laser.beams = 13;
  guard_laser.field_of_view = 1.4;
  guard_laser.range_max = std::min(o.laser.range_max, 1.0);
  guard_laser.noise_stddev = 0.0;
  const internal::GuardRule guard_rule =
      o.guard == FrontGuard::kCone ? internal::GuardRule::kCone : internal::GuardRule::kCorridor;

  ExplorationResult result;
  result.method = o.method;
  result.robots = o.robots;
  result.reachable_free_cells = reachable_count;
  result.recording.geometry = g;
  result.recording.starts = starts;

  const double plan_radius = body + o.clearance;
  constexpr double kRobotAwareRange = 3.0;  // [m] robots nearer than this block planning
  constexpr double kCrowdRange = 2.0;       // [m] ExplorationOptions::crowd_limit
  BinaryGrid trav;
  planning::BfsFlood flood;
  const bool tree_method =
      o.method == ExplorationMethod::kTree || o.method == ExplorationMethod::kTreeFrontier;
  const bool hybrid = o.method == ExplorationMethod::kTreeFrontier;
  const double tree_start = hybrid ? o.hybrid_tree_start_time : o.tree_start_time;
  bool dispatched = false;  // the single dispatch of the first tree has happened
  double next_tree_time = tree_start;
  double next_replan = 0.0, next_check = 0.0, last_coverage = 0.0;
  // The clock, step count and periodic tasks (core/stepper.hpp, shared with sim/netsim).
  const Stepper clock(o.dt, o.time_limit, "ExplorationOptions.dt", "ExplorationOptions.time_limit");
  result.recording.reveal_time.assign(blocked.size(), -1.0F);

  const auto coverage_now = [&] {
    const auto l = team.log_odds().data();
    std::size_t known = 0;
    for (std::size_t i = 0; i < l.size(); ++i)
      if (reachable[i] && l[i] != 0.0F) ++known;
    return reachable_count ? static_cast<double>(known) / static_cast<double>(reachable_count)
                           : 0.0;
  };

  const auto start_follow = [&](Agent& a, std::vector<Vec2> route) {
    a.route = std::move(route);
    a.next = 0;
    a.mode = a.route.empty() ? AgentMode::kReactive : AgentMode::kFollow;
    a.block.on_new_route();  // not progress: the block clock goes on (block_clock.hpp)
    a.since_progress = 0.0;
    a.unsticking = false;
    a.escaping = false;
  };
  // An unstick or margin-escape route: out of the allocation and off the tree while it runs.
  const auto start_unstick_route = [&](Agent& a, std::vector<Vec2> route) {
    start_follow(a, std::move(route));
    a.unsticking = true;
    a.on_tree = false;
    a.goal.reset();
    a.goal_leaf = false;
    a.reactive_until = 0.0;
  };

  // --- tree dispatch (seed 004) ---
  // Path on `grid` from p to the free cell nearest q (BFS descent, simplified); empty when none.
  const auto path_on = [&](const BinaryGrid& grid, Vec2 p, Vec2 q) -> std::vector<Vec2> {
    const auto from = nearest_free(grid, p);
    const auto to = nearest_free(grid, q, 4);
    if (!from || !to || flood.flood(grid, *from, planning::Connectivity::k8) == 0) return {};
    std::vector<Vec2> path = descend(grid, flood, *to);
    if (path.empty()) return {};
    path.insert(path.begin(), p);
    return simplify(grid, path);
  };
  // The next leg of a robot's tree route, or (none left) the end of its dispatch.
  const auto start_leg = [&](Agent& a, double t) {
    if (!a.legs.empty()) {
      start_follow(a, a.legs.front());
      a.on_tree = true;
      return;
    }
    a.on_tree = false;
    a.tree_done = true;
    a.mode = AgentMode::kReactive;  // the paper: search reactively again
    a.route.clear();
    a.retry_at = t;
  };
  const auto log_event = [&](double t, const Agent& a, const char* kind) {
    int id = -1;
    for (std::size_t i = 0; i < agents.size(); ++i)
      if (agents[i].get() == &a) id = static_cast<int>(i);
    result.recording.events.push_back({t, id, kind});
  };
  const auto finish_leg = [&](Agent& a, double t) {
    if (!a.legs.empty()) {
      if (distance(a.body.true_pose().position, a.legs.front().back()) < 2.0 * o.goal_tolerance) {
        ++result.leaves_reached;
        log_event(t, a, "leaf");
      }
      a.legs.pop_front();
    }
    start_leg(a, t);
  };
  const auto unknown_fraction = [&](const OccupancyGrid& map, Vec2 p) {
    const auto c = g.world_to_cell(p);
    if (!c) return 0.0;
    const int r = static_cast<int>(std::ceil(o.gain_radius / g.resolution));
    int unknown = 0, all = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const Cell n{c->x + dx, c->y + dy};
        if (dx * dx + dy * dy > r * r) continue;
        ++all;
        if (!map.contains(n) || map[n] == kUnknown) ++unknown;
      }
    return all ? static_cast<double>(unknown) / all : 0.0;
  };
  const auto record_dispatch = [&](double t, std::size_t i, bool first, Vec2 root,
                                   const std::vector<Vec2>& leaves) {
    Agent& a = *agents[i];
    TreeDispatch d;
    d.t = t;
    d.robot = static_cast<int>(i);
    d.first = first;
    d.from = a.body.true_pose().position;
    d.root = root;
    d.leaves = leaves;
    d.route = a.legs.empty() ? std::vector<Vec2>{} : a.legs.front();
    result.recording.dispatches.push_back(std::move(d));
    ++result.dispatches;
  };

  // The single dispatch (figure 9): the tree of all feature points on the team map where only
  // known obstacles block, rooted at the vertex nearest the start; leaves by distance, robot i
  // takes leaves i, i + N, ...; the route runs from the root down the common trunk.
  const auto dispatch_first = [&](double t) {
    const OccupancyGrid tg = team_grid(team);
    const BinaryGrid opt = tree_grid(tg, plan_radius);
    const PointVoronoi vor = voronoi_of_points(features.positions());
    VoronoiTree tree = build_voronoi_tree(vor, opt, centre, o.tree);
    ++result.trees;
    const std::vector<int> leaves = tree.leaves_by_distance();
    if (tree.empty() || leaves.empty()) return false;
    std::vector<std::vector<int>> dispatch = dispatch_leaves(leaves, o.robots);
    const Vec2 root = tree.nodes[static_cast<std::size_t>(tree.root)].position;
    std::vector<std::vector<Vec2>> routes;
    for (std::size_t i = 0; i < agents.size(); ++i) {
      Agent& a = *agents[i];
      const Vec2 pos = a.body.true_pose().position;
      a.legs.clear();
      std::vector<Vec2> full{pos}, goals;
      int at = tree.root;
      for (std::size_t k = 0; k < dispatch[i].size(); ++k) {
        const int leaf = dispatch[i][k];
        std::vector<Vec2> leg;
        if (k == 0) {
          const Vec2 entry = tree.nodes[static_cast<std::size_t>(at)].position;
          leg = path_on(opt, pos, entry);
          if (leg.size() < 2)
            leg = {pos, entry};
          else
            leg.back() = entry;  // the path ends in the entry node's cell: end exactly on it
        } else {
          leg = {tree.nodes[static_cast<std::size_t>(at)].position};
        }
        const std::vector<Vec2> w = tree.waypoints(at, leaf);
        leg.insert(leg.end(), w.begin() + 1, w.end());
        full.insert(full.end(), leg.begin() + 1, leg.end());
        goals.push_back(tree.nodes[static_cast<std::size_t>(leaf)].position);
        a.legs.push_back(std::move(leg));
        at = leaf;
      }
      routes.push_back(std::move(full));
      a.tree_done = false;
      a.reactive_until = 0.0;
      if (a.legs.empty()) {
        a.tree_done = true;
        continue;
      }
      start_leg(a, t);
      record_dispatch(t, i, true, root, goals);
    }
    result.leaves = static_cast<int>(tree.leaves_by_distance().size());
    result.recording.tree = std::move(tree);
    result.recording.dispatch = std::move(dispatch);
    result.recording.routes = std::move(routes);
    result.recording.tree_time = t;
    return true;
  };

  // TreeReplan::kFromRobots: a robot done with its leaves gets a tree rooted where it is and goes
  // to the nearest leaf that still looks into unknown space and no other robot is heading to.
  const auto replan_from_robot = [&](std::size_t i, double t) {
    Agent& a = *agents[i];
    a.retry_at = t + 10.0;
    const Vec2 pos = a.body.true_pose().position;
    const OccupancyGrid tg = team_grid(team);
    const BinaryGrid opt = tree_grid(tg, plan_radius);
    const PointVoronoi vor = voronoi_of_points(features.positions());
    const VoronoiTree tree = build_voronoi_tree(vor, opt, pos, o.tree);
    ++result.trees;
    if (tree.empty()) return;
    for (int leaf : tree.leaves_by_distance()) {
      const Vec2 lp = tree.nodes[static_cast<std::size_t>(leaf)].position;
      if (unknown_fraction(tg, lp) < o.min_leaf_gain) continue;
      bool taken = false;
      for (std::size_t j = 0; j < agents.size(); ++j)
        if (j != i && agents[j]->on_tree && !agents[j]->legs.empty())
          taken = taken || distance(agents[j]->legs.back().back(), lp) < 2.0;
      if (taken) continue;
      const Vec2 root = tree.nodes[static_cast<std::size_t>(tree.root)].position;
      std::vector<Vec2> leg = path_on(opt, pos, root);
      if (leg.empty()) return;
      if (leg.size() > 1)
        leg.back() = root;
      else
        leg.push_back(root);
      const std::vector<Vec2> w = tree.waypoints(tree.root, leaf);
      leg.insert(leg.end(), w.begin() + 1, w.end());
      a.legs.assign(1, std::move(leg));
      a.tree_done = false;
      start_leg(a, t);
      record_dispatch(t, i, false, root, {lp});
      return;
    }
  };

  // Tree routes run through unknown space: when the map shows a known obstacle on the rest of a
  // leg, the leg is re-planned from where the robot is to its leaf (BFS on the grid where only
  // known obstacles block); a leaf that became unreachable is given up.
  const auto check_tree_routes = [&](double t) {
    bool any = false;
    for (auto& ap : agents)
      any = any || (ap->on_tree && ap->mode == AgentMode::kFollow);
    if (!any) return;
    const BinaryGrid opt = tree_grid(team_grid(team), plan_radius);
    for (auto& ap : agents) {
      Agent& a = *ap;
      if (!a.on_tree || a.mode != AgentMode::kFollow || t < a.reactive_until) continue;
      const Vec2 pos = a.body.true_pose().position;
      bool ok = nearest_free(opt, a.route.back(), 1).has_value();
      const auto pc = g.world_to_cell(pos);
      if (ok && a.next < a.route.size() && pc && opt[*pc] == 0)
        ok = segment_free(opt, pos, a.route[a.next]);
      for (std::size_t k = std::max<std::size_t>(a.next, 1); ok && k < a.route.size(); ++k)
        ok = segment_free(opt, a.route[k - 1], a.route[k]);
      if (ok) continue;
      std::vector<Vec2> path = path_on(opt, pos, a.route.back());
      if (path.empty() || distance(path.back(), a.route.back()) > 0.5) {
        finish_leg(a, t);  // unreachable now: give the leaf up
        continue;
      }
      a.legs.front() = path;
      // Same goal, new route: the robot's progress clock goes on (resetting it, and the block
      // clock, let a robot that the route check re-routed every 2 s stand still for minutes;
      // willow, 16).
      const double no_progress = a.since_progress;
      start_follow(a, std::move(path));
      a.since_progress = no_progress;
    }
  };

  // TreeLegReplan::kAroundRobots: a robot blocked on a tree leg re-plans the rest of the leg
  // from where it is to the same leaf on the current tree grid, with the discs of the robots
  // within kRobotAwareRange blocked (the frontier methods' robot-aware planning). True when a
  // new leg was started. Without it the single dispatch sends all robots along the common trunk
  // and on willow with 16 robots they jammed in cluttered passages for minutes (issue 14).
  const auto replan_leg = [&](std::size_t i, double t) {
    Agent& a = *agents[i];
    if (!a.on_tree || a.route.empty() || a.legs.empty()) return false;
    const Vec2 pos = a.body.true_pose().position, leaf = a.route.back();
    // A re-plan that did not get the robot moving is not repeated on the same spot for 15 s.
    if (t - a.leg_replan_t < 15.0 && distance(pos, a.leg_replan_at) < o.stall_distance)
      return false;
    a.leg_replan_t = t;
    a.leg_replan_at = pos;
    BinaryGrid opt = tree_grid(team_grid(team), plan_radius);
    std::vector<Vec2> others_at;
    for (std::size_t j = 0; j < agents.size(); ++j)
      if (j != i) others_at.push_back(agents[j]->body.true_pose().position);
    const std::vector<std::size_t> marked =
        block_robot_discs(opt, pos, others_at, 2.0 * body + 0.05, kRobotAwareRange);
    std::vector<Vec2> path = path_on(opt, pos, leaf);
    restore_free_cells(opt, marked);
    if (path.size() < 2 || distance(path.back(), leaf) > 0.5) return false;
    ++result.leg_replans;
    a.legs.front() = path;
    start_follow(a, std::move(path));
    a.on_tree = true;
    return true;
  };

  // ExplorationOptions::unstick (ours, every method): a robot that the progress watchdog finds on
  // one spot drives to open space nearby: on the team map's known-free cells (inflated by the
  // body radius + clearance) with the discs of the robots within kRobotAwareRange blocked, the
  // reachable cell 1-4 m of path away with the most clearance (unstick_target, unstick.hpp).
  // When no such cell is reachable (boxed in by robots), the robots touching it move away the
  // same way. Traced on willow with 16 robots (issue 14): a robot in a small room with three
  // robots at its door, and one between map speckle and two robots, dithered in avoid turns and
  // 1 m corridor escapes for 60 s (stalled).
  const auto unstick = [&](auto&& self, std::size_t i, double t, bool ask_others) -> bool {
    Agent& a = *agents[i];
    const Vec2 pos = a.body.true_pose().position;
    BinaryGrid grid = traversable_of(team_grid(team), plan_radius);
    const field::DistanceField clearance = field::distance_transform(grid);  // without robots
    std::vector<Vec2> others_at;
    for (std::size_t j = 0; j < agents.size(); ++j)
      if (j != i) others_at.push_back(agents[j]->body.true_pose().position);
    (void)block_robot_discs(grid, pos, others_at, 2.0 * body + 0.05, kRobotAwareRange);
    std::vector<Vec2> path;
    const auto from = nearest_free(grid, pos, 3);
    if (from && flood.flood(grid, *from, planning::Connectivity::k8) > 0) {
      const std::optional<Cell> best = unstick_target(grid, flood, clearance);
      if (best) path = descend(grid, flood, *best);
      if (!path.empty()) {
        path.insert(path.begin(), pos);
        path = simplify(grid, path);
      }
    }
    if (path.size() >= 2) {
      start_unstick_route(a, std::move(path));
      ++result.unsticks;
      log_event(t, a, "unstick");
      return true;
    }
    if (ask_others)
      for (std::size_t j = 0; j < agents.size(); ++j)
        if (j != i && !agents[j]->unsticking &&
            distance(agents[j]->body.true_pose().position, pos) < 2.0 * body + 0.3)
          self(self, j, t, false);
    return false;
  };
  // The end of an unstick route: a robot with tree legs left goes on with the next one, planned
  // from where it is; else it searches reactively (and the frontier methods allocate again).
  const auto end_unstick = [&](Agent& a, double t) {
    a.unsticking = false;
    a.escaping = false;
    a.route.clear();
    a.mode = AgentMode::kReactive;
    if (a.legs.empty()) return;
    const BinaryGrid opt = tree_grid(team_grid(team), plan_radius);
    std::vector<Vec2> path = path_on(opt, a.body.true_pose().position, a.legs.front().back());
    if (path.size() >= 2 && distance(path.back(), a.legs.front().back()) <= 0.5)
      a.legs.front() = std::move(path);
    else
      a.legs.pop_front();  // the leaf is out of reach from here: give it up
    start_leg(a, t);
  };

  // kTreeFrontier (ours): the current tree's leaves, rebuilt every hybrid_tree_period from all
  // feature points on the team map (only known obstacles block), rooted at the team's start.
  std::vector<Vec2> leaf_goals;
  const auto rebuild_hybrid_tree = [&](double t) {
    const BinaryGrid opt = tree_grid(team_grid(team), plan_radius);
    VoronoiTree tree =
        build_voronoi_tree(voronoi_of_points(features.positions()), opt, centre, o.tree);
    ++result.trees;
    leaf_goals.clear();
    for (int l : tree.leaves_by_distance())
      leaf_goals.push_back(tree.nodes[static_cast<std::size_t>(l)].position);
    if (result.recording.tree_time < 0.0 && !tree.empty()) {
      result.leaves = static_cast<int>(leaf_goals.size());
      result.recording.tree = std::move(tree);
      result.recording.tree_time = t;
    }
  };

  // Frontier allocation (kFrontier, kCoordinated). kTreeFrontier adds the tree's leaves that
  // look into unknown space as candidate targets (costs on the grid where only known obstacles
  // block) and ranks every target by its information gain (the unknown fraction around it).
  planning::BfsFlood flood_opt;
  // ExplorationOptions::share_bans (internal/team_bans.hpp).
  internal::TeamBans team_bans;
  // Robot-aware planning: for robot i, the discs of the other robots within kRobotAwareRange
  // block `trav` (a robot centre cannot come within two body radii of another's), so a robot
  // plans around a robot in its way, and a goal reachable only through a crowd costs the detour
  // or is out of reach this round. Without it 16 robots on willow crowded into the corridors
  // at the last frontiers and jammed there (stalled robots). Returns the cells to restore.
  const auto mark_others_on = [&](BinaryGrid& grid, std::size_t i) {
    std::vector<Vec2> others_at;
    for (std::size_t j = 0; j < agents.size(); ++j)
      if (j != i) others_at.push_back(agents[j]->body.true_pose().position);
    return block_robot_discs(grid, agents[i]->body.true_pose().position, others_at,
                             2.0 * body + 0.05, kRobotAwareRange);
  };
  const auto mark_others = [&](std::size_t i) { return mark_others_on(trav, i); };
  const auto unmark = [&](const std::vector<std::size_t>& marked) {
    restore_free_cells(trav, marked);
  };
  const auto replan_frontiers = [&](double t) {
    std::vector<std::size_t> active;
    for (std::size_t i = 0; i < agents.size(); ++i)
      if (!agents[i]->unsticking) active.push_back(i);
    const OccupancyGrid tg = team_grid(team);
    trav = traversable_of(tg, plan_radius);
    std::vector<Frontier> fr = find_frontiers(tg, trav, o.frontier);
    const std::size_t n_frontiers = fr.size();
    if (o.share_bans)
      result.shared_bans +=
          team_bans.update(tg, team.log_odds(), std::span<const Frontier>(fr.data(), n_frontiers),
                           o.laser.range_max, t, o.map_period);
    std::vector<double> gains;
    BinaryGrid opt;
    if (hybrid) {
      for (const Frontier& f : fr)
        gains.push_back(unknown_fraction(tg, g.cell_center(f.target)));
      opt = tree_grid(tg, plan_radius);
      for (const Vec2& l : leaf_goals) {
        const double gain = unknown_fraction(tg, l);
        if (gain < o.min_leaf_gain) continue;
        const auto c = nearest_free(opt, l, 2);
        if (!c) continue;
        Frontier leaf;
        leaf.centroid = l;
        leaf.target = *c;
        fr.push_back(std::move(leaf));
        gains.push_back(gain);
      }
    }
    // ExplorationOptions::crowd_limit (kFrontier): robots at a frontier = within kCrowdRange of
    // its target or heading to it (an earlier robot's choice in this allocation, else its goal).
    std::vector<std::optional<Vec2>> heading(agents.size());
    for (std::size_t i = 0; i < agents.size(); ++i)
      if (agents[i]->goal && !agents[i]->goal_leaf) heading[i] = agents[i]->goal;
    const auto crowded = [&](std::size_t i, std::size_t f) {
      if (o.crowd_limit <= 0 || o.method != ExplorationMethod::kFrontier) return false;
      const Vec2 tp = g.cell_center(fr[f].target);
      if (distance(agents[i]->body.true_pose().position, tp) < kCrowdRange) return false;
      int n = 0;
      for (std::size_t j = 0; j < agents.size(); ++j)
        if (j != i && (distance(agents[j]->body.true_pose().position, tp) < kCrowdRange ||
                       (heading[j] && distance(*heading[j], tp) < 0.5)))
          ++n;
      if (n < o.crowd_limit) return false;
      ++result.crowd_skips;
      return true;
    };
    std::vector<std::vector<double>> costs(active.size(), std::vector<double>(fr.size(), -1.0));
    std::vector<std::vector<std::vector<Vec2>>> paths(active.size());
    for (std::size_t r = 0; r < active.size(); ++r) {
      Agent& a = *agents[active[r]];
      const Vec2 pos = a.body.true_pose().position;
      const auto banned = [&](Vec2 tp) {
        for (const Vec2& b : a.blacklist)
          if (distance(b, tp) < 0.5) return true;
        for (const Vec2& b : a.soft_bans)
          if (distance(b, tp) < 0.5) return true;
        return o.share_bans && team_bans.banned(tp);
      };
      if (fr.size() > n_frontiers) {
        // Leaves are costed robot-aware too, as the frontiers below: without it leaf routes ran
        // head-on through robots in a doorway and jammed there (willow, 16 robots, issue 14).
        const std::vector<std::size_t> marked_opt = mark_others_on(opt, active[r]);
        const auto from = nearest_free(opt, pos);
        if (from && flood_opt.flood(opt, *from, planning::Connectivity::k8) > 0)
          for (std::size_t f = n_frontiers; f < fr.size(); ++f) {
            const std::int32_t s = flood_opt.steps(opt, fr[f].target);
            if (s >= 0 && !banned(fr[f].centroid)) costs[r][f] = s * g.resolution;
          }
        restore_free_cells(opt, marked_opt);
      }
      const std::vector<std::size_t> marked = mark_others(active[r]);
      const auto from = nearest_free(trav, pos);
      if (!from || flood.flood(trav, *from, planning::Connectivity::k8) == 0) {
        unmark(marked);
        continue;
      }
      for (std::size_t f = 0; f < n_frontiers; ++f) {
        const Vec2 tp = g.cell_center(fr[f].target);
        const std::int32_t s = flood.steps(trav, fr[f].target);
        if (!banned(tp) && s >= 0 && !crowded(active[r], f)) costs[r][f] = s * g.resolution;
      }
      // Paths only for the frontiers this robot might take are made below (same flood reused).
      paths[r].resize(fr.size());
      const std::vector<int> mine = o.method == ExplorationMethod::kFrontier
                                        ? assign_nearest(fr, {costs[r]}, o.frontier)
                                        : std::vector<int>{};
      if (!mine.empty() && mine[0] >= 0) {
        const auto k = static_cast<std::size_t>(mine[0]);
        paths[r][k] = descend(trav, flood, fr[k].target);
        if (o.crowd_limit > 0) heading[active[r]] = g.cell_center(fr[k].target);
      }
      unmark(marked);
    }
    std::vector<int> choice = o.method == ExplorationMethod::kFrontier
                                  ? assign_nearest(fr, costs, o.frontier)
                                  : assign_coordinated(fr, costs, o.frontier, gains);
    for (std::size_t r = 0; r < active.size(); ++r) {
      Agent& a = *agents[active[r]];
      if (choice[r] < 0) {
        // ExplorationOptions::retry_banned: no goal left for this robot, yet it gave goals up
        // only because it was blocked or made no progress: it may try them again (at the next
        // allocation), at most once per stall_time.
        if (o.retry_banned && !a.soft_bans.empty() && t - a.ban_reset_t >= o.stall_time) {
          a.soft_bans.clear();
          a.ban_reset_t = t;
          ++result.ban_resets;
        }
        // ExplorationOptions::drop_goalless_routes: the route led to a goal that is gone.
        if (o.drop_goalless_routes && a.goal && a.mode == AgentMode::kFollow) {
          a.route.clear();
          ++result.route_drops;
        }
        a.goal.reset();
        if (a.mode == AgentMode::kFollow && a.route.empty()) a.mode = AgentMode::kReactive;
        continue;
      }
      const auto k = static_cast<std::size_t>(choice[r]);
      if (k >= n_frontiers) {
        // A tree leaf: the route runs through unknown space, so it is planned afresh from where
        // the robot is at every allocation (a route the map has since blocked is replaced).
        const bool same = a.goal_leaf && a.goal && distance(*a.goal, fr[k].centroid) < 0.5;
        const std::vector<std::size_t> marked_opt = mark_others_on(opt, active[r]);
        std::vector<Vec2> path = path_on(opt, a.body.true_pose().position, fr[k].centroid);
        restore_free_cells(opt, marked_opt);
        if (path.empty()) continue;
        if (!same) ++result.leaf_goals;
        a.goal = fr[k].centroid;
        a.goal_leaf = true;
        const double keep_progress = a.since_progress;
        start_follow(a, std::move(path));
        if (same) a.since_progress = keep_progress;
        continue;
      }
      const Vec2 tp = g.cell_center(fr[k].target);
      if (a.goal && !a.goal_leaf && distance(*a.goal, tp) < 0.5 && a.mode == AgentMode::kFollow)
        continue;
      a.goal_leaf = false;
      std::vector<Vec2> path = paths[r][k];
      if (path.empty()) {
        const std::vector<std::size_t> marked = mark_others(active[r]);
        const auto from = nearest_free(trav, a.body.true_pose().position);
        if (from && flood.flood(trav, *from, planning::Connectivity::k8) > 0)
          path = descend(trav, flood, fr[k].target);
        unmark(marked);
      }
      if (path.empty()) continue;
      path.insert(path.begin(), a.body.true_pose().position);
      a.goal = tp;
      ++result.frontier_goals;
      start_follow(a, simplify(trav, path));
    }
  };

  // --- the loop: sense -> decide -> move (act) -> record, every step (core/stepper.hpp) ---
  std::vector<robot::Disc> others;
  for (auto& ap : agents)
    ap->anchor = ap->body.true_pose().position;
  // Sense and map (every map_period).
  const auto sense = [&](const Stepper::Step&) {
    for (auto& ap : agents) {
      Agent& a = *ap;
      const robot::LaserScan scan =
          robot::cast_scan(blocked, a.body.true_pose(), map_laser, {}, nullptr);
      mapping::RangeScan rs;
      rs.pose = scan.pose;
      rs.bearings.resize(scan.ranges.size());
      rs.ranges.resize(scan.ranges.size());
      for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
        rs.bearings[k] = scan.angle(k);
        rs.ranges[k] = scan.ranges[k];
      }
      a.map.insert_scan(rs, beam_model);
      team.insert_scan(rs, beam_model);
      if (tree_method) features.add(extract_feature_points(scan, o.features));
    }
  };
  // Decide.
  const auto decide = [&](const Stepper::Step& s) {
    const double t = s.t;
    if (hybrid) {
      if (t >= next_tree_time) {
        rebuild_hybrid_tree(t);
        next_tree_time = t + o.hybrid_tree_period;
      }
      if (t >= next_replan) {
        replan_frontiers(t);
        next_replan = t + o.replan_period;
      }
    } else if (tree_method) {
      if (!dispatched && t >= next_tree_time) {
        if (dispatch_first(t)) {
          dispatched = true;
        } else {
          next_tree_time = t + 30.0;  // too few feature points yet: try again later
        }
      }
      if (dispatched && t >= next_check) {
        check_tree_routes(t);
        next_check = t + o.replan_period;
      }
      if (dispatched && o.tree_replan == TreeReplan::kFromRobots)
        for (std::size_t i = 0; i < agents.size(); ++i)
          if (agents[i]->tree_done && !agents[i]->on_tree && t >= agents[i]->retry_at &&
              !agents[i]->unsticking)
            replan_from_robot(i, t);
    } else if (t >= next_replan) {
      replan_frontiers(t);
      next_replan = t + o.replan_period;
    }
  };
  // Act: every robot's command for this step, then its motion to the step's end.
  const auto act = [&](const Stepper::Step& s) {
    const double t = s.t;
    for (std::size_t i = 0; i < agents.size(); ++i) {
      Agent& a = *agents[i];
      others.clear();
      for (std::size_t j = 0; j < agents.size(); ++j)
        if (j != i) others.push_back({agents[j]->body.true_pose().position, body});
      const Pose2 pose = a.body.true_pose();
      robot::BodyVelocity cmd;
      const bool was_guard_stopped = a.guard_stopped;
      a.guard_stopped = false;
      if (a.mode == AgentMode::kFollow && t < a.reactive_until) {
        cmd = a.controller.update(robot::cast_scan(blocked, pose, o.laser, others, &rng), o.dt);
      } else if (a.mode == AgentMode::kFollow) {
        // Waypoint following: advance past reached waypoints, steer to the farthest visible one.
        // A margin escape ends on its exit cell (kCornerReach), not 0.3 m short of it, where the
        // robot would still be in the margin.
        const double tolerance = a.escaping ? internal::kCornerReach : o.goal_tolerance;
        while (a.next < a.route.size() && distance(pose.position, a.route[a.next]) < tolerance) {
          // FrontGuard::kCorridor: no cutting a corner of the route where the body would not
          // clear the wall (internal/front_guard.hpp); drive on to the waypoint instead.
          if (o.guard == FrontGuard::kCorridor && a.next + 1 < a.route.size() &&
              distance(pose.position, a.route[a.next]) > internal::kCornerReach &&
              !internal::line_clear(blocked, pose.position, a.route[a.next + 1], body))
            break;
          ++a.next;
          a.since_progress = 0.0;
        }
        if (a.next >= a.route.size()) {
          if (a.goal_leaf && a.goal) {
            // A leaf is visited once: reached (or its route ended short of it) it is done.
            if (distance(pose.position, *a.goal) < 2.0 * o.goal_tolerance) {
              ++result.leaves_reached;
              log_event(t, a, "leaf");
            }
            a.blacklist.push_back(*a.goal);
          } else if (a.goal && distance(pose.position, *a.goal) < 2.0 * o.goal_tolerance) {
            // A frontier still there once the robot stands on its target cannot be observed
            // from here (unknown cells walled in, e.g. in clutter): not this robot's goal again.
            // Chasing it again kept a robot circling on one spot (willow, 16 robots).
            a.blacklist.push_back(*a.goal);
            // ExplorationOptions::share_bans: nor any robot's (same map, same laser), when the
            // frontier is still there at the next allocation.
            if (o.share_bans) team_bans.reached(*a.goal, t);
          }
          a.goal.reset();
          a.goal_leaf = false;
          if (a.on_tree) {
            finish_leg(a, t);
          } else if (a.unsticking) {
            end_unstick(a, t);
          } else {
            a.mode = AgentMode::kReactive;
          }
          cmd = {};
        } else {
          const Vec2 target = a.route[a.next];
          const double e = wrap_angle(
              std::atan2(target.y - pose.position.y, target.x - pose.position.x) - pose.yaw);
          cmd.omega = std::clamp(1.5 * e, -o.drive.max_angular_speed, o.drive.max_angular_speed);
          cmd.v = std::abs(e) > 0.6 ? 0.0 : o.controller.drive_velocity * std::cos(e);
          // Guard: a robot right in front, or a wall (ExplorationOptions::guard: anything in the
          // cone, or a wall on the route's swept corridor; internal/front_guard.hpp) -> stop.
          const internal::GuardVerdict gv =
              cmd.v > 0.0 ? internal::front_guard(guard_rule, blocked, pose, a.route, a.next,
                                                  others, body, guard_laser)
                          : internal::GuardVerdict{};
          if (gv.stop && !was_guard_stopped)
            ++(gv.by_robot ? result.guard_robot_stops : result.guard_wall_stops);
          a.guard_stopped = gv.stop;
          if (gv.stop) {
            cmd.v = 0.0;
            a.block.on_step_refused(o.dt);
            // Right of way: blocked by a robot with a lower index (not by a wall), this robot
            // backs off for a moment so that a jam in a doorway dissolves.
            // ExplorationOptions::yield_to_held: also from a robot in front that is held up
            // itself (internal/right_of_way.hpp).
            if (gv.by_robot)
              for (std::size_t j = 0; j < agents.size(); ++j) {
                const Agent& b = *agents[j];
                const internal::RightOfWayPeer peer{
                    static_cast<int>(j), b.body.true_pose().position,
                    b.mode == AgentMode::kFollow && b.block.blocked_for() > 0.5 &&
                        t >= b.back_off_until};
                if (internal::backs_off_for(static_cast<int>(i), pose, peer, 2.0 * body + 0.3,
                                            o.yield_to_held)) {
                  if (j > i && t >= a.back_off_until) ++result.yields;
                  a.back_off_until = t + 2.0;
                }
              }
          }
          if (t < a.back_off_until) cmd = {-0.1, 0.0};
          a.since_progress += o.dt;
          if (a.block.fires() || a.since_progress > 30.0) {
            // Deadlock or no progress: search reactively for a while, then drop the goal (banned
            // for this robot). Banning only goals without progress for 30 s, not blocked ones,
            // was tried (issue 14, fifth pass): depot seed 8 (frontier) then reached 99.5 %
            // instead of 96.3 %, but willow seed 2 (16 robots, frontier) stalled 4 robots.
            a.reactive_until = t + 5.0;
            a.block.on_fired();
            a.since_progress = 0.0;
            if (a.unsticking) {
              end_unstick(a, t);
            } else if (!a.on_tree) {
              if (a.goal) a.soft_bans.push_back(*a.goal);
              a.goal.reset();
              a.route.clear();
              a.mode = AgentMode::kReactive;
            } else if (o.tree_leg_replan == TreeLegReplan::kAroundRobots && replan_leg(i, t)) {
              a.reactive_until = 0.0;  // a new leg around the robots in the way
            } else {
              ++a.next;  // skip the waypoint that cannot be reached
            }
          }
        }
      } else {
        cmd = a.controller.update(robot::cast_scan(blocked, pose, o.laser, others, &rng), o.dt);
      }
      a.body.command(cmd);
      // Footprint safety (as a check of the scan points around the footprint would do): a
      // command that would touch an obstacle within the next few steps becomes a turn on the spot.
      if (cmd.v != 0.0) {
        const double ahead = std::copysign(std::min(0.1, std::abs(cmd.v) * 3.0 * o.dt), cmd.v);
        const Vec2 next = pose.position + Vec2{std::cos(pose.yaw), std::sin(pose.yaw)} * ahead;
        if (robot::disc_collides(blocked, next, body + 0.01, others)) {
          cmd.v = 0.0;
          if (cmd.omega == 0.0) cmd.omega = o.controller.obs_avoid;
          a.block.on_step_refused(o.dt);
        } else if (cmd.v > 0.0) {
          // Only a forward step that is taken ends a block, for every method: not a step the
          // guard lets through (its 13 beams may see a clear front while the footprint check
          // refuses) and not a new route. Either reset kept a robot standing still with the 3 s
          // block rule never firing: a tree leg until the 20 s watchdog (willow, 16 robots,
          // tree), and tree-frontier robots whose allocation changed goal every 2 s in a doorway
          // jam for 60 s and more (issue 14, fifth pass).
          a.block.on_forward_step_taken();
        }
      }
      a.body.command(cmd);
      a.body.step(o.dt, blocked, others);
      // Stall watch: idle (within stall_distance of one spot) for stall_time while reachable
      // unknown space remains.
      const Vec2 now = a.body.true_pose().position;
      // Progress watchdog: a robot that has not left a stall_distance circle for a third of
      // stall_time gives up its goal (tree leaf or frontier) and searches reactively for a while.
      if (distance(now, a.wd_anchor) > o.stall_distance) {
        a.wd_anchor = now;
        a.wd_t = t;
      } else if (t - a.wd_t > o.stall_time / 3.0) {
        a.wd_anchor = now;
        a.wd_t = t;
        ++result.watchdog_events;
        log_event(t, a, "watchdog");
        const bool had_goal = a.mode == AgentMode::kFollow;
        if (a.on_tree) {
          finish_leg(a, t);
        } else if (a.mode == AgentMode::kFollow) {
          if (a.goal) a.soft_bans.push_back(*a.goal);
          a.goal.reset();
          a.route.clear();
          a.mode = AgentMode::kReactive;
          a.unsticking = false;
        }
        a.reactive_until = t + 10.0;
        // ExplorationOptions::margin_escape: inside the planning margin, out of it first.
        std::optional<Vec2> exit_at;
        if (o.margin_escape)
          exit_at = margin_exit(traversable_of(team_grid(team), plan_radius), blocked, now, body,
                                plan_radius);
        if (exit_at) {
          start_unstick_route(a, {now, *exit_at});
          a.block.on_fired();  // its own 3 s: the clock ran on the route that stopped it
          a.escaping = true;
          ++result.margin_escapes;
          log_event(t, a, "margin_escape");
        } else if (o.method == ExplorationMethod::kTree ? o.unstick : o.frontier_unstick) {
          unstick(unstick, i, t, true);
        } else if (o.idle_unstick && !had_goal && o.method != ExplorationMethod::kTree) {
          // ExplorationOptions::idle_unstick: a goalless robot moves to open space.
          if (unstick(unstick, i, t, true)) ++result.idle_unsticks;
        }
      }
      if (distance(now, a.anchor) > o.stall_distance) {
        a.anchor = now;
        a.anchor_t = t;
      } else if (!a.stalled && t - a.anchor_t > o.stall_time && last_coverage < 0.99) {
        a.stalled = true;
        ++result.stalled_robots;
        log_event(t, a, "stalled");
      }
    }
  };
  // Record (every record_period, and at the end): a frame at the step's end.
  bool stop = false;  // stop_at_coverage reached
  const auto record = [&](const Stepper::Step& s) {
    ExplorationFrame f;
    f.t = s.t_end;
    for (auto& ap : agents)
      f.poses.push_back(ap->body.true_pose());
    f.coverage = coverage_now();
    last_coverage = f.coverage;
    if (o.on_frame) o.on_frame(f.t, f.coverage);
    {
      const auto l = team.log_odds().data();
      auto& rt = result.recording.reveal_time;
      for (std::size_t k = 0; k < l.size(); ++k)
        if (rt[k] < 0.0F && l[k] != 0.0F) rt[k] = static_cast<float>(f.t);
    }
    if (!result.t90_s && f.coverage >= 0.90) result.t90_s = f.t;
    if (!result.t99_s && f.coverage >= 0.99) result.t99_s = f.t;
    stop = f.coverage >= o.stop_at_coverage;
    result.recording.frames.push_back(std::move(f));
  };
  Stepper::Phases phases;
  phases.sense = sense;
  phases.decide = decide;
  phases.move = act;
  phases.record = record;
  phases.done = [&] { return stop; };
  phases.sense_every = clock.every(o.map_period, "ExplorationOptions.map_period");
  phases.record_every = clock.every(o.record_period, "ExplorationOptions.record_period");
  clock.run(phases);
  // --- results ---
  result.sim_time_s = result.recording.frames.empty() ? 0.0 : result.recording.frames.back().t;
  result.coverage = coverage_now();
  std::size_t team_known = 0, sum_known = 0;
  for (const float l : team.log_odds().data())
    team_known += l != 0.0F ? 1 : 0;
  for (auto& ap : agents) {
    result.distance_m += ap->body.distance_travelled();
    result.collisions += ap->body.collisions();
    for (const float l : ap->map.log_odds().data())
      sum_known += l != 0.0F ? 1 : 0;
  }
  result.overlap =
      team_known ? static_cast<double>(sum_known) / static_cast<double>(team_known) - 1.0 : 0.0;
  for (auto& ap : agents)
    result.escapes += ap->controller.escapes();
  result.feature_points = static_cast<int>(features.size());
  result.recording.feature_points = features.points();
  result.recording.team_map = team_grid(team);
  return result;
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
     << ",\"watchdog_events\":" << r.watchdog_events << ",\"leg_replans\":" << r.leg_replans
     << ",\"escapes\":" << r.escapes << ",\"unsticks\":" << r.unsticks
     << ",\"idle_unsticks\":" << r.idle_unsticks << ",\"yields\":" << r.yields
     << ",\"ban_resets\":" << r.ban_resets << ",\"shared_bans\":" << r.shared_bans
     << ",\"crowd_skips\":" << r.crowd_skips << ",\"route_drops\":" << r.route_drops
     << ",\"margin_escapes\":" << r.margin_escapes << ",\"guard_wall_stops\":" << r.guard_wall_stops
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
