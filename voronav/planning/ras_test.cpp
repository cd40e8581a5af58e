// Tests of the RAS planner (seed 001): the paper's figure 2 numbering, the count rule of Table 1
// against an independent BFS with parent pointers, minimum region counts, density guarantees and
// statuses.
#include "voronav/planning/ras.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <numbers>
#include <random>

#include "voronav/core/internal/test_grids.hpp"
#include "voronav/core/error.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/planner_factory.hpp"
#include "voronav/planning/ras_maps.hpp"

namespace voronav::planning {
namespace {

using test::from_rows;
using test::random_grid;

Cell random_free(std::mt19937& rng, const BinaryGrid& g) {
  std::uniform_int_distribution<int> x(0, g.width() - 1), y(0, g.height() - 1);
  for (int i = 0; i < 10000; ++i) {
    const Cell c{x(rng), y(rng)};
    if (g[c] == 0) return c;
  }
  return {-1, -1};
}

constexpr Cell kDir[8] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

// ----- An independent reference: BFS with a FIFO queue and explicit parent pointers. ----------
// The neighbour order is computed from angles (atan2) rather than the planner's tables.
struct RefBfs {
  GridMap<std::int32_t> id;          // -1 unnumbered
  std::vector<std::int32_t> parent;  // by id
  std::vector<Cell> cell;            // by id
};

std::vector<int> ref_order(Cell at, std::optional<Cell> goal, bool optimal, bool eight) {
  std::vector<int> dirs;
  for (int k = 0; k < 8; k += eight ? 1 : 2)
    dirs.push_back(k);
  if (!optimal || !goal || *goal == at) return dirs;
  const double theta = std::atan2(goal->y - at.y, goal->x - at.x) * 180.0 / std::numbers::pi;
  auto signed_diff = [&](int k) {
    double s = 45.0 * k - theta;
    while (s > 180.0)
      s -= 360.0;
    while (s <= -180.0)
      s += 360.0;
    return s;
  };
  std::stable_sort(dirs.begin(), dirs.end(), [&](int a, int b) {
    const double da = signed_diff(a), db = signed_diff(b);
    if (std::abs(std::abs(da) - std::abs(db)) > 1e-9) return std::abs(da) < std::abs(db);
    return da > db;  // tie: the direction counter-clockwise of the goal first
  });
  return dirs;
}

int ref_density(const BinaryGrid& g, Cell c) {
  int d = 0;
  for (const Cell o : kDir) {
    const Cell n = c + o;
    d += g.contains(n) && g[n] == 0;
  }
  return d;
}

RefBfs ref_bfs(const BinaryGrid& g, Cell start, std::optional<Cell> goal, const RasOptions& o) {
  RefBfs r{GridMap<std::int32_t>(g.width(), g.height(), -1), {}, {}};
  GridMap<std::uint8_t> rejected(g.width(), g.height(), 0);
  const bool eight = o.connectivity == Connectivity::k8;
  std::deque<std::int32_t> queue;
  r.id[start] = 0;
  r.parent.push_back(-1);
  r.cell.push_back(start);
  queue.push_back(0);
  if (goal && *goal == start && o.extent == RasExtent::kUntilGoal) return r;
  while (!queue.empty()) {
    const std::int32_t k = queue.front();
    queue.pop_front();
    const Cell c = r.cell[static_cast<std::size_t>(k)];
    // kOptimal: one order, from the start toward the goal; kOptimalPerRegion: from each region.
    const bool per_region = o.direction == RasDirection::kOptimalPerRegion;
    for (const int dir :
         ref_order(per_region ? c : start, goal, o.direction != RasDirection::kDefault, eight)) {
      const Cell n = c + kDir[dir];
      if (!g.contains(n) || g[n] != 0 || r.id[n] >= 0 || rejected[n]) continue;
      if ((dir % 2) == 1 && o.corner_rule == RasCornerRule::kNoCornerCutting) {
        const Cell a = c + kDir[(dir + 7) % 8], b = c + kDir[(dir + 1) % 8];
        if (!g.contains(a) || g[a] != 0 || !g.contains(b) || g[b] != 0) continue;
      }
      if (o.density > 0 && ref_density(g, n) < o.density) {
        rejected[n] = 1;
        continue;
      }
      const auto id = static_cast<std::int32_t>(r.cell.size());
      r.id[n] = id;
      r.parent.push_back(k);
      r.cell.push_back(n);
      queue.push_back(id);
      if (goal && n == *goal && o.extent == RasExtent::kUntilGoal) return r;
    }
  }
  return r;
}

// Plain BFS distance in steps, no ordering, no parents: the minimum region count oracle.
int bfs_steps(const BinaryGrid& g, Cell s, Cell t, const RasOptions& o) {
  GridMap<int> dist(g.width(), g.height(), -1);
  std::deque<Cell> q{s};
  dist[s] = 0;
  const bool eight = o.connectivity == Connectivity::k8;
  auto usable = [&](Cell n) {
    return g.contains(n) && g[n] == 0 &&
           (o.density == 0 || n == s || ref_density(g, n) >= o.density);
  };
  while (!q.empty()) {
    const Cell c = q.front();
    q.pop_front();
    if (c == t) return dist[c];
    for (int dir = 0; dir < 8; dir += eight ? 1 : 2) {
      const Cell n = c + kDir[dir];
      if (!usable(n) || dist[n] >= 0) continue;
      if (dir % 2 == 1 && o.corner_rule == RasCornerRule::kNoCornerCutting &&
          (!g.contains(c + kDir[(dir + 7) % 8]) || g[c + kDir[(dir + 7) % 8]] ||
           !g.contains(c + kDir[(dir + 1) % 8]) || g[c + kDir[(dir + 1) % 8]]))
        continue;
      dist[n] = dist[c] + 1;
      q.push_back(n);
    }
  }
  return -1;
}

// ----- Figure 2 of the paper. ------------------------------------------------------------------
// 8x8 regions, start 0 at column 4, row 4 (rows counted from the top as printed), obstacles at
// (2,2), (6,5), (3,6). Ids as printed (the OCR'd "8" at the start position is the 0).
constexpr int kFig2[8][8] = {{60, 51, 50, 49, 48, 47, 46, 45}, {53, 52, 31, 30, 29, 28, 27, 26},
                             {54, 32, -1, 14, 13, 12, 11, 25}, {55, 33, 15, 4, 3, 2, 10, 24},
                             {56, 34, 16, 5, 0, 1, 9, 23},     {57, 35, 17, 6, 7, 8, -1, 22},
                             {58, 36, 18, -1, 19, 20, 21, 44}, {59, 37, 38, 39, 40, 41, 42, 43}};

BinaryGrid fig2_map() {
  BinaryGrid g(8, 8, 0);
  for (int row = 0; row < 8; ++row)
    for (int col = 0; col < 8; ++col)
      if (kFig2[row][col] < 0) g[Cell{col, 7 - row}] = 1;
  return g;
}

int fig2_step(int id) {
  if (id == 0) return 0;
  if (id <= 8) return 1;
  if (id <= 21) return 2;
  if (id <= 44) return 3;
  if (id <= 59) return 4;
  return 5;
}

TEST(Ras, Figure2StepsZeroToTwoIdForIdAndLaterStepsAsSets) {
  const BinaryGrid g = fig2_map();
  RasSearch search;
  const RegionGrid regions(g, {});
  ASSERT_EQ(search.run(regions, {4, 3}, std::nullopt, {.extent = RasExtent::kWholeMap}),
            RasStatus::kOk);
  const RasField& f = search.field();
  EXPECT_EQ(f.size(), 61);
  EXPECT_EQ(f.steps(), 6);
  for (int row = 0; row < 8; ++row) {
    for (int col = 0; col < 8; ++col) {
      const int want = kFig2[row][col];
      const std::int32_t got = f.id_at({col, 7 - row});
      if (want < 0) {
        EXPECT_EQ(got, RasField::kObstacle);
        continue;
      }
      ASSERT_GE(got, 0);
      EXPECT_EQ(f.step(got), fig2_step(want)) << "col " << col << " row " << row;
      // Steps 0-2 follow the text's rule and the figure exactly. The figure numbers step 3 as a
      // sweep around the ring, which the text's rule does not produce; only the sets agree.
      if (want <= 21) {
        EXPECT_EQ(got, want) << "col " << col << " row " << row;
      }
    }
  }
}

TEST(Ras, Figure2FieldRecordsF) {
  const BinaryGrid g = fig2_map();
  const RegionGrid regions(g, {});
  RasSearch search;
  ASSERT_EQ(search.run(regions, {4, 3}, std::nullopt, {.extent = RasExtent::kWholeMap}),
            RasStatus::kOk);
  const RasField& f = search.field();
  // F_0 = (0, p_0, 8, 8, (1..8)) and F_1 = (1, p_1, 2, 7, (9, 10)): the count rule then gives 0 as
  // the parent of 1..8 and 1 as the parent of 9 and 10 (eq. 3-4, 9-11).
  const RasRegion f0 = f.region(0, regions);
  EXPECT_EQ(f0.N, 8);
  EXPECT_EQ(f0.d, 8);
  EXPECT_EQ(f0.first_child, 1);
  EXPECT_EQ(f0.region, (Cell{4, 3}));
  EXPECT_DOUBLE_EQ(f0.p.x, 4.5);
  EXPECT_DOUBLE_EQ(f0.p.y, 3.5);
  const RasRegion f1 = f.region(1, regions);
  EXPECT_EQ(f1.N, 2);
  EXPECT_EQ(f1.d, 7);  // (6,5) in the figure is blocked
  EXPECT_EQ(f1.first_child, 9);
  EXPECT_EQ(f1.step, 1);
  for (int k = 1; k <= 8; ++k)
    EXPECT_EQ(f.parent(k), 0);
  EXPECT_EQ(f.parent(9), 1);
  EXPECT_EQ(f.parent(10), 1);
  EXPECT_EQ(f.parent(11), 2);
  EXPECT_EQ(f.parent(0), -1);
  // Sum of all N = every numbered region except the start.
  std::int32_t total = 0;
  for (std::int32_t k = 0; k < f.size(); ++k)
    total += f.count(k);
  EXPECT_EQ(total, f.size() - 1);
  EXPECT_THROW((void)f.parent(61), Error);
  EXPECT_THROW((void)f.region_of(-1), Error);
}

// ----- The count rule is the BFS parent, on many random maps and all option combinations. -----
TEST(Ras, CountRuleParentEqualsBfsParentOnRandomMaps) {
  std::mt19937 rng(20061);
  int compared = 0;
  for (int trial = 0; trial < 240; ++trial) {
    const int w = 5 + static_cast<int>(rng() % 40), h = 5 + static_cast<int>(rng() % 40);
    const BinaryGrid g = random_grid(rng, w, h, 0.1 + 0.05 * (trial % 6));
    const Cell s = random_free(rng, g), t = random_free(rng, g);
    if (s.x < 0 || t.x < 0) continue;
    RasOptions o;
    o.connectivity = trial % 2 ? Connectivity::k8 : Connectivity::k4;
    o.direction = (trial / 2) % 2 == 0 ? RasDirection::kDefault
                  : (trial / 48) % 2   ? RasDirection::kOptimalPerRegion
                                       : RasDirection::kOptimal;
    o.density = (trial / 4) % 3 == 0 ? 0 : ((trial / 4) % 3 == 1 ? 5 : 8);
    o.extent = (trial / 12) % 2 ? RasExtent::kWholeMap : RasExtent::kUntilGoal;
    o.corner_rule =
        (trial / 24) % 2 ? RasCornerRule::kAllowCornerCutting : RasCornerRule::kNoCornerCutting;
    if (o.density > 0 && s != t && ref_density(g, t) < o.density) continue;
    const RegionGrid regions(g, {});
    RasSearch search;
    const RasStatus st = search.run(regions, s, t, o);
    const RefBfs ref = ref_bfs(g, s, t, o);
    const RasField& f = search.field();
    ASSERT_EQ(f.size(), static_cast<std::int32_t>(ref.cell.size())) << "trial " << trial;
    for (std::int32_t k = 0; k < f.size(); ++k) {
      ASSERT_EQ(f.region_of(k), ref.cell[static_cast<std::size_t>(k)]) << "trial " << trial;
      ASSERT_EQ(f.parent(k), ref.parent[static_cast<std::size_t>(k)]) << "trial " << trial;
      ++compared;
    }
    if (o.extent == RasExtent::kUntilGoal) {
      EXPECT_EQ(st == RasStatus::kOk, ref.id[t] >= 0) << "trial " << trial;
    }
  }
  EXPECT_GT(compared, 20000);
}

TEST(Ras, PathHasMinimumRegionCountAndIsFoundWheneverOneExists) {
  std::mt19937 rng(7);
  int found = 0, unreachable = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const BinaryGrid g = random_grid(rng, 30, 25, 0.25 + 0.1 * (trial % 3));
    const Cell s = random_free(rng, g), t = random_free(rng, g);
    if (s.x < 0 || t.x < 0) continue;
    RasOptions o;
    o.connectivity = trial % 2 ? Connectivity::k8 : Connectivity::k4;
    o.direction = (trial / 2) % 2 == 0 ? RasDirection::kDefault
                  : (trial / 8) % 2    ? RasDirection::kOptimalPerRegion
                                       : RasDirection::kOptimal;
    o.density = (trial / 4) % 2 ? 6 : 0;
    o.corner_rule = RasCornerRule::kNoCornerCutting;  // cell paths checked without corner cuts
    if (o.density > 0 && s != t && ref_density(g, t) < o.density) continue;
    RasPlanner ras(o, {.connectivity = o.connectivity});
    const RasResult r = ras.plan_ras(g, s, t);
    const int want = bfs_steps(g, s, t, o);
    if (want < 0) {
      EXPECT_EQ(r.status, RasStatus::kUnreachable);
      ++unreachable;
      continue;
    }
    ASSERT_TRUE(r.ok()) << "trial " << trial;
    ++found;
    EXPECT_EQ(static_cast<int>(r.path_regions.size()) - 1, want) << "trial " << trial;
    EXPECT_EQ(r.path_regions.front(), s);
    EXPECT_EQ(r.path_regions.back(), t);
    EXPECT_TRUE(is_valid_path(g, r.path_cells, o.connectivity)) << "trial " << trial;
  }
  EXPECT_GT(found, 80);
  EXPECT_GT(unreachable, 10);
}

// ----- Density guarantees. ---------------------------------------------------------------------
TEST(Ras, Density8NeverYieldsAPathRegionWithABlockedNeighbour) {
  std::mt19937 rng(88);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int r = 1 + trial % 4;
    const BinaryGrid g = random_grid(rng, 60, 50, 0.01 + 0.004 * (trial % 5));
    const Cell s = random_free(rng, g), t = random_free(rng, g);
    if (s.x < 0 || t.x < 0) continue;
    RasOptions o{.region_size = r, .density = 8};
    o.direction = trial % 2 ? RasDirection::kOptimal : RasDirection::kDefault;
    o.start_density = (trial / 2) % 2 ? RasStartDensity::kEnforced : RasStartDensity::kExempt;
    RasPlanner ras(o);
    const RasResult res = ras.plan_ras(g, s, t);
    if (!res.ok()) continue;
    const RegionGrid& regions = ras.region_grid();
    const auto df = field::distance_transform(g, {.border_is_blocked = true});
    const Cell start_region = regions.region_of(s);
    for (const Cell pr : res.path_regions) {
      if (pr == start_region && o.start_density == RasStartDensity::kExempt) continue;
      for (const Cell d : kDir) {
        const Cell n = pr + d;
        ASSERT_TRUE(regions.contains(n)) << "trial " << trial;
        ASSERT_FALSE(regions.is_blocked(n)) << "trial " << trial;
      }
      ++checked;
    }
    // Clearance: every path cell outside the start region is >= r cells from any blocked cell.
    for (const Cell c : res.path_cells) {
      if (regions.region_of(c) == start_region) continue;
      EXPECT_GE(std::sqrt(df.squared_distance[c]), r - 1e-9) << "trial " << trial;
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(Ras, DensityClosesGapsNarrowerThanTheRobot) {
  // A wall with a 1-cell gap: with density 0 the path goes through the gap, with density 8 it
  // goes around the end of the wall.
  const BinaryGrid g = from_rows({
      ".................",
      ".................",
      ".................",
      ".................",
      "######.#####.....",
      ".................",
      ".................",
      ".................",
      ".................",
  });
  RasPlanner d0({.density = 0});
  RasPlanner d8({.density = 8});
  const RasResult a = d0.plan_ras(g, {6, 1}, {6, 7});
  const RasResult b = d8.plan_ras(g, {6, 1}, {6, 7});
  ASSERT_TRUE(a.ok());
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(a.path_regions.size(), 7u);  // straight up through the gap
  EXPECT_GT(b.path_regions.size(), a.path_regions.size());
  for (const Cell c : b.path_regions)
    EXPECT_NE(c, (Cell{6, 4}));
  EXPECT_EQ(d8.field().id_at({6, 3}), RasField::kBelowDensity);  // beside the wall
  EXPECT_EQ(d8.field().id_at({6, 4}), RasField::kUnnumbered);    // the gap: never a candidate
}

// ----- Statuses and bad input. -----------------------------------------------------------------
TEST(Ras, Statuses) {
  const BinaryGrid g = from_rows({
      "..#..",
      "..#..",
      "..#..",
  });
  RasPlanner ras;
  EXPECT_EQ(ras.plan_ras(g, {0, 0}, {4, 0}).status, RasStatus::kUnreachable);
  EXPECT_EQ(ras.plan_ras(g, {2, 0}, {4, 0}).status, RasStatus::kStartBlocked);
  EXPECT_EQ(ras.plan_ras(g, {0, 0}, {2, 1}).status, RasStatus::kGoalBlocked);
  EXPECT_EQ(ras.plan_ras(g, {0, 0}, {5, 0}).status, RasStatus::kOutOfMap);
  EXPECT_EQ(ras.plan_ras(g, {-1, 0}, {1, 0}).status, RasStatus::kOutOfMap);
  const RasResult same = ras.plan_ras(g, {1, 1}, {1, 1});
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same.path_regions.size(), 1u);
  EXPECT_EQ(same.path_cells, (std::vector<Cell>{Cell{1, 1}}));
  EXPECT_EQ(ras.plan(g, {0, 0}, {4, 0}).status, PlanStatus::kUnreachable);
  EXPECT_EQ(ras.plan(g, {2, 0}, {4, 0}).status, PlanStatus::kStartOccupied);
  EXPECT_EQ(ras.plan(g, {0, 0}, {2, 2}).status, PlanStatus::kGoalOccupied);

  // Region size 2: the start cell (3,0) is free but its region (cells x 2-3) holds the wall.
  RasPlanner r2({.region_size = 2});
  EXPECT_EQ(r2.plan_ras(g, {3, 0}, {0, 0}).status, RasStatus::kStartBlocked);
  EXPECT_EQ(r2.plan_ras(g, {0, 0}, {3, 2}).status, RasStatus::kGoalBlocked);

  // Density: the goal region touches the wall; the start too (only enforced on request).
  const BinaryGrid open = from_rows({
      ".....",
      ".....",
      ".....",
      ".....",
  });
  RasPlanner d8({.density = 8});
  EXPECT_EQ(d8.plan_ras(open, {2, 1}, {0, 0}).status, RasStatus::kGoalBelowDensity);
  EXPECT_EQ(d8.plan(open, {2, 1}, {0, 0}).status, PlanStatus::kUnreachable);
  EXPECT_TRUE(d8.plan_ras(open, {0, 0}, {2, 1}).ok());  // start exempt
  RasPlanner d8e({.density = 8, .start_density = RasStartDensity::kEnforced});
  EXPECT_EQ(d8e.plan_ras(open, {0, 0}, {2, 1}).status, RasStatus::kStartBelowDensity);
}

TEST(Ras, CancelAndDeadline) {
  const BinaryGrid g(300, 300, 0);
  int calls = 0;
  RasPlanner cancelled({}, {.cancel = [&] { return ++calls > 0; }});
  EXPECT_EQ(cancelled.plan_ras(g, {0, 0}, {299, 299}).status, RasStatus::kCancelled);
  EXPECT_GE(calls, 1);
  RasPlanner late({}, {.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1)});
  EXPECT_EQ(late.plan(g, {0, 0}, {299, 299}).status, PlanStatus::kCancelled);
}

TEST(Ras, BadOptionsThrow) {
  EXPECT_THROW(RasPlanner({.region_size = 0}), Error);
  EXPECT_THROW(RasPlanner({.density = 9}), Error);
  EXPECT_THROW(RasPlanner({.density = -1}), Error);
  EXPECT_THROW(RegionGrid(BinaryGrid(4, 4, 0), {.region_size = -3}), Error);
  try {
    validate(RasOptions{.density = 12});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.source(), "density");
    EXPECT_NE(std::string(e.what()).find("12"), std::string::npos);
  }
  EXPECT_THROW((void)ras_parameters_for_robot(std::nan(""), 0.05), Error);
  EXPECT_THROW((void)ras_parameters_for_robot(0.3, 0.0), Error);
  EXPECT_THROW((void)ras_parameters_for_robot(-1.0, 0.05), Error);
  EXPECT_THROW((void)ras_parameters_for_robot(0.3, 0.05, 4), Error);
  // Empty map: nothing is inside.
  RasPlanner ras;
  EXPECT_EQ(ras.plan_ras(BinaryGrid(0, 0, 0), {0, 0}, {0, 0}).status, RasStatus::kOutOfMap);
}

TEST(Ras, RobotParameters) {
  // The paper's robot: 32 px, 1 px per cell -> r = ceil(16.5) = 17 with density 8 (paper: 18).
  EXPECT_EQ(ras_parameters_for_robot(32.0, 1.0).region_size, 17);
  EXPECT_EQ(ras_parameters_for_robot(32.0, 1.0, 0).region_size, 34);
  EXPECT_EQ(ras_parameters_for_robot(0.3, 0.05).region_size, 4);  // 3 cells + 0.5 -> 4
  EXPECT_EQ(ras_parameters_for_robot(0.3, 0.05).density, 8);
}

// ----- Region grid. ----------------------------------------------------------------------------
TEST(RegionGrid, AnyAndMajorityRulesAndPartialRegions) {
  const BinaryGrid g = from_rows({
      "#....",
      "#....",
      "##...",
      ".....",
      ".....",
  });
  const RegionGrid any(g, {.region_size = 2});
  EXPECT_EQ(any.width(), 3);
  EXPECT_EQ(any.height(), 3);
  EXPECT_TRUE(any.is_blocked({0, 1}));   // cells (0..1, 2..3) hold 3 blocked
  EXPECT_FALSE(any.is_blocked({0, 0}));  // cells (0..1, 0..1) free
  EXPECT_TRUE(any.is_blocked({0, 2}));   // partial top row: cell (0,4) blocked
  EXPECT_FALSE(any.is_blocked({2, 2}));
  const RegionGrid maj(g, {.region_size = 2, .rule = RegionRule::kMajorityBlocked});
  EXPECT_TRUE(maj.is_blocked({0, 1}));   // 3 of 4
  EXPECT_FALSE(maj.is_blocked({0, 2}));  // 1 of 2: not more than half
  EXPECT_EQ(any.region_of({4, 4}), (Cell{2, 2}));
  EXPECT_EQ(any.cell_box({2, 2}).first, (Cell{4, 4}));
  EXPECT_EQ(any.cell_box({2, 2}).second, (Cell{4, 4}));
  EXPECT_EQ(any.center_cell({1, 1}), (Cell{3, 3}));
  EXPECT_DOUBLE_EQ(any.center_world({1, 1}).x, 3.0);
  EXPECT_DOUBLE_EQ(any.center_world({2, 2}).y, 4.5);
  EXPECT_DOUBLE_EQ(any.blocked().resolution(), 2.0);
}

TEST(Ras, LargerRegionsMatchBfsOnTheRegionGridAndGiveValidCellPaths) {
  std::mt19937 rng(16);
  int ok = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int r = 2 + trial % 5;
    BinaryGrid g = random_grid(rng, 90, 70, 0.0);
    // Sparse rectangles as obstacles.
    for (int i = 0; i < 15; ++i) {
      const int x0 = static_cast<int>(rng() % 85), y0 = static_cast<int>(rng() % 65);
      const int ww = 1 + static_cast<int>(rng() % 12), hh = 1 + static_cast<int>(rng() % 12);
      for (int y = y0; y < std::min(70, y0 + hh); ++y)
        for (int x = x0; x < std::min(90, x0 + ww); ++x)
          g[Cell{x, y}] = 1;
    }
    const Cell s = random_free(rng, g), t = random_free(rng, g);
    RasOptions o{.region_size = r, .corner_rule = RasCornerRule::kNoCornerCutting};
    o.direction = trial % 2 ? RasDirection::kOptimal : RasDirection::kDefault;
    RasPlanner ras(o);
    const RasResult res = ras.plan_ras(g, s, t);
    const RegionGrid regions(g, {.region_size = r});
    const Cell sr = regions.region_of(s), gr = regions.region_of(t);
    if (regions.is_blocked(sr) || regions.is_blocked(gr)) {
      EXPECT_NE(res.status, RasStatus::kOk);
      continue;
    }
    const int want = bfs_steps(regions.blocked(), sr, gr, o);
    if (want < 0) {
      EXPECT_EQ(res.status, RasStatus::kUnreachable);
      continue;
    }
    ASSERT_TRUE(res.ok());
    ++ok;
    EXPECT_EQ(static_cast<int>(res.path_regions.size()) - 1, want);
    // A* on the same region grid finds the same number of path regions (or its octile optimum
    // needs at least as many steps).
    AStarPlanner astar;
    const PlanResult a = astar.plan(regions.blocked(), sr, gr);
    ASSERT_TRUE(a.ok());
    EXPECT_GE(a.path.size(), res.path_regions.size());
    EXPECT_TRUE(is_valid_path(g, res.path_cells, Connectivity::k8)) << "trial " << trial;
    EXPECT_EQ(res.path_cells.front(), s);
    EXPECT_EQ(res.path_cells.back(), t);
    EXPECT_EQ(res.waypoints.size(), res.path_regions.size() + 2);
  }
  EXPECT_GT(ok, 20);
}

TEST(Ras, OptimalDirectionNumbersFewerRegionsWithTheSamePathLength) {
  const BinaryGrid g(200, 200, 0);
  RasPlanner def({.direction = RasDirection::kDefault});
  RasPlanner opt({.direction = RasDirection::kOptimal});
  RasPlanner per({.direction = RasDirection::kOptimalPerRegion});
  // Goals west, north-east and south of the start: the default order (east first) is worst for
  // the first.
  for (const Cell goal : {Cell{20, 130}, Cell{180, 170}, Cell{110, 5}}) {
    const Cell start{180, 100};
    const RasResult a = def.plan_ras(g, start, goal);
    const RasResult b = opt.plan_ras(g, start, goal);
    const RasResult c = per.plan_ras(g, start, goal);
    ASSERT_TRUE(a.ok() && b.ok() && c.ok());
    const auto regions = static_cast<std::size_t>(
        std::max(std::abs(goal.x - start.x), std::abs(goal.y - start.y)) + 1);
    EXPECT_EQ(a.path_regions.size(), regions);  // Chebyshev distance + 1, whatever the order
    EXPECT_EQ(b.path_regions.size(), regions);
    EXPECT_EQ(c.path_regions.size(), regions);
    EXPECT_LT(b.regions, a.regions) << goal.x << "," << goal.y;
    EXPECT_LE(c.regions, b.regions) << goal.x << "," << goal.y;
  }
}

TEST(Ras, WholeMapFieldAnswersEveryGoal) {
  std::mt19937 rng(3);
  const BinaryGrid g = random_grid(rng, 40, 40, 0.3);
  const Cell s = random_free(rng, g);
  RasSearch search;
  const RegionGrid regions(g, {});
  ASSERT_EQ(search.run(regions, s, std::nullopt, {.extent = RasExtent::kWholeMap}), RasStatus::kOk);
  const RasField& f = search.field();
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      const std::int32_t k = f.id_at({x, y});
      const int want = g[Cell{x, y}] ? -2 : bfs_steps(g, s, {x, y}, {});
      if (k < 0) {
        EXPECT_TRUE(want < 0);
        continue;
      }
      EXPECT_EQ(static_cast<int>(f.path_to(k).size()) - 1, want);
      EXPECT_EQ(f.step(k), want);
    }
  }
}

TEST(Ras, FactoryBuildsRas) {
  EXPECT_EQ(parse_planner_kind("ras"), PlannerKind::kRas);
  auto p = make_planner(PlannerKind::kRas, {}, {.region_size = 2, .density = 8});
  EXPECT_EQ(p->name(), "ras");
  const BinaryGrid g(40, 40, 0);
  const PlanResult r = p->plan(g, {10, 10}, {30, 20});
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(is_valid_path(g, r.path, Connectivity::k8));
  EXPECT_GT(r.length_cells, 20.0);
  EXPECT_GT(r.expanded, 0u);
  const auto names = planner_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "ras"), names.end());
}

TEST(RasMaps, StandInsAreDeterministicAndMatchTheirDocumentation) {
  const RasStandInMap t3 = ras_table3_map();
  EXPECT_EQ(t3.grid, ras_table3_map().grid);
  ASSERT_EQ(t3.grid.width(), 512);
  ASSERT_EQ(t3.grid.height(), 512);
  const RasOptions nc{.corner_rule = RasCornerRule::kNoCornerCutting};
  for (const auto& [r, want] : {std::pair{16, 56u}, std::pair{8, 107u}}) {
    RasOptions o = nc;
    o.region_size = r;
    RasPlanner ras(o);
    const RasResult res = ras.plan_ras(t3.grid, t3.start, t3.goal);
    ASSERT_TRUE(res.ok()) << r;
    EXPECT_EQ(res.path_regions.size(), want) << r;
  }
  const RasStandInMap t4 = ras_table4_map();
  ASSERT_EQ(t4.grid.width(), 1000);
  EXPECT_EQ(t4.start, (Cell{100, 749}));  // image (100, 250)
  EXPECT_EQ(t4.goal, (Cell{700, 749}));   // image (700, 250)
  // Density 8 must take a longer route than density 0 (the dot field), at both region sizes.
  for (const int r : {2, 8}) {
    RasOptions o = nc;
    o.region_size = r;
    RasPlanner d0(o);
    o.density = 8;
    RasPlanner d8(o);
    const RasResult a = d0.plan_ras(t4.grid, t4.start, t4.goal);
    const RasResult b = d8.plan_ras(t4.grid, t4.start, t4.goal);
    ASSERT_TRUE(a.ok() && b.ok()) << r;
    EXPECT_GT(b.path_regions.size(), a.path_regions.size()) << r;
  }
}

}  // namespace
}  // namespace voronav::planning
