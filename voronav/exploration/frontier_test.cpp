// Tests of the frontier baselines: frontier detection and the two assignment rules.
#include <gtest/gtest.h>

#include "voronav/core/error.hpp"
#include "voronav/exploration/frontier.hpp"
#include "voronav/planning/bfs.hpp"

namespace voronav::exploration {
namespace {

TEST(Frontier, KnownFreeNextToUnknown) {
  // 20 x 10 cells of 1 m: left half known free, right half unknown; one occupied column.
  OccupancyGrid map(GridGeometry{20, 10, 1.0, {}}, kUnknown);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      map[Cell{x, y}] = kFree;
  for (int y = 0; y < 4; ++y)
    map[Cell{9, y}] = kOccupied;
  const BinaryGrid trav = binarize(map);  // unknown blocked
  const auto fr = find_frontiers(map, trav);
  ASSERT_EQ(fr.size(), 1u);
  // Frontier cells: column 9 where free (rows 4..9) = 6 cells.
  EXPECT_EQ(fr[0].cells.size(), 6u);
  for (const Cell c : fr[0].cells)
    EXPECT_EQ(c.x, 9);
  EXPECT_NEAR(fr[0].centroid.x, 9.5, 1e-12);
  EXPECT_NEAR(fr[0].centroid.y, 7.0, 1e-12);
  EXPECT_EQ(trav[fr[0].target], 0);
  // Too small a cluster is dropped.
  FrontierOptions big;
  big.min_frontier_cells = 7;
  EXPECT_TRUE(find_frontiers(map, trav, big).empty());
  // Mismatched geometry.
  EXPECT_THROW((void)find_frontiers(map, BinaryGrid(3, 3)), Error);
  // A fully known map has no frontier.
  const OccupancyGrid known(GridGeometry{5, 5, 1.0, {}}, kFree);
  EXPECT_TRUE(find_frontiers(known, binarize(known)).empty());
}

std::vector<Frontier> at(std::initializer_list<Vec2> centroids) {
  std::vector<Frontier> f;
  for (Vec2 c : centroids) {
    Frontier x;
    x.centroid = c;
    x.cells.resize(10);
    f.push_back(x);
  }
  return f;
}

TEST(Frontier, NearestSendsEveryRobotToItsClosestFrontier) {
  const auto fr = at({{0, 0}, {10, 0}});
  // Both robots are closest to frontier 0: uncoordinated, both go there.
  const std::vector<std::vector<double>> costs{{1.0, 9.0}, {2.0, 8.0}};
  EXPECT_EQ(assign_nearest(fr, costs), (std::vector<int>{0, 0}));
  // Unreachable (-1) frontiers are skipped.
  EXPECT_EQ(assign_nearest(fr, {{-1.0, 9.0}, {-1.0, -1.0}}), (std::vector<int>{1, -1}));
}

TEST(Frontier, CoordinatedSpreadsTheRobots) {
  // Burgard 2005: after robot 0 takes frontier 0, frontier 0's utility drops to 0, so robot 1
  // takes frontier 1 although frontier 0 is nearer to it.
  const auto fr = at({{0, 0}, {10, 0}});
  const std::vector<std::vector<double>> costs{{1.0, 9.0}, {2.0, 8.0}};
  EXPECT_EQ(assign_coordinated(fr, costs), (std::vector<int>{0, 1}));
  // Frontiers within utility_radius of an assigned one lose utility: with two frontiers close
  // together (1 m apart, radius 3 m: P = 2/3) and one far, the second robot goes far.
  const auto fr3 = at({{0, 0}, {1, 0}, {20, 0}});
  const std::vector<std::vector<double>> c3{{1.0, 1.5, 20.0}, {1.2, 1.4, 12.0}};
  const auto a = assign_coordinated(fr3, c3);
  EXPECT_EQ(a[0], 0);
  EXPECT_EQ(a[1], 2);
  // More robots than frontiers: the extra robot still gets one.
  const auto one = at({{0, 0}});
  EXPECT_EQ(assign_coordinated(one, {{1.0}, {2.0}}), (std::vector<int>{0, 0}));
  EXPECT_EQ(assign_coordinated({}, {{}, {}}), (std::vector<int>{-1, -1}));
  FrontierOptions bad;
  bad.utility_radius = 0;
  EXPECT_THROW(bad.validate(), Error);
}

TEST(Frontier, InformationGainRanksTheCoordinatedAllocation) {
  // One robot, costs 2 and 6 m (normalised by 6). Burgard's utility 1: 1 - 2/6 > 1 - 6/6, so the
  // near frontier. With gains 0.1 and 0.9 (utilities 1/9 and 1): 1/9 - 1/3 < 1 - 1, the far one.
  const auto fr = at({{0, 0}, {10, 0}});
  const std::vector<std::vector<double>> costs{{2.0, 6.0}};
  EXPECT_EQ(assign_coordinated(fr, costs), (std::vector<int>{0}));
  const std::vector<double> gains{0.1, 0.9};
  EXPECT_EQ(assign_coordinated(fr, costs, {}, gains), (std::vector<int>{1}));
  const std::vector<double> wrong{0.5};
  EXPECT_THROW((void)assign_coordinated(fr, costs, {}, wrong), Error);
}

TEST(Frontier, RobotDiscsBlockACorridorAndAreRestored) {
  // A corridor 3 cells wide (0.1 m cells, 2 m long); a robot stands in its middle. With its
  // disc (radius 0.29 m = two body radii + 5 cm) blocked, the far end cannot be reached from
  // the near end; a robot out of range (> 3 m) blocks nothing; restoring gives the grid back.
  BinaryGrid g(GridGeometry{20, 5, 0.1, {}}, 1);
  for (int x = 0; x < 20; ++x)
    for (int y = 1; y <= 3; ++y)
      g[Cell{x, y}] = 0;
  const BinaryGrid before = g;
  const Vec2 self{0.05, 0.25}, blocker{1.05, 0.25}, far_away{1.05, 4.0};
  const std::vector<Vec2> others{blocker, far_away};
  planning::BfsFlood flood;
  ASSERT_GT(flood.flood(g, Cell{0, 2}, planning::Connectivity::k8), 0u);
  EXPECT_GE(flood.steps(g, Cell{19, 2}), 0);
  const std::vector<std::size_t> changed = block_robot_discs(g, self, others, 0.29, 3.0);
  // Free cells with centres within 0.29 m of (1.05, 0.25): columns 8..12 (dx <= 0.2 m) of the
  // 3 free rows (dy <= 0.1 m; 0.2^2 + 0.1^2 < 0.29^2); columns 7 and 13 are 0.3 m off: 15 cells.
  EXPECT_EQ(changed.size(), 15u);
  flood.flood(g, Cell{0, 2}, planning::Connectivity::k8);
  EXPECT_LT(flood.steps(g, Cell{19, 2}), 0);
  EXPECT_GE(flood.steps(g, Cell{7, 2}), 0);
  restore_free_cells(g, changed);
  EXPECT_EQ(g.data().size(), before.data().size());
  for (std::size_t k = 0; k < g.size(); ++k)
    EXPECT_EQ(g[k], before[k]) << k;
  // Out of range: nothing changes.
  EXPECT_TRUE(block_robot_discs(g, self, std::vector<Vec2>{far_away}, 0.29, 3.0).empty());
}

}  // namespace
}  // namespace voronav::exploration
