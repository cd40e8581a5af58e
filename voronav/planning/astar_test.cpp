#include "voronav/planning/astar.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <cstring>
#include <random>

#include "voronav/core/internal/test_grids.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/planning/bfs.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::planning {
namespace {

using test::from_rows;
using test::random_grid;

TEST(AStar, OpenGridOctileLength) {
  const BinaryGrid g(10, 10, 0);
  AStarPlanner astar;
  const PlanResult r = astar.plan(g, {0, 0}, {7, 3});
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.length_cells, 4.0 + 3.0 * std::numbers::sqrt2, 1e-12);
  EXPECT_EQ(r.path.front(), (Cell{0, 0}));
  EXPECT_EQ(r.path.back(), (Cell{7, 3}));
  EXPECT_EQ(r.path.size(), 8u);
  EXPECT_TRUE(is_valid_path(g, r.path, Connectivity::k8));
  // A* with the octile heuristic on an open grid expands only the cells of one optimal path.
  EXPECT_EQ(r.expanded, r.path.size());
}

TEST(AStar, OpenSpaceTiesBrokenTowardLargerG) {
  // Issue #16: an empty 970x170 map corner to corner expanded 118,974 nodes when f ties were
  // ordered by floating-point noise; with exact costs and larger-g tie-breaking it is the path.
  const BinaryGrid g(970, 170, 0);
  AStarPlanner astar;
  const PlanResult r = astar.plan(g, {0, 0}, {969, 169});
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.length_cells, 800.0 + 169.0 * std::numbers::sqrt2);
  EXPECT_LT(r.expanded, 2000u);
  EXPECT_EQ(r.expanded, r.path.size());
}

TEST(AStar, FourConnectedIsManhattan) {
  const BinaryGrid g(10, 10, 0);
  AStarPlanner astar({.connectivity = Connectivity::k4});
  const PlanResult r = astar.plan(g, {1, 1}, {6, 9});
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.length_cells, 13.0);
  EXPECT_TRUE(is_valid_path(g, r.path, Connectivity::k4));
}

TEST(AStar, NoCornerCutting) {
  // The diagonal step from (0,0) to (1,1) passes the corner of the blocked cell (1,0): forbidden.
  const BinaryGrid g = from_rows({
      "...",
      "...",
      ".#.",
  });
  AStarPlanner astar;
  const PlanResult r = astar.plan(g, {0, 0}, {2, 0});
  ASSERT_TRUE(r.ok());
  // (0,0)->(0,1)->(1,2)? no: (0,1)->(1,1) diagonal to (2,0) cuts (1,0). Optimal: up, right, right, down = 4
  // or up, diag... (0,0)->(0,1) 1, (0,1)->(1,1) 1, (1,1)->(2,1) 1, (2,1)->(2,0) 1.
  EXPECT_DOUBLE_EQ(r.length_cells, 4.0);
  EXPECT_TRUE(is_valid_path(g, r.path, Connectivity::k8));
}

TEST(AStar, StatusCodes) {
  const BinaryGrid g = from_rows({
      ".#.",
      "##.",
      "...",
  });
  AStarPlanner astar;
  EXPECT_EQ(astar.plan(g, {0, 2}, {2, 0}).status, PlanStatus::kUnreachable);
  EXPECT_EQ(astar.plan(g, {1, 2}, {2, 0}).status, PlanStatus::kStartOccupied);
  EXPECT_EQ(astar.plan(g, {2, 0}, {0, 1}).status, PlanStatus::kGoalOccupied);
  EXPECT_EQ(astar.plan(g, {-1, 0}, {2, 0}).status, PlanStatus::kOutOfMap);
  EXPECT_EQ(astar.plan(g, {0, 0}, {3, 0}).status, PlanStatus::kOutOfMap);
  EXPECT_EQ(astar.plan(BinaryGrid{}, {0, 0}, {0, 0}).status, PlanStatus::kOutOfMap);
  const PlanResult same = astar.plan(g, {2, 0}, {2, 0});
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same.path.size(), 1u);
  EXPECT_EQ(same.length_cells, 0.0);
  EXPECT_EQ(to_string(PlanStatus::kGoalOccupied), "goal_occupied");
}

TEST(AStar, MatchesDijkstraAndBfsOnRandomMaps) {
  std::mt19937 rng(2024);
  AStarPlanner astar;
  DijkstraPlanner dijkstra;
  AStarPlanner astar4({.connectivity = Connectivity::k4});
  BfsFlood bfs8, bfs4;
  for (int trial = 0; trial < 300; ++trial) {
    const int w = 5 + static_cast<int>(rng() % 40), h = 5 + static_cast<int>(rng() % 40);
    const BinaryGrid g = random_grid(rng, w, h, 0.05 + 0.05 * (trial % 7));
    const Cell s{static_cast<int>(rng() % static_cast<unsigned>(w)),
                 static_cast<int>(rng() % static_cast<unsigned>(h))};
    const Cell t{static_cast<int>(rng() % static_cast<unsigned>(w)),
                 static_cast<int>(rng() % static_cast<unsigned>(h))};
    const PlanResult a = astar.plan(g, s, t);
    const PlanResult d = dijkstra.plan(g, s, t);
    ASSERT_EQ(a.status, d.status) << "trial " << trial;
    bfs8.flood(g, s, Connectivity::k8);
    if (g[s] == 0 && g[t] == 0) {
      EXPECT_EQ(a.ok(), bfs8.steps(g, t) >= 0) << "trial " << trial;
    }
    if (!a.ok()) continue;
    EXPECT_NEAR(a.length_cells, d.length_cells, 1e-9) << "trial " << trial;
    EXPECT_NEAR(a.length_cells, path_length_cells(a.path), 1e-9);
    EXPECT_TRUE(is_valid_path(g, a.path, Connectivity::k8));
    EXPECT_TRUE(is_valid_path(g, d.path, Connectivity::k8));
    EXPECT_LE(a.expanded, d.expanded);
    // 4-connected: the optimal length is the BFS step count.
    const PlanResult a4 = astar4.plan(g, s, t);
    bfs4.flood(g, s, Connectivity::k4);
    EXPECT_EQ(a4.ok(), bfs4.steps(g, t) >= 0);
    if (a4.ok()) {
      EXPECT_DOUBLE_EQ(a4.length_cells, bfs4.steps(g, t));
      EXPECT_TRUE(is_valid_path(g, a4.path, Connectivity::k4));
    }
  }
}

TEST(AStar, ReusedPlannerEqualsFreshPlanner) {
  std::mt19937 rng(5);
  AStarPlanner reused;
  for (int trial = 0; trial < 100; ++trial) {
    const int w = 5 + static_cast<int>(rng() % 60), h = 5 + static_cast<int>(rng() % 30);
    const BinaryGrid g = random_grid(rng, w, h, 0.25);
    const Cell s{0, 0}, t{w - 1, h - 1};
    AStarPlanner fresh;
    const PlanResult a = reused.plan(g, s, t), b = fresh.plan(g, s, t);
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.path, b.path);
    EXPECT_EQ(a.expanded, b.expanded);
  }
}

TEST(AStar, CancelAndDeadline) {
  BinaryGrid g(300, 300, 0);
  for (int y = 0; y < 299; ++y) g[Cell{150, y}] = 1;  // a long detour
  int calls = 0;
  AStarPlanner cancelled({.cancel = [&] { return ++calls >= 2; }});
  EXPECT_EQ(cancelled.plan(g, {0, 0}, {299, 0}).status, PlanStatus::kCancelled);
  EXPECT_EQ(calls, 2);
  AStarPlanner late({.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1)});
  EXPECT_EQ(late.plan(g, {0, 0}, {299, 0}).status, PlanStatus::kCancelled);
  // The same planner object still works after a cancelled search.
  EXPECT_TRUE(late.plan(g, {0, 0}, {1, 1}).ok());
  DijkstraPlanner never({.cancel = [] { return false; }});
  EXPECT_TRUE(never.plan(g, {0, 0}, {299, 0}).ok());
}

TEST(AStar, RecordsExpandedCells) {
  const BinaryGrid g(8, 8, 0);
  DijkstraPlanner d({.record_expanded = true});
  const PlanResult r = d.plan(g, {0, 0}, {7, 7});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.expanded_cells.size(), r.expanded);
  EXPECT_EQ(r.expanded_cells.front(), (Cell{0, 0}));
  EXPECT_EQ(r.expanded_cells.back(), (Cell{7, 7}));
}

TEST(RobotRadius, PathKeepsClearance) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    BinaryGrid g(60, 40, 0, 0.1);
    std::bernoulli_distribution b(0.02);
    for (std::size_t i = 0; i < g.size(); ++i) g[i] = b(rng) ? 1 : 0;
    const double radius = 0.1 + 0.05 * (trial % 4);
    PlannerOptions opt{.robot_radius = radius};
    const BinaryGrid inflated = make_planning_grid(g, radius);
    AStarPlanner astar(opt);
    const PlanResult r = astar.plan(inflated, {0, 0}, {59, 39});
    if (!r.ok()) continue;
    const field::DistanceField df = field::distance_transform(g);
    for (Cell c : r.path) EXPECT_GE(df.distance_m(c), radius - 1e-9);
  }
}

TEST(PlannerFactory, NamesAndErrors) {
  EXPECT_EQ(parse_planner_kind("astar"), PlannerKind::kAStar);
  EXPECT_EQ(parse_planner_kind("dijkstra"), PlannerKind::kDijkstra);
  EXPECT_THROW((void)parse_planner_kind("rrt"), Error);
  EXPECT_EQ(make_planner(PlannerKind::kDijkstra)->name(), "dijkstra");
  OccupancyGrid m(5, 5, kFree);
  m[Cell{2, 2}] = kUnknown;
  const PlanResult r = plan_on_map(m, {0, 2}, {4, 2});
  ASSERT_TRUE(r.ok());
  for (Cell c : r.path) EXPECT_NE(c, (Cell{2, 2}));
}

}  // namespace
}  // namespace voronav::planning
