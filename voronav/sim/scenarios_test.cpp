// Change runs of Table 7 (scenarios.cpp, time_changes_on_routes): where no door that both sources
// drive through can close without cutting off the destination, the change is a partial block (a
// box put down on both routes), and both methods meet it on the route ahead (issue #13).
#include <gtest/gtest.h>

#include <algorithm>

#include "voronav/sim/scenarios.hpp"

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
  for (Method m : {Method::kCentralized, Method::kDecentralized}) {
    NetSimOptions o;
    o.method = m;
    const auto r = run_netsim(sc, o).metrics;
    EXPECT_TRUE(r.success) << to_string(m);
    EXPECT_EQ(r.changes_applied, 1) << to_string(m);
    EXPECT_EQ(r.changes_on_route, 1) << to_string(m) << ": the box is on the route ahead";
  }
}

}  // namespace
}  // namespace voronav::sim
