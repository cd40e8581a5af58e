// Tests of the stall rule's "reachable unknown space remains" (internal/stall_rule.hpp, issue 14,
// stop 26), on hand-made 0.1 m grids.
#include "voronav/exploration/internal/stall_rule.hpp"

#include <gtest/gtest.h>

#include "voronav/core/error.hpp"

#include <vector>

namespace voronav::exploration::internal {
namespace {

GridGeometry geometry(int w, int h) {
  GridGeometry g;
  g.width = w;
  g.height = h;
  g.resolution = 0.1;
  return g;
}

// Two 2 x 2 m rooms joined by a door 0.6 m wide (x 1.9-2.1 m is the wall).
BinaryGrid two_rooms(int door_cells) {
  BinaryGrid b(geometry(41, 20), 0);
  for (int y = 0; y < 20; ++y) {
    b[Cell{0, y}] = b[Cell{40, y}] = 1;
    if (y < 10 - door_cells / 2 || y >= 10 - door_cells / 2 + door_cells) b[Cell{20, y}] = 1;
  }
  for (int x = 0; x < 41; ++x)
    b[Cell{x, 0}] = b[Cell{x, 19}] = 1;
  return b;
}

TEST(StallRule, ReachStopsAtADoorTooNarrowForTheRadius) {
  const std::vector<Vec2> start{{0.5, 1.0}};
  // A 0.6 m door passes a centre of clearance 0.22 m (the planning radius), not one of 0.35 m.
  const std::vector<char> wide = robot_reach(two_rooms(6), 0.22, start);
  const std::vector<char> narrow = robot_reach(two_rooms(6), 0.35, start);
  const BinaryGrid b = two_rooms(6);
  const std::size_t far = b.index(Cell{30, 10});
  EXPECT_EQ(wide[b.index(Cell{5, 10})], 1);
  EXPECT_EQ(wide[far], 1);
  EXPECT_EQ(narrow[b.index(Cell{5, 10})], 1);
  EXPECT_EQ(narrow[far], 0);
  EXPECT_EQ(wide[b.index(Cell{20, 5})], 0);  // a wall cell
}

TEST(StallRule, AThreeByThreeUnknownPatchCountsARayGapDoesNot) {
  const GridGeometry g = geometry(20, 20);
  const std::vector<char> reach(g.size(), 1);
  std::vector<float> known(g.size(), -2.0F);  // everything mapped free
  EXPECT_FALSE(unknown_patch_in_reach(g, reach, known));
  // A diagonal streak of unknown cells, one cell wide (rays that missed them) ...
  std::vector<float> streak = known;
  for (int k = 3; k < 15; ++k)
    streak[static_cast<std::size_t>(k * 20 + k)] = 0.0F;
  EXPECT_FALSE(unknown_patch_in_reach(g, reach, streak));
  // ... and a band two cells wide do not count; a 3 x 3 patch does.
  std::vector<float> band = known;
  for (int x = 2; x < 18; ++x)
    band[static_cast<std::size_t>(8 * 20 + x)] = band[static_cast<std::size_t>(9 * 20 + x)] = 0.0F;
  EXPECT_FALSE(unknown_patch_in_reach(g, reach, band));
  std::vector<float> patch = known;
  for (int y = 4; y < 7; ++y)
    for (int x = 11; x < 14; ++x)
      patch[static_cast<std::size_t>(y * 20 + x)] = 0.0F;
  EXPECT_TRUE(unknown_patch_in_reach(g, reach, patch));
  // Out of reach (the patch's centre cell not reachable), it does not count.
  std::vector<char> cut = reach;
  cut[static_cast<std::size_t>(5 * 20 + 12)] = 0;
  EXPECT_FALSE(unknown_patch_in_reach(g, cut, patch));
  EXPECT_THROW((void)unknown_patch_in_reach(geometry(5, 5), reach, patch), Error);
}

}  // namespace
}  // namespace voronav::exploration::internal
