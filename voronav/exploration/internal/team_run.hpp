// One exploration run (run_exploration; not installed): the ground-truth world, the team of
// robots and its shared map, and the mechanisms that decide where each robot goes, stepped by
// core/stepper.hpp as sense -> decide -> move (act) -> record. One class whose methods are split
// by mechanism, so that a reader finds one paper's rule in one file:
//  * team_run.cpp: the start (team placement, the reachable cells that coverage counts), the four
//    phases of a step, the results, and the grids every mechanism plans on, built once per team
//    map version (internal/map_cache.hpp);
//  * team_run_act.cpp: a robot's command for a step (route following, front guard, right of way,
//    footprint safety), the progress watchdog and the stall watch;
//  * team_run_tree.cpp: seed 004's single tree dispatch (figure 9), tree legs and their checks,
//    and the re-plans beyond the paper (TreeReplan::kFromRobots, TreeLegReplan::kAroundRobots);
//  * team_run_frontiers.cpp: the frontier allocation (Yamauchi's nearest frontier, Burgard's
//    coordinated assignment, and kTreeFrontier's tree leaves among the targets);
//  * team_run_unstick.cpp: unstick routes to open space (ExplorationOptions::unstick and its
//    variants) and margin escapes (ExplorationOptions::margin_escape).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/stepper.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/exploration/explorer.hpp"
#include "voronav/exploration/internal/agent.hpp"
#include "voronav/exploration/internal/front_guard.hpp"
#include "voronav/exploration/internal/map_cache.hpp"
#include "voronav/exploration/internal/team_bans.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/planning/bfs.hpp"
#include "voronav/robot/diff_drive.hpp"
#include "voronav/robot/laser.hpp"

namespace voronav::exploration::internal {

class TeamRun {
 public:
  /// Places the team in `world` (already resampled; o.validate() done) and makes its robots.
  /// Throws voronav::Error when there is no room for the team.
  TeamRun(OccupancyGrid world, const ExplorationOptions& o);

  /// Steps the run to its end (time limit or o.stop_at_coverage) and returns the result.
  ExplorationResult run();

 private:
  static constexpr double kRobotAwareRange = 3.0;  // [m] robots nearer than this block planning
  static constexpr double kCrowdRange = 2.0;       // [m] ExplorationOptions::crowd_limit

  // --- team_run.cpp: the start, the phases of a step, the results ---
  void place_team_start();
  void count_reachable();
  /// stall_reach: the ground-truth cells where a robot centre fits at the stall rule's radius,
  /// 8-connected to a start (ExplorationOptions::stall_reach_radius).
  void map_stall_reach();
  /// Reachable unknown space remains (ExplorationOptions::stall_time): evaluated once per step.
  [[nodiscard]] bool unknown_space_remains(double t);
  [[nodiscard]] double coverage_now() const;
  void sense();
  void decide(double t);
  void record(double t_end);
  void finish();
  void log_event(double t, const Agent& a, const char* kind);
  /// The team map as a ROS-valued grid (team_grid()), built once per team map version.
  [[nodiscard]] const OccupancyGrid& team_grid_now();
  /// Its tree grid (tree_grid(): only known obstacles block), once per team map version.
  [[nodiscard]] const BinaryGrid& tree_grid_now();
  /// A new route for `a` (empty: reactive search); its block clock goes on.
  void start_follow(Agent& a, std::vector<Vec2> route);
  /// An unstick or margin-escape route: out of the allocation and off the tree while it runs.
  void start_unstick_route(Agent& a, std::vector<Vec2> route);
  /// Path on `grid` from p to the free cell nearest q (BFS descent, simplified); empty when none.
  [[nodiscard]] std::vector<Vec2> path_on(const BinaryGrid& grid, Vec2 p, Vec2 q);
  /// The fraction of the cells within o.gain_radius of p that `map` does not know.
  [[nodiscard]] double unknown_fraction(const OccupancyGrid& map, Vec2 p) const;
  /// Blocks the discs of the robots other than i within kRobotAwareRange on `grid`; returns the
  /// cells to restore.
  [[nodiscard]] std::vector<std::size_t> mark_others_on(BinaryGrid& grid, std::size_t i) const;

  // --- team_run_act.cpp ---
  void act(double t);
  /// Route following for robot i: its command for this step.
  [[nodiscard]] robot::BodyVelocity follow(std::size_t i, double t, bool was_guard_stopped);
  /// The progress watchdog and the stall watch of robot i, after its motion.
  void watch(std::size_t i, double t);
  void watchdog_fires(std::size_t i, double t, Vec2 now);

  // --- team_run_tree.cpp ---
  void start_leg(Agent& a, double t);
  void skip_known_leaves(Agent& a, double t);
  /// A leg starting farther than this from the robot is planned afresh (unknown_leaves_first).
  static constexpr double kLegJoin = 1.0;  // [m]
  void unknown_leaves_first(Agent& a, double t);
  /// ExplorationOptions::nearest_leaf_next: a robot without legs takes the pooled leaf nearest
  /// its last one along the tree (false: none left that it can reach).
  bool take_nearest_leaf(Agent& a);
  bool leg_from_here(Agent& a, const BinaryGrid& opt);
  void finish_leg(Agent& a, double t);
  void record_dispatch(double t, std::size_t i, bool first, Vec2 root,
                       const std::vector<Vec2>& leaves);
  bool dispatch_first(double t);
  void replan_from_robot(std::size_t i, double t);
  void check_tree_routes(double t);
  bool replan_leg(std::size_t i, double t);

  // --- team_run_frontiers.cpp ---
  void rebuild_hybrid_tree(double t);
  void replan_frontiers(double t);

  // --- team_run_unstick.cpp ---
  bool unstick(std::size_t i, double t, bool ask_others);
  /// The team map's planning grid (known free cells inflated by plan_radius), built once per
  /// team map version (team_run.cpp, with the other map caches).
  [[nodiscard]] const BinaryGrid& plan_grid_now();
  /// Its clearance (unstick targets), also once per team map version.
  [[nodiscard]] const field::DistanceField& plan_clearance_now();
  /// ExplorationOptions::disperse_neighbours: the robots without a route near robot i drive
  /// unstick routes away; they are listed in `leaving` until i has planned its own.
  void disperse_around(std::size_t i, double t);
  /// ExplorationOptions::clear_way_out: the robots whose discs touch robot i's way out (its
  /// unstick route planned without the robots) drive unstick routes away; they are listed in
  /// `leaving` until i has planned its own.
  void clear_way_out(std::size_t i, double t);
  void end_unstick(Agent& a, double t);
  /// ExplorationOptions::margin_escape: true when robot a at `now` started a route out of the
  /// planning margin.
  bool margin_escape(Agent& a, double t, Vec2 now);

  const ExplorationOptions& o;
  const OccupancyGrid world;
  const GridGeometry g;
  const BinaryGrid blocked;  // the world, closed at its edge
  const double body;         // [m] robot radius
  const double plan_radius;  // [m] body + clearance
  std::mt19937_64 rng;
  std::vector<Vec2> starts;
  Vec2 centre;                  // the team's start centre (the tree's root)
  std::vector<char> reachable;  // ground truth: the free cells reachable from the start
  std::size_t reachable_count = 0;
  std::vector<char> stall_reach;  // ground truth: robot centres at the stall rule's radius
  double unknown_checked_t = -1.0;
  bool unknown_remains = true;
  std::vector<std::unique_ptr<Agent>> agents;
  mapping::OccupancyMap team;
  mapping::LaserModelOptions beam_model;
  robot::LaserOptions map_laser;
  FeatureMap features;
  robot::LaserOptions guard_laser;  // front check while following a path
  GuardRule guard_rule;
  ExplorationResult result;

  BinaryGrid trav;  // the frontier allocation's traversable grid
  planning::BfsFlood flood, flood_opt;
  TeamBans team_bans;               // ExplorationOptions::share_bans
  std::vector<Vec2> leaf_goals;     // kTreeFrontier: the current tree's leaves
  std::vector<robot::Disc> others;  // act(): the other robots' discs
  // The team map changes only in sense(), which bumps team_version; the grids derived from it
  // are built once per version (internal/map_cache.hpp), whichever mechanism asks first.
  std::uint64_t team_version = 0;
  MapCache<OccupancyGrid> team_grid_cache;              // team_grid_now()
  MapCache<BinaryGrid> tree_grid_cache;                 // tree_grid_now()
  MapCache<BinaryGrid> plan_grid_cache;                 // plan_grid_now()
  MapCache<field::DistanceField> plan_clearance_cache;  // plan_clearance_now()
  std::vector<std::size_t> leaving;  // disperse_around(): robots sent away (not planned around)
  bool tree_method, hybrid;
  double tree_start;
  bool dispatched = false;     // the single dispatch of the first tree has happened
  std::vector<int> leaf_pool;  // nearest_leaf_next: the first tree's leaves not yet taken
  double next_tree_time, next_replan = 0.0, next_check = 0.0;
  /// The last frontier allocation found a target (frontier or leaf) some robot could reach
  /// (ExplorationResult::stalled_without_target).
  bool team_has_target = true;
  bool stop = false;  // stop_at_coverage reached
};

}  // namespace voronav::exploration::internal
