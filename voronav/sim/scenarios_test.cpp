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
