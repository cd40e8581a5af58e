// The paper's priority search (seed 002 section 4.2: GA with DPX crossover, mutation removing
// 4..7 edges, 3-opt segment moves, elitism) over the priority orders of prioritized SIPP
// (prioritized.hpp) instead of the (M,D) network's delay resolution (issue #21).
//
// An order is evaluated by planning every robot with SIPP in that order (no restarts; an order in
// which some robot has no plan is worth infinity), scored by the makespan or the sum of arrivals
// (the other breaks ties). Differences from the delay GA (priority_search.hpp), decided here:
//  - DPX reconnects the fragments in a random order avoiding both parents' edges: the greedy
//    reconnection by the largest M + D needs the (M,D) network, which SIPP does not use (the
//    operators are the delay GA's, internal/ga_operators.hpp, with no weights: all edges tie);
//  - one evaluation is a full prioritized planning run (milliseconds to a second), so the
//    population, the children per generation and the 3-opt moves per child are small options
//    and the search stops at a CPU-time budget (sipp_ga_budget()); the seeds (EDF and the other
//    order rules) are in the initial population, so the result is never worse than the best seed
//    planned (the first seed, EDF, is always planned; the others only while the budget lasts).
#pragma once

#include <utility>
#include <vector>

#include "voronav/coordination/prioritized.hpp"

namespace voronav::coordination {

struct SippGaResult {
  PrioritizedResult best;  ///< the best order's plans (ok == false when no order worked)
  std::vector<int> order;
  int generations = 0;
  std::size_t evaluations = 0;
  int improved_over_seeds = 0;  ///< 1 when the GA found an order better than every seed
};

/// The GA's CPU budget [s]: options.time_limit_s when > 0, else auto_seconds_per_robot per robot
/// clamped to [auto_min_s, auto_max_s].
[[nodiscard]] double sipp_ga_budget(const SippGaOptions& options, std::size_t robots);

/// `seeds`: initial orders (each a permutation of the robot indices).
[[nodiscard]] SippGaResult sipp_genetic_search(const BinaryGrid& blocked,
                                               const std::vector<SippRobot>& robots,
                                               const std::vector<std::vector<int>>& seeds,
                                               Objective objective,
                                               const PrioritizedOptions& planning,
                                               const SippGaOptions& options = {});

}  // namespace voronav::coordination
