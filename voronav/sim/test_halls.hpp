// Test helper (not part of the library): the hand-made hall the netsim and Repair tests share,
// 30 m long, robots in two rows every 3.5 m, optionally with a block that closes the lower half
// of the hall on the route ahead of the source after the first route; and the check of a
// Table 7 change run that the netsim and scenario tests share.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <string>

#include "voronav/sim/netsim.hpp"

namespace voronav::sim::testing {

/// A hall of 150 x h cells at 0.2 m (2 cells of wall around), robots at y 2.5 and 5.5 m every
/// 3.5 m from x 1.5 m (the source is robot 0 at (1.5, 2.5)), destination (28.5, 2.5). With
/// block_after_route_s, that long after the first route a block closes x 20..20.8 m, y 0.4..4 m.
inline NetSimScenario two_row_hall(int h, std::optional<double> block_after_route_s) {
  const double res = 0.2;
  const int w = 150;
  NetSimScenario sc;
  sc.world = OccupancyGrid(GridGeometry{w, h, res, {}}, kOccupied);
  for (int y = 2; y < h - 2; ++y)
    for (int x = 2; x < w - 2; ++x)
      sc.world[Cell{x, y}] = kFree;
  for (double x = 1.5; x < 29.0; x += 3.5) {
    sc.robots.push_back({x, 2.5});
    sc.robots.push_back({x, 5.5});
  }
  sc.destination = {28.5, 2.5};
  if (block_after_route_s) {
    ObstacleChange ch;
    ch.after_route_s = *block_after_route_s;
    for (int y = 2; y < 20; ++y)
      for (int x = 100; x < 104; ++x)
        ch.cells.push_back({x, y});
    sc.changes.push_back(ch);
  }
  return sc;
}

/// Runs `sc` with each method (default options) and expects success and `n` obstacle changes
/// applied, all of them on the route ahead (`why` names the case in failure messages). Returns
/// the metrics {centralized, decentralized} for further checks.
inline std::array<NetSimMetrics, 2> expect_changes_met(const NetSimScenario& sc, int n,
                                                       const std::string& why) {
  std::array<NetSimMetrics, 2> out;
  for (Method m : {Method::kCentralized, Method::kDecentralized}) {
    NetSimOptions o;
    o.method = m;
    const auto r = run_netsim(sc, o).metrics;
    EXPECT_TRUE(r.success) << to_string(m);
    EXPECT_EQ(r.changes_applied, n) << to_string(m);
    EXPECT_EQ(r.changes_on_route, n) << to_string(m) << ": " << why;
    out[m == Method::kCentralized ? 0 : 1] = r;
  }
  return out;
}

}  // namespace voronav::sim::testing
