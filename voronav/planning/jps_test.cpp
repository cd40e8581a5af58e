#include "voronav/planning/jps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "voronav/core/internal/test_grids.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::planning {
namespace {

using test::from_rows;

// Random maps of three kinds: scattered cells, random rectangles (rooms and long walls, which
// give long straight jumps across several 64-bit words), and both.
BinaryGrid random_map(std::mt19937& rng, int w, int h) {
  BinaryGrid g(w, h, 0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int kind = static_cast<int>(rng() % 3);
  if (kind != 1) {
    const double p = 0.45 * u(rng);
    for (std::size_t i = 0; i < g.size(); ++i)
      g[i] = u(rng) < p ? 1 : 0;
  }
  if (kind != 0) {
    const int rects = static_cast<int>(rng() % 12);
    for (int r = 0; r < rects; ++r) {
      const int x0 = static_cast<int>(rng() % static_cast<unsigned>(w));
      const int y0 = static_cast<int>(rng() % static_cast<unsigned>(h));
      const bool horizontal = rng() % 2 == 0;
      const int len = 1 + static_cast<int>(rng() % static_cast<unsigned>(std::max(w, h)));
      const int thick = 1 + static_cast<int>(rng() % 3);
      for (int a = 0; a < len; ++a)
        for (int b = 0; b < thick; ++b) {
          const Cell c = horizontal ? Cell{x0 + a, y0 + b} : Cell{x0 + b, y0 + a};
          if (g.contains(c)) g[c] = 1;
        }
    }
  }
  return g;
}

struct Totals {
  std::size_t solved = 0, astar_expanded = 0, jps_expanded = 0;
};

void expect_same_as_astar(const BinaryGrid& g, Cell s, Cell t, AStarPlanner& astar, JpsPlanner& jps,
                          const std::string& what, Totals& tot) {
  const PlanResult a = astar.plan(g, s, t);
  const PlanResult j = jps.plan(g, s, t);
  ASSERT_EQ(j.status, a.status) << what << " " << jps.name();
  if (!a.ok()) return;
  ++tot.solved;
  tot.astar_expanded += a.expanded;
  tot.jps_expanded += j.expanded;
  // Exact costs (a + b sqrt 2 from integer counts): the optimal length is bit-identical.
  EXPECT_EQ(j.length_cells, a.length_cells) << what << " " << jps.name();
  ASSERT_TRUE(is_valid_path(g, j.path, Connectivity::k8)) << what << " " << jps.name();
  EXPECT_EQ(j.path.front(), s);
  EXPECT_EQ(j.path.back(), t);
  EXPECT_NEAR(path_length_cells(j.path), j.length_cells, 1e-9) << what;
}

TEST(Jps, SameLengthsAsAStarOnRandomMaps) {
  AStarPlanner astar;
  JpsPlanner jps;
  JpsPlusPlanner jps_plus;
  Totals tot_jps, tot_plus;
  for (unsigned seed = 1; seed <= 240; ++seed) {
    std::mt19937 rng(seed);
    // Widths past 64 and 128 make the bit scans cross word boundaries.
    const int w = 1 + static_cast<int>(rng() % 150), h = 1 + static_cast<int>(rng() % 70);
    const BinaryGrid g = random_map(rng, w, h);
    for (int q = 0; q < 12; ++q) {
      const Cell s{static_cast<int>(rng() % static_cast<unsigned>(w)),
                   static_cast<int>(rng() % static_cast<unsigned>(h))};
      const Cell t{static_cast<int>(rng() % static_cast<unsigned>(w)),
                   static_cast<int>(rng() % static_cast<unsigned>(h))};
      const std::string what = "seed " + std::to_string(seed) + " query " + std::to_string(q);
      expect_same_as_astar(g, s, t, astar, jps, what, tot_jps);
      expect_same_as_astar(g, s, t, astar, jps_plus, what, tot_plus);
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GT(tot_jps.solved, 1000u);
  // On a few tiny cases JPS expands a few more nodes than A*, but far fewer overall.
  EXPECT_LT(tot_jps.jps_expanded * 3, tot_jps.astar_expanded);
  EXPECT_LT(tot_plus.jps_expanded * 3, tot_plus.astar_expanded);
}

TEST(Jps, ShippedMovingAiScenariosAreOptimal) {
  const std::filesystem::path dir = std::filesystem::path(VORONAV_SOURCE_DIR) / "data/movingai";
  for (const char* name : {"arena", "den312d", "maze-100-1"}) {
    const BinaryGrid g = binarize(io::load_movingai_map(dir / (std::string(name) + ".map")));
    const auto scen = io::load_movingai_scen(dir / (std::string(name) + ".map.scen"));
    ASSERT_FALSE(scen.empty());
    JpsPlanner jps;
    JpsPlusPlanner jps_plus;
    AStarPlanner astar;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < scen.size(); ++i) {
      const auto& q = scen[i];
      const Cell s = io::movingai_to_cell(q.start_x, q.start_y, g.height());
      const Cell t = io::movingai_to_cell(q.goal_x, q.goal_y, g.height());
      for (JpsPlanner* p : {&jps, static_cast<JpsPlanner*>(&jps_plus)}) {
        const PlanResult r = p->plan(g, s, t);
        ASSERT_TRUE(r.ok()) << name << " line " << q.line;
        EXPECT_NEAR(r.length_cells, q.optimal_length, q.optimal_rounding + 1e-6)
            << name << " line " << q.line << " " << p->name();
        EXPECT_TRUE(is_valid_path(g, r.path, Connectivity::k8)) << name << " line " << q.line;
      }
      if (i % 7 == 0) {  // and bit-identical to A* on a sample
        EXPECT_EQ(jps.plan(g, s, t).length_cells, astar.plan(g, s, t).length_cells);
        ++checked;
      }
    }
    EXPECT_GT(checked, 0u);
  }
}

TEST(Jps, HandCasesAndStatuses) {
  const BinaryGrid g = from_rows({
      "....#....",
      "....#....",
      "....#....",
      ".........",
      "....#....",
  });
  for (PlannerKind kind : {PlannerKind::kJps, PlannerKind::kJpsPlus}) {
    auto p = make_planner(kind);
    PlanResult r = p->plan(g, {0, 4}, {8, 4});  // around the wall through the gap at row 1
    ASSERT_TRUE(r.ok());
    // 3 diagonal steps to (3,1), 2 straight through the gap (a diagonal out of it would cut the
    // wall's corner), 3 diagonal steps up to (8,4).
    EXPECT_NEAR(r.length_cells, 2.0 + 6.0 * std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(is_valid_path(g, r.path, Connectivity::k8));
    r = p->plan(g, {2, 2}, {2, 2});
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.path.size(), 1u);
    EXPECT_EQ(r.length_cells, 0.0);
    EXPECT_EQ(p->plan(g, {4, 0}, {0, 0}).status, PlanStatus::kStartOccupied);
    EXPECT_EQ(p->plan(g, {0, 0}, {4, 4}).status, PlanStatus::kGoalOccupied);
    EXPECT_EQ(p->plan(g, {0, 0}, {9, 0}).status, PlanStatus::kOutOfMap);
  }
  // Sealed: no corner cutting through the diagonal gap between (1,0) and (0,1).
  const BinaryGrid sealed = from_rows({
      "#..",
      ".#.",
  });
  JpsPlanner jps;
  EXPECT_EQ(jps.plan(sealed, {0, 0}, {2, 1}).status, PlanStatus::kUnreachable);
  JpsPlusPlanner plus;
  EXPECT_EQ(plus.plan(sealed, {0, 0}, {2, 1}).status, PlanStatus::kUnreachable);
  EXPECT_THROW(JpsPlanner({.connectivity = Connectivity::k4}), Error);
}

TEST(Jps, OpenSpaceExpandsOnlyJumpPoints) {
  const BinaryGrid g(970, 170, 0);
  for (PlannerKind kind : {PlannerKind::kJps, PlannerKind::kJpsPlus}) {
    auto p = make_planner(kind, {.record_expanded = true});
    const PlanResult r = p->plan(g, {0, 0}, {969, 169});
    ASSERT_TRUE(r.ok());
    EXPECT_DOUBLE_EQ(r.length_cells, 800.0 + 169.0 * std::sqrt(2.0));
    EXPECT_LE(r.expanded, 3u);  // start, (169,169) on the goal's row, goal
    EXPECT_EQ(r.expanded_cells.size(), r.expanded);
    EXPECT_EQ(r.path.size(), 970u);
  }
}

TEST(JpsPlus, TablesAreBuiltOncePerMapAndInvalidated) {
  BinaryGrid g(40, 30, 0);
  JpsPlusPlanner p;
  PlanResult r = p.plan(g, {0, 0}, {39, 29});
  ASSERT_TRUE(r.ok());
  EXPECT_GT(r.preprocess_ms, 0.0);
  r = p.plan(g, {0, 29}, {39, 0});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.preprocess_ms, 0.0);  // cached
  // A wall added in place is ignored until invalidate(): then the tables are rebuilt.
  for (int y = 0; y < 29; ++y)
    g[Cell{20, y}] = 1;
  p.invalidate();
  r = p.plan(g, {0, 0}, {39, 0});
  ASSERT_TRUE(r.ok());
  EXPECT_GT(r.preprocess_ms, 0.0);
  AStarPlanner astar;
  EXPECT_EQ(r.length_cells, astar.plan(g, {0, 0}, {39, 0}).length_cells);
  EXPECT_GT(p.total_build_ms(), 0.0);
  // Two grids alternate without rebuilding (the land and water grids of a Moving AI map).
  const BinaryGrid other(40, 30, 0);
  EXPECT_GT(p.prepare(other), 0.0);
  EXPECT_EQ(p.prepare(g), 0.0);
  EXPECT_EQ(p.prepare(other), 0.0);
}

// JPS+ stores one byte per entry: jumps past 127 cells chain through kFarJump entries. Long
// walls far from the edges put jump points 128-290 cells away in all eight directions.
TEST(JpsPlus, JumpsFartherThan127CellsMatchAStar) {
  BinaryGrid g(300, 300, 0);
  for (int i = 40; i < 260; ++i) {
    g[Cell{150, i}] = 1;  // vertical wall with a gap
    g[Cell{i, 20}] = 1;   // horizontal walls
    g[Cell{i, 280}] = 1;
  }
  g[Cell{150, 200}] = 0;
  std::mt19937 rng(11);
  AStarPlanner astar;
  JpsPlusPlanner plus({.record_expanded = true});
  JpsPlanner online({.record_expanded = true});
  int long_paths = 0;
  for (int q = 0; q < 60; ++q) {
    const Cell s{static_cast<int>(rng() % 300), static_cast<int>(rng() % 300)};
    const Cell t{static_cast<int>(rng() % 300), static_cast<int>(rng() % 300)};
    const PlanResult a = astar.plan(g, s, t);
    const PlanResult j = plus.plan(g, s, t);
    ASSERT_EQ(j.status, a.status) << q;
    if (!a.ok()) continue;
    EXPECT_EQ(j.length_cells, a.length_cells) << q;
    EXPECT_TRUE(is_valid_path(g, j.path, Connectivity::k8)) << q;
    // The tables stand for the online scans: the same jump points, expanded in the same order.
    EXPECT_EQ(j.expanded_cells, online.plan(g, s, t).expanded_cells) << q;
    long_paths += a.length_cells > 200.0;
  }
  EXPECT_GT(long_paths, 10);
}

TEST(Jps, CancelHookStopsTheSearch) {
  std::mt19937 rng(7);
  BinaryGrid g(200, 200, 0);
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = rng() % 3 == 0 ? 1 : 0;
  g[Cell{0, 0}] = g[Cell{199, 199}] = 0;
  JpsPlanner free_run;
  ASSERT_GT(free_run.plan(g, {0, 0}, {199, 199}).expanded, 256u);  // long enough to be checked
  JpsPlanner jps({.cancel = [] { return true; }});
  EXPECT_EQ(jps.plan(g, {0, 0}, {199, 199}).status, PlanStatus::kCancelled);
}

}  // namespace
}  // namespace voronav::planning
