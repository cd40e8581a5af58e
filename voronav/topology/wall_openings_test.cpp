#include "voronav/topology/wall_openings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "voronav/core/error.hpp"
#include "voronav/topology/topological_map.hpp"
#include "voronav/voronoi/test_maps.hpp"

namespace voronav::topology {
namespace {

using voronoi::testing::fill_rect;

// 0.05 m cells. A corridor (y 1..30, clearance 15) under a room (y 37..136), the wall between
// them (y 31..36, 6 cells) open over x 80..117 (38 cells = 1.9 m): wider than the corridor, so
// the clearance along the diagram has no minimum there (NLB's room open onto a corridor).
BinaryGrid room_open_onto_a_corridor() {
  BinaryGrid g(GridGeometry{302, 138, 0.05, {}}, 0);
  fill_rect(g, 0, 0, 301, 0);
  fill_rect(g, 0, 137, 301, 137);
  fill_rect(g, 0, 0, 0, 137);
  fill_rect(g, 301, 0, 301, 137);
  fill_rect(g, 1, 31, 300, 36);      // the wall between corridor and room
  fill_rect(g, 80, 31, 117, 36, 0);  // its opening
  fill_rect(g, 200, 37, 205, 136);   // the room ends at x = 199
  return g;
}

// A 100 x 100 room (x, y 1..100) whose lower part (y 1..49) and upper strip (y 56..85; above it
// walled off) are parted by a wall stub from the left wall (y 50..55, x 1..69): the gap between
// the stub's end and the right wall is x 70..100 (31 cells = 1.55 m). The strip is as narrow as
// the gap (NLB's rooms behind wall stubs).
BinaryGrid room_behind_a_wall_stub() {
  BinaryGrid g(GridGeometry{102, 102, 0.05, {}}, 0);
  fill_rect(g, 0, 0, 101, 0);
  fill_rect(g, 0, 0, 0, 101);
  fill_rect(g, 101, 0, 101, 101);
  fill_rect(g, 0, 86, 101, 101);  // above the strip
  fill_rect(g, 1, 50, 69, 55);    // the stub
  return g;
}

TEST(WallOpenings, SegmentsOfARectangularRoomAreItsFourWalls) {
  BinaryGrid g(GridGeometry{22, 12, 0.05, {}}, 1);
  fill_rect(g, 1, 1, 20, 10, 0);  // free 20 x 10
  const auto segs = wall_segments(g, 1.0, 1.0);
  ASSERT_EQ(segs.size(), 4U);
  double total = 0.0;
  for (const auto& s : segs) {
    total += s.length();
    EXPECT_TRUE(std::abs(s.length() - 20.0) < 1e-9 || std::abs(s.length() - 10.0) < 1e-9)
        << s.length();
  }
  EXPECT_NEAR(total, 60.0, 1e-9);
}

TEST(WallOpenings, GapBetweenCollinearWallFacesIsClosedOnTheWallsMiddleLine) {
  const BinaryGrid g = room_open_onto_a_corridor();
  const auto ops = find_wall_openings(g, WallOpeningOptions{});
  ASSERT_EQ(ops.size(), 1U);
  EXPECT_TRUE(ops[0].both_faces);
  EXPECT_FALSE(ops[0].wall_end);
  EXPECT_NEAR(ops[0].width_cells, 38.0, 0.5);
  // The first blocked cells left and right of the gap.
  EXPECT_EQ(std::min(ops[0].jambs[0].x, ops[0].jambs[1].x), 79);
  EXPECT_EQ(std::max(ops[0].jambs[0].x, ops[0].jambs[1].x), 118);
  ASSERT_EQ(ops[0].line.size(), 38U);
  for (const Cell c : ops[0].line) {
    EXPECT_GE(c.x, 80);
    EXPECT_LE(c.x, 117);
    EXPECT_TRUE(c.y == 33 || c.y == 34) << c;  // the wall's middle line (y 31..36)
  }
  // Off (max_width 0) or too narrow a range: none.
  WallOpeningOptions off;
  off.max_width = 0.0;
  EXPECT_TRUE(find_wall_openings(g, off).empty());
  WallOpeningOptions narrow;
  narrow.max_width = 1.8;
  EXPECT_TRUE(find_wall_openings(g, narrow).empty());
}

TEST(WallOpenings, OpenRoomFrontIsARegionBoundaryOnlyWithTheRule) {
  const BinaryGrid g = room_open_onto_a_corridor();
  const Cell corridor{150, 15}, room{100, 90};
  TopologyOptions without;
  without.wall_openings.max_width = 0.0;
  const TopologicalMap a = build_topological_map(g, without);
  EXPECT_EQ(a.region_of(corridor), a.region_of(room));  // no narrowing: one region
  const TopologicalMap b = build_topological_map(g);    // the rule is on by default
  EXPECT_NE(b.region_of(corridor), b.region_of(room));
  int wall_lines = 0;
  for (const auto& cp : b.critical_points)
    if (cp.wall_gap) {
      ++wall_lines;
      EXPECT_TRUE(cp.separates);
    }
  EXPECT_EQ(wall_lines, 1);
  // Every room cell is in the room's region, every corridor cell in the corridor's.
  for (int y = 37; y <= 136; ++y)
    for (int x = 1; x <= 199; ++x)
      ASSERT_EQ(b.region_of(Cell{x, y}), b.region_of(room)) << Cell{x, y};
  for (int y = 1; y <= 30; ++y)
    for (int x = 1; x <= 300; ++x)
      ASSERT_EQ(b.region_of(Cell{x, y}), b.region_of(corridor)) << Cell{x, y};
}

TEST(WallOpenings, WallStubPointingAtAWallClosesTheStripBehindIt) {
  const BinaryGrid g = room_behind_a_wall_stub();
  const auto ops = find_wall_openings(g, WallOpeningOptions{});
  ASSERT_EQ(ops.size(), 1U);
  EXPECT_TRUE(ops[0].wall_end);
  EXPECT_NEAR(ops[0].width_cells, 31.0, 1.0);
  EXPECT_EQ(ops[0].jambs[0].x, 69);   // the stub's end
  EXPECT_EQ(ops[0].jambs[1].x, 101);  // the right wall
  for (const Cell c : ops[0].line)
    EXPECT_TRUE(c.y == 52 || c.y == 53) << c;  // the stub's middle line (y 50..55)
  WallOpeningOptions no_ends;
  no_ends.wall_ends = false;
  EXPECT_TRUE(find_wall_openings(g, no_ends).empty());

  const Cell strip{30, 70}, room{30, 25};
  TopologyOptions without;
  without.wall_openings.max_width = 0.0;
  const TopologicalMap a = build_topological_map(g, without);
  EXPECT_EQ(a.region_of(strip), a.region_of(room));
  const TopologicalMap b = build_topological_map(g);
  EXPECT_NE(b.region_of(strip), b.region_of(room));
  for (int x = 1; x <= 100; ++x) {
    EXPECT_EQ(b.region_of(Cell{x, 60}), b.region_of(strip)) << x;  // the strip's full length
    EXPECT_EQ(b.region_of(Cell{x, 45}), b.region_of(room)) << x;
  }
}

TEST(WallOpenings, OptionsAreChecked) {
  const BinaryGrid g = room_open_onto_a_corridor();
  auto bad = [&](auto set) {
    WallOpeningOptions o;
    set(o);
    EXPECT_THROW((void)find_wall_openings(g, o), Error);
    TopologyOptions t;
    set(t.wall_openings);
    EXPECT_THROW((void)build_topological_map(g, t), Error);
  };
  bad([](WallOpeningOptions& o) { o.min_width = -1.0; });
  bad([](WallOpeningOptions& o) { o.max_width = 0.4; });  // below min_width 0.5
  bad([](WallOpeningOptions& o) { o.max_angle_deg = 90.0; });
  bad([](WallOpeningOptions& o) { o.max_wall_thickness = std::nan(""); });
}

}  // namespace
}  // namespace voronav::topology
