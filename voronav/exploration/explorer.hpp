// The exploration runner: a deterministic stepping loop over a ground-truth world with a team of
// simulated differential-drive robots (robot module), each mapping with its laser (mapping
// module), exploring with one of four methods:
//  * kTree (seed 004): reactive 4-sector search with wall following until tree_start_time
//    (400 s in the paper), collecting feature points; then ONE dispatch: the Voronoi tree of the
//    feature points (nodes may lie in unknown space; only known obstacles block) and the robots
//    travel from the root along the common trunk and split to its leaves in figure 9's order;
//    a robot whose leaves are done searches reactively again (the paper). The option
//    tree_replan = kFromRobots (ours, not the paper's) gives such a robot a new tree rooted
//    where it is, never back at the start;
//  * kFrontier: nearest frontier per robot (Yamauchi; ROS explore_lite);
//  * kCoordinated: Burgard et al. 2005 utility - cost assignment;
//  * kTreeFrontier (ours): Burgard's coordinated allocation from the start, where the candidate
//    targets are the frontiers plus the leaves of seed 004's Voronoi tree that look into unknown
//    space (the tree is rebuilt every hybrid_tree_period from the feature points collected so
//    far; routes to a leaf may cross unknown space) and every target is ranked by its
//    information gain (the unknown fraction within gain_radius) instead of Burgard's utility 1.
// Everything is seeded: the same options give the same result. The recording (poses per frame,
// feature points, tree, routes) is a plain struct written as JSON for replay viewers.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"
#include "voronav/exploration/feature_points.hpp"
#include "voronav/exploration/frontier.hpp"
#include "voronav/exploration/voronoi_tree.hpp"
#include "voronav/robot/diff_drive.hpp"
#include "voronav/robot/laser.hpp"
#include "voronav/robot/reactive_controller.hpp"

namespace voronav::exploration {

enum class ExplorationMethod { kTree, kFrontier, kCoordinated, kTreeFrontier };
[[nodiscard]] std::string_view to_string(ExplorationMethod m);
/// "tree" / "frontier" / "coordinated" / "tree-frontier"; throws voronav::Error naming the
/// accepted values.
[[nodiscard]] ExplorationMethod parse_exploration_method(std::string_view name);

/// What a kTree robot does after its dispatched leaves: kNone = reactive search (the paper);
/// kFromRobots = a new tree rooted at the vertex nearest the robot, to the nearest leaf that still
/// looks into unknown space and no other robot is heading to (ours; never back to the start).
enum class TreeReplan { kNone, kFromRobots };
[[nodiscard]] std::string_view to_string(TreeReplan r);
/// "none" / "robots"; throws voronav::Error naming the accepted values.
[[nodiscard]] TreeReplan parse_tree_replan(std::string_view name);

/// What a robot blocked for 3 s on a tree leg does: kNone = skips the waypoint it cannot reach
/// and searches reactively for 5 s (before issue 14's willow trace); kAroundRobots = re-plans the
/// rest of the leg to the same leaf with the other robots within 3 m blocked, as the frontier
/// methods plan (ours; the paper's robots are never blocked by each other in its figures).
enum class TreeLegReplan { kNone, kAroundRobots };
[[nodiscard]] std::string_view to_string(TreeLegReplan r);
/// "none" / "robots"; throws voronav::Error naming the accepted values.
[[nodiscard]] TreeLegReplan parse_tree_leg_replan(std::string_view name);

/// The front guard of a robot following a route (issue 14, stop 21; internal/front_guard.hpp):
/// kCone = stop for anything (wall or robot) within body + 0.12 m in a +-0.7 rad fan (before
/// stop 21; it stopped robots on wall corners beside legal routes); kCorridor = stop for a robot
/// in that fan, for a wall only when the body's disc (+ 0.01 m) swept along the next 0.12 m of
/// the route would touch it, and a robot switches to its next waypoint before reaching the one it
/// heads for (0.3 m tolerance) only when the straight line there clears the walls too, so that it
/// drives the route the planner checked instead of cutting its corners (ours).
enum class FrontGuard { kCone, kCorridor };
[[nodiscard]] std::string_view to_string(FrontGuard r);
/// "cone" / "corridor"; throws voronav::Error naming the accepted values.
[[nodiscard]] FrontGuard parse_front_guard(std::string_view name);

/// Controller options of kTree's reactive search and of the frontier methods' reactive windows.
[[nodiscard]] inline robot::ReactiveControllerOptions tree_search_controller() {
  robot::ReactiveControllerOptions c;
  c.random_turn_rate = 0.0;
  c.avoid_escape = robot::AvoidEscape::kCorridor;
  return c;
}
[[nodiscard]] inline robot::ReactiveControllerOptions frontier_window_controller() {
  robot::ReactiveControllerOptions c;
  c.random_turn_rate = 0.4;
  c.avoid_escape = robot::AvoidEscape::kSpin;
  return c;
}

struct ExplorationOptions {
  ExplorationMethod method = ExplorationMethod::kTree;
  int robots = 4;                  ///< team size (1..64)
  double time_limit = 600.0;       ///< simulated time [s]
  double dt = 0.1;                 ///< control / integration step [s]
  std::uint64_t seed = 1;          ///< start spot (when no start is given), random driving, noise
  std::optional<Vec2> start;       ///< team start [m]; else a seeded free spot
  double start_spacing = 0.45;     ///< [m] robots start on a small grid around the start
  double stop_at_coverage = 1.01;  ///< stop early when coverage reaches this (> 1: never)
  double map_period = 0.5;         ///< scans are inserted into the maps this often [s]
  int map_beam_stride = 2;         ///< every k-th beam is used for mapping
  double record_period = 1.0;      ///< a frame is recorded this often [s]
  double tree_start_time = 400.0;  ///< [s] reactive search before the first tree (seed 004)
  TreeReplan tree_replan = TreeReplan::kNone;                    ///< kTree only (see TreeReplan)
  TreeLegReplan tree_leg_replan = TreeLegReplan::kAroundRobots;  ///< kTree (see TreeLegReplan)
  /// [s] kTreeFrontier: its first tree (feature points are collected from the start).
  double hybrid_tree_start_time = 10.0;
  double hybrid_tree_period = 10.0;  ///< [s] kTreeFrontier: the tree is rebuilt this often
  /// A leaf "looks into unknown space" when at least this fraction of the cells within
  /// gain_radius of it is unknown in the team map (kTreeFrontier, kFromRobots, and kTree's
  /// skip_known_leaves and unknown_leaves_first).
  double min_leaf_gain = 0.15;
  double gain_radius = 3.0;  ///< [m] (the laser range)
  /// Ours (issue 14, stop 24): a target's gain counts only the unknown cells within gain_radius
  /// that connect to it through cells not known to be occupied (internal/information_gain.hpp).
  /// Without it the unknown hollows of closed obstacles count: on depot (tree-frontier, seed 14)
  /// leaves beside the shelves kept a gain above min_leaf_gain and the robots chased them for
  /// 300 s at 84 % coverage while the far side of the depot stayed unexplored. On by default
  /// since stop 25 (tree-frontier's t90 under the coordinated frontier's on paper and depot, 16
  /// seeds; docs/reproductions/exploration.md, "Issue 14, stop 25").
  bool gain_through_free = true;
  /// A robot is stalled when it stays within stall_distance [m] of one spot for stall_time [s]
  /// while reachable unknown space remains (issue 14's definition; stop 26). Reachable unknown
  /// space: a cell unknown to the team whose 8 neighbours are unknown too (a patch of 3 x 3
  /// cells, so a ray gap in mapped space does not count) and where a robot centre fits at
  /// stall_reach_radius in the ground truth, connected to the team's starts. Until stop 25 the
  /// rule was coverage < 0.99, which counted robots idle after a map's reachable part was done
  /// (willow: 98.5 %) and would miss stalls on maps explored beyond 99 %.
  double stall_time = 60.0;
  double stall_distance = 0.5;
  /// [m] The robot centre's clearance for the stall rule's reach; 0 = the planning radius
  /// (drive.body_radius + clearance, the space the team's planners can use). The body radius
  /// (drive.body_radius) also counts space only a robot without the planning margin can reach.
  double stall_reach_radius = 0.0;
  /// Ours, kTree: a robot the progress watchdog finds on one spot (stall_time / 3 within
  /// stall_distance) drives 1-4 m to the most open known-free place it can reach around the other
  /// robots; boxed in by robots, those touching it move away instead (`unsticks` in the result).
  /// Willow, 16 robots, 900 s: tree stalled 1 and 1 robots (seeds 1, 2) without, 0 and 0 with.
  bool unstick = true;
  /// Ours (issue 14, stop 26), kTree: when the progress watchdog fires for a robot that has been
  /// on one spot (stall_distance) for half of stall_time, the robots without a route (reactive
  /// search) within disperse_range [m] of it drive an unstick route to open space first, and its
  /// own unstick route may pass where they stood (`dispersals`). The
  /// frontier methods' goalless robots have idle_unstick; their willow runs have no stall left.
  /// Traced on willow (16 robots, tree, seeds 1 and 12): in the reactive phase a robot in a
  /// 1.3 m wide dead-end pocket at (1.8, 9.8) m had robots of the random search wander at its
  /// mouth 0.3-0.5 m away for 60 s; its own unstick took it deeper in (stalled).
  bool disperse_neighbours = false;
  double disperse_range = 1.0;
  /// Ours (issue 14, stop 27), kTree: disperse_neighbours aimed at the robots in the way. When
  /// the progress watchdog fires for a robot, its unstick route is planned as if no other robot
  /// were there (the way out to open space); the robots (not on an unstick route themselves)
  /// whose discs touch that way drive an unstick route to open space first, and the stuck robot's
  /// own unstick route may pass where they stood (`way_clearances` counts the robots moved).
  /// Robots beside it but not in its way keep their search. Both options move the other robots
  /// even with `unstick` off; the stuck robot then plans no route of its own (it keeps the
  /// reactive search), so they only make room.
  bool clear_way_out = false;
  /// Ours (issue 14, stop 28), kTree with `unstick`: a robot the progress watchdog found on one
  /// spot keeps trying to get away until it has left that spot (stall_distance) or the next
  /// watchdog: every unstick_retry_period [s] that it has no route (its unstick or margin-escape
  /// route was ended by the 3 s block clock, or none was found) it plans an unstick route again
  /// around the robots where they are now, and asks the robots touching it to move when boxed in
  /// (`unstick_retries` counts the routes started so). Without it the next attempt comes with the
  /// next watchdog, 20 s later, and the third falls on the stall itself (60 s). Traced on willow
  /// (16 robots, tree, seeds 1, 10, 12): the stuck robot's route out of a dead-end pocket or corner
  /// was blocked by robots of the random search for 3 s, or it was boxed in until the asked robot
  /// had left, and the robot then searched reactively in the pocket until it stalled.
  /// On by default since stop 28 with unstick_right_of_way: together they are the only setting
  /// measured with 0 stalled robots in every multi-seed run (willow 16 robots included), and paper
  /// and depot runs are unchanged (31 of 32 identical); willow's tree coverage is 5.1 points lower
  /// (docs/reproductions/exploration.md, stop 28).
  bool unstick_retry = true;
  double unstick_retry_period = 2.0;  ///< [s]
  /// Ours (issue 14, stop 28), kTree: the right of way (a robot the front guard stops because of
  /// a robot backs off from the lower index, internal/right_of_way.hpp) puts a robot on an unstick
  /// route first: the robot not on one backs off, whatever the indices (`unstick_yields` counts
  /// the back-offs for a higher index). Traced on willow (16 robots, tree, seed 9, with
  /// unstick_retry): robot 15, the highest index, had unstick routes out of a crowd of ten robots
  /// on their tree legs and backed off from each robot it met, for 60 s. On by default since
  /// stop 28 (see unstick_retry).
  bool unstick_right_of_way = true;
  /// The same for the frontier methods; off by default: on willow (16 robots) it stalled more
  /// robots (frontier 3 and 7 against 0 and 0; an unstick route stopped by the front guard kept
  /// the robot out of the allocation until the watchdog fired again). After the block clock fix
  /// (issue 14, fifth pass) one partial tree-frontier run with it on still stalled a robot.
  bool frontier_unstick = false;
  /// Ours (issue 14, lab_intel 8 robots): with frontier_unstick off, a frontier-method robot
  /// WITHOUT a goal that the progress watchdog finds on one spot still drives the unstick route
  /// (a goalless robot has no route to lose; lab_intel coordinated seed 1: a robot whose goals
  /// were all banned turned on the spot in a corner for 52 s and stalled).
  bool idle_unstick = true;
  /// Ours (issue 14, lab_intel 8 robots): the guard's right of way also makes a robot back off
  /// from a robot in front of it that is held up itself (its block clock running, not backing
  /// off), whatever their indices; before, only the higher index backed off, so a robot
  /// tailgating a lower-index robot that a door corner stopped boxed it in (frontier seed 4:
  /// stalled).
  bool yield_to_held = true;
  /// Ours (issue 14, depot 2 robots coordinated seed 3): frontier methods: a robot that the
  /// allocation leaves without a goal forgets the goals it gave up only because it was blocked
  /// (3 s rule) or made no progress (30 s, watchdog), at most once per stall_time, and may take
  /// them again; goals it reached whose frontier stayed (unobservable) stay banned. Without it
  /// both robots had banned every frontier left by 360 s and wandered reactively to 900 s at
  /// 69.1 % coverage.
  bool retry_banned = true;
  /// Ours (issue 14, stop 22, willow 16 robots frontier seed 1), frontier methods: a frontier goal
  /// that a robot reached is banned for the whole team, not only for that robot, when at an
  /// allocation at least one scan later its frontier is still there and no unknown cell next to it
  /// is in sight of its target cell (a line through known free cells within the laser's range):
  /// the robots share one map and the same laser, and robots do not occlude the mapping scans, so
  /// no robot can observe it from there. The ban ends when the team map within 1 m of the goal
  /// gains known cells (new information). Without it every robot had to reach each such frontier
  /// itself, and the nearest-frontier rule sent up to 12 robots into a 1 m wide dead-end pocket
  /// (5 stalled, boxed in; with it 0, at most 2 robots there). Off: over willow seeds 1-8 it
  /// stalled as many robots (6) in more runs (5 of 8 against 2), so it is not the cure
  /// (bench/results/exploration.md, stop 22).
  bool share_bans = false;
  /// Ours (issue 14, stop 22), kFrontier only: a frontier that crowd_limit other robots are at
  /// already (within 2 m of its target, or heading to it) is left out of a robot's nearest-frontier
  /// choice unless the robot is within 2 m of it itself; 0 = off (Yamauchi's rule: every robot
  /// takes its nearest frontier). Meant against the herds of the nearest-frontier rule; willow,
  /// 16 robots, seeds 1-8, limit 3: 3 stalled robots in 3 runs (off: 6 in 2), mean t90 607 s
  /// (off: 557 s), so off.
  int crowd_limit = 0;
  /// Ours (issue 14, stop 22), frontier methods: a robot that the allocation leaves without a goal
  /// stops following the route to the goal it had (that frontier is gone or banned) and searches
  /// reactively, where idle_unstick looks after it. Before, it drove the old route on; traced on
  /// willow (16 robots, frontier, seed 8): such a robot stood 0.47 m in front of a robot with a
  /// goal, which stalled. Willow seeds 1-16: 3 stalled robots in 2 runs (off: 7 in 3), but mean
  /// coverage 97.69 % (off: 98.33 %) with two runs under 95 %, and coordinated seed 2 stalled a
  /// robot (off: 0), so off (stop 22).
  bool drop_goalless_routes = false;
  /// Ours (issue 14, stop 23), every method: a robot that the progress watchdog finds on one spot
  /// while its centre is inside the planning margin (nearer than the body radius + clearance to a
  /// known obstacle of the team map, or to a wall its front guard senses) first drives straight to
  /// the nearest cell outside it that its disc can reach without touching a wall (margin_exit,
  /// unstick.hpp), as an unstick route; then it takes goals (or its tree legs) again, on routes the
  /// planner checked. Routes are planned from the free cell nearest a robot and joined to its
  /// position, so from inside the margin the first leg can clip a wall corner: traced on willow (16
  /// robots, coordinated, seed 5), a robot 0.14 m from a corner was given new routes from that spot
  /// for 600 s, every one stopped by the front guard (stalled). `margin_escapes` counts them.
  /// On by default since stop 25: with gain_through_free it leaves no stalled robot in 16 willow
  /// runs of tree-frontier (16 robots) and lowers the stalls of the other methods (stop 23);
  /// docs/reproductions/exploration.md, "Issue 14, stop 25".
  bool margin_escape = true;
  /// Ours (issue 14, stop 24), kTree only: a robot about to drive a tree leg (at the dispatch and
  /// after each leaf) skips the leaves whose surroundings the team map already knows (less than
  /// min_leaf_gain of the cells within gain_radius unknown), and a leg whose leaf becomes known
  /// while it is driven ends there; the robot goes on to its next leaf on a route planned from
  /// where it stands (tree grid: only known obstacles block). The dispatch itself (tree, leaves,
  /// figure 9's order) is the paper's. Traced on depot (seeds 3, 10, 13, stop 22): the paper's
  /// order deals the deep leaves that face unexplored space last, after every shallow leaf in
  /// explored space, so coverage stays flat for minutes. `leaves_skipped` counts the skips.
  bool skip_known_leaves = false;
  /// Ours (issue 14, stop 27), kTree only: a robot about to drive a tree leg (at the dispatch and
  /// after each leaf) drives first to the next of its dealt leaves that still faces unknown space
  /// (at least min_leaf_gain of the cells within gain_radius unknown), on a route planned from
  /// where it stands (tree grid: only known obstacles block); the leaves it passes over stay in
  /// its list, in figure 9's order, and are visited after. Unlike skip_known_leaves no dealt leaf
  /// is dropped for being known; a leaf out of reach from where the robot stands is given up (not
  /// counted). `leaves_promoted` counts the leaves moved ahead.
  bool unknown_leaves_first = false;
  /// Ours (issue 14, stop 27), kTree only; another reading of figure 9's "then the next nearest"
  /// (다음으로 가까운 거리의). At the dispatch every robot takes the first leaf of its figure 9
  /// list (the N leaves nearest the root, one each, as the paper); the other leaves form one pool,
  /// and a robot done with a leaf takes from it the leaf nearest its last one along the tree (ties:
  /// the nearer to the root), route along the tree. Off: robot i drives its dealt list i, i + N,
  /// ... in order (our reading). `leaves_pooled` counts the leaves taken from the pool. With
  /// skip_known_leaves or unknown_leaves_first also on, those act on the dealt first leaf only: a
  /// leaf taken from the pool is driven to as it is (they run before the pool is asked).
  bool nearest_leaf_next = false;
  /// Ours (issue 14, stop 27), kTree only, beyond the paper: a robot done with its dealt leaves
  /// takes goals from Burgard's coordinated frontier allocation (kCoordinated's, every
  /// replan_period, among the robots done with their leaves) instead of the paper's reactive
  /// search; with no frontier left for it, it searches reactively. `frontier_goals` counts them.
  /// Traced on depot (4 robots, seeds 3, 10, 13): the unknown left at 900 s lies in corners of
  /// the hall that no leaf faces, and the reactive search reaches them only after 900 s.
  /// With tree_replan kFromRobots as well, both act on the robots done with their leaves: a new
  /// tree's legs, when one is built, replace the frontier goal.
  bool frontiers_after_leaves = false;
  /// The front guard's rule (see FrontGuard); every method.
  FrontGuard guard = FrontGuard::kCorridor;
  double replan_period = 2.0;   ///< [s] frontier targets are re-assigned this often
  double goal_tolerance = 0.3;  ///< [m] a waypoint or goal counts as reached
  double clearance = 0.1;       ///< [m] added to the body radius when planning paths
  /// [m] worlds with finer cells are resampled to cells of about this size (a coarse cell is
  /// occupied when any of its cells is); keeps 16-robot runs on 50 m maps fast.
  double min_cell_size = 0.1;
  robot::DiffDriveOptions drive;
  robot::LaserOptions laser;
  /// kTree's reactive search (seed 004, section 3.2): straight ahead while the front is clear
  /// (Table 1: CLEAR -> F; random_turn_rate 0) and the corridor escape of rule 2 (issue 14).
  robot::ReactiveControllerOptions controller = tree_search_controller();
  /// The reactive windows of the frontier methods (kFrontier, kCoordinated, kTreeFrontier): the
  /// controller as before issue 14's tree work (random turns of up to 0.4 rad/s, rule 2 spins),
  /// which their measured stall fixes rely on (willow, 16 robots, seed 1, frontier: 59.6 %,
  /// 0 stalled; with the corridor escape 65.9 %, 1 stalled).
  robot::ReactiveControllerOptions frontier_controller = frontier_window_controller();
  FeaturePointOptions features;
  VoronoiTreeOptions tree;
  FrontierOptions frontier;
  /// Called after each recorded frame with the simulated time [s] and the coverage (0..1), e.g.
  /// for a progress line; empty: nothing.
  std::function<void(double t_s, double coverage)> on_frame;

  void validate() const;
};

struct ExplorationFrame {
  double t = 0.0;            ///< [s]
  std::vector<Pose2> poses;  ///< ground truth, one per robot
  double coverage = 0.0;     ///< 0..1
};

/// One tree dispatch of one robot: when, from where, the root it was sent through and its leaves.
struct TreeDispatch {
  double t = 0.0;  ///< [s]
  int robot = 0;
  bool first = true;         ///< the single dispatch of the first tree (else a re-plan)
  Vec2 from;                 ///< the robot's position [m]
  Vec2 root;                 ///< the root of the tree it was sent along [m]
  std::vector<Vec2> leaves;  ///< its goals, in order [m]
  std::vector<Vec2> route;   ///< waypoints to its first leaf [m]
};

/// A moment worth marking on the replay's event track, logged where it happened.
struct ExplorationEvent {
  double t = 0.0;  ///< [s]
  int robot = -1;
  std::string kind;  ///< "leaf" (a tree leaf reached), "watchdog" (goal given up), "stalled",
                     ///< "idle" (ExplorationResult::idle_when_explored),
                     ///< "unstick", "margin_escape" (ExplorationOptions::margin_escape),
                     ///< "leaf_skipped" (ExplorationOptions::skip_known_leaves)
};

struct ExplorationRecording {
  GridGeometry geometry;
  std::vector<Vec2> starts;
  std::vector<ExplorationFrame> frames;
  std::vector<FeaturePoint> feature_points;
  VoronoiTree tree;                        ///< the first tree (kTree only)
  std::vector<std::vector<int>> dispatch;  ///< leaves per robot of the first tree
  std::vector<std::vector<Vec2>> routes;   ///< waypoints per robot of the first tree
  double tree_time = -1.0;                 ///< [s] when the first tree was built (-1: never)
  std::vector<TreeDispatch> dispatches;    ///< every tree dispatch, in time order
  std::vector<ExplorationEvent> events;    ///< leaves reached, goals given up, stalls (time order)
  OccupancyGrid team_map;                  ///< final merged map (ROS values)
  /// [s] per cell (row-major, the recording's geometry): when the team map first knew the cell;
  /// negative = never.
  std::vector<float> reveal_time;
};

struct ExplorationResult {
  ExplorationMethod method = ExplorationMethod::kTree;
  int robots = 0;
  double coverage = 0.0;        ///< final fraction of reachable free cells known (0..1)
  std::optional<double> t90_s;  ///< first time coverage >= 0.90 [s]
  std::optional<double> t99_s;  ///< first time coverage >= 0.99 [s]
  double sim_time_s = 0.0;      ///< simulated time [s]
  double distance_m = 0.0;      ///< total distance driven by the team [m]
  int collisions = 0;           ///< refused steps (body would overlap a wall or a robot)
  double overlap = 0.0;         ///< sum of per-robot known cells / team known cells - 1
  int feature_points = 0;
  int leaves = 0;          ///< leaves of the first tree (kTree)
  int trees = 0;           ///< trees built (first dispatch and re-plans)
  int dispatches = 0;      ///< robot dispatches along a tree (first + re-plans)
  int leaves_reached = 0;  ///< dispatched (kTree) or allocated (kTreeFrontier) leaves reached
  /// Frontier goals assigned (frontier methods, kTreeFrontier, kTree's frontiers_after_leaves).
  int frontier_goals = 0;
  int leaf_goals = 0;  ///< tree leaves assigned as goals by the allocation (kTreeFrontier)
  /// Robots that stayed within stall_distance of one spot for stall_time while reachable unknown
  /// space remained (ExplorationOptions::stall_time; each robot counted once).
  int stalled_robots = 0;
  /// Robots that stayed on one spot for stall_time when no reachable unknown space remained
  /// (their work was done: not stalls; each robot counted once; replay event "idle").
  int idle_when_explored = 0;
  /// Of stalled_robots, those declared while the last frontier allocation found no target that
  /// any robot could reach on its planning grid of the team map (frontier methods and
  /// kTreeFrontier; never kTree), although the ground truth had reachable unknown space (stop
  /// 25: a frontier herd on lab_intel). The rest stalled while the team had a target.
  int stalled_without_target = 0;
  /// Goals given up by the progress watchdog (no progress for stall_time / 3).
  int watchdog_events = 0;
  int leg_replans = 0;  ///< tree legs re-planned around robots (TreeLegReplan::kAroundRobots)
  int escapes = 0;      ///< corridor escapes of the reactive controllers (AvoidEscape::kCorridor)
  int unsticks = 0;     ///< unstick routes started (ExplorationOptions::unstick)
  int way_clearances = 0;  ///< robots moved out of a stuck robot's way (clear_way_out)
  int dispersals = 0;      ///< of them, robots sent away (ExplorationOptions::disperse_neighbours)
  int idle_unsticks = 0;   ///< of those, by ExplorationOptions::idle_unstick
  int yields = 0;          ///< back-offs from a held-up robot of higher index (yield_to_held)
  int ban_resets = 0;      ///< goalless robots that forgot their soft bans (retry_banned)
  /// Unstick routes started by a retry (unstick_retry; also counted in unsticks).
  int unstick_retries = 0;
  /// Back-offs for a robot of higher index on an unstick route (unstick_right_of_way).
  int unstick_yields = 0;
  /// Reached goals banned for the whole team as out of sight of their target (share_bans).
  int shared_bans = 0;
  /// (robot, frontier) pairs left out of the nearest-frontier choice as crowded (crowd_limit).
  int crowd_skips = 0;
  int route_drops = 0;      ///< routes dropped by goalless robots (drop_goalless_routes)
  int margin_escapes = 0;   ///< watchdog escapes out of the planning margin (margin_escape)
  int leaves_skipped = 0;   ///< tree leaves skipped as already known (skip_known_leaves)
  int leaves_pooled = 0;    ///< tree leaves taken from the shared pool (nearest_leaf_next)
  int leaves_promoted = 0;  ///< tree leaves driven to ahead of their turn (unknown_leaves_first)
  /// Front guard stops (a robot that drove forward the step before and is stopped now): by a wall
  /// and by a robot (the right of way applies).
  int guard_wall_stops = 0;
  int guard_robot_stops = 0;
  std::size_t reachable_free_cells = 0;
  ExplorationRecording recording;
};

/// Runs one exploration. `world`: ground truth (>= 50 occupied; unknown counts as occupied),
/// resampled to options.min_cell_size; the recording's geometry is the resampled one.
/// Throws voronav::Error for invalid options, an empty world, or a start that is not free.
[[nodiscard]] ExplorationResult run_exploration(const OccupancyGrid& world,
                                                const ExplorationOptions& options = {});

/// The world as the runner sees it: cells finer than min_cell_size [m] are merged k x k
/// (k = floor(min_cell_size / resolution)); a coarse cell is occupied when any of its cells is,
/// else unknown when any is. Returns the input when k < 2.
[[nodiscard]] OccupancyGrid resample_world(const OccupancyGrid& world, double min_cell_size);

/// JSON of the result: coverage, t90_s, t99_s (null if not reached), distance_m, collisions,
/// feature_points, leaves, ... With `include_recording`, the recording too (frames, features,
/// tree nodes, routes; not the maps).
[[nodiscard]] std::string to_json(const ExplorationResult& result, bool include_recording = false);

/// The options a run used, as one JSON object (the CLI's and Python's `input`): every top-level
/// field by its name (on/off switches as "on"/"off"; `time_limit` as "time_s", `tree_start_time` as
/// "tree_start_s", the tree controller's two switches as "random_turn_rate"/"avoid_escape", the
/// frontier controller's with a "frontier_" prefix; `start` only when set). The nested robot,
/// laser, feature, tree and frontier options are not echoed. One function for both front ends, so
/// a test that compares them checks that each front end sets the member it names.
[[nodiscard]] std::string to_json(const ExplorationOptions& options);

/// The paper's 20 x 20 m world (seed 004, figure 7), reconstructed: outer walls, rectangular
/// blocks, round obstacles and partial walls (the figure has no coordinates; see
/// docs/reproductions/exploration.md). resolution [m/cell]. Robots start near (2, 2).
[[nodiscard]] OccupancyGrid paper_world(double resolution = 0.05);
inline constexpr Vec2 kPaperWorldStart{2.0, 2.0};

}  // namespace voronav::exploration
