// SIPP and prioritized planning (issue #21): hand-computed waits, a swap that start delays cannot
// solve, parked robots, and every plan through the continuous-time checker.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "voronav/coordination/coordinator.hpp"
#include "voronav/coordination/internal/sipp_test_instances.hpp"
#include "voronav/coordination/prioritized.hpp"
#include "voronav/coordination/sipp.hpp"
#include "voronav/coordination/verify.hpp"

namespace voronav::coordination {
namespace {

/// A grid from rows of '.' (free) and '@' (blocked); row 0 is y = 0.
BinaryGrid grid(const std::vector<std::string>& rows) {
  BinaryGrid g(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
  for (int y = 0; y < g.geometry().height; ++y)
    for (int x = 0; x < g.geometry().width; ++x)
      g[Cell{x, y}] = rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] == '@';
  return g;
}

Vec2 centre(Cell c) {
  return {c.x + 0.5, c.y + 0.5};
}

Agent straight(int id, Cell a, Cell b) {
  return Agent{id, TimedPath({centre(a), centre(b)}, {1.0, kInfinity}), 0.5};
}

TEST(Sipp, CrossingWaitsInASafeInterval) {
  // A plus-shaped map: row 2 and column 2. A crosses first along the row; B goes up the column
  // and must wait: it may follow A's path no closer than 1 (the radii sum), so it departs the
  // last cell before the crossing at 1 + sqrt(2) and arrives at 4 + sqrt(2) (hand computed:
  // d^2 = u^2 + (u - c)^2 has minimum c^2 / 2 >= 1).
  const BinaryGrid g = grid({"@@.@@", "@@.@@", ".....", "@@.@@", "@@.@@"});
  const std::vector<SippRobot> robots{{1, {0, 2}, {4, 2}, 0.5, 1.0}, {2, {2, 0}, {2, 4}, 0.5, 1.0}};
  for (const AtGoal at_goal : {AtGoal::kStay, AtGoal::kLeave}) {
    PrioritizedOptions o;
    o.sipp.at_goal = at_goal;
    o.max_restarts = 0;
    const PrioritizedResult r = plan_prioritized(g, robots, {0, 1}, o);
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(r.arrivals[0], 4.0, 1e-9);
    EXPECT_NEAR(r.arrivals[1], 4.0 + std::sqrt(2.0), 1e-6);
    bool waited = false;
    for (std::size_t k = 1; k < r.plans[1].size(); ++k)
      waited |= r.plans[1][k].p == r.plans[1][k - 1].p;
    EXPECT_TRUE(waited);
    std::vector<Trajectory> tr;
    for (const auto& p : r.plans)
      tr.push_back(trajectory_of(p, AtStart::kWait, at_goal));
    const std::vector<double> radii{0.5, 0.5};
    const Verification v = verify_trajectories(tr, radii);
    EXPECT_TRUE(v.valid);
    EXPECT_NEAR(v.min_clearance, 0.0, 1e-6);  // B follows A at exactly the radii sum
  }
}

TEST(Sipp, CorridorSwapThatDelaysCannotSolve) {
  // A one-cell corridor with a pocket next to robot 1's start. On fixed paths the robots meet head
  // on: no start delay helps. SIPP lets robot 1 step into the pocket and wait.
  const BinaryGrid g = grid({"@.@@@@@", ".......", "@@@@@@@"});
  const std::vector<Agent> agents{straight(1, {0, 1}, {6, 1}), straight(2, {6, 1}, {0, 1})};
  const CoordinationResult delays = coordinate(agents);
  EXPECT_NE(delays.status, ResolveStatus::kOk);
  for (const AtStart at_start : {AtStart::kWait, AtStart::kAppear}) {
    for (const AtGoal at_goal : {AtGoal::kStay, AtGoal::kLeave}) {
      SippCoordinateOptions o;
      o.map.at_start = at_start;
      o.map.at_goal = at_goal;
      const SippCoordinationResult r = coordinate_sipp(g, agents, o);
      ASSERT_TRUE(r.plan.ok) << r.message;
      EXPECT_TRUE(r.valid);
      Verification walls;
      const std::vector<double> radii{0.5, 0.5};
      check_map(walls, r.trajectories, radii, g);
      EXPECT_TRUE(walls.valid);
      if (at_start == AtStart::kWait) {
        // Both are in the corridor from time 0: robot 1 must step into the pocket and let robot
        // 2 pass (after a restart if robot 1 was planned first).
        EXPECT_NEAR(r.plan.arrivals[1], 6.0, 1e-9);
        EXPECT_GT(r.plan.arrivals[0], 6.0);
      } else {
        // A robot may appear once the other has passed: at worst one after the other.
        EXPECT_LE(r.plan.makespan, 12.0 + 1e-9);
      }
    }
  }
}

TEST(Sipp, ParkedRobotIsNeverPassedUnderStay) {
  // Robot 1 parks in the middle of a corridor; robot 2 (lower priority) must pass it.
  const BinaryGrid g = grid({"@@@@@@@", ".......", "@@@@@@@"});
  const std::vector<SippRobot> robots{{1, {2, 1}, {3, 1}, 0.5, 1.0}, {2, {0, 1}, {6, 1}, 0.5, 1.0}};
  PrioritizedOptions o;
  o.max_restarts = 0;
  o.sipp.at_start = AtStart::kAppear;
  o.sipp.at_goal = AtGoal::kStay;
  const PrioritizedResult stay = plan_prioritized(g, robots, {0, 1}, o);
  EXPECT_FALSE(stay.ok);
  EXPECT_EQ(stay.failed, 1);
  o.sipp.at_goal = AtGoal::kLeave;  // robot 1 leaves the world at its goal: robot 2 passes
  const PrioritizedResult leave = plan_prioritized(g, robots, {0, 1}, o);
  ASSERT_TRUE(leave.ok);
  EXPECT_NEAR(leave.arrivals[1], 6.0, 1e-9);
}

TEST(Sipp, BadDeparturesOfAStaticDisc) {
  // Moving (0,0) -> (1,0) at speed 1 past a disc parked at (2,0) on [5, 10]: contact at the end
  // of the move (distance 1 = radii sum) is allowed, so no departure is bad.
  const Reservations::Segment parked{5.0, 10.0, {2.0, 0.0}, {0.0, 0.0}, 0.5};
  EXPECT_FALSE(bad_departures({0, 0}, {1, 0}, 1.0, 0.5, parked, 1e-7));
  // Parked at (1.5, 0) on [5, 10]: the move is closer than 1 for s in (0.5, 1], so departures
  // in (5 - 1, 10 - 0.5) are bad.
  const Reservations::Segment close{5.0, 10.0, {1.5, 0.0}, {0.0, 0.0}, 0.5};
  const auto iv = bad_departures({0, 0}, {1, 0}, 1.0, 0.5, close, 0.0);
  ASSERT_TRUE(iv);
  EXPECT_NEAR(iv->first, 4.0, 1e-12);
  EXPECT_NEAR(iv->second, 9.5, 1e-12);
}

TEST(Sipp, EveryPlanPassesTheChecker) {
  // Property: random maps and robots; whatever prioritized SIPP returns is valid in continuous
  // time and stays off the walls, under every presence convention.
  std::mt19937 rng(21);
  int solved = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int n = 8;
    auto [g, robots] = internal::random_sipp_instance(rng, 12, 10, 0.15, n);
    for (auto& r : robots) {
      r.radius = trial % 3 == 0 ? 0.35 : 0.5;
      r.v_max = trial % 2 == 0 ? 1.0 : 1.7;
    }
    PrioritizedOptions o;
    o.sipp.at_start = trial % 4 < 2 ? AtStart::kWait : AtStart::kAppear;
    o.sipp.at_goal = trial % 2 == 0 ? AtGoal::kStay : AtGoal::kLeave;
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i)
      order[static_cast<std::size_t>(i)] = i;
    const PrioritizedResult r = plan_prioritized(g, robots, order, o);
    if (!r.ok) continue;
    ++solved;
    std::vector<Trajectory> tr;
    std::vector<double> radii;
    for (int i = 0; i < n; ++i) {
      const auto& p = r.plans[static_cast<std::size_t>(i)];
      EXPECT_EQ(p.front().p, centre(robots[static_cast<std::size_t>(i)].start));
      EXPECT_EQ(p.back().p, centre(robots[static_cast<std::size_t>(i)].goal));
      tr.push_back(trajectory_of(p, o.sipp.at_start, o.sipp.at_goal));
      radii.push_back(robots[static_cast<std::size_t>(i)].radius);
    }
    Verification v = verify_trajectories(tr, radii);
    EXPECT_TRUE(v.valid) << "trial " << trial;
    check_map(v, tr, radii, g);
    EXPECT_TRUE(v.wall_hits.empty()) << "trial " << trial;
  }
  EXPECT_GE(solved, 12);
}

TEST(Sipp, DependencyOrderPutsStartsFirstAndGoalsLast) {
  // A corridor y = 1 from x = 0 to 8. Robot 0 goes 0 -> 8 along it. Robot 1 starts at x = 4 on
  // robot 0's path (it should leave first) and goes into the side cell (4, 0).
  // Robot 2's goal (6, 1) is on robot 0's path (robot 0 should pass first); it starts at (6, 2).
  const BinaryGrid g = grid({"@@@@.@@@@", ".........", "@@@@@@.@@"});
  const std::vector<SippRobot> robots{
      {1, {0, 1}, {8, 1}, 0.5, 1.0}, {2, {4, 1}, {4, 0}, 0.5, 1.0}, {3, {6, 2}, {6, 1}, 0.5, 1.0}};
  std::vector<Agent> agents;
  for (const auto& r : robots)
    agents.push_back(
        Agent{r.id, TimedPath({centre(r.start), centre(r.goal)}, {1.0, kInfinity}), 0.5});
  const IndividualBounds lb = individual_bounds(g, agents);
  ASSERT_EQ(lb.paths.size(), 3u);
  EXPECT_EQ(lb.paths[0].size(), 9u);
  EXPECT_NEAR(lb.travel[0], 8.0, 1e-12);
  // 1 before 0 (start), 0 before 2 (goal): the only order with both.
  EXPECT_EQ(dependency_order(g.geometry(), robots, lb, true, true), (std::vector<int>{1, 0, 2}));
  // Goal arcs only: 0 before 2; 1 is free and, with 0, has no predecessor: longer travel first.
  EXPECT_EQ(dependency_order(g.geometry(), robots, lb, false, true), (std::vector<int>{0, 1, 2}));
  // And the planned result is valid under wait/stay in that order without restarts.
  PrioritizedOptions o;
  o.max_restarts = 0;
  const PrioritizedResult r = plan_prioritized(g, robots, {1, 0, 2}, o);
  ASSERT_TRUE(r.ok);
  EXPECT_NEAR(r.arrivals[0], 8.0, 1e-9);
}

}  // namespace
}  // namespace voronav::coordination
