// Tests of a target's information gain (internal/information_gain.hpp) on hand-made 11 x 11 maps
// of 1 m cells, radius 3 m: the disc holds 29 cells (the lattice points with dx² + dy² <= 9).
#include "voronav/exploration/internal/information_gain.hpp"

#include <gtest/gtest.h>

namespace voronav::exploration::internal {
namespace {

constexpr double kRadius = 3.0;
constexpr double kDisc = 29.0;

OccupancyGrid free_map() {
  return OccupancyGrid(GridGeometry{11, 11, 1.0, {}}, kFree);
}
Vec2 centre_of(const OccupancyGrid& m, Cell c) {
  return m.geometry().cell_center(c);
}

TEST(InformationGain, TheHollowOfAClosedObstacleDoesNotCount) {
  OccupancyGrid m = free_map();
  for (int y = 4; y <= 6; ++y)
    for (int x = 6; x <= 8; ++x)
      m[Cell{x, y}] = kOccupied;
  m[Cell{7, 5}] = kUnknown;  // the hollow, 2 cells from the target
  const Vec2 p = centre_of(m, {5, 5});
  EXPECT_DOUBLE_EQ(information_gain(m, p, kRadius, false), 1.0 / kDisc);
  EXPECT_DOUBLE_EQ(information_gain(m, p, kRadius, true), 0.0);
  // An unknown cell in the open, 3 cells away, counts both ways.
  m[Cell{5, 8}] = kUnknown;
  EXPECT_DOUBLE_EQ(information_gain(m, p, kRadius, false), 2.0 / kDisc);
  EXPECT_DOUBLE_EQ(information_gain(m, p, kRadius, true), 1.0 / kDisc);
}

TEST(InformationGain, UnknownBehindAWallCountsOnlyWithAWayRoundInsideTheRadius) {
  OccupancyGrid m = free_map();
  m[Cell{5, 8}] = kUnknown;
  for (int x = 3; x <= 7; ++x)
    m[Cell{x, 7}] = kOccupied;  // the ways round, (2, 7) and (8, 7), lie outside the disc
  const Vec2 p = centre_of(m, {5, 5});
  EXPECT_DOUBLE_EQ(information_gain(m, p, kRadius, false), 1.0 / kDisc);
  EXPECT_DOUBLE_EQ(information_gain(m, p, kRadius, true), 0.0);
  m[Cell{5, 7}] = kUnknown;  // a gap in the wall below it: both unknown cells are reached
  EXPECT_DOUBLE_EQ(information_gain(m, p, kRadius, true), 2.0 / kDisc);
}

TEST(InformationGain, OffTheMapCountsOnlyAsUnknownWithoutTheOption) {
  const OccupancyGrid m = free_map();
  const Vec2 corner = centre_of(m, {0, 0});
  // In the disc around (0, 0), the 11 cells with dx >= 0 and dy >= 0 are on the map.
  EXPECT_DOUBLE_EQ(information_gain(m, corner, kRadius, false), (kDisc - 11.0) / kDisc);
  EXPECT_DOUBLE_EQ(information_gain(m, corner, kRadius, true), 0.0);
  EXPECT_DOUBLE_EQ(information_gain(m, {-5.0, -5.0}, kRadius, true), 0.0);  // off the map
}

}  // namespace
}  // namespace voronav::exploration::internal
