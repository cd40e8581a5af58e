// The GA's iterated local search (GaOptions::ils_patience, issue #16) and the named GA settings
// (ga_preset): never worse than the GA's best, the same result for every thread count, the
// evaluation cap stops it at the step it names, and bad options are refused.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "voronav/coordination/paper_networks.hpp"
#include "voronav/coordination/priority_search.hpp"
#include "voronav/core/error.hpp"

namespace voronav::coordination {
namespace {

SearchOptions ils_options(std::uint64_t seed, int patience, int threads) {
  SearchOptions so;
  so.edf_reduction = false;
  so.ga.seed = seed;
  so.ga.three_opt_order = ThreeOptOrder::kCriticalDelayed;
  so.ga.delayed_gate = 5;
  so.ga.stall_generations = 2;
  so.ga.ils_patience = patience;
  so.ga.threads = threads;
  return so;
}

// Without the ILS the GA is unchanged; with it the result starts from the GA's best, is never
// worse, is the same for 1, 2 and 3 threads, and the ILS really improved some seeds' orders.
TEST(GaIls, NeverWorseThanTheGaAndTheSameForEveryThreadCount) {
  int improved = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const MdNetwork net = random_network(40, 160, seed);
    const SearchResult plain = search_priority(net, ils_options(seed, 0, 1));
    EXPECT_EQ(plain.ils_steps, 0);
    EXPECT_EQ(plain.ils_improvements, 0);
    const SearchResult one = search_priority(net, ils_options(seed, 4, 1));
    EXPECT_EQ(one.makespan_before_ils, plain.resolution.makespan) << seed;
    EXPECT_FALSE(better(plain.resolution, one.resolution)) << seed;
    EXPECT_EQ(resolve(net, one.order).makespan, one.resolution.makespan) << seed;
    EXPECT_EQ(resolve(net, one.order).sum_of_arrivals, one.resolution.sum_of_arrivals) << seed;
    // patience 4: at least 4 steps, the last 4 without improvement
    EXPECT_GE(one.ils_steps, 4 + one.ils_improvements) << seed;
    EXPECT_GT(one.evaluations, plain.evaluations) << seed;
    for (const int threads : {2, 3}) {
      const SearchResult r = search_priority(net, ils_options(seed, 4, threads));
      EXPECT_EQ(r.order, one.order) << seed << " threads " << threads;
      EXPECT_EQ(r.evaluations, one.evaluations) << seed << " threads " << threads;
      EXPECT_EQ(r.ils_steps, one.ils_steps) << seed << " threads " << threads;
      EXPECT_EQ(r.resolution.delays, one.resolution.delays) << seed << " threads " << threads;
    }
    improved += one.ils_improvements > 0 && better(one.resolution, plain.resolution) ? 1 : 0;
  }
  EXPECT_GE(improved, 2);
}

// The evaluation cap counts the whole search: a cap equal to the GA's own evaluations lets no
// step start, one more evaluation lets exactly one start (a step makes far more than one).
TEST(GaIls, EvaluationCapStopsAtTheStepItNames) {
  const MdNetwork net = random_network(40, 160, 3);
  const SearchResult plain = search_priority(net, ils_options(3, 0, 1));
  SearchOptions so = ils_options(3, 50, 2);
  so.ga.ils_evaluations = plain.evaluations;
  const SearchResult none = search_priority(net, so);
  EXPECT_EQ(none.ils_steps, 0);
  EXPECT_EQ(none.order, plain.order);
  EXPECT_EQ(none.evaluations, plain.evaluations);
  so.ga.ils_evaluations = plain.evaluations + 1;
  const SearchResult step = search_priority(net, so);
  EXPECT_EQ(step.ils_steps, 1);
  // one step = 10 kicks, each one full resolution and its 3-opt moves
  EXPECT_GE(step.evaluations, plain.evaluations + 10);
  EXPECT_FALSE(better(plain.resolution, step.resolution));
}

TEST(GaIls, BadOptionsAreRefused) {
  const MdNetwork net = random_network(5, 10, 1);
  GaOptions bad;
  bad.ils_patience = -1;
  EXPECT_THROW((void)genetic_search(net, {0, 1, 2, 3, 4}, {}, {}, bad), Error);
  bad = GaOptions{};
  bad.ils_patience = 3;
  bad.ils_kick = 0;
  EXPECT_THROW((void)genetic_search(net, {0, 1, 2, 3, 4}, {}, {}, bad), Error);
}

// "paper" is the paper's GA (GaOptions{}); "fast" is the setting the docs name for issue #16.
TEST(GaIls, PresetsNameTheDocumentedSettings) {
  const GaOptions paper = ga_preset("paper");
  const GaOptions def;
  EXPECT_EQ(paper.three_opt_order, def.three_opt_order);
  EXPECT_EQ(paper.ils_patience, 0);
  EXPECT_EQ(paper.threads, 0);
  EXPECT_EQ(paper.stall_generations, 0);
  EXPECT_EQ(paper.delayed_gate, 0);
  const GaOptions fast = ga_preset("fast");
  EXPECT_EQ(fast.three_opt_order, ThreeOptOrder::kCriticalDelayed);
  EXPECT_EQ(fast.delayed_gate, 10);
  EXPECT_EQ(fast.stall_generations, 2);
  EXPECT_EQ(fast.ils_patience, 15);
  EXPECT_EQ(fast.ils_kick, 2);
  EXPECT_EQ(fast.ils_evaluations, 250000U);
  EXPECT_EQ(fast.threads, 2);
  EXPECT_THROW((void)ga_preset("quick"), Error);
}

}  // namespace
}  // namespace voronav::coordination
