#include "voronav/field/distance_transform.hpp"

#include <gtest/gtest.h>

#include <random>

#include "voronav/core/internal/test_grids.hpp"

namespace voronav::field {
namespace {

using test::random_grid;

TEST(DistanceTransform, EqualsBruteForceOnRandomMaps) {
  std::mt19937 rng(42);
  for (int seed = 0; seed < 60; ++seed) {
    const int w = 1 + static_cast<int>(rng() % 40), h = 1 + static_cast<int>(rng() % 40);
    const double p = (seed % 6) * 0.05 + 0.005;
    for (bool border : {false, true}) {
      const BinaryGrid g = random_grid(rng, w, h, p);
      const DistanceField df = distance_transform(g, {.border_is_blocked = border});
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          double best = HUGE_VAL;
          for (int yy = 0; yy < h; ++yy)
            for (int xx = 0; xx < w; ++xx)
              if (g[Cell{xx, yy}]) best = std::min(best, double((x - xx) * (x - xx) + (y - yy) * (y - yy)));
          if (border) {
            best = std::min({best, double((x + 1) * (x + 1)), double((w - x) * (w - x)),
                             double((y + 1) * (y + 1)), double((h - y) * (h - y))});
          }
          const float got = df.squared_distance[Cell{x, y}];
          if (std::isinf(best)) {
            EXPECT_TRUE(std::isinf(got));
            EXPECT_EQ((df.nearest[Cell{x, y}]), kNoSite);
            continue;
          }
          ASSERT_EQ(got, static_cast<float>(best)) << x << "," << y << " seed " << seed;
          const std::int32_t n = df.nearest[Cell{x, y}];
          if (n != kNoSite) {  // the named site is a blocked cell at exactly that distance
            const Cell s = g.cell_at(static_cast<std::size_t>(n));
            EXPECT_TRUE(g[s]);
            EXPECT_EQ((s.x - x) * (s.x - x) + (s.y - y) * (s.y - y), static_cast<int>(best));
          } else {
            EXPECT_TRUE(border);
          }
        }
    }
  }
}

TEST(DistanceTransform, ATieGoesToTheLowerSiteOfTheColumn) {
  // One column, sites at rows 0 and 4: row 2 is 2 cells from both and names row 0 (the lower
  // parabola of the envelope), row 3 names row 4; a column without sites has none.
  BinaryGrid g(2, 7, 0);
  g[Cell{0, 0}] = 1;
  g[Cell{0, 4}] = 1;
  const DistanceField df = distance_transform(g);
  EXPECT_EQ((df.nearest[Cell{0, 2}]), static_cast<std::int32_t>(g.index(Cell{0, 0})));
  EXPECT_EQ((df.nearest[Cell{0, 3}]), static_cast<std::int32_t>(g.index(Cell{0, 4})));
  EXPECT_EQ((df.nearest[Cell{0, 6}]), static_cast<std::int32_t>(g.index(Cell{0, 4})));
  EXPECT_EQ((df.squared_distance[Cell{0, 2}]), 4.0f);
  EXPECT_EQ((df.squared_distance[Cell{0, 6}]), 4.0f);
  // Column 1 has no site: its cells take the nearest of column 0 through the row pass.
  EXPECT_EQ((df.nearest[Cell{1, 2}]), static_cast<std::int32_t>(g.index(Cell{0, 0})));
  EXPECT_EQ((df.squared_distance[Cell{1, 2}]), 5.0f);
}

TEST(DistanceTransform, EmptyAndAllFree) {
  const DistanceField e = distance_transform(BinaryGrid{});
  EXPECT_TRUE(e.squared_distance.empty());
  const DistanceField f = distance_transform(BinaryGrid(5, 4, 0));
  EXPECT_TRUE(std::isinf(f.squared_distance[Cell{2, 2}]));
}

TEST(Inflate, BlocksCellsCloserThanRadius) {
  BinaryGrid g(21, 21, 0, 0.1);
  g[Cell{10, 10}] = 1;
  const BinaryGrid inf = inflate(g, 0.3);  // 3 cells
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 21; ++x) {
      const int d2 = (x - 10) * (x - 10) + (y - 10) * (y - 10);
      EXPECT_EQ((inf[Cell{x, y}] != 0), (d2 < 9)) << x << "," << y;
    }
  EXPECT_EQ(inflate(g, 0.0), g);
  EXPECT_THROW((void)inflate(g, -1.0), Error);
  EXPECT_THROW((void)inflate(g, std::nan("")), Error);
}

TEST(Inflate, SmallRadiiGiveTheSameGridAsTheDistanceTransform) {
  // inflate() spreads blocked cells directly for radii up to 8 cells: the grid must be the one the
  // EDT definition gives (blocked, or squared distance < r^2), on random maps, at the grid's
  // edges, and for radii that are and are not whole cells (0.3 / 0.1 is just below 3 cells).
  std::mt19937 rng(7);
  int spread = 0;
  for (int seed = 0; seed < 80; ++seed) {
    const int w = 1 + static_cast<int>(rng() % 30), h = 1 + static_cast<int>(rng() % 30);
    const BinaryGrid cells = random_grid(rng, w, h, 0.02 + 0.5 * (seed % 5) / 4.0);
    BinaryGrid g(w, h, 0, 0.1);
    for (std::size_t i = 0; i < g.size(); ++i)
      g[i] = cells[i];
    const DistanceField df = distance_transform(g);
    for (double r : {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.45, 0.8, 0.85}) {
      const BinaryGrid inf = inflate(g, r);
      const double r2 = (r / 0.1) * (r / 0.1);
      for (std::size_t i = 0; i < g.size(); ++i) {
        const bool want = g[i] != 0 || static_cast<double>(df.squared_distance[i]) < r2;
        ASSERT_EQ(inf[i] != 0, want) << "seed " << seed << " r " << r << " cell " << i;
        spread += (want && g[i] == 0) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(spread, 1000);  // the radii did block free cells
}

}  // namespace
}  // namespace voronav::field
