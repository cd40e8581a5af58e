#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/core/pose2.hpp"
#include "voronav/core/require.hpp"

namespace voronav {
namespace {

TEST(Pose2, ComposeInverseRoundTrip) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int i = 0; i < 200; ++i) {
    const Pose2 a{{u(rng), u(rng)}, u(rng)};
    const Pose2 id = a.compose(a.inverse());
    EXPECT_NEAR(id.position.x, 0.0, 1e-9);
    EXPECT_NEAR(id.position.y, 0.0, 1e-9);
    EXPECT_NEAR(id.yaw, 0.0, 1e-9);
    const Vec2 p{u(rng), u(rng)};
    const Vec2 back = a.inverse_transform(a.transform(p));
    EXPECT_NEAR(back.x, p.x, 1e-9);
    EXPECT_NEAR(back.y, p.y, 1e-9);
  }
}

TEST(Pose2, RotationIsCounterClockwise) {
  const Pose2 p{{1, 2}, std::numbers::pi / 2};
  const Vec2 w = p.transform({1, 0});
  EXPECT_NEAR(w.x, 1.0, 1e-12);
  EXPECT_NEAR(w.y, 3.0, 1e-12);
  EXPECT_NEAR(wrap_angle(3 * std::numbers::pi), std::numbers::pi, 1e-12);
  EXPECT_NEAR(wrap_angle(-std::numbers::pi), std::numbers::pi, 1e-12);
}

TEST(GridGeometry, WorldCellRoundTripWithOriginAndYaw) {
  GridGeometry g{40, 30, 0.05, {{-1.0, 2.0}, 0.3}};
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const Cell c{x, y};
      EXPECT_EQ(g.world_to_cell(g.cell_center(c)), c);
      EXPECT_EQ(g.cell_at(g.index(c)), c);
    }
  EXPECT_FALSE(g.world_to_cell({std::nan(""), 0.0}).has_value());
  EXPECT_FALSE(g.contains({40, 0}));
  EXPECT_FALSE(g.contains({0, -1}));
}

TEST(GridGeometry, CellCenterMatchesRosConvention) {
  // origin [-10, -5, 0], resolution 0.5: cell (0,0) spans [-10,-9.5] x [-5,-4.5].
  GridGeometry g{10, 10, 0.5, {{-10.0, -5.0}, 0.0}};
  const Vec2 c = g.cell_center({0, 0});
  EXPECT_DOUBLE_EQ(c.x, -9.75);
  EXPECT_DOUBLE_EQ(c.y, -4.75);
  EXPECT_EQ(g.world_to_cell({-9.99, -4.51}), (Cell{0, 0}));
  EXPECT_EQ(g.world_to_cell({-10.01, -4.51}), (Cell{-1, 0}));
}

TEST(GridMap, CheckedAccessAndErrors) {
  GridMap<int> m(3, 2, 7);
  EXPECT_EQ(m.at({2, 1}), 7);
  m[Cell{1, 1}] = 5;
  EXPECT_EQ(m[m.index({1, 1})], 5);
  EXPECT_THROW((void)m.at({3, 0}), Error);
  EXPECT_THROW(GridMap<int>(GridGeometry{2, 2, 0.0, {}}), Error);
  EXPECT_THROW(GridMap<int>(GridGeometry{2, 2, std::nan(""), {}}), Error);
  EXPECT_THROW(GridMap<int>(-1, 2), Error);
}

TEST(Error, MessageNamesSourceAndLine) {
  const Error e("a.yaml", 3, "resolution: expected a positive number");
  EXPECT_STREQ(e.what(), "a.yaml:3: resolution: expected a positive number");
  EXPECT_STREQ(Error("x.pgm", 0, "bad").what(), "x.pgm: bad");
}

TEST(Binarize, ThresholdAndUnknown) {
  OccupancyGrid g(4, 1);
  g[Cell{0, 0}] = kFree;
  g[Cell{1, 0}] = kOccupied;
  g[Cell{2, 0}] = kUnknown;
  g[Cell{3, 0}] = 49;
  const BinaryGrid b = binarize(g);
  EXPECT_EQ(b.values(), (std::vector<std::uint8_t>{0, 1, 1, 0}));
  const BinaryGrid b2 = binarize(g, {.occupied_threshold = 40, .unknown_is_blocked = false});
  EXPECT_EQ(b2.values(), (std::vector<std::uint8_t>{0, 1, 0, 1}));
}

TEST(LineCells, EndpointsAndConnectivity) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> u(-20, 20);
  for (int i = 0; i < 500; ++i) {
    const Cell a{u(rng), u(rng)}, b{u(rng), u(rng)};
    const auto cells = line_cells(a, b);
    ASSERT_FALSE(cells.empty());
    EXPECT_EQ(cells.front(), a);
    EXPECT_EQ(cells.back(), b);
    EXPECT_EQ(cells.size(),
              static_cast<std::size_t>(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) + 1));
    for (std::size_t k = 1; k < cells.size(); ++k) {
      EXPECT_LE(std::abs(cells[k].x - cells[k - 1].x), 1);
      EXPECT_LE(std::abs(cells[k].y - cells[k - 1].y), 1);
    }
  }
  EXPECT_EQ(line_cells({0, 0}, {3, 1}), (std::vector<Cell>{{0, 0}, {1, 0}, {2, 1}, {3, 1}}));
}

TEST(LineCells, VisitorCanStopEarly) {
  int n = 0;
  EXPECT_FALSE(for_each_line_cell(Cell{0, 0}, Cell{10, 0}, [&](Cell) { return ++n < 3; }));
  EXPECT_EQ(n, 3);
}

TEST(DiscCells, MatchesBruteForce) {
  for (double r : {0.0, 0.5, 1.0, 1.5, 2.3, 5.0, 7.9}) {
    const auto cells = disc_cells({3, -2}, r);
    std::set<Cell> got(cells.begin(), cells.end());
    EXPECT_EQ(got.size(), cells.size());
    std::set<Cell> want;
    for (int y = -12; y <= 12; ++y)
      for (int x = -12; x <= 12; ++x)
        if (x * x + y * y <= r * r) want.insert({3 + x, -2 + y});
    EXPECT_EQ(got, want) << "r=" << r;
  }
  EXPECT_TRUE(disc_cells({0, 0}, std::nan("")).empty());
  EXPECT_TRUE(disc_cells({0, 0}, -1).empty());
}

}  // namespace
}  // namespace voronav

TEST(Error, OptionChecksNameTheOptionAndRefuseNanAndInfinity) {
  EXPECT_NO_THROW(voronav::require_finite_nonneg("o.a", 0.0));
  EXPECT_NO_THROW(voronav::require_finite_positive("o.a", 1e-9));
  for (double bad : {-1e-12, std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      voronav::require_finite_nonneg("o.a", bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const voronav::Error& e) {
      EXPECT_EQ(e.source(), "o.a");
      EXPECT_NE(e.reason().find("expected a finite number >= 0"), std::string::npos);
    }
  }
  for (double bad : {0.0, -2.0, std::nan(""), -std::numeric_limits<double>::infinity()})
    EXPECT_THROW(voronav::require_finite_positive("o.b", bad), voronav::Error) << bad;
}
