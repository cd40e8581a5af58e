#include "voronav/topology/segmentation.hpp"

#include <gtest/gtest.h>

#include "voronav/core/error.hpp"
#include "voronav/io/floorplan.hpp"
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

// A real floor plan from the bundled data (ipa_room_segmentation, Freiburg52_scan, 643 x 354): the
// issue asks for recall and precision above the published 95.0 % / 94.8 %.
TEST(Segmentation, RealFloorPlanBeatsThePublishedVoronoiSegmentation) {
  const std::string dir = std::string(VORONAV_SOURCE_DIR) + "/data/floorplans/";
  io::FloorplanOptions fo;
  fo.occupied_below = 250;
  fo.free_from = 250;
  const BinaryGrid map = binarize(io::load_floorplan(dir + "Freiburg52_scan.png", fo));
  const BinaryGrid truth =
      binarize(io::load_floorplan(dir + "Freiburg52_scan_gt_segmentation.png", fo));
  const TopologicalMap m = build_topological_map(map);
  const SegmentationScores s = segmentation_scores(m.region, free_components(truth), 400);
  EXPECT_EQ(s.rooms, 10);
  EXPECT_GT(s.recall, 0.95);
  EXPECT_GT(s.precision, 0.95);
  EXPECT_GE(m.edges.size(), 9U);  // a connected building: at least rooms - 1 doors
}

}  // namespace
}  // namespace voronav::topology
