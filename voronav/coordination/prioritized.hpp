// Prioritized planning with SIPP (issue #21): robots are planned one after the other in a priority
// order, each with SIPP (sipp.hpp) against the trajectories of the robots planned before it
// (Erdmann & Lozano-Perez 1987; Silver 2005 for the grid version). Prioritized planning is
// incomplete: a robot can fail because a higher-priority robot parks on its only way, passes its
// start before it can leave, or crosses its goal after it would arrive. The fallback here is the
// classic restart rule: the robot that failed moves to the top of the order and every robot is
// planned again, at most max_restarts times (each restart is reported); PBS (Ma et al. 2019,
// pbs.hpp) is the fallback when every order fails. Before that, each robot first tries to keep off
// the starts (with --at-start wait) and goals (with --at-goal stay) of the robots not planned yet,
// as stationary discs, and plans without them only when that fails (the same rule as the fixed-path
// planner of seed 002's scenario, scenario.hpp); `soft_fallbacks` counts those robots.
//
// coordinate_sipp(): the priority order comes from the paper's machinery (seed 002): by default
// its GA over orders (sipp_ga.hpp) seeded with the Bottom-level EDF order of the (M,D) network of
// the robots' fixed paths (section 4.1) and the other order rules; then prioritized SIPP; then the
// same continuous-time checker as the delay schedules.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "voronav/coordination/coordinator.hpp"
#include "voronav/coordination/sipp.hpp"

namespace voronav::coordination {

struct SippRobot {
  int id = 0;
  Cell start, goal;
  double radius = 0.5;  ///< [m]
  double v_max = 1.0;   ///< [m/s]
};

enum class Objective { kMakespan, kSumOfArrivals };

struct PrioritizedOptions {
  SippOptions sipp;
  int max_restarts = -1;        ///< -1 = the number of robots
  bool avoid_unplanned = true;  ///< keep off the starts/goals of robots not planned yet if possible
  /// First tier avoids unplanned starts for all time (true) or only while they get away (false).
  bool full_starts = false;
  /// First tier avoids unplanned goals (with --at-goal stay) for all time.
  bool avoid_goals = true;
  /// ... from the time the goal's robot could arrive at the earliest (its shortest travel time;
  /// before that its goal is free whatever it does), not from time 0.
  bool goals_from_arrival = true;
};

struct PrioritizedResult {
  bool ok = false;
  std::vector<std::vector<TimedWaypoint>> plans;  ///< per robot (by index)
  std::vector<int> order;                         ///< the order that succeeded (or the last tried)
  int restarts = 0;                               ///< failed-robot-first restarts used
  int failed = -1;                                ///< robot index that failed last (when !ok)
  std::vector<int> failures;                      ///< the robot that failed, per attempt
  std::vector<double> arrivals;                   ///< per robot [s]
  double makespan = 0.0, sum_of_arrivals = 0.0;
  std::size_t expansions = 0;
  int soft_fallbacks = 0;  ///< robots that had to cross an unplanned robot's start or goal
};

/// `blocked`: the raw map (1 = blocked); it is inflated per robot radius.
[[nodiscard]] PrioritizedResult plan_prioritized(const BinaryGrid& blocked,
                                                 const std::vector<SippRobot>& robots,
                                                 std::vector<int> order,
                                                 const PrioritizedOptions& options = {});

/// Where the priority order comes from: the EDF order of the (M,D) network (seed 002, section
/// 4.1), the index order, the robots by increasing or decreasing shortest travel time, the
/// start/goal dependency order (dependency_order()), all of them keeping the best by the
/// objective, or PBS (pbs.hpp: a search over priority pairs instead of one order).
/// kGa: the paper's GA over SIPP orders (sipp_ga.hpp), seeded with all the rules before it.
enum class OrderRule {
  kEdf,
  kIndex,
  kShortestFirst,
  kLongestFirst,
  kDependencies,
  kBest,
  kPbs,
  kGa
};
[[nodiscard]] OrderRule parse_order_rule(const std::string& s);
[[nodiscard]] const char* to_string(OrderRule r);

/// GA over SIPP orders (sipp_ga.hpp): the paper's operators, small budgets (an evaluation is a
/// whole prioritized planning run).
struct SippGaOptions {
  std::uint64_t seed = 1;
  int population = 8;  ///< orders kept (seeds first, then random orders)
  int children = 4;    ///< crossovers per generation
  double mutation_rate = 0.2;
  int mutation_min_edges = 4, mutation_max_edges = 7;
  double elitism = 0.2;  ///< the best fraction survives unchanged
  int three_opt = 4;     ///< 3-opt segment moves tried per child (first improvement)
  int max_generations = 50;
  /// CPU-time budget [s]; 0 = auto: auto_seconds_per_robot per robot, clamped to
  /// [auto_min_s, auto_max_s] (K = 100: 1 s, so that the whole command stays under 2 s CPU).
  double time_limit_s = 0.0;
  double auto_seconds_per_robot = 0.01, auto_min_s = 0.2, auto_max_s = 2.0;
};

/// PBS budgets (pbs.hpp; declared here so that the coordinate options carry them).
struct PbsBudget {
  std::size_t max_nodes = 20'000;  ///< high-level nodes
  double time_limit_s = 60.0;      ///< wall clock [s]
};

struct SippCoordinateOptions {
  CollisionMapOptions map;           ///< at-start / at-goal, node spacing for the (M,D) network
  OrderRule order = OrderRule::kGa;  ///< the GA seeded with EDF and the other rules (docs)
  Objective objective = Objective::kMakespan;  ///< used by kBest and PBS (ties: the other one)
  PrioritizedOptions planning;
  /// When prioritized planning fails in every order (after its restarts), run PBS.
  bool pbs_fallback = true;
  PbsBudget pbs;
  SippGaOptions ga;         ///< --order ga
  double tolerance = 1e-6;  ///< checker tolerance [m]
};

/// Lower bounds: each robot's shortest 8-connected travel time on the map inflated by its radius
/// (A*), ignoring the others; makespan bound = their max, sum bound = their sum.
struct IndividualBounds {
  std::vector<double> travel;            ///< [s] per robot
  std::vector<std::vector<Cell>> paths;  ///< the shortest paths (empty when none)
  double makespan = 0.0, sum = 0.0;
};

struct SippCoordinationResult {
  PrioritizedResult plan;
  std::vector<Trajectory> trajectories;  ///< per robot, under the presence conventions
  Verification verification;
  bool valid = false;
  std::string order_source;     ///< the rule that gave the returned order ("pbs" when PBS planned)
  bool pbs_used = false;        ///< the plans come from PBS (--order pbs or the fallback)
  std::size_t pbs_nodes = 0;    ///< PBS high-level nodes expanded
  std::size_t pbs_pairs = 0;    ///< priority pairs of PBS's solution
  std::size_t pbs_replans = 0;  ///< PBS low-level SIPP calls
  int ga_generations = 0;       ///< --order ga: generations run
  std::size_t ga_evaluations = 0;  ///< --order ga: orders planned
  bool ga_improved = false;        ///< --order ga: found an order better than every seed
  /// individual_bounds(), when an order rule needed them (shortest/longest-first, deps, best,
  /// ga); empty otherwise. Computed once per call.
  IndividualBounds bounds;
  double order_ms = 0.0, plan_ms = 0.0, verify_ms = 0.0, time_ms = 0.0;
  std::string message;
};

/// The bounds of IndividualBounds above (A* per robot).
[[nodiscard]] IndividualBounds individual_bounds(const BinaryGrid& blocked,
                                                 const std::vector<Agent>& agents);

/// Robots from `agents` (start = first path node, goal = last, in `blocked`'s cells).
[[nodiscard]] SippCoordinationResult coordinate_sipp(const BinaryGrid& blocked,
                                                     const std::vector<Agent>& agents,
                                                     const SippCoordinateOptions& options = {});

/// Start/goal dependency order (issue #21, for --at-start wait / --at-goal stay): robot i should
/// precede j when i's start lies on j's shortest path (i waits there until it leaves, so it should
/// leave first) and follow j when i's goal lies on j's path (i parks there for ever, so j should
/// pass first). "Lies on" counts the path's cells and the two side cells of each diagonal step
/// (a disc parked there blocks the diagonal move). The dependency graph usually has cycles; the
/// order is greedy: repeatedly the robot with the fewest predecessors not placed yet, ties by
/// longer travel time first. `use_starts` / `use_goals` select the two kinds of arcs.
[[nodiscard]] std::vector<int> dependency_order(const GridGeometry& geometry,
                                                const std::vector<SippRobot>& robots,
                                                const IndividualBounds& bounds, bool use_starts,
                                                bool use_goals);

}  // namespace voronav::coordination
