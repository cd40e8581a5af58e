// Getting a stuck robot going in an exploration run (ours, not in seed 004; internal/team_run.hpp):
// unstick routes to open space nearby (ExplorationOptions::unstick, frontier_unstick,
// idle_unstick) and the straight drive out of the planning margin (margin_escape).
#include "voronav/exploration/internal/plan_grid.hpp"
#include "voronav/exploration/internal/team_run.hpp"
#include "voronav/exploration/unstick.hpp"
#include "voronav/exploration/voronoi_tree.hpp"
#include "voronav/field/distance_transform.hpp"

namespace voronav::exploration::internal {

// ExplorationOptions::unstick (ours, every method): a robot that the progress watchdog finds on
// one spot drives to open space nearby: on the team map's known-free cells (inflated by the
// body radius + clearance) with the discs of the robots within kRobotAwareRange blocked, the
// reachable cell 1-4 m of path away with the most clearance (unstick_target, unstick.hpp).
// When no such cell is reachable (boxed in by robots), the robots touching it move away the
// same way. Traced on willow with 16 robots (issue 14): a robot in a small room with three
// robots at its door, and one between map speckle and two robots, dithered in avoid turns and
// 1 m corridor escapes for 60 s (stalled).
bool TeamRun::unstick(std::size_t i, double t, bool ask_others) {
  Agent& a = *agents[i];
  const Vec2 pos = a.body.true_pose().position;
  const field::DistanceField& clearance = plan_clearance_now();  // without robots
  BinaryGrid grid = plan_grid_now();
  (void)mark_others_on(grid, i);
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
        unstick(j, t, false);
  return false;
}

// ExplorationOptions::disperse_neighbours (ours, kTree): the robots near a robot the watchdog
// found on one spot that have no route of their own (the reactive search) drive
// to open space first; the stuck robot then plans its own way out without their discs.
void TeamRun::disperse_around(std::size_t i, double t) {
  const Vec2 pos = agents[i]->body.true_pose().position;
  for (std::size_t j = 0; j < agents.size(); ++j) {
    const Agent& b = *agents[j];
    if (j == i || b.unsticking || b.mode == AgentMode::kFollow ||
        distance(b.body.true_pose().position, pos) > o.disperse_range)
      continue;
    if (unstick(j, t, false)) {
      ++result.dispersals;
      leaving.push_back(j);
    }
  }
}

// ExplorationOptions::clear_way_out (ours, kTree): robot i's way out is the unstick route it would
// take if no other robot were there; the robots whose discs (2 body radii + 5 cm from its centre
// line, the robot-aware planning's disc) touch it drive to open space first, and i then plans its
// own unstick route without their discs. Traced on willow (16 robots, tree, seeds 1 and 12): a
// robot in a 1.3 m wide dead-end pocket had robots of the random search at its mouth, and its
// unstick route, planned around them, led deeper in or was not found.
void TeamRun::clear_way_out(std::size_t i, double t) {
  const Vec2 pos = agents[i]->body.true_pose().position;
  const BinaryGrid& grid = plan_grid_now();  // the team map's planning grid, without robots
  const auto from = nearest_free(grid, pos, 3);
  if (!from || flood.flood(grid, *from, planning::Connectivity::k8) == 0) return;
  const std::optional<Cell> best = unstick_target(grid, flood, plan_clearance_now());
  if (!best) return;
  std::vector<Vec2> way = descend(grid, flood, *best);
  way.insert(way.begin(), pos);
  // The robots not on an unstick route already, by index, and their positions.
  std::vector<std::size_t> ids;
  std::vector<Vec2> at;
  for (std::size_t j = 0; j < agents.size(); ++j)
    if (j != i && !agents[j]->unsticking) {
      ids.push_back(j);
      at.push_back(agents[j]->body.true_pose().position);
    }
  for (const std::size_t k : robots_in_way(way, at, 2.0 * body + 0.05))
    if (unstick(ids[k], t, false)) {
      ++result.way_clearances;
      leaving.push_back(ids[k]);
    }
}

// The end of an unstick route: a robot with tree legs left goes on with the next one, planned
// from where it is; else it searches reactively (and the frontier methods allocate again).
void TeamRun::end_unstick(Agent& a, double t) {
  a.unsticking = false;
  a.escaping = false;
  a.route.clear();
  a.mode = AgentMode::kReactive;
  if (a.legs.empty()) return;
  if (!leg_from_here(a, tree_grid_now()))
    a.legs.pop_front();  // the leaf is out of reach from here: give it up
  start_leg(a, t);
}
// ExplorationOptions::margin_escape (ours, every method): a robot that the watchdog finds inside
// the planning margin (nearer than body + clearance to a known wall, or to one its guard senses)
// drives straight to the exit cell margin_exit() picks (unstick.hpp), then takes goals again.
bool TeamRun::margin_escape(Agent& a, double t, Vec2 now) {
  const std::optional<Vec2> exit_at = margin_exit(plan_grid_now(), blocked, now, body, plan_radius);
  if (!exit_at) return false;
  start_unstick_route(a, {now, *exit_at});
  a.block.on_fired();  // its own 3 s: the clock ran on the route that stopped it
  a.escaping = true;
  ++result.margin_escapes;
  log_event(t, a, "margin_escape");
  return true;
}

}  // namespace voronav::exploration::internal
