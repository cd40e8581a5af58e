// Tests of the stall recovery's target (unstick.hpp) on hand-made grids.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// unstick_target scans only the flood's reached cells (BfsFlood::reached), so that list must be
// exactly the cells with a step count, in non-decreasing step order, the start first.
TEST(Unstick, FloodListsExactlyTheReachedCellsInStepOrder) {
  BinaryGrid g = corridor_and_room();
  for (int y = 9; y <= 11; ++y)
    g[Cell{7, y}] = 1;  // cut the corridor: columns 0..6 are not reached from the room
  planning::BfsFlood flood;
  const std::size_t n = flood.flood(g, Cell{30, 10}, planning::Connectivity::k8);
  const auto reached = flood.reached();
  ASSERT_EQ(reached.size(), n);
  ASSERT_EQ(n, 20u * 20u + 12u * 3u);  // the room and corridor columns 8..19
  EXPECT_EQ(g.cell_at(static_cast<std::size_t>(reached[0])), (Cell{30, 10}));
  std::size_t with_steps = 0;
  for (std::size_t k = 0; k < g.size(); ++k)
    with_steps += flood.steps(g, g.cell_at(k)) >= 0 ? 1 : 0;
  EXPECT_EQ(with_steps, n);
  for (std::size_t k = 1; k < reached.size(); ++k)
    ASSERT_LE(flood.steps(g, g.cell_at(static_cast<std::size_t>(reached[k - 1]))),
              flood.steps(g, g.cell_at(static_cast<std::size_t>(reached[k]))));
  // A blocked start reaches nothing, and the list says so.
  EXPECT_EQ(flood.flood(g, Cell{0, 0}, planning::Connectivity::k8), 0u);
  EXPECT_TRUE(flood.reached().empty());
}

// Equal clearance and equal path length: the lower cell index wins (the rule of the whole-grid
// scan this replaced, which met cells in index order). 41 x 41 cells of 0.1 m with a blocked
// border, start in the middle: every cell 10 steps away with >= 1 m clearance ties; the lowest
// index among them is (10, 10) (1 m from the walls at x = 0 and y = 0).
TEST(Unstick, TiesGoToTheLowerCellIndex) {
  BinaryGrid g(GridGeometry{41, 41, 0.1, {}}, 0);
  for (int k = 0; k < 41; ++k) {
    g[Cell{k, 0}] = g[Cell{k, 40}] = 1;
    g[Cell{0, k}] = g[Cell{40, k}] = 1;
  }
  planning::BfsFlood flood;
  ASSERT_GT(flood.flood(g, Cell{20, 20}, planning::Connectivity::k8), 0u);
  const auto t = unstick_target(g, flood, field::distance_transform(g));
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, (Cell{10, 10}));
}

// The scan of the reached cells picks the same target as a scan of the whole grid in index order
// (the implementation it replaced), on random grids with random options.
TEST(Unstick, SameTargetAsAWholeGridScan) {
  std::mt19937 rng(14);
  planning::BfsFlood flood;
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    BinaryGrid g(GridGeometry{40, 30, 0.1, {}}, 0);
    for (std::size_t k = 0; k < g.size(); ++k)
      g[k] = static_cast<std::uint8_t>(rng() % 100 < 25 ? 1 : 0);
    const Cell start{static_cast<int>(rng() % 40), static_cast<int>(rng() % 30)};
    g[start] = 0;
    if (flood.flood(g, start, planning::Connectivity::k8) == 0) continue;
    const field::DistanceField clear = field::distance_transform(g);
    UnstickOptions o;
    o.min_path = 0.1 * static_cast<double>(rng() % 10);
    o.max_path = o.min_path + 0.1 * static_cast<double>(rng() % 20);
    o.clearance_cap = 0.1 + 0.1 * static_cast<double>(rng() % 5);
    // Reference: every cell in index order, the first best kept.
    const auto lo = static_cast<std::int32_t>(std::ceil(o.min_path / 0.1 - 1e-9));
    const auto hi = static_cast<std::int32_t>(std::floor(o.max_path / 0.1 + 1e-9));
    std::optional<Cell> want;
    double best_clear = -1.0;
    std::int32_t best_steps = 0;
    for (std::size_t k = 0; k < g.size(); ++k) {
      const Cell c = g.cell_at(k);
      const std::int32_t st = flood.steps(g, c);
      if (st < lo || st > hi) continue;
      const double cl = std::min(o.clearance_cap, clear.distance_m(c));
      if (cl > best_clear + 1e-9 || (std::abs(cl - best_clear) <= 1e-9 && st < best_steps)) {
        want = c;
        best_clear = cl;
        best_steps = st;
      }
    }
    const std::optional<Cell> got = unstick_target(g, flood, clear, o);
    ASSERT_EQ(got.has_value(), want.has_value()) << "trial " << trial;
    if (want) {
      EXPECT_EQ(*got, *want) << "trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(compared, 20);
}

}  // namespace
}  // namespace voronav::exploration

namespace voronav::exploration {
namespace {

// ExplorationOptions::clear_way_out (issue 14, stop 27): which robots stand in a stuck robot's
// way out. Way (0, 0) -> (2, 0) -> (2, 2), reach 0.29 m (two body radii + 5 cm).
TEST(ClearWayOut, RobotsWhoseDiscsTouchTheWay) {
  const std::vector<Vec2> way{{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}};
  const std::vector<Vec2> robots{
      {1.0, 0.2},    // 0: 0.2 m beside the first leg
      {1.0, 0.35},   // 1: 0.35 m beside it: not in the way
      {2.25, 1.0},   // 2: 0.25 m beside the second leg
      {-0.2, 0.1},   // 3: behind the start, 0.224 m from it
      {2.0, 2.3},    // 4: 0.3 m beyond the end: not in the way
      {2.15, -0.2},  // 5: 0.25 m from the corner (2, 0)
      {0.5, -0.3}};  // 6: exactly 0.3 m from the first leg: not in the way
  EXPECT_EQ(robots_in_way(way, robots, 0.29), (std::vector<std::size_t>{0, 2, 3, 5}));
  EXPECT_EQ(robots_in_way(way, robots, 0.31), (std::vector<std::size_t>{0, 2, 3, 4, 5, 6}));
  // A way of one point (the robot stands at its target): the disc around it.
  EXPECT_EQ(robots_in_way({{1.0, 0.0}}, robots, 0.29), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(robots_in_way({}, robots, 0.29).empty());
}

}  // namespace
}  // namespace voronav::exploration
