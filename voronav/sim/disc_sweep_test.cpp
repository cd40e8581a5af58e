#include "voronav/sim/disc_sweep.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>

namespace voronav::sim {
namespace {

using CellSet = std::set<std::pair<int, int>>;

TEST(DiscSweep, VisitsTheUnionOfTheDiscsAlongTheLine) {
  // The cells visited must be exactly the union of for_each_disc_cell over the Bresenham cells
  // (what a check of every disc cell looks at), for radii of robots at 0.2, 0.1 and 0.05 m cells
  // and odd ones, on lines in every direction (steps of all 8 kinds).
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coord(-12, 12);
  int lines = 0;
  for (double radius : {-0.01, 0.0, 0.99, 1.0, 1.5, 1.99, 2.5, 3.99, 4.3}) {
    const DiscSweep sweep(radius);
    for (int k = 0; k < 60; ++k) {
      const Cell a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)};
      CellSet want, got;
      for_each_line_cell(a, b, [&](Cell c) {
        for_each_disc_cell(c, radius, [&](Cell d) { want.insert({d.x, d.y}); });
      });
      EXPECT_TRUE(sweep.visit(a, b, [&](Cell d) {
        got.insert({d.x, d.y});
        return true;
      }));
      ASSERT_EQ(got, want) << "radius " << radius << " from " << a.x << "," << a.y << " to " << b.x
                           << "," << b.y;
      ++lines;
    }
  }
  EXPECT_EQ(lines, 9 * 60);
  // The reach is the disc's extent, and a visit stops when told to.
  EXPECT_EQ(DiscSweep(3.99).reach(), (Cell{3, 3}));
  EXPECT_EQ(DiscSweep(-1.0).reach(), (Cell{0, 0}));
  int seen = 0;
  EXPECT_FALSE(DiscSweep(1.5).visit({0, 0}, {9, 4}, [&](Cell) { return ++seen < 5; }));
  EXPECT_EQ(seen, 5);
}

}  // namespace
}  // namespace voronav::sim
