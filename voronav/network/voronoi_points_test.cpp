#include "voronav/network/voronoi_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
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
  std::size_t reached_total = 0, fewer_candidates = 0, heard_total = 0, checked_total = 0;
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
    if (with_edge) {
      // With on_asked the caller hears every pair it was asked about (the same count), and the
      // search asks edge() only where the answer can lower a cost: same result, fewer checks.
      std::size_t heard = 0, checked = 0;
      BoundedExtraEdges lazy = extra;
      std::size_t* sink = &heard;
      lazy.on_asked = [&](std::size_t i, std::size_t j) {
        asked = sink;
        (void)edge(i, j);  // counts the pair if edge() would count it
      };
      lazy.edge = [&](std::size_t i, std::size_t j) {
        ++checked;
        std::size_t ignore = 0;
        asked = &ignore;
        return edge(i, j);
      };
      const auto skipped = search_points_bucketed(pts, start, r, lazy);
      ASSERT_EQ(plain.cost, skipped.cost) << "seed " << seed;
      ASSERT_EQ(plain.parent, skipped.parent) << "seed " << seed;
      ASSERT_EQ(plain.work, skipped.work) << "seed " << seed;
      ASSERT_EQ(heard, asked_plain) << "seed " << seed;
      heard_total += heard;
      checked_total += checked;
    }
    fewer_candidates += bucketed.candidates < plain.candidates;
    for (double c : plain.cost)
      reached_total += std::isfinite(c);
  }
  // The sets are not trivial: many points are reached through edges, and the grid prunes.
  EXPECT_GT(reached_total, 2000u);
  EXPECT_GT(fewer_candidates, 50u);
  // on_asked saves checks (edge() is asked about fewer pairs than the caller hears of).
  EXPECT_LT(checked_total * 2, heard_total);
}

// Merged Searches carry the same point many times (re-forwards): the search takes one point per
// group of copies and gives every copy the result of the all-pairs search (cost, parent, work).
TEST(VoronoiPoints, BucketedSearchMergesCopiesWithTheAllPairsResult) {
  const double r = 0.2;
  std::size_t copies_total = 0, reached_via_copy = 0, ties = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    std::mt19937_64 rng(seed * 7919);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::size_t unique = 1 + rng() % 60;
    const double side = 2.0 + 30.0 * u(rng);
    // Even seeds: points on a 0.5 m lattice with costs in 0.5 steps, so a relaxation often
    // equals a copy's start cost exactly (as float costs of real Searches do).
    const bool lattice = seed % 2 == 0;
    auto q = [&](double v) { return lattice ? 0.5 * std::round(2.0 * v) : v; };
    std::vector<VoronoiPoint> base;
    for (std::size_t i = 0; i < unique; ++i)
      base.push_back({{q(side * u(rng)), q(side * u(rng))},
                      static_cast<float>(lattice ? 0.45 + 0.25 * static_cast<double>(rng() % 4)
                                                 : 0.1 + 2.5 * u(rng)),
                      0.0f});
    // Each point appears 1-6 times in random order; the copies of a start point carry the same
    // cost (a re-forward that did not improve it), a better one, or none.
    std::vector<VoronoiPoint> pts;
    std::vector<double> start;
    std::vector<double> base_cost(unique, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < unique; ++i)
      if (rng() % 2 == 0) base_cost[i] = q(3.0 * u(rng));
    for (std::size_t i = 0; i < unique; ++i)
      for (std::size_t k = 0, copies = 1 + rng() % 6; k < copies; ++k) {
        pts.push_back(base[i]);
        const auto pick = rng() % 3;
        start.push_back(pick == 0   ? base_cost[i]
                        : pick == 1 ? std::numeric_limits<double>::infinity()
                                    : base_cost[i] + q(2.0 * u(rng)));
        copies_total += k > 0;
      }
    std::vector<std::size_t> perm(pts.size());
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<VoronoiPoint> p2;
    std::vector<double> s2;
    for (std::size_t i : perm) {
      p2.push_back(pts[i]);
      s2.push_back(start[i]);
    }
    // Own points (an edge range at the end, never merged) joined by a few straight moves.
    const std::size_t own_begin = p2.size();
    for (std::size_t k = 0; k < 5; ++k) {
      p2.push_back(base[rng() % unique]);  // an own point may sit where a sender point is
      s2.push_back(std::numeric_limits<double>::infinity());
    }
    BoundedExtraEdges extra;
    extra.max_distance_m = 4.0;
    extra.range_begin = own_begin;
    extra.range_end = p2.size();
    auto edge = [&](std::size_t i, std::size_t j) {
      if (i < own_begin || j < own_begin) return false;
      return distance(p2[i].position, p2[j].position) <= 4.0 && (i + j) % 2 == 1;
    };
    extra.edge = edge;
    const auto plain = search_points(p2, s2, r, edge);
    const auto merged = search_points_bucketed(p2, s2, r, extra);
    ASSERT_EQ(plain.cost, merged.cost) << "seed " << seed;
    ASSERT_EQ(plain.parent, merged.parent) << "seed " << seed;
    ASSERT_EQ(plain.work, merged.work) << "seed " << seed;
    BoundedExtraEdges lazy = extra;  // edge() asked only where it matters: the same result
    lazy.on_asked = [](std::size_t, std::size_t) {};
    const auto skipped = search_points_bucketed(p2, s2, r, lazy);
    ASSERT_EQ(plain.cost, skipped.cost) << "seed " << seed;
    ASSERT_EQ(plain.parent, skipped.parent) << "seed " << seed;
    ASSERT_EQ(plain.work, skipped.work) << "seed " << seed;
    for (std::size_t i = 0; i < p2.size(); ++i) {
      if (plain.parent[i] < 0) continue;
      const auto& par = p2[static_cast<std::size_t>(plain.parent[i])];
      if (par.position == p2[i].position) ++reached_via_copy;
      if (par.position != p2[i].position && std::isfinite(s2[i]) && plain.cost[i] < s2[i]) {
        for (std::size_t k = 0; k < p2.size(); ++k)  // a copy of i kept this cost as its start
          if (k != i && p2[k].position == p2[i].position && p2[k].clearance == p2[i].clearance &&
              s2[k] == plain.cost[i]) {
            ++ties;
            break;
          }
      }
    }
  }
  EXPECT_GT(copies_total, 1000u);
  EXPECT_GT(reached_via_copy, 100u);  // copies relaxed by their first settled copy occur
  EXPECT_GT(ties, 10u);  // copies reached exactly at their cheapest start from another point
  // Copies are compared once: 300 copies of 3 points need a handful of comparisons.
  std::vector<VoronoiPoint> many;
  std::vector<double> start;
  for (int k = 0; k < 100; ++k)
    for (int i = 0; i < 3; ++i) {
      many.push_back({{1.0 * i, 0.0}, 1.0f, 0.0f});
      start.push_back(k == 50 && i == 0 ? 0.0 : std::numeric_limits<double>::infinity());
    }
  const auto s = search_points_bucketed(many, start, r);
  EXPECT_LE(s.candidates, 9u);
  EXPECT_EQ(s.work, 300u * 300u);
  EXPECT_EQ(s.cost[150], 0.0);
  EXPECT_EQ(s.parent[150], -1);
  EXPECT_EQ(s.parent[0], 150);    // a copy of the start, reached from it at distance 0
  EXPECT_EQ(s.parent[151], 150);  // the next point, from the first settled copy
  EXPECT_EQ(s.cost[299], 2.0);
  EXPECT_EQ(s.parent[299], 1);  // from the first settled copy of (1, 0)
}

// Table 2's "new Search" check (search_would_improve) says what the search over the held points
// plus the copy's points would say: a target (own point, trail, destination) whose cost drops by
// more than the tolerance, or that is reached for the first time. Random sets with copies of
// held points (cheaper, equal, dearer), points that only join two held points, and own edges.
TEST(VoronoiPoints, ImprovementCheckAgreesWithTheSearchOverAllPoints) {
  const double r = 0.2, tol = 1e-6;
  const double inf = std::numeric_limits<double>::infinity();
  int improving = 0, not_improving = 0, by_joining = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    std::mt19937_64 rng(seed * 104729);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double side = 4.0 + 12.0 * u(rng);
    auto point = [&] {
      return VoronoiPoint{
          {side * u(rng), side * u(rng)}, static_cast<float>(0.3 + 1.2 * u(rng)), 0.0f};
    };
    const std::size_t senders = 2 + rng() % 20, own = 1 + rng() % 15;
    std::vector<VoronoiPoint> pts;
    std::vector<double> start;
    for (std::size_t i = 0; i < senders; ++i) {
      pts.push_back(point());
      start.push_back(rng() % 4 == 0 ? inf : 10.0 * u(rng));
    }
    for (std::size_t i = 0; i < own; ++i) {
      pts.push_back(point());
      start.push_back(inf);
    }
    const std::size_t n = pts.size();
    // Own edges join own points only (as a robot's straight moves in its own map).
    auto own_edge = [&](std::size_t i, std::size_t j) {
      return i >= senders && j >= senders && i < n && j < n && (i * 7 + j * 7) % 3 == 0;
    };
    const auto done = search_points(pts, start, r, own_edge);
    const CopyCheck index(pts, done, r, senders);  // one index for every copy heard
    for (int copy = 0; copy < 3; ++copy) {
      std::vector<VoronoiPoint> added;
      std::vector<double> add_start;
      for (std::size_t k = 0, m = 1 + rng() % 6; k < m; ++k) {
        const auto pick = rng() % 4;
        if (pick == 0) {  // a copy of a held sender point, cheaper, equal or dearer
          const std::size_t i = rng() % senders;
          added.push_back(pts[i]);
          const double c = std::isfinite(done.cost[i]) ? done.cost[i] : 5.0;
          add_start.push_back(c + (static_cast<double>(rng() % 3) - 1.0) * 2.0 * u(rng));
        } else if (pick == 1) {  // a point with no start of its own (it can only join others)
          added.push_back(point());
          add_start.push_back(inf);
        } else {
          added.push_back(point());
          add_start.push_back(15.0 * u(rng));
        }
      }
      const auto chk = index.improves(added, add_start, tol);
      ASSERT_EQ(search_would_improve(pts, done, added, add_start, r, senders, tol).improves,
                chk.improves);
      auto all = pts;
      auto all_start = start;
      all.insert(all.end(), added.begin(), added.end());
      all_start.insert(all_start.end(), add_start.begin(), add_start.end());
      const auto full = search_points(all, all_start, r, own_edge);
      bool expect = false;
      for (std::size_t t = senders; t < n; ++t)
        if (full.cost[t] < done.cost[t] - tol) expect = true;
      ASSERT_EQ(chk.improves, expect) << "seed " << seed;
      EXPECT_GT(chk.work, 0u);
      (expect ? improving : not_improving) += 1;
      if (expect) {
        // Did only points without a start of their own make the difference?
        auto starts = all_start;
        for (std::size_t k = 0; k < added.size(); ++k)
          if (std::isfinite(add_start[k])) starts[n + k] = inf;
        const auto joined = search_points(all, starts, r, own_edge);
        for (std::size_t t = senders; t < n; ++t)
          if (joined.cost[t] < done.cost[t] - tol) {
            ++by_joining;
            break;
          }
      }
    }
  }
  EXPECT_GT(improving, 200);
  EXPECT_GT(not_improving, 200);
  EXPECT_GT(by_joining, 15);  // a copy that only joins two held points is new too
  // The usual re-forward: the same points at the same costs is not new, and costs nothing but
  // one comparison per held point.
  std::vector<VoronoiPoint> pts = {{{0.0, 0.0}, 1.0f, 0.0f}, {{1.5, 0.0}, 1.0f, 0.0f}};
  std::vector<double> start = {2.0, inf};
  const auto done = search_points(pts, start, r);
  std::vector<VoronoiPoint> same = {pts[0]};
  std::vector<double> same_start = {2.0};
  const auto chk = search_would_improve(pts, done, same, same_start, r, 1, tol);
  EXPECT_FALSE(chk.improves);
  EXPECT_EQ(chk.work, 1u);
  same_start = {1.0};
  EXPECT_TRUE(search_would_improve(pts, done, same, same_start, r, 1, tol).improves);
  EXPECT_THROW((void)search_would_improve(pts, done, same, start, r, 1, tol), Error);
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
