// Tests of the stall recovery's target (unstick.hpp) on hand-made grids.
#include <gtest/gtest.h>

#include <cmath>

#include "voronav/exploration/unstick.hpp"
#include "voronav/field/distance_transform.hpp"

namespace voronav::exploration {
namespace {

// 40 x 20 cells of 0.1 m: a dead-end corridor (rows 9..11, columns 0..19) opening into a room
// (columns 20..39, all rows); everything else blocked.
BinaryGrid corridor_and_room() {
  BinaryGrid g(GridGeometry{40, 20, 0.1, {}}, 1);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x)
      if (x >= 20 || (y >= 9 && y <= 11)) g[Cell{x, y}] = 0;
  return g;
}

TEST(Unstick, LeavesADeadEndForTheNearestOpenPlace) {
  const BinaryGrid g = corridor_and_room();
  planning::BfsFlood flood;
  ASSERT_GT(flood.flood(g, Cell{1, 10}, planning::Connectivity::k8), 0u);
  const auto t = unstick_target(g, flood, field::distance_transform(g));
  ASSERT_TRUE(t.has_value());
  // Clearance 1 m (the cap) needs 10 cells from the walls at column 19 (and from the corridor's
  // corners at rows 8 and 12): first at column 29, 28 steps from column 1. The corridor's cells
  // have at most 0.2 m of clearance.
  EXPECT_EQ(t->x, 29);
  EXPECT_EQ(flood.steps(g, *t), 28);
  EXPECT_GE(field::distance_transform(g).distance_m(*t), 1.0 - 1e-9);
}

TEST(Unstick, TargetLiesBetweenTheMinimumAndMaximumPathLength) {
  const BinaryGrid g = corridor_and_room();
  planning::BfsFlood flood;
  ASSERT_GT(flood.flood(g, Cell{30, 10}, planning::Connectivity::k8), 0u);  // already in the open
  UnstickOptions o;
  o.min_path = 1.0;
  o.max_path = 2.0;
  const field::DistanceField clear = field::distance_transform(g);
  const auto t = unstick_target(g, flood, clear, o);
  ASSERT_TRUE(t.has_value());
  const int st = flood.steps(g, *t);
  EXPECT_GE(st, 10);  // never "stay where you are"
  EXPECT_LE(st, 20);
  // Too long a minimum: nothing that far is reachable (the room's far corner is 29 steps away).
  o.min_path = 3.5;
  o.max_path = 4.0;
  EXPECT_FALSE(unstick_target(g, flood, clear, o).has_value());
}

TEST(Unstick, BoxedInHasNoTarget) {
  BinaryGrid g = corridor_and_room();
  const field::DistanceField clear = field::distance_transform(g);  // the walls, not the robots
  // Other robots' discs (as block_robot_discs marks them) close the corridor on both sides.
  for (int y = 9; y <= 11; ++y) {
    g[Cell{3, y}] = 1;
    g[Cell{7, y}] = 1;
  }
  planning::BfsFlood flood;
  ASSERT_GT(flood.flood(g, Cell{5, 10}, planning::Connectivity::k8), 0u);
  EXPECT_FALSE(unstick_target(g, flood, clear).has_value());
}

}  // namespace
}  // namespace voronav::exploration
