// An exploration run's start, the phases of its steps and its results (internal/team_run.hpp).
#include "voronav/exploration/internal/team_run.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "voronav/core/error.hpp"
#include "voronav/exploration/internal/information_gain.hpp"
#include "voronav/exploration/internal/plan_grid.hpp"
#include "voronav/exploration/internal/stall_rule.hpp"
#include "voronav/exploration/voronoi_tree.hpp"
#include "voronav/field/distance_transform.hpp"

namespace voronav::exploration::internal {
namespace {

// The world ends at the map's edge for the laser as for the body: the outermost ring of cells
// becomes a wall. The footprint check (robot::disc_collides) already refuses cells outside the
// map, but laser rays pass out of it unhit, so on a map whose free space runs to its edge a robot
// saw open space ahead, drove at the edge, was refused every step and stood there (issue 14:
// lab_intel seed 3, 8 robots tree and 2 robots coordinated, stalled at the edge).
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

TeamRun::TeamRun(OccupancyGrid world_in, const ExplorationOptions& opts)
    : o(opts),
      world(std::move(world_in)),
      g(world.geometry()),
      blocked(closed_at_edge(binarize(world, {50, true}))),
      body(o.drive.body_radius),
      plan_radius(body + o.clearance),
      rng(o.seed),
      team(g),
      features(o.features),
      guard_rule(o.guard == FrontGuard::kCone ? GuardRule::kCone : GuardRule::kCorridor),
      tree_method(o.method == ExplorationMethod::kTree ||
                  o.method == ExplorationMethod::kTreeFrontier),
      hybrid(o.method == ExplorationMethod::kTreeFrontier),
      tree_start(hybrid ? o.hybrid_tree_start_time : o.tree_start_time),
      next_tree_time(tree_start) {
  place_team_start();
  count_reachable();
  map_stall_reach();
  for (int i = 0; i < o.robots; ++i) {
    const double yaw = std::uniform_real_distribution<double>(-3.14159, 3.14159)(rng);
    agents.push_back(std::make_unique<Agent>(o, Pose2{starts[static_cast<std::size_t>(i)], yaw},
                                             o.seed * 1000003ULL + static_cast<std::uint64_t>(i),
                                             g));
  }
  beam_model.max_range = o.laser.range_max;
  map_laser = o.laser;
  map_laser.beams = std::max(1, o.laser.beams / o.map_beam_stride);
  guard_laser = o.laser;
  guard_laser.beams = 13;
  guard_laser.field_of_view = 1.4;
  guard_laser.range_max = std::min(o.laser.range_max, 1.0);
  guard_laser.noise_stddev = 0.0;
  result.method = o.method;
  result.robots = o.robots;
  result.reachable_free_cells = reachable_count;
  result.recording.geometry = g;
  result.recording.starts = starts;
  result.recording.reveal_time.assign(blocked.size(), -1.0F);
}

// The team's start: o.start, or a seeded spot with room (0.8 m clearance, less in cramped
// worlds); the robots on a square spiral of spacing start_spacing around it, each in line of
// sight of the centre.
void TeamRun::place_team_start() {
  const auto place_team = [&](Vec2 at) {
    std::vector<Vec2> out;
    for (int ring = 0; ring < 12 && static_cast<int>(out.size()) < o.robots; ++ring) {
      for (int dy = -ring; dy <= ring && static_cast<int>(out.size()) < o.robots; ++dy)
        for (int dx = -ring; dx <= ring && static_cast<int>(out.size()) < o.robots; ++dx) {
          if (std::max(std::abs(dx), std::abs(dy)) != ring) continue;
          const Vec2 p = at + Vec2{dx * o.start_spacing, dy * o.start_spacing};
          if (robot::disc_collides(blocked, p, body + 0.05)) continue;
          if (!segment_free(blocked, at, p)) continue;
          out.push_back(p);
        }
    }
    return out;
  };
  if (o.start) {
    if (robot::disc_collides(blocked, *o.start, body + 0.05)) {
      std::ostringstream m;
      m << "the start is not free for a robot of radius " << body << " m";
      throw Error("--start", 0, m.str());
    }
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
  for (const Vec2& s : starts)
    centre += s;
  centre = centre / static_cast<double>(starts.size());
}

// The reachable free cells (ground truth; 4-connected from the first start), the denominator of
// coverage.
void TeamRun::count_reachable() {
  reachable.assign(blocked.size(), 0);
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

void TeamRun::map_stall_reach() {
  stall_reach =
      robot_reach(blocked, o.stall_reach_radius > 0.0 ? o.stall_reach_radius : plan_radius, starts);
}

// Once none remains it stays so (the team map only learns), so the scan of the whole map runs
// when a robot first reaches stall_time on one spot while some remains (then it is stalled) and
// at most once per step, not every step for robots idle when explored.
bool TeamRun::unknown_space_remains(double t) {
  if (t == unknown_checked_t || !unknown_remains) return unknown_remains;
  unknown_checked_t = t;
  unknown_remains = unknown_patch_in_reach(g, stall_reach, team.log_odds().data());
  return unknown_remains;
}

// The loop: sense -> decide -> move (act) -> record, every step (core/stepper.hpp, shared with
// sim/netsim), then the results.
ExplorationResult TeamRun::run() {
  const Stepper clock(o.dt, o.time_limit, "ExplorationOptions.dt", "ExplorationOptions.time_limit");
  for (auto& ap : agents)
    ap->anchor = ap->body.true_pose().position;
  Stepper::Phases phases;
  phases.sense = [&](const Stepper::Step&) { sense(); };
  phases.decide = [&](const Stepper::Step& s) { decide(s.t); };
  phases.move = [&](const Stepper::Step& s) { act(s.t); };
  phases.record = [&](const Stepper::Step& s) { record(s.t_end); };
  phases.done = [&] { return stop; };
  phases.sense_every = clock.every(o.map_period, "ExplorationOptions.map_period");
  phases.record_every = clock.every(o.record_period, "ExplorationOptions.record_period");
  clock.run(phases);
  finish();
  return std::move(result);
}

void TeamRun::finish() {
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
  result.recording.team_map = team_grid_now();
}

double TeamRun::coverage_now() const {
  const auto l = team.log_odds().data();
  std::size_t known = 0;
  for (std::size_t i = 0; i < l.size(); ++i)
    if (reachable[i] && l[i] != 0.0F) ++known;
  return reachable_count ? static_cast<double>(known) / static_cast<double>(reachable_count) : 0.0;
}

void TeamRun::start_follow(Agent& a, std::vector<Vec2> route) {
  a.route = std::move(route);
  a.next = 0;
  a.mode = a.route.empty() ? AgentMode::kReactive : AgentMode::kFollow;
  a.block.on_new_route();  // not progress: the block clock goes on (block_clock.hpp)
  a.since_progress = 0.0;
  a.unsticking = false;
  a.escaping = false;
}

void TeamRun::start_unstick_route(Agent& a, std::vector<Vec2> route) {
  start_follow(a, std::move(route));
  a.unsticking = true;
  a.on_tree = false;
  a.goal.reset();
  a.goal_leaf = false;
  a.reactive_until = 0.0;
}

std::vector<Vec2> TeamRun::path_on(const BinaryGrid& grid, Vec2 p, Vec2 q) {
  const auto from = nearest_free(grid, p);
  const auto to = nearest_free(grid, q, 4);
  if (!from || !to || flood.flood(grid, *from, planning::Connectivity::k8) == 0) return {};
  std::vector<Vec2> path = descend(grid, flood, *to);
  if (path.empty()) return {};
  path.insert(path.begin(), p);
  return simplify(grid, path);
}

// The grids derived from the team map, each built once per map version (sense() bumps it), by
// whichever mechanism asks first: the tree dispatch and its leg checks, the frontier allocation
// and the unstick routes of one step plan on the same grids.
const OccupancyGrid& TeamRun::team_grid_now() {
  return team_grid_cache.get(team_version, [&] { return team_grid(team); });
}

const BinaryGrid& TeamRun::tree_grid_now() {
  return tree_grid_cache.get(team_version, [&] { return tree_grid(team_grid_now(), plan_radius); });
}

const BinaryGrid& TeamRun::plan_grid_now() {
  return plan_grid_cache.get(team_version,
                             [&] { return traversable_of(team_grid_now(), plan_radius); });
}

const field::DistanceField& TeamRun::plan_clearance_now() {
  return plan_clearance_cache.get(team_version,
                                  [&] { return field::distance_transform(plan_grid_now()); });
}

void TeamRun::log_event(double t, const Agent& a, const char* kind) {
  int id = -1;
  for (std::size_t i = 0; i < agents.size(); ++i)
    if (agents[i].get() == &a) id = static_cast<int>(i);
  result.recording.events.push_back({t, id, kind});
}

double TeamRun::unknown_fraction(const OccupancyGrid& map, Vec2 p) const {
  return information_gain(map, p, o.gain_radius, o.gain_through_free);
}

// Robot-aware planning: for robot i, the discs of the other robots within kRobotAwareRange
// block `grid` (a robot centre cannot come within two body radii of another's), so a robot
// plans around a robot in its way, and a goal reachable only through a crowd costs the detour
// or is out of reach this round. Without it 16 robots on willow crowded into the corridors
// at the last frontiers and jammed there (stalled robots). Returns the cells to restore.
std::vector<std::size_t> TeamRun::mark_others_on(BinaryGrid& grid, std::size_t i) const {
  std::vector<Vec2> others_at;
  for (std::size_t j = 0; j < agents.size(); ++j)
    if (j != i && std::find(leaving.begin(), leaving.end(), j) == leaving.end())
      others_at.push_back(agents[j]->body.true_pose().position);
  return block_robot_discs(grid, agents[i]->body.true_pose().position, others_at, 2.0 * body + 0.05,
                           kRobotAwareRange);
}

// Sense and map (every map_period): the only place the team map changes, so the grids derived
// from it are built afresh after (team_version).
void TeamRun::sense() {
  ++team_version;
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
}

// Decide.
void TeamRun::decide(double t) {
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
    // ExplorationOptions::frontiers_after_leaves (ours): the robots done with their leaves.
    if (dispatched && o.frontiers_after_leaves && t >= next_replan) {
      replan_frontiers(t);
      next_replan = t + o.replan_period;
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
}

void TeamRun::record(double t_end) {
  ExplorationFrame f;
  f.t = t_end;
  for (auto& ap : agents)
    f.poses.push_back(ap->body.true_pose());
  f.coverage = coverage_now();
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
}
}  // namespace voronav::exploration::internal
