#include "voronav/topology/segmentation.hpp"

#include <gtest/gtest.h>

#include "voronav/core/error.hpp"
#include "voronav/topology/topological_map.hpp"
#include "voronav/voronoi/test_maps.hpp"

namespace voronav::topology {
namespace {

TEST(Segmentation, HandComputedScores) {
  // 1 x 10 strip: rooms [0..5] and [6..9]; regions [0..3] and [4..9].
  GridMap<std::int32_t> rooms(10, 1, 0), regions(10, 1, 0);
  for (int x = 6; x < 10; ++x)
    rooms[Cell{x, 0}] = 1;
  for (int x = 4; x < 10; ++x)
    regions[Cell{x, 0}] = 1;
  const SegmentationScores s = segmentation_scores(regions, rooms);
  EXPECT_EQ(s.rooms, 2);
  EXPECT_EQ(s.regions, 2);
  EXPECT_DOUBLE_EQ(s.recall, (4.0 / 6.0 + 4.0 / 4.0) / 2.0);
  EXPECT_DOUBLE_EQ(s.precision, (4.0 / 4.0 + 4.0 / 6.0) / 2.0);
  EXPECT_DOUBLE_EQ(segmentation_scores(rooms, rooms).recall, 1.0);
  // Ignoring rooms under 5 cells leaves room 0 (6 cells) only, and region 1 overlaps it by 2.
  const SegmentationScores big = segmentation_scores(regions, rooms, 5);
  EXPECT_EQ(big.rooms, 1);
  EXPECT_EQ(big.regions, 2);
  EXPECT_DOUBLE_EQ(big.recall, 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(big.precision, (4.0 / 4.0 + 2.0 / 2.0) / 2.0);
  EXPECT_THROW((void)segmentation_scores(rooms, GridMap<std::int32_t>(3, 1, 0)), Error);
}

TEST(Segmentation, TwoRoomsAreSegmentedPerfectly) {
  const BinaryGrid g = voronoi::testing::two_rooms(30, 24, 4);
  BinaryGrid truth = g;  // the ground truth closes the door
  voronoi::testing::fill_rect(truth, 31, 0, 31, 25);
  const GridMap<std::int32_t> rooms = free_components(truth);
  const TopologicalMap m = build_topological_map(g);
  const SegmentationScores s = segmentation_scores(m.region, rooms);
  EXPECT_EQ(s.rooms, 2);
  EXPECT_EQ(s.regions, 2);
  EXPECT_DOUBLE_EQ(s.recall, 1.0);
  EXPECT_DOUBLE_EQ(s.precision, 1.0);
}

}  // namespace
}  // namespace voronav::topology
