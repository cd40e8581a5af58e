// The frontier allocation of an exploration run (internal/team_run.hpp): Yamauchi's nearest
// frontier (kFrontier), Burgard et al.'s coordinated utility - cost assignment (kCoordinated),
// and kTreeFrontier (ours), where the leaves of seed 004's Voronoi tree that look into unknown
// space join the frontiers as targets ranked by information gain. Every robot plans around the
// robots near it.
#include <optional>

#include "voronav/exploration/frontier.hpp"
#include "voronav/exploration/internal/plan_grid.hpp"
#include "voronav/exploration/internal/team_run.hpp"
#include "voronav/exploration/point_voronoi.hpp"
#include "voronav/exploration/voronoi_tree.hpp"

namespace voronav::exploration::internal {

// kTreeFrontier (ours): the current tree's leaves, rebuilt every hybrid_tree_period from all
// feature points on the team map (only known obstacles block), rooted at the team's start.
void TeamRun::rebuild_hybrid_tree(double t) {
  const BinaryGrid& opt = tree_grid_now();
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
}

// Frontier allocation (kFrontier, kCoordinated). kTreeFrontier adds the tree's leaves that
// look into unknown space as candidate targets (costs on the grid where only known obstacles
// block) and ranks every target by its information gain (the unknown fraction around it).
void TeamRun::replan_frontiers(double t) {
  std::vector<std::size_t> active;
  // kTree (ExplorationOptions::frontiers_after_leaves): only the robots done with their leaves.
  const bool tree_done_only = o.method == ExplorationMethod::kTree;
  for (std::size_t i = 0; i < agents.size(); ++i)
    if (!agents[i]->unsticking &&
        (!tree_done_only || (agents[i]->tree_done && !agents[i]->on_tree)))
      active.push_back(i);
  const OccupancyGrid& tg = team_grid_now();
  trav = plan_grid_now();  // a copy: the robots' discs are marked on it and restored
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
    opt = tree_grid_now();  // a copy, as trav
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
  bool any_cost = false;  // some robot can reach some target (team_has_target)
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
          if (s >= 0 && !banned(fr[f].centroid)) {
            costs[r][f] = s * g.resolution;
            any_cost = true;
          }
        }
      restore_free_cells(opt, marked_opt);
    }
    const std::vector<std::size_t> marked = mark_others_on(trav, active[r]);
    const auto from = nearest_free(trav, pos);
    if (!from || flood.flood(trav, *from, planning::Connectivity::k8) == 0) {
      restore_free_cells(trav, marked);
      continue;
    }
    for (std::size_t f = 0; f < n_frontiers; ++f) {
      const Vec2 tp = g.cell_center(fr[f].target);
      const std::int32_t s = flood.steps(trav, fr[f].target);
      if (!banned(tp) && s >= 0 && !crowded(active[r], f)) {
        costs[r][f] = s * g.resolution;
        any_cost = true;
      }
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
    restore_free_cells(trav, marked);
  }
  // ExplorationResult::stalled_without_target (an allocation without robots in it says nothing).
  if (!active.empty()) team_has_target = any_cost;
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
      const std::vector<std::size_t> marked = mark_others_on(trav, active[r]);
      const auto from = nearest_free(trav, a.body.true_pose().position);
      if (from && flood.flood(trav, *from, planning::Connectivity::k8) > 0)
        path = descend(trav, flood, fr[k].target);
      restore_free_cells(trav, marked);
    }
    if (path.empty()) continue;
    path.insert(path.begin(), a.body.true_pose().position);
    a.goal = tp;
    ++result.frontier_goals;
    if (tree_done_only) log_event(t, a, "frontier_goal");  // frontiers_after_leaves (replay)
    start_follow(a, simplify(trav, path));
  }
}
}  // namespace voronav::exploration::internal
