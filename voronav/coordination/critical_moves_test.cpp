// The critical-first 3-opt neighbourhood of the delay GA (issue #16): its moves, the blockers it
// reads from a resolution, the exact cut against brute force, and the GA option end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "voronav/coordination/internal/critical_moves.hpp"
#include "voronav/coordination/internal/strided_threads.hpp"
#include "voronav/coordination/paper_networks.hpp"
#include "voronav/coordination/priority_search.hpp"
#include "voronav/core/error.hpp"

namespace voronav::coordination {
namespace {

std::vector<int> ranks_of(const std::vector<int>& order) {
  std::vector<int> rank(order.size());
  for (std::size_t p = 0; p < order.size(); ++p)
    rank[static_cast<std::size_t>(order[p])] = static_cast<int>(p);
  return rank;
}

std::vector<int> random_order(int n, std::mt19937_64& rng) {
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  return order;
}

// A search run another way (workers, threads) gave bit for bit the search `one`: the same order,
// evaluations, per-round best, 3-opt improvements and delays.
void expect_same_search(const SearchResult& r, const SearchResult& one, const std::string& what) {
  EXPECT_EQ(r.order, one.order) << what;
  EXPECT_EQ(r.evaluations, one.evaluations) << what;
  EXPECT_EQ(r.best_per_round, one.best_per_round) << what;
  EXPECT_EQ(r.three_opt_improvements, one.three_opt_improvements) << what;
  EXPECT_EQ(r.resolution.delays, one.resolution.delays) << what;
}

// Runs `so` as given, then with the GaOptions count `field` (workers, threads) set to 2 and 3, and
// expects the same search each time; returns the first run.
SearchResult expect_same_for_2_and_3(const MdNetwork& net, SearchOptions so, int GaOptions::*field,
                                     const std::string& what) {
  const SearchResult one = search_priority(net, so);
  for (const int n : {2, 3}) {
    so.ga.*field = n;
    expect_same_search(search_priority(net, so), one, what + " " + std::to_string(n));
  }
  return one;
}

// search_priority on a random network with the 3-opt order `order` (no EDF reduction), checked as
// every GA test needs: the same seed gives the same order and evaluation count, the order is a
// permutation whose exact resolution has the reported makespan, and it is never worse than the
// EDF seed's.
SearchResult checked_search(const MdNetwork& net, std::uint64_t seed, ThreeOptOrder order,
                            int patience = 0) {
  SearchOptions so;
  so.edf_reduction = false;
  so.ga.seed = seed;
  so.ga.three_opt_order = order;
  so.ga.three_opt_patience = patience;
  SearchResult a = search_priority(net, so);
  const SearchResult b = search_priority(net, so);
  EXPECT_EQ(a.order, b.order);
  EXPECT_EQ(a.evaluations, b.evaluations);
  check_order(a.order, net.size());
  EXPECT_EQ(resolve(net, a.order).makespan, a.resolution.makespan);
  EXPECT_FALSE(better(resolve(net, bottom_level_edf(net).order), a.resolution)) << seed;
  return a;
}

// The shifts of a robot's blockers add up to its delay, and every blocker is above it.
TEST(CriticalMoves, BlockerShiftsSumToTheDelay) {
  int robots_with_blockers = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const MdNetwork net = random_network(20, 80, seed);
    std::mt19937_64 rng(seed);
    const auto order = random_order(net.size(), rng);
    const auto rank = ranks_of(order);
    const Resolution res = resolve(net, order);
    ASSERT_EQ(res.status, ResolveStatus::kOk);
    for (int x = 0; x < net.size(); ++x) {
      const auto bl = internal::blockers(net, rank, res, x);
      double sum = 0.0;
      for (const auto& b : bl) {
        EXPECT_LT(rank[static_cast<std::size_t>(b.robot)], rank[static_cast<std::size_t>(x)]);
        EXPECT_GT(b.shift, 0.0);
        sum += b.shift;
      }
      for (std::size_t q = 1; q < bl.size(); ++q)
        EXPECT_GE(bl[q - 1].shift, bl[q].shift);
      EXPECT_NEAR(sum, res.delays[static_cast<std::size_t>(x)], 1e-9) << seed << " robot " << x;
      robots_with_blockers += bl.empty() ? 0 : 1;
    }
  }
  EXPECT_GT(robots_with_blockers, 50);
}

// Every listed move gives a permutation; the first moves put the critical robot above one of its
// blockers (or that blocker below it), i.e. the critical robot really changes sides.
TEST(CriticalMoves, MovesArePermutationsThatMoveTheCriticalRobot) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const MdNetwork net = random_network(15, 50, seed);
    std::mt19937_64 rng(seed);
    const auto order = random_order(net.size(), rng);
    const auto rank = ranks_of(order);
    const Resolution res = resolve(net, order);
    const int c = internal::critical_robot(res, rank);
    ASSERT_GE(c, 0);
    EXPECT_DOUBLE_EQ(res.completion[static_cast<std::size_t>(c)], res.makespan);
    const auto bl = internal::blockers(net, rank, res, c);
    const auto moves = internal::critical_moves(net, net.size(), rank, res, 2);
    if (bl.empty()) {
      EXPECT_TRUE(moves.empty()) << seed;  // c is not delayed: nothing lowers the makespan
      continue;
    }
    ASSERT_GE(moves.size(), 2 * bl.size());
    for (std::size_t q = 0; q < moves.size(); ++q) {
      std::vector<int> cand;
      int from = 0, to = 0;
      internal::apply_segment_move(order, moves[q], cand, from, to);
      std::vector<int> sorted = cand;
      std::sort(sorted.begin(), sorted.end());
      std::vector<int> ids(order.size());
      std::iota(ids.begin(), ids.end(), 0);
      ASSERT_EQ(sorted, ids);
      for (int p = 0; p < static_cast<int>(order.size()); ++p) {
        if (p < from || p >= to) {
          EXPECT_EQ(cand[static_cast<std::size_t>(p)], order[static_cast<std::size_t>(p)]);
        }
      }
      for (std::size_t r = 0; r < q; ++r)
        EXPECT_FALSE(moves[r] == moves[q]);  // no move listed twice
      if (q < 2 * bl.size()) {
        const auto nr = ranks_of(cand);
        const int b = bl[q / 2].robot;
        EXPECT_LT(nr[static_cast<std::size_t>(c)], nr[static_cast<std::size_t>(b)])
            << seed << " move " << q;
      }
    }
  }
}

// The exact cut must never skip a move that lowers the makespan: over every segment move of
// small random networks, a cut move leaves the critical robot's delay bitwise unchanged.
TEST(CriticalMoves, ExactCutNeverSkipsAMakespanImprovement) {
  int cut = 0, kept = 0, improving = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const int n = 6 + static_cast<int>(seed % 5);
    const MdNetwork net = random_network(n, 3 * n, 1000 + seed);
    std::mt19937_64 rng(seed);
    const auto order = random_order(n, rng);
    const auto rank = ranks_of(order);
    const Resolution res = resolve(net, order);
    if (res.status != ResolveStatus::kOk) continue;
    const int c = internal::critical_robot(res, rank);
    std::vector<char> support, scratch;
    internal::support_of(net, rank, c, support);
    for (int i = 0; i < n; ++i) {
      for (int j = i; j < n; ++j) {
        const int len = j - i + 1;
        if (len >= n) continue;
        for (int k = 0; k <= n - len; ++k) {
          if (k == i) continue;
          const internal::SegmentMove mv{i, j, k};
          std::vector<int> cand;
          int from = 0, to = 0;
          internal::apply_segment_move(order, mv, cand, from, to);
          const Resolution r = resolve(net, cand);
          const bool lowers = r.status == ResolveStatus::kOk && r.makespan < res.makespan - 1e-9;
          improving += lowers ? 1 : 0;
          const auto bl = internal::swapped_blocks(mv);
          if (internal::can_lower_makespan(net, order, support, bl.a_begin, bl.a_end, bl.b_end,
                                           scratch)) {
            ++kept;
            continue;
          }
          ++cut;
          EXPECT_FALSE(lowers) << seed << " move " << i << " " << j << " " << k;
          EXPECT_EQ(r.delays[static_cast<std::size_t>(c)], res.delays[static_cast<std::size_t>(c)]);
        }
      }
    }
  }
  EXPECT_GT(cut, 100);
  EXPECT_GT(kept, 100);
  EXPECT_GT(improving, 10);
}

// The GA with the critical-first 3-opt: the same seed gives the same order; the result is a
// permutation resolved exactly, never worse than the EDF seed, and the local search really ran.
// GaOptions::workers (issue #16): the one-stream paper GA with its children on 2 or 3 threads
// gives the result of the sequential run bit for bit (order, delays, evaluations, every round),
// and workers > 1 is refused where the stream cannot be skipped ahead.
TEST(CriticalMoves, GaWorkersGiveTheOneStreamResult) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const MdNetwork net = random_network(20, 60, seed);
    SearchOptions so;
    so.edf_reduction = false;
    so.ga.seed = seed;
    so.ga.three_opt_iterations = 150;
    const auto one = expect_same_for_2_and_3(net, so, &GaOptions::workers,
                                             "seed " + std::to_string(seed) + " workers");
    EXPECT_GE(one.generations, 2);
    EXPECT_GT(one.three_opt_improvements, 0U);
  }
  SearchOptions bad;
  bad.ga.workers = 2;
  bad.ga.threads = 1;
  EXPECT_THROW((void)search_priority(random_network(10, 30, 1), bad), Error);
  bad.ga.threads = 0;
  bad.ga.three_opt_order = ThreeOptOrder::kCriticalFirst;
  EXPECT_THROW((void)search_priority(random_network(10, 30, 1), bad), Error);
  bad.ga.three_opt_order = ThreeOptOrder::kPaper;
  bad.ga.workers = 0;
  EXPECT_THROW((void)search_priority(random_network(10, 30, 1), bad), Error);
}

TEST(CriticalMoves, GaCriticalFirstIsDeterministicAndNeverWorseThanTheSeed) {
  EXPECT_EQ(parse_three_opt_order("critical-first"), ThreeOptOrder::kCriticalFirst);
  EXPECT_EQ(parse_three_opt_order("paper"), ThreeOptOrder::kPaper);
  EXPECT_THROW((void)parse_three_opt_order("best"), Error);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto a = checked_search(random_network(30, 90, seed), seed, ThreeOptOrder::kCriticalFirst,
                                  seed % 2 == 0 ? 20 : 0);
    EXPECT_GT(a.three_opt_improvements, 0U);
    EXPECT_GT(a.three_opt_local_optima, 0U);
  }
}

// Per-child RNG streams: the same result for 1, 2 and 3 threads (whatever the threads' timing),
// for both 3-opt neighbourhoods.
TEST(CriticalMoves, GaResultDoesNotDependOnTheThreadCount) {
  for (const auto order :
       {ThreeOptOrder::kPaper, ThreeOptOrder::kCriticalFirst, ThreeOptOrder::kCriticalDelayed}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const MdNetwork net = random_network(20, 60, seed);
      SearchOptions so;
      so.edf_reduction = false;
      so.ga.seed = seed;
      so.ga.three_opt_order = order;
      so.ga.three_opt_iterations = 100;
      so.ga.threads = 1;
      const auto one = expect_same_for_2_and_3(net, so, &GaOptions::threads,
                                               "seed " + std::to_string(seed) + " threads");
      EXPECT_GE(one.generations, 2);
    }
  }
}

// The delayed pairs: every delayed robot of the searched prefix with each of its blockers, once,
// the latest completion first, every blocker above its robot.
TEST(CriticalMoves, DelayedPairsListEveryBlockerOfEveryDelayedRobot) {
  int pairs_seen = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const MdNetwork net = random_network(20, 80, seed);
    std::mt19937_64 rng(seed + 100);
    const auto order = random_order(net.size(), rng);
    const auto rank = ranks_of(order);
    const Resolution res = resolve(net, order);
    ASSERT_EQ(res.status, ResolveStatus::kOk);
    const int n = 15;  // the last 5 robots are a fixed suffix
    const auto pairs = internal::delayed_pairs(net, n, rank, res);
    std::set<std::pair<int, int>> unique;
    std::size_t expected = 0;
    for (int x = 0; x < net.size(); ++x) {
      if (rank[static_cast<std::size_t>(x)] < n && res.delays[static_cast<std::size_t>(x)] > 1e-9)
        expected += internal::blockers(net, rank, res, x).size();
    }
    EXPECT_EQ(pairs.size(), expected) << seed;
    for (std::size_t q = 0; q < pairs.size(); ++q) {
      const auto& p = pairs[q];
      EXPECT_LT(rank[static_cast<std::size_t>(p.x)], n);
      EXPECT_GT(res.delays[static_cast<std::size_t>(p.x)], 0.0);
      EXPECT_LT(rank[static_cast<std::size_t>(p.b)], rank[static_cast<std::size_t>(p.x)]);
      const auto bl = internal::blockers(net, rank, res, p.x);
      EXPECT_TRUE(std::any_of(bl.begin(), bl.end(), [&](const auto& b) { return b.robot == p.b; }));
      EXPECT_TRUE(unique.insert({p.x, p.b}).second) << "pair listed twice";
      if (q > 0) {
        EXPECT_GE(res.completion[static_cast<std::size_t>(pairs[q - 1].x)],
                  res.completion[static_cast<std::size_t>(p.x)]);
      }
    }
    pairs_seen += static_cast<int>(pairs.size());
  }
  EXPECT_GT(pairs_seen, 50);
  // An order no delay resolves has no pairs (the critical moves handle it).
  Resolution blocked;
  blocked.status = ResolveStatus::kNoDelaySchedule;
  EXPECT_TRUE(
      internal::delayed_pairs(random_network(5, 10, 1), 5, {0, 1, 2, 3, 4}, blocked).empty());
}

// critical-delayed: deterministic, never worse than the EDF seed, and the delayed sweep really
// took moves (critical-first never does); the best is no worse than critical-first's on average.
TEST(CriticalMoves, GaCriticalDelayedSweepFires) {
  EXPECT_EQ(parse_three_opt_order("critical-delayed"), ThreeOptOrder::kCriticalDelayed);
  EXPECT_EQ(to_string(ThreeOptOrder::kCriticalDelayed), "critical-delayed");
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const MdNetwork net = random_network(30, 90, seed);
    const auto a = checked_search(net, seed, ThreeOptOrder::kCriticalDelayed);
    EXPECT_GT(a.three_opt_delayed_improvements, 0U) << seed;
    EXPECT_LE(a.three_opt_delayed_improvements, a.three_opt_improvements);
    SearchOptions so;
    so.edf_reduction = false;
    so.ga.seed = seed;
    so.ga.three_opt_order = ThreeOptOrder::kCriticalFirst;
    EXPECT_EQ(search_priority(net, so).three_opt_delayed_improvements, 0U);
  }
}

// The delayed gate: with k > 0 only the children that critical-first makes no worse than the k-th
// best get the sweeps, so fewer orders are evaluated and fewer sweep moves taken than with the
// sweeps on every child; the result stays deterministic and thread-count independent.
TEST(CriticalMoves, GaDelayedGateSpendsTheSweepsOnTheBestChildren) {
  int fewer = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const MdNetwork net = random_network(30, 90, seed);
    SearchOptions so;
    so.edf_reduction = false;
    so.ga.seed = seed;
    so.ga.three_opt_order = ThreeOptOrder::kCriticalDelayed;
    so.ga.threads = 1;
    const auto all = search_priority(net, so);
    so.ga.delayed_gate = 1;
    const auto gated = search_priority(net, so);
    so.ga.threads = 2;
    const auto gated2 = search_priority(net, so);
    EXPECT_EQ(gated.order, gated2.order);
    EXPECT_EQ(gated.evaluations, gated2.evaluations);
    EXPECT_EQ(gated.three_opt_delayed_improvements, gated2.three_opt_delayed_improvements);
    EXPECT_EQ(resolve(net, gated.order).makespan, gated.resolution.makespan);
    EXPECT_LE(gated.three_opt_delayed_improvements, all.three_opt_delayed_improvements);
    fewer += gated.evaluations < all.evaluations ? 1 : 0;
  }
  EXPECT_GE(fewer, 3);
  GaOptions bad;
  bad.delayed_gate = -1;
  EXPECT_THROW((void)genetic_search(random_network(5, 10, 1), {0, 1, 2, 3, 4}, {}, {}, bad), Error);
}

// The stall rule: the GA runs until `stall_generations` generations brought no better makespan,
// so the last rounds repeat the best; a negative value is refused.
TEST(CriticalMoves, GaStallRuleStopsAfterGenerationsWithoutImprovement) {
  const MdNetwork net = random_network(30, 90, 2);
  SearchOptions so;
  so.edf_reduction = false;
  so.ga.three_opt_order = ThreeOptOrder::kCriticalFirst;
  const auto paper_rule = search_priority(net, so);
  so.ga.stall_generations = 8;
  const auto r = search_priority(net, so);
  ASSERT_GE(r.best_per_round.size(), 4U);
  const auto& b = r.best_per_round;
  for (std::size_t q = b.size() - 4; q < b.size(); ++q)
    EXPECT_LE(b[q] - b.back(), 1e-4 * b.back());  // 4 rounds = 8 generations, no real change
  EXPECT_GE(r.generations, paper_rule.generations + 4);
  EXPECT_FALSE(better(paper_rule.resolution, r.resolution));
  so.ga.stall_generations = -1;
  EXPECT_THROW((void)search_priority(net, so), Error);
}

// The final polish (GaOptions::polish_sweeps): the returned order is a local optimum of every
// single-robot segment move (checked by brute force), never worse than the GA's best, the same for
// the same seed and any thread count; without the polish a GA without 3-opt leaves improving moves.
TEST(CriticalMoves, GaPolishEndsAtALocalOptimumOfThePapersMoves) {
  auto improving_moves = [](const MdNetwork& net, const std::vector<int>& order) {
    const Resolution base = resolve(net, order);
    const int n = static_cast<int>(order.size());
    int count = 0;
    std::vector<int> cand;
    int from = 0, to = 0;
    for (int p = 0; p < n; ++p) {
      for (int k = 0; k < n; ++k) {
        if (k == p) continue;
        internal::apply_segment_move(order, internal::SegmentMove{p, p, k}, cand, from, to);
        count += better(resolve(net, cand), base) ? 1 : 0;
      }
    }
    return count;
  };
  int unpolished_with_moves = 0;
  std::size_t taken = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const MdNetwork net = random_network(16, 48, seed);
    SearchOptions so;
    so.edf_reduction = false;
    so.ga.seed = seed;
    so.ga.three_opt_iterations = -1;  // no 3-opt: the GA alone rarely ends at a local optimum
    so.ga.threads = 1;
    const auto plain = search_priority(net, so);
    unpolished_with_moves += improving_moves(net, plain.order) > 0 ? 1 : 0;
    EXPECT_EQ(plain.polish_sweeps, 0);
    so.ga.polish_sweeps = 50;
    const auto a = search_priority(net, so);
    so.ga.threads = 2;
    const auto b = search_priority(net, so);
    EXPECT_EQ(a.order, b.order);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_EQ(a.makespan_before_polish, plain.resolution.makespan);
    EXPECT_FALSE(better(plain.resolution, a.resolution)) << seed;
    EXPECT_EQ(resolve(net, a.order).makespan, a.resolution.makespan);
    EXPECT_EQ(improving_moves(net, a.order), 0) << seed;
    EXPECT_LT(a.polish_sweeps, 50);  // stopped by a sweep that took no move
    taken += a.polish_improvements;
  }
  EXPECT_GE(unpolished_with_moves, 2);
  EXPECT_GT(taken, 0U);
  GaOptions bad;
  bad.polish_sweeps = -1;
  EXPECT_THROW((void)genetic_search(random_network(5, 10, 1), {0, 1, 2, 3, 4}, {}, {}, bad), Error);
}

// A worker's exception is rethrown on the caller's thread (never std::terminate): the lowest
// item that threw wins, for every thread count, and every thread was joined.
TEST(CriticalMoves, StridedThreadsRethrowAWorkersExceptionOnTheCaller) {
  const auto caller = std::this_thread::get_id();
  for (const int threads : {1, 2, 3}) {
    std::vector<int> done(10, 0);
    std::vector<std::thread::id> who(10);  // each item writes its own slot
    try {
      internal::run_strided(10, threads, [&](int, int c) {
        who[static_cast<std::size_t>(c)] = std::this_thread::get_id();
        if (c == 5 || c == 7) throw std::runtime_error("item " + std::to_string(c));
        done[static_cast<std::size_t>(c)] = 1;
      });
      ADD_FAILURE() << "no exception, threads " << threads;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "item 5") << threads;
    }
    EXPECT_EQ(done[0], 1);
    if (threads == 2) {
      // Item 5 threw on worker 1 (5 mod 2), not on the caller; the caller finished its items.
      EXPECT_NE(who[5], caller);
      EXPECT_EQ(who[8], caller);
      EXPECT_EQ(done[8], 1);
    }
  }
}

}  // namespace
}  // namespace voronav::coordination
