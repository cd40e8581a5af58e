// Change runs of Table 7 (scenarios.cpp, time_changes_on_routes): where no door that both sources
// drive through can close without cutting off the destination, the change is a partial block (a
// box put down on both routes), and both methods meet it on the route ahead (issue #13).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "voronav/sim/scenarios.hpp"
#include "voronav/sim/test_halls.hpp"

namespace voronav::sim {
namespace {

TEST(Scenarios, WithoutAClosableDoorTheChangeIsABoxOnBothRoutesInUse) {
  // Scenario 1, placement 2 (run 6): no door on both routes can close (the second pass had no
  // change in this run).
  const auto sc = make_paper_run(1, 6, 1);
  ASSERT_EQ(sc.changes.size(), 1u);
  const auto& cells = sc.changes[0].cells;
  ASSERT_FALSE(cells.empty());
  int x0 = cells[0].x, x1 = x0, y0 = cells[0].y, y1 = y0;
  for (Cell c : cells) {
    x0 = std::min(x0, c.x);
    x1 = std::max(x1, c.x);
    y0 = std::min(y0, c.y);
    y1 = std::max(y1, c.y);
  }
  const double res = sc.world.geometry().resolution;
  EXPECT_LE((x1 - x0 + 1) * res, 0.8 + 1e-9) << "a box of at most 0.8 m";
  EXPECT_LE((y1 - y0 + 1) * res, 0.8 + 1e-9);
  testing::expect_changes_met(sc, 1, "the box is on the route ahead");
}

// repair_rejoin_m (fourth pass of issue #13), on the run above: the source, 2 m before the box,
// sees only its front; the first route point after the blocked move, (23.9, 20.7), lies inside
// the box but its cell is still unknown to the source. Robot 5, which has not seen the box,
// answered the Repair with a detour that re-joins the route at that point; the source refused it
// (it runs into the box) and, with no other answer, passed the box on its own plan after
// repair_timeout_s: no Repair executed. With the break moved past the route points next to the
// block, robot 5's detour re-joins the route past the box and the source takes it.
TEST(Scenarios, TheBoxOfRunSixIsPassedByARepairThatReJoinsTheRoutePastIt) {
  const auto sc = make_paper_run(1, 6, 1);
  ASSERT_EQ(sc.changes.size(), 1u);
  for (double rejoin_m : {1.0, 0.0}) {
    NetSimOptions o;
    o.method = Method::kDecentralized;
    o.record = true;
    o.repair_rejoin_m = rejoin_m;
    // The rule alone: repair_fix_answer (stop 21) would repair the refused detour by A*.
    o.repair_fix_answer = false;
    const auto res = run_netsim(sc, o);
    const auto& r = res.metrics;
    ASSERT_TRUE(r.success) << "repair_rejoin_m " << rejoin_m;
    ASSERT_EQ(r.changes_on_route, 1);
    int taken = 0;
    for (const auto& e : res.recording.repairs)
      if (e.robot == 0 && e.executed && e.what.find("takes robot 5") != std::string::npos) ++taken;
    if (rejoin_m > 0.0) {
      EXPECT_EQ(taken, 1) << "robot 5's detour round the box is taken";
      EXPECT_EQ(r.repairs_executed, 1);
    } else {
      EXPECT_EQ(taken, 0) << "robot 5's detour re-joins inside the box: refused";
      EXPECT_EQ(r.repairs_executed, 0);
    }
  }
}

}  // namespace
}  // namespace voronav::sim

namespace voronav::sim {
namespace {

/// A 30 x 14 m hall split by a block (x 6..24 m, y 6..10 m) into a lower corridor, the straight
/// way from the source (3, 4) to the destination (27, 4), and an upper one. Robots stand only in
/// the upper corridor and at its ends, so the relays know the upper way and nobody has sensed the
/// lower one: the decentralized route goes up, while the centralized source plans through the
/// unknown lower corridor (unknown counts as free) and drives straight. The two routes share no
/// door (there is none) and no place ahead of both sources.
OfficeWorld two_corridor_hall() {
  OfficeWorld w;
  w.grid = OccupancyGrid(GridGeometry{150, 70, 0.2, {}}, kOccupied);
  for (int y = 2; y < 68; ++y)
    for (int x = 2; x < 148; ++x) {
      const bool block = x >= 30 && x < 120 && y >= 30 && y < 50;
      w.grid[Cell{x, y}] = block ? kOccupied : kFree;
    }
  return w;
}

NetSimScenario two_corridor_scenario(const OfficeWorld& w) {
  NetSimScenario sc;
  sc.world = w.grid;
  sc.robots = {{3.0, 4.0}, {3.0, 8.0}, {27.0, 6.5}, {27.0, 10.0}};
  for (double x = 6.0; x < 25.0; x += 3.5)
    sc.robots.push_back({x, 11.8});
  sc.source = 0;
  sc.destination = {27.0, 4.0};
  return sc;
}

// Issue #13: where the two methods' routes share no place (s3 runs 7, 11, 15 had no change), the
// Table 7 change is a pair, one on each method's route, at the same times and places for both
// methods. Without the pair rule this hall gets no change at all.
TEST(Scenarios, WhereTheRoutesShareNoPlaceEachMethodsRouteGetsOneOfAPair) {
  const auto w = two_corridor_hall();
  auto sc = two_corridor_scenario(w);
  time_changes_on_routes(w, sc, 1, 4.0, 0.2);
  ASSERT_EQ(sc.changes.size(), 2u) << "a pair: one change on each route";
  for (const auto& ch : sc.changes) {
    EXPECT_GE(ch.at_s, 0.0);
    EXPECT_LT(ch.centralized_at_s, 0.0) << "no time of its own for the centralized method";
    // Identical times for both methods: due at the same step, not a step before.
    for (Method m : {Method::kCentralized, Method::kDecentralized}) {
      EXPECT_TRUE(changes_due(sc, 1.0, ch.at_s - 0.2, 0, m).size() < sc.changes.size());
      EXPECT_FALSE(changes_due(sc, 1.0, ch.at_s, 0, m).empty());
    }
  }
  EXPECT_LE(sc.changes[0].at_s, sc.changes[1].at_s);
  // One entry on the straight way along y = 4 m (the centralized route), the other off it, on
  // the decentralized source's way up to the upper corridor.
  auto mean_y = [&](const ObstacleChange& ch) {
    double y = 0.0;
    for (Cell c : ch.cells)
      y += sc.world.geometry().cell_center(c).y;
    return y / static_cast<double>(ch.cells.size());
  };
  const double lo = std::min(mean_y(sc.changes[0]), mean_y(sc.changes[1]));
  const double hi = std::max(mean_y(sc.changes[0]), mean_y(sc.changes[1]));
  EXPECT_NEAR(lo, 4.0, 0.5) << "on the centralized route";
  EXPECT_GT(hi, 5.5) << "off the centralized route";
  for (Method m : {Method::kCentralized, Method::kDecentralized}) {
    NetSimOptions o;
    o.method = m;
    const auto r = run_netsim(sc, o).metrics;
    EXPECT_TRUE(r.success) << to_string(m);
    EXPECT_EQ(r.changes_applied, 2) << to_string(m);
    EXPECT_GE(r.changes_on_route, 1) << to_string(m) << ": the entry on its route is met";
  }
}

}  // namespace
}  // namespace voronav::sim
