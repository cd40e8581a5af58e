#include "voronav/network/voronoi_points.hpp"

#include <gtest/gtest.h>

#include <random>

#include "voronav/core/error.hpp"

namespace voronav::network {
namespace {

// A known disc of radius R cells around the centre of an otherwise unknown map.
OccupancyGrid sensed_disc(int size, double radius_cells, double res) {
  OccupancyGrid m(GridGeometry{size, size, res, {}}, kUnknown);
  const Cell c{size / 2, size / 2};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double dx = x - c.x, dy = y - c.y;
      if (dx * dx + dy * dy <= radius_cells * radius_cells) m[Cell{x, y}] = kFree;
    }
  return m;
}

TEST(VoronoiPoints, OpenDiscGivesOneCentralPointWithItsRadius) {
  const auto m = sensed_disc(41, 15, 0.2);
  const auto vp = make_voronoi_points(m, {.robot_radius_m = 0.2});
  ASSERT_GE(vp.open.size(), 1u);
  const Vec2 centre = m.geometry().cell_center(Cell{20, 20});
  EXPECT_LT(distance(vp.open[0].position, centre), 0.3);
  EXPECT_NEAR(vp.open[0].clearance, 3.0, 0.25);
  EXPECT_GT(vp.cells_processed, 0u);
  // The compression of section 3.4: a few points instead of ~1300 cells.
  EXPECT_LT(points_payload_bytes(vp.open.size(), vp.close.size()) * 5, grid_payload_bytes(m));
}

TEST(VoronoiPoints, CorridorPointsChainAlongTheCorridor) {
  // A 1.2 m wide (6 cells) known corridor, 10 m long, walls above and below.
  OccupancyGrid m(GridGeometry{54, 12, 0.2, {}}, kUnknown);
  for (int x = 1; x < 53; ++x) {
    m[Cell{x, 2}] = kOccupied;
    m[Cell{x, 9}] = kOccupied;
    for (int y = 3; y < 9; ++y)
      m[Cell{x, y}] = kFree;
  }
  const double r = 0.2;
  const auto vp = make_voronoi_points(m, {.robot_radius_m = r});
  ASSERT_GE(vp.open.size(), 2u);
  for (const auto& p : vp.open) {
    EXPECT_NEAR(p.position.y, 1.2, 0.15) << "on the centre line";
    EXPECT_GT(p.clearance, r);
  }
  // The open points connect end to end.
  std::vector<double> start(vp.open.size(), std::numeric_limits<double>::infinity());
  std::size_t left = 0, right = 0;
  for (std::size_t i = 0; i < vp.open.size(); ++i) {
    if (vp.open[i].position.x < vp.open[left].position.x) left = i;
    if (vp.open[i].position.x > vp.open[right].position.x) right = i;
  }
  start[left] = 0.0;
  const auto s = search_points(vp.open, start, r);
  EXPECT_TRUE(std::isfinite(s.cost[right]));
  EXPECT_GT(vp.open[right].position.x - vp.open[left].position.x, 7.0);
  // Consecutive points are about (c - r) * 2 - one cell apart, not one per skeleton cell.
  EXPECT_LT(vp.open.size(), 30u);
}

TEST(VoronoiPoints, NarrowGapHasNoOpenPoint) {
  OccupancyGrid m(GridGeometry{30, 30, 0.2, {}}, kFree);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x)
      if (x != 15) m[Cell{x, y}] = kOccupied;  // a 1-cell slit, too narrow for r = 0.2
  const auto vp = make_voronoi_points(m, {.robot_radius_m = 0.2});
  EXPECT_TRUE(vp.open.empty());
}

TEST(VoronoiPoints, ContinuityRuleIsTheDiscOverlap) {
  const VoronoiPoint a{{0, 0}, 1.0f, 0};
  const VoronoiPoint b{{1.6, 0}, 1.0f, 0};
  EXPECT_TRUE(continues(a, b, 0.2));
  EXPECT_FALSE(continues(a, VoronoiPoint{{1.7, 0}, 1.0f, 0}, 0.2));
  EXPECT_FALSE(continues(a, VoronoiPoint{{0.1, 0}, 0.15f, 0}, 0.2));
}

TEST(VoronoiPoints, SearchFindsShortestChain) {
  std::vector<VoronoiPoint> pts{
      {{0, 0}, 1, 0}, {{1.5, 0}, 1, 0}, {{3, 0}, 1, 0}, {{1.5, 1.2}, 1, 0}};
  std::vector<double> start{0, INFINITY, INFINITY, INFINITY};
  const auto s = search_points(pts, start, 0.2);
  EXPECT_NEAR(s.cost[2], 3.0, 1e-9);
  EXPECT_EQ(trace_points(s, 2), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_NEAR(route_length(pts), 1.5 + 1.5 + std::hypot(1.5, 1.2), 1e-9);
}

TEST(VoronoiPoints, BadInputIsRejected) {
  OccupancyGrid m(4, 4, kFree);
  EXPECT_THROW((void)make_voronoi_points(m, {.robot_radius_m = -1}), Error);
  EXPECT_THROW((void)make_voronoi_points(m, {.robot_radius_m = std::nan("")}), Error);
  EXPECT_TRUE(make_voronoi_points(OccupancyGrid{}).open.empty());
  std::vector<VoronoiPoint> pts(2);
  std::vector<double> start(1, 0.0);
  EXPECT_THROW((void)search_points(pts, start, 0.2), Error);
}

TEST(VoronoiPoints, ClearanceAtMatchesDistanceToUnknown) {
  const auto m = sensed_disc(41, 15, 0.2);
  EXPECT_NEAR(clearance_at(m, m.geometry().cell_center(Cell{20, 20})), 3.0, 0.25);
  EXPECT_EQ(clearance_at(m, {-5, -5}), 0.0);
}

// The grid-bucketed search is an optimisation only: on random point sets (clustered, with
// duplicates, points that cannot continue anything, bounded extra edges and long unbounded ones)
// it must give the all-pairs search's costs, parents and work, and ask the extra edge about every
// pair the all-pairs search asks about that can be true.
TEST(VoronoiPoints, BucketedSearchEqualsAllPairsSearch) {
  const double r = 0.2;
  std::size_t reached_total = 0, fewer_candidates = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::size_t n = 1 + rng() % 250;
    const double side = 2.0 + 60.0 * u(rng);
    const double cmax = 0.1 + 3.0 * u(rng);
    std::vector<VoronoiPoint> pts;
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0 && rng() % 8 == 0) {  // a duplicate, as merged Searches carry
        pts.push_back(pts[rng() % i]);
        continue;
      }
      Vec2 p{side * u(rng), side * u(rng)};
      if (seed % 3 == 0) p = p * 0.1 + Vec2{100.0, -50.0};  // a tight cluster off the origin
      pts.push_back({p, static_cast<float>(cmax * u(rng)), 0.0f});
    }
    std::vector<double> start(n, std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < 1 + rng() % 3; ++k)
      start[rng() % n] = 2.0 * u(rng);
    const double bound = seed % 4 == 0 ? 0.0 : 6.0 * u(rng);
    BoundedExtraEdges extra;
    extra.max_distance_m = bound;
    if (seed % 2 == 0) {  // the edge joins only points of a range (a robot's own points)
      extra.range_begin = rng() % n;
      extra.range_end = extra.range_begin + rng() % (n - extra.range_begin + 1);
    }
    for (std::size_t k = 0; k < rng() % 20 && n > 1; ++k)
      extra.unbounded_pairs.emplace_back(rng() % n, rng() % n);
    auto is_long = [&](std::size_t i, std::size_t j) {
      for (const auto& [a, b] : extra.unbounded_pairs)
        if ((a == i && b == j) || (a == j && b == i)) return true;
      return false;
    };
    std::size_t asked_plain = 0, asked_bucketed = 0;
    std::size_t* asked = &asked_plain;
    auto edge = [&](std::size_t i, std::size_t j) {
      if (is_long(i, j)) {
        ++*asked;
        return true;
      }
      const auto in = [&](std::size_t k) { return k >= extra.range_begin && k < extra.range_end; };
      if (!in(i) || !in(j) || distance(pts[i].position, pts[j].position) > bound) return false;
      ++*asked;
      return (i * 31 + j * 17) % 5 == 0;  // some near pairs are joined
    };
    const bool with_edge = seed % 5 != 0;
    if (with_edge) extra.edge = edge;
    const auto plain = search_points(pts, start, r, with_edge ? ExtraEdge(edge) : ExtraEdge{});
    asked = &asked_bucketed;
    const auto bucketed = search_points_bucketed(pts, start, r, extra);
    ASSERT_EQ(plain.cost, bucketed.cost) << "seed " << seed;
    ASSERT_EQ(plain.parent, bucketed.parent) << "seed " << seed;
    ASSERT_EQ(plain.work, bucketed.work) << "seed " << seed;
    ASSERT_EQ(asked_plain, asked_bucketed) << "seed " << seed;
    ASSERT_LE(bucketed.candidates, plain.candidates) << "seed " << seed;
    fewer_candidates += bucketed.candidates < plain.candidates;
    for (double c : plain.cost)
      reached_total += std::isfinite(c);
  }
  // The sets are not trivial: many points are reached through edges, and the grid prunes.
  EXPECT_GT(reached_total, 2000u);
  EXPECT_GT(fewer_candidates, 50u);
}

TEST(VoronoiPoints, BucketedSearchRejectsBadInput) {
  std::vector<VoronoiPoint> pts(2);
  std::vector<double> start(1, 0.0);
  EXPECT_THROW((void)search_points_bucketed(pts, start, 0.2), Error);
  start.assign(2, 0.0);
  BoundedExtraEdges extra;
  extra.edge = [](std::size_t, std::size_t) { return true; };
  extra.max_distance_m = 1.0;
  extra.unbounded_pairs = {{0, 5}};
  EXPECT_THROW((void)search_points_bucketed(pts, start, 0.2, extra), Error);
}

}  // namespace
}  // namespace voronav::network
