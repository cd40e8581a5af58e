// Priority-based search (PBS; Ma, Harabor, Stuckey, Li & Koenig, "Searching with consistent
// prioritization for multi-agent path finding", AAAI 2019) with SIPP (sipp.hpp) as the low level,
// in continuous time with disc robots (issue #21).
//
// PBS searches over partial priority orders instead of one total order. A node holds a set of
// priority pairs (i before j, a DAG), one timed plan per robot in which every robot avoids all the
// robots transitively above it, and the robot pairs whose plans still collide. Expansion takes the
// earliest collision (i, j) and makes two children, one with i above j and one with j above i (a
// child is skipped when its pair would close a cycle); each child replans, in a topological order,
// the robot put below and every robot below it whose plan collides with one above it (Ma et al.'s
// UpdatePlan). Children whose replanning fails are pruned. The high level is depth first; the
// child with the smaller cost is expanded first. A node without collisions is the solution.
//
// Collisions are decided by the same exact pairwise minimum as the checker (verify.hpp,
// trajectory.hpp first_below); robots are present as the --at-start / --at-goal convention says.
// PBS is complete for neither total orders nor MAPF in general, but it does not cycle like the
// failed-robot-first restarts of plan_prioritized(); it is bounded by node and time budgets.
#pragma once

#include <cstddef>
#include <vector>

#include "voronav/coordination/prioritized.hpp"

namespace voronav::coordination {

struct PbsOptions {
  SippOptions sipp;  ///< at_start / at_goal, per-robot expansion limit
  Objective objective = Objective::kSumOfArrivals;  ///< node cost (which child goes first)
  std::size_t max_nodes = 20'000;                   ///< high-level nodes expanded before giving up
  double time_limit_s = 60.0;                       ///< wall-clock budget [s] before giving up
  double tolerance = 1e-6;  ///< collision test tolerance [m] (the checker's)
  /// Low level keeps off the starts (--at-start wait, while they get away) and goals (--at-goal
  /// stay, from their earliest arrival) of the robots not above it when it can (a tie-breaking
  /// choice of the low level that the paper leaves open; without it a robot that passes another's
  /// start at once leaves no order feasible).
  bool soft_obstacles = true;
};

struct PbsResult {
  bool ok = false;
  std::vector<std::vector<TimedWaypoint>> plans;  ///< per robot (by index) when ok
  std::vector<double> arrivals;                   ///< per robot [s]
  double makespan = 0.0, sum_of_arrivals = 0.0;
  std::vector<int> order;           ///< a total order consistent with the final priority pairs
  std::size_t priority_pairs = 0;   ///< pairs in the final node
  std::size_t nodes_expanded = 0;   ///< high-level nodes expanded
  std::size_t nodes_generated = 0;  ///< children that could be planned
  std::size_t replans = 0;          ///< low-level SIPP calls
  std::size_t expansions = 0;       ///< SIPP state expansions in total
  std::string message;              ///< why it stopped when !ok
};

/// `blocked`: the raw map (1 = blocked), inflated per robot radius.
[[nodiscard]] PbsResult plan_pbs(const BinaryGrid& blocked, const std::vector<SippRobot>& robots,
                                 const PbsOptions& options = {});

}  // namespace voronav::coordination
