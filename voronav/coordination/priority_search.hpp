// Priority search for the (M,D) network, seed 002 section 4: the objective J = max T^completed
// (eq. 8) over priority orders, which is a dynamic asymmetric TSP (eq. 10).
//  - bottom_level_edf(): the search-space reduction of section 4.1 (eq. 11, Table 4).
//  - exhaustive_search(): every order of the urgent group (branch and bound on the makespan).
//  - genetic_search(): GA with DPX crossover and greedy reconnection by the largest M + D,
//    mutation removing 4..7 edges, 3-opt local search, elitism and the convergence rule of
//    sections 4.2 and 5.1, all parameters in GaOptions, seeded; beyond the paper (issue #16,
//    options, off by default): other 3-opt neighbourhoods, an iterated local search and a polish
//    after the GA, and named settings (ga_preset()).
// Orders are compared by (makespan, sum of arrivals), so that among orders with the same makespan
// the one that lets the others arrive earlier wins (the paper only names the makespan).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "voronav/coordination/md_network.hpp"

namespace voronav::coordination {

/// One round of the Bottom-level EDF scheduler (a row of Table 4).
struct EdfRound {
  std::vector<double> completion;  ///< T^completed per robot (NaN when already removed)
  std::vector<int> urgent_group;   ///< UG at the start of the round
  int removed = -1;                ///< robot placed at the bottom in this round (-1: none)
};

struct EdfResult {
  double deadline = 0.0;           ///< E = max T^traveled
  std::vector<int> removal_order;  ///< robots in the order they were placed at the bottom
  std::vector<int> urgent_group;   ///< robots left in UG (the reduced search space)
  std::vector<EdfRound> rounds;
  /// A full order: UG by increasing slack (most urgent first), then the removed robots, the first
  /// removed last.
  std::vector<int> order;
};

/// What the EDF scheduler counts as the cost of an arc between robot i and a UG robot j. The paper
/// says "the sum of all arc costs (delay time and slack time)"; two readings fit its Table 4:
enum class EdfCost {
  /// k0 = M + D, the time both robots spend in the box (delay + slack). Symmetric; with it Table 4
  /// leaves one parameter fewer free (A2's 80 s is predicted) and figure 17's urgent fraction is
  /// reproduced. Default.
  kSharedTime,
  /// max(0, D) with i below j: the delay i would get at the bottom (order-dependent).
  kDelay,
};

struct EdfOptions {
  EdfCost cost = EdfCost::kSharedTime;
};

/// Bottom-level EDF (seed 002, section 4.1, eq. 11): deadline E = max T^traveled; T^delayed of
/// robot i = sum of the arc costs between i and the UG robots; repeatedly the robot with the
/// largest non-negative slack S = E - T^completed goes to the bottom and leaves UG.
[[nodiscard]] EdfResult bottom_level_edf(const MdNetwork& net, const EdfOptions& options = {});

enum class SearchKind { kNone, kExhaustive, kEdf, kGa };
[[nodiscard]] std::string_view to_string(SearchKind k);
/// Parses "none", "exhaustive", "edf", "ga"; throws voronav::Error otherwise.
[[nodiscard]] SearchKind parse_search_kind(std::string_view s);

/// Which 3-opt moves the GA tries on a child (issue #16; docs/reproductions/coordination.md).
enum class ThreeOptOrder {
  /// The paper's: N (N - 1) uniform random segment moves, first improvement (section 5.1 caps the
  /// "iterations" at N (N - 1); each tried move is one iteration here).
  kPaper,
  /// Moves that lift the critical robot (the last to arrive) and the robots delaying it above a
  /// blocker, or drop a blocker below it (internal/critical_moves.hpp), first improvement, again
  /// from the new critical robot after each improvement; stops at a local optimum of this
  /// neighbourhood or at the same N (N - 1) cap.
  kCriticalFirst,
  /// kCriticalFirst, and at its local optimum the same moves for every delayed robot (latest
  /// completion first; internal::delayed_moves()), accepted when (makespan, sum of arrivals)
  /// improves; an improvement returns to the critical moves. Stops at a local optimum of both
  /// lists or at the N (N - 1) cap.
  kCriticalDelayed,
};
[[nodiscard]] std::string_view to_string(ThreeOptOrder o);
/// Parses "paper", "critical-first", "critical-delayed"; throws voronav::Error otherwise.
[[nodiscard]] ThreeOptOrder parse_three_opt_order(std::string_view s);

/// Genetic algorithm parameters; defaults are the paper's (section 5.1, 5.2.2).
struct GaOptions {
  std::uint64_t seed = 1;
  int crossovers_per_generation = 10;
  int crossovers_per_round = 20;  ///< convergence is checked after this many crossovers
  double mutation_rate = 0.2;     ///< probability that a child is mutated
  int mutation_min_edges = 4;     ///< mutation removes a random number of edges in
  int mutation_max_edges = 7;     ///< [min, max] and reconnects greedily
  double elitism = 0.2;           ///< fraction of the best orders always kept unchanged
  /// false (default): children replace random non-elite members (the paper's elitism);
  /// true: the population is the best of old and children (plain truncation, before issue #16).
  bool truncation = false;
  double convergence = 1e-4;  ///< stop when the best makespan changes less (relative)
  int max_rounds = 50;        ///< hard limit on rounds
  /// 0: the convergence rule above (the best makespan of two consecutive rounds). > 0: stop
  /// instead when the best makespan has not improved by more than `convergence` (relative) for
  /// this many generations in a row (max_rounds still applies).
  int stall_generations = 0;
  /// Population size; 0 = the number of robots searched (the paper's "N random orders").
  int population = 0;
  /// 3-opt attempts per child; 0 = N (N - 1) as in the paper; < 0 disables 3-opt.
  int three_opt_iterations = 0;
  ThreeOptOrder three_opt_order = ThreeOptOrder::kPaper;
  /// kCriticalFirst: levels of "robots delaying the critical robot" whose moves are listed.
  int three_opt_depth = 2;
  /// kCriticalFirst: at a local optimum of the critical moves, random segment moves follow (the
  /// paper's draw, minus the moves the exact cut proves cannot lower the makespan) until this many
  /// evaluated moves in a row did not improve; an improvement returns to the critical moves.
  /// 0 = none.
  int three_opt_patience = 0;
  /// kCriticalDelayed: 0 = every child gets the delayed sweeps. k > 0: a child first gets
  /// critical-first alone, and the sweeps (then critical-first again) only if it is then no worse
  /// than the k-th best order of the population its parents come from (the sweeps cost ~6x the
  /// critical moves; this spends them on the children that can enter the top).
  int delayed_gate = 0;
  /// After the GA: the paper's 3-opt neighbourhood applied exhaustively to the best order only
  /// (every robot moved to every other position, N (N - 1) moves per sweep, each taken when
  /// (makespan, sum of arrivals) improves; sweeps repeat until one takes no move or this many
  /// sweeps ran). 0 = none (the paper's GA).
  int polish_sweeps = 0;
  /// After the GA, before the polish (beyond the paper, issue #16): iterated local search from
  /// the GA's best order. Each step makes crossovers_per_generation kicks of the current best
  /// (ils_kick random segment moves, the paper's 3-opt draw), runs the child's 3-opt on each
  /// (kCriticalDelayed: critical-first, and the delayed sweeps only when the kick is then no worse
  /// than the current best), and the best kick of the step replaces the current best when
  /// (makespan, sum of arrivals) improves. Every kick draws from its own stream seeded from the
  /// main one, so the result does not depend on the thread count. Stops after this many steps in
  /// a row without a better order, after max_rounds steps, or at ils_evaluations. 0 = none (the
  /// paper's GA). Never returns an order worse than the GA's best. Needs the 3-opt
  /// (three_opt_iterations >= 0) and at least 3 searched robots; skipped otherwise.
  int ils_patience = 0;
  /// Random segment moves per kick of the iterated local search (>= 1).
  int ils_kick = 2;
  /// The iterated local search starts no step once the whole search (GA and ILS, all threads)
  /// has made this many evaluations; 0 = no cap. Evaluations are counted the same way for every
  /// thread count, so the cap keeps the result independent of it.
  std::size_t ils_evaluations = 0;
  /// 0: one RNG stream for the whole GA (the results of earlier versions). >= 1: each child of a
  /// generation (crossover, mutation, 3-opt) draws from its own stream, seeded from the main one,
  /// and the children are made on this many threads; the result is the same for every value >= 1.
  int threads = 0;
  /// threads == 0 and ThreeOptOrder::kPaper only: the children of a generation are made on this
  /// many threads, each with the RNG state it has in the one-stream run (its parents, crossover and
  /// mutation are drawn first on the main stream, in child order; the paper's 3-opt draws the same
  /// number of moves whatever the orders, so the main stream skips past a child's 3-opt draws
  /// without evaluating them). The result equals workers = 1 bit for bit (issue #16).
  int workers = 1;
};

/// Named GA settings (issue #16): "paper" = GaOptions{} (the paper's GA); "fast" = the setting
/// that met the check (docs/coordination.md, bench/results/coordination.md tenth pass):
/// critical-delayed 3-opt, delayed gate 10, stall 2, then the iterated local search (patience 15,
/// kicks of 2 segment moves, at most 250,000 evaluations for the whole search), on 2 threads
/// (the result is the same for every thread count >= 1). The seed is left at its default.
/// Throws voronav::Error for another name.
[[nodiscard]] GaOptions ga_preset(std::string_view name);

struct SearchOptions {
  SearchKind kind = SearchKind::kGa;
  /// Search only the EDF urgent group (the paper's reduction); false searches all robots.
  bool edf_reduction = true;
  /// Exhaustive search refuses more robots than this (N! orders).
  int exhaustive_max = 10;
  EdfOptions edf;
  GaOptions ga;
};

struct SearchResult {
  std::vector<int> order;  ///< highest priority first
  Resolution resolution;
  std::vector<int> urgent_group;           ///< the robots that were searched
  std::size_t evaluations = 0;             ///< orders resolved
  int rounds = 0;                          ///< GA rounds until convergence
  int generations = 0;                     ///< GA generations
  std::vector<double> best_per_round;      ///< GA best makespan after each round
  std::size_t three_opt_improvements = 0;  ///< 3-opt moves accepted (all children)
  std::size_t three_opt_local_optima = 0;  ///< children whose 3-opt ended at a local optimum
  std::size_t three_opt_exact_cuts = 0;    ///< random moves skipped: they cannot lower the makespan
  /// Of three_opt_improvements, the moves taken by the delayed-robot sweep (kCriticalDelayed).
  std::size_t three_opt_delayed_improvements = 0;
  /// GaOptions::polish_sweeps: moves the final polish took, sweeps it ran, and the makespan of
  /// the GA's best order before the polish.
  std::size_t polish_improvements = 0;
  int polish_sweeps = 0;
  double makespan_before_polish = 0.0;
  /// GaOptions::ils_patience: steps the iterated local search ran, steps that improved the best
  /// order, and the makespan of the GA's best order before it.
  int ils_steps = 0;
  int ils_improvements = 0;
  double makespan_before_ils = 0.0;
};

/// True when (makespan, sum_of_arrivals) of a is better than b (with a 1e-9 tolerance).
[[nodiscard]] bool better(const Resolution& a, const Resolution& b);

/// Runs the search selected by options.kind. kNone keeps the index order; kEdf returns
/// EdfResult::order. Throws voronav::Error when exhaustive search is asked for too many robots.
[[nodiscard]] SearchResult search_priority(const MdNetwork& net, const SearchOptions& options = {});

/// Exhaustive search over the orders of `searched` robots placed above `suffix` (branch and bound).
[[nodiscard]] SearchResult exhaustive_search(const MdNetwork& net, const std::vector<int>& searched,
                                             const std::vector<int>& suffix);
/// GA over the orders of `searched` robots placed above `suffix`, seeded with `seed_order`
/// (an order of `searched`; may be empty). Never returns an order worse than the seed.
[[nodiscard]] SearchResult genetic_search(const MdNetwork& net, const std::vector<int>& searched,
                                          const std::vector<int>& suffix,
                                          const std::vector<int>& seed_order,
                                          const GaOptions& options);

}  // namespace voronav::coordination
