// GA over SIPP orders (issue #21): never worse than its seeds, deterministic for a seed, its
// plans pass the continuous-time checker; the first seed is planned whatever the budget; the auto
// budget.
#include <gtest/gtest.h>

#include <random>

#include "voronav/coordination/internal/sipp_test_instances.hpp"
#include "voronav/coordination/sipp_ga.hpp"
#include "voronav/coordination/verify.hpp"

namespace voronav::coordination {
namespace {

TEST(SippGa, NeverWorseThanItsSeedsAndDeterministic) {
  std::mt19937 rng(7);
  const int n = 8;
  const auto [g, robots] = internal::random_sipp_instance(rng, 10, 8, 0.12, n);
  PrioritizedOptions po;
  po.sipp.at_start = AtStart::kAppear;
  po.sipp.at_goal = AtGoal::kLeave;
  std::vector<int> seed(n);
  for (int i = 0; i < n; ++i)
    seed[static_cast<std::size_t>(i)] = i;
  po.max_restarts = 0;
  const PrioritizedResult seeded = plan_prioritized(g, robots, seed, po);
  ASSERT_TRUE(seeded.ok);
  SippGaOptions o;
  o.time_limit_s = 1e9;  // bounded by generations only: deterministic
  o.max_generations = 6;
  const SippGaResult a = sipp_genetic_search(g, robots, {seed}, Objective::kSumOfArrivals, po, o);
  const SippGaResult b = sipp_genetic_search(g, robots, {seed}, Objective::kSumOfArrivals, po, o);
  ASSERT_TRUE(a.best.ok);
  EXPECT_EQ(a.generations, 6);
  EXPECT_LE(a.best.sum_of_arrivals, seeded.sum_of_arrivals + 1e-9);
  EXPECT_EQ(a.order, b.order);
  EXPECT_EQ(a.best.sum_of_arrivals, b.best.sum_of_arrivals);
  std::vector<Trajectory> tr;
  std::vector<double> radii;
  for (const auto& p : a.best.plans) {
    tr.push_back(trajectory_of(p, po.sipp.at_start, po.sipp.at_goal));
    radii.push_back(0.5);
  }
  EXPECT_TRUE(verify_trajectories(tr, radii).valid);
  EXPECT_THROW((void)sipp_genetic_search(g, robots, {{0, 1}}, Objective::kMakespan, po, o), Error);

  // A budget spent before the first evaluation: the first seed (EDF in coordinate_sipp) is still
  // planned, and nothing else (no second seed, no generation).
  SippGaOptions tiny;
  tiny.time_limit_s = 1e-12;
  std::vector<int> reversed(seed.rbegin(), seed.rend());
  const SippGaResult t =
      sipp_genetic_search(g, robots, {seed, reversed}, Objective::kSumOfArrivals, po, tiny);
  EXPECT_EQ(t.evaluations, 1U);
  EXPECT_EQ(t.generations, 0);
  EXPECT_EQ(t.order, seed);
  EXPECT_EQ(t.best.sum_of_arrivals, seeded.sum_of_arrivals);
}

TEST(SippGa, AutoBudgetScalesWithTheRobots) {
  SippGaOptions o;  // time_limit_s = 0: auto, 0.01 s per robot within [0.2, 2]
  EXPECT_DOUBLE_EQ(sipp_ga_budget(o, 100), 1.0);
  EXPECT_DOUBLE_EQ(sipp_ga_budget(o, 5), 0.2);
  EXPECT_DOUBLE_EQ(sipp_ga_budget(o, 1000), 2.0);
  o.time_limit_s = 3.0;
  EXPECT_DOUBLE_EQ(sipp_ga_budget(o, 100), 3.0);
}

}  // namespace
}  // namespace voronav::coordination
