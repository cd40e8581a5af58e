// The critical-first 3-opt neighbourhood of the delay GA (issue #16): its moves, the blockers it
// reads from a resolution, the exact cut against brute force, and the GA option end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "voronav/coordination/internal/critical_moves.hpp"
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
TEST(CriticalMoves, GaCriticalFirstIsDeterministicAndNeverWorseThanTheSeed) {
  EXPECT_EQ(parse_three_opt_order("critical-first"), ThreeOptOrder::kCriticalFirst);
  EXPECT_EQ(parse_three_opt_order("paper"), ThreeOptOrder::kPaper);
  EXPECT_THROW((void)parse_three_opt_order("best"), Error);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const MdNetwork net = random_network(30, 90, seed);
    SearchOptions so;
    so.edf_reduction = false;
    so.ga.seed = seed;
    so.ga.three_opt_order = ThreeOptOrder::kCriticalFirst;
    so.ga.three_opt_patience = seed % 2 == 0 ? 20 : 0;
    const auto a = search_priority(net, so);
    const auto b = search_priority(net, so);
    EXPECT_EQ(a.order, b.order);
    EXPECT_EQ(a.evaluations, b.evaluations);
    check_order(a.order, net.size());
    const Resolution full = resolve(net, a.order);
    EXPECT_EQ(full.makespan, a.resolution.makespan);
    const auto edf = bottom_level_edf(net);
    EXPECT_FALSE(better(resolve(net, edf.order), a.resolution)) << seed;
    EXPECT_GT(a.three_opt_improvements, 0U);
    EXPECT_GT(a.three_opt_local_optima, 0U);
  }
}

// Per-child RNG streams: the same result for 1, 2 and 3 threads (whatever the threads' timing),
// for both 3-opt neighbourhoods.
TEST(CriticalMoves, GaResultDoesNotDependOnTheThreadCount) {
  for (const auto order : {ThreeOptOrder::kPaper, ThreeOptOrder::kCriticalFirst}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const MdNetwork net = random_network(20, 60, seed);
      SearchOptions so;
      so.edf_reduction = false;
      so.ga.seed = seed;
      so.ga.three_opt_order = order;
      so.ga.three_opt_iterations = 100;
      so.ga.threads = 1;
      const auto one = search_priority(net, so);
      for (const int t : {2, 3}) {
        so.ga.threads = t;
        const auto r = search_priority(net, so);
        EXPECT_EQ(r.order, one.order) << seed << " threads " << t;
        EXPECT_EQ(r.evaluations, one.evaluations);
        EXPECT_EQ(r.best_per_round, one.best_per_round);
        EXPECT_EQ(r.three_opt_improvements, one.three_opt_improvements);
        EXPECT_EQ(r.resolution.delays, one.resolution.delays);
      }
      EXPECT_GE(one.generations, 2);
    }
  }
}

}  // namespace
}  // namespace voronav::coordination
