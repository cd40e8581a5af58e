// PBS with SIPP (issue #21): a hand-computed case that no fixed order with the robot parked first
// solves, and every PBS plan through the continuous-time checker on random instances.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "voronav/coordination/internal/sipp_test_instances.hpp"
#include "voronav/coordination/pbs.hpp"
#include "voronav/coordination/verify.hpp"

namespace voronav::coordination {
namespace {

BinaryGrid grid(const std::vector<std::string>& rows) {
  BinaryGrid g(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
  for (int y = 0; y < g.geometry().height; ++y)
    for (int x = 0; x < g.geometry().width; ++x)
      g[Cell{x, y}] = rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] == '@';
  return g;
}

TEST(Pbs, PutsTheRobotThatParksOnTheWayBelow) {
  // Robot 1 (index 0) parks at (3,1) in a corridor that robot 2 must traverse. Index order fails
  // (robot 2 cannot pass a parked robot); PBS orders robot 2 above robot 1 with one pair. Robot 2
  // arrives at 6 unhindered; robot 1 appears at (2,1) when robot 2 is at (3,1) (t = 3, touching)
  // and arrives at (3,1) at t = 4 (hand computed).
  const BinaryGrid g = grid({"@@@@@@@", ".......", "@@@@@@@"});
  const std::vector<SippRobot> robots{{1, {2, 1}, {3, 1}, 0.5, 1.0}, {2, {0, 1}, {6, 1}, 0.5, 1.0}};
  PrioritizedOptions po;
  po.max_restarts = 0;
  po.sipp.at_start = AtStart::kAppear;
  po.sipp.at_goal = AtGoal::kStay;
  EXPECT_FALSE(plan_prioritized(g, robots, {0, 1}, po).ok);
  PbsOptions o;
  o.sipp = po.sipp;
  const PbsResult r = plan_pbs(g, robots, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.priority_pairs, 1u);
  EXPECT_EQ(r.order, (std::vector<int>{1, 0}));
  EXPECT_NEAR(r.arrivals[1], 6.0, 1e-9);
  EXPECT_NEAR(r.arrivals[0], 4.0, 1e-6);
  std::vector<Trajectory> tr;
  for (const auto& p : r.plans)
    tr.push_back(trajectory_of(p, o.sipp.at_start, o.sipp.at_goal));
  const std::vector<double> radii{0.5, 0.5};
  EXPECT_TRUE(verify_trajectories(tr, radii).valid);
}

TEST(Pbs, EveryPlanPassesTheCheckerAndSolvesWhatPrioritizedSolves) {
  // Property: on random maps, whatever PBS returns is valid in continuous time and off the walls,
  // under every presence convention; and PBS solves every instance that prioritized planning in
  // the index order (with its restarts) solves.
  std::mt19937 rng(2119);
  int pp_solved = 0, pbs_solved = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const int n = 8;
    const auto [g, robots] = internal::random_sipp_instance(rng, 10, 8, 0.15, n);
    PbsOptions o;
    o.sipp.at_start = trial % 4 < 2 ? AtStart::kWait : AtStart::kAppear;
    o.sipp.at_goal = trial % 2 == 0 ? AtGoal::kStay : AtGoal::kLeave;
    o.max_nodes = 2000;
    PrioritizedOptions po;
    po.sipp = o.sipp;
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i)
      order[static_cast<std::size_t>(i)] = i;
    const bool pp = plan_prioritized(g, robots, order, po).ok;
    pp_solved += pp ? 1 : 0;
    const PbsResult r = plan_pbs(g, robots, o);
    if (pp) {
      EXPECT_TRUE(r.ok) << "trial " << trial << ": " << r.message;
    }
    if (!r.ok) continue;
    ++pbs_solved;
    std::vector<Trajectory> tr;
    std::vector<double> radii;
    for (int i = 0; i < n; ++i) {
      const auto& p = r.plans[static_cast<std::size_t>(i)];
      EXPECT_EQ(p.front().p, g.geometry().cell_center(robots[static_cast<std::size_t>(i)].start));
      EXPECT_EQ(p.back().p, g.geometry().cell_center(robots[static_cast<std::size_t>(i)].goal));
      tr.push_back(trajectory_of(p, o.sipp.at_start, o.sipp.at_goal));
      radii.push_back(0.5);
    }
    Verification v = verify_trajectories(tr, radii);
    EXPECT_TRUE(v.valid) << "trial " << trial;
    check_map(v, tr, radii, g);
    EXPECT_TRUE(v.wall_hits.empty()) << "trial " << trial;
    EXPECT_EQ(r.order.size(), static_cast<std::size_t>(n));
  }
  EXPECT_GE(pbs_solved, pp_solved);
  EXPECT_GE(pbs_solved, 8);
}

}  // namespace
}  // namespace voronav::coordination
