// Seed 004's tree in an exploration run (Lee & Joo 2018, section 3 and figure 9;
// internal/team_run.hpp): the single dispatch of the robots along the Voronoi tree of the
// feature points, the legs to their leaves and the checks of those legs against the map, and the
// re-plans that are ours, each behind its option (TreeReplan::kFromRobots,
// TreeLegReplan::kAroundRobots).
#include <optional>

#include "voronav/exploration/internal/plan_grid.hpp"
#include "voronav/exploration/internal/team_run.hpp"
#include "voronav/exploration/point_voronoi.hpp"
#include "voronav/exploration/voronoi_tree.hpp"

namespace voronav::exploration::internal {

// The next leg of a robot's tree route, or (none left) the end of its dispatch.
void TeamRun::start_leg(Agent& a, double t) {
  if (o.skip_known_leaves) skip_known_leaves(a, t);
  if (o.unknown_leaves_first) unknown_leaves_first(a, t);
  if (o.nearest_leaf_next && a.legs.empty()) take_nearest_leaf(a);
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
}

// ExplorationOptions::skip_known_leaves (ours): the legs whose leaves the team map already knows
// are dropped; the next one is planned from where the robot stands (its tree route started at the
// leaf before, which the robot did not visit). A leaf out of reach from here is given up.
void TeamRun::skip_known_leaves(Agent& a, double t) {
  if (a.legs.empty()) return;
  const OccupancyGrid& tg = team_grid_now();
  bool skipped = false;
  while (!a.legs.empty() && unknown_fraction(tg, a.legs.front().back()) < o.min_leaf_gain) {
    a.legs.pop_front();
    ++result.leaves_skipped;
    log_event(t, a, "leaf_skipped");
    skipped = true;
  }
  if (!skipped) return;
  const BinaryGrid& opt = tree_grid_now();
  while (!a.legs.empty() && !leg_from_here(a, opt))
    a.legs.pop_front();
}

// ExplorationOptions::unknown_leaves_first (ours): the first of the robot's legs whose leaf still
// faces unknown space moves ahead of the others (their order stays figure 9's). A leg that does
// not start where the robot stands (moved ahead, or after a leaf given up) is planned afresh from
// here; a leaf out of reach from here is given up.
void TeamRun::unknown_leaves_first(Agent& a, double t) {
  if (a.legs.empty()) return;
  const OccupancyGrid& tg = team_grid_now();
  const Vec2 pos = a.body.true_pose().position;
  while (!a.legs.empty()) {
    std::size_t k = 0;
    while (k < a.legs.size() && unknown_fraction(tg, a.legs[k].back()) < o.min_leaf_gain)
      ++k;
    if (k > 0 && k < a.legs.size()) {
      std::vector<Vec2> leg = std::move(a.legs[k]);
      a.legs.erase(a.legs.begin() + static_cast<std::ptrdiff_t>(k));
      a.legs.push_front(std::move(leg));
      ++result.leaves_promoted;
      log_event(t, a, "leaf_promoted");
    }
    if (distance(pos, a.legs.front().front()) <= kLegJoin) return;
    if (leg_from_here(a, tree_grid_now())) return;
    a.legs.pop_front();  // out of reach from here: given up
  }
}

// ExplorationOptions::nearest_leaf_next (ours): the pooled leaf nearest the robot's last leaf along
// the tree (the route up to the lowest common ancestor and down), its route along the tree; from
// where the robot stands when that is not at its last leaf (a leaf given up). A leaf out of reach
// from here goes back to the pool for the others.
bool TeamRun::take_nearest_leaf(Agent& a) {
  const VoronoiTree& tree = result.recording.tree;
  if (leaf_pool.empty() || tree.empty() || a.tree_node < 0) return false;
  const auto along = [&](int from, int to) {
    const std::vector<int> r = tree.node_route(from, to);
    double d = 0.0;
    for (std::size_t k = 1; k < r.size(); ++k)
      d += std::abs(tree.nodes[static_cast<std::size_t>(r[k])].depth -
                    tree.nodes[static_cast<std::size_t>(r[k - 1])].depth);
    return d;
  };
  // (distance along the tree, pool index); the pool is in order of distance from the root, so
  // the stable sort breaks ties toward the root.
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t k = 0; k < leaf_pool.size(); ++k)
    order.emplace_back(along(a.tree_node, leaf_pool[k]), k);
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  const Vec2 pos = a.body.true_pose().position;
  for (const auto& [d, k] : order) {
    const int leaf = leaf_pool[k];
    a.legs.push_back(tree.waypoints(a.tree_node, leaf));
    if (distance(pos, a.legs.front().front()) > kLegJoin && !leg_from_here(a, tree_grid_now())) {
      a.legs.clear();
      continue;
    }
    a.tree_node = leaf;
    leaf_pool.erase(leaf_pool.begin() + static_cast<std::ptrdiff_t>(k));
    ++result.leaves_pooled;
    return true;
  }
  return false;
}

// The robot's next leg planned afresh on `opt` from where it stands to the same leaf (within
// 0.5 m of it); false, leg unchanged, when the leaf is out of reach from here.
bool TeamRun::leg_from_here(Agent& a, const BinaryGrid& opt) {
  const Vec2 leaf = a.legs.front().back();
  std::vector<Vec2> path = path_on(opt, a.body.true_pose().position, leaf);
  if (path.size() < 2 || distance(path.back(), leaf) > 0.5) return false;
  a.legs.front() = std::move(path);
  return true;
}

void TeamRun::finish_leg(Agent& a, double t) {
  if (!a.legs.empty()) {
    if (distance(a.body.true_pose().position, a.legs.front().back()) < 2.0 * o.goal_tolerance) {
      ++result.leaves_reached;
      log_event(t, a, "leaf");
    }
    a.legs.pop_front();
  }
  start_leg(a, t);
}

void TeamRun::record_dispatch(double t, std::size_t i, bool first, Vec2 root,
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
}

// The single dispatch (figure 9): the tree of all feature points on the team map where only
// known obstacles block, rooted at the vertex nearest the start; leaves by distance, robot i
// takes leaves i, i + N, ...; the route runs from the root down the common trunk.
bool TeamRun::dispatch_first(double t) {
  const BinaryGrid& opt = tree_grid_now();
  const PointVoronoi vor = voronoi_of_points(features.positions());
  VoronoiTree built = build_voronoi_tree(vor, opt, centre, o.tree);
  ++result.trees;
  const std::vector<int> leaves = built.leaves_by_distance();
  if (built.empty() || leaves.empty()) return false;
  std::vector<std::vector<int>> dispatch = dispatch_leaves(leaves, o.robots);
  if (o.nearest_leaf_next) {
    // Figure 9's first round (the N leaves nearest the root, one per robot); the rest pooled in
    // order of distance from the root.
    leaf_pool.clear();
    for (std::size_t k = std::min(leaves.size(), dispatch.size()); k < leaves.size(); ++k)
      leaf_pool.push_back(leaves[k]);
    for (auto& list : dispatch)
      if (list.size() > 1) list.erase(list.begin() + 1, list.end());
  }
  // Recorded before the legs start: nearest_leaf_next takes leaves along it from start_leg on.
  result.recording.tree = std::move(built);
  const VoronoiTree& tree = result.recording.tree;
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
    a.tree_node = dispatch[i].empty() ? -1 : dispatch[i].front();
    if (a.legs.empty()) {
      a.tree_done = true;
      continue;
    }
    start_leg(a, t);
    record_dispatch(t, i, true, root, goals);
  }
  result.leaves = static_cast<int>(leaves.size());
  result.recording.dispatch = std::move(dispatch);
  result.recording.routes = std::move(routes);
  result.recording.tree_time = t;
  return true;
}

// TreeReplan::kFromRobots: a robot done with its leaves gets a tree rooted where it is and goes
// to the nearest leaf that still looks into unknown space and no other robot is heading to.
void TeamRun::replan_from_robot(std::size_t i, double t) {
  Agent& a = *agents[i];
  a.retry_at = t + 10.0;
  const Vec2 pos = a.body.true_pose().position;
  const OccupancyGrid& tg = team_grid_now();
  const BinaryGrid& opt = tree_grid_now();
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
}

// Tree routes run through unknown space: when the map shows a known obstacle on the rest of a
// leg, the leg is re-planned from where the robot is to its leaf (BFS on the grid where only
// known obstacles block); a leaf that became unreachable is given up.
void TeamRun::check_tree_routes(double t) {
  bool any = false;
  for (auto& ap : agents)
    any = any || (ap->on_tree && ap->mode == AgentMode::kFollow);
  if (!any) return;
  const OccupancyGrid& tg = team_grid_now();
  const BinaryGrid& opt = tree_grid_now();
  for (auto& ap : agents) {
    Agent& a = *ap;
    if (!a.on_tree || a.mode != AgentMode::kFollow || t < a.reactive_until) continue;
    const Vec2 pos = a.body.true_pose().position;
    // ExplorationOptions::skip_known_leaves: a leaf the team came to know (by another robot: one
    // within gain_radius of it is about to reach it) ends the leg here.
    if (o.skip_known_leaves && !a.legs.empty() && distance(pos, a.route.back()) > o.gain_radius &&
        unknown_fraction(tg, a.route.back()) < o.min_leaf_gain) {
      start_leg(a, t);
      continue;
    }
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
}

// TreeLegReplan::kAroundRobots: a robot blocked on a tree leg re-plans the rest of the leg
// from where it is to the same leaf on the current tree grid, with the discs of the robots
// within kRobotAwareRange blocked (the frontier methods' robot-aware planning). True when a
// new leg was started. Without it the single dispatch sends all robots along the common trunk
// and on willow with 16 robots they jammed in cluttered passages for minutes (issue 14).
bool TeamRun::replan_leg(std::size_t i, double t) {
  Agent& a = *agents[i];
  if (!a.on_tree || a.route.empty() || a.legs.empty()) return false;
  const Vec2 pos = a.body.true_pose().position, leaf = a.route.back();
  // A re-plan that did not get the robot moving is not repeated on the same spot for 15 s.
  if (t - a.leg_replan_t < 15.0 && distance(pos, a.leg_replan_at) < o.stall_distance) return false;
  a.leg_replan_t = t;
  a.leg_replan_at = pos;
  BinaryGrid opt = tree_grid_now();  // a copy: the robots' discs are marked on it
  const std::vector<std::size_t> marked = mark_others_on(opt, i);
  std::vector<Vec2> path = path_on(opt, pos, leaf);
  restore_free_cells(opt, marked);
  if (path.size() < 2 || distance(path.back(), leaf) > 0.5) return false;
  ++result.leg_replans;
  a.legs.front() = path;
  start_follow(a, std::move(path));
  a.on_tree = true;
  return true;
}
}  // namespace voronav::exploration::internal
