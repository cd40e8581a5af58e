// Tests of explain_failure: hand-made maps where the hint's numbers are known.
#include "voronav/planning/failure_hint.hpp"

#include <gtest/gtest.h>

#include "voronav/planning/astar.hpp"
#include "voronav/planning/grid_planner.hpp"

namespace voronav::planning {
namespace {

// 21 x 11 cells of 0.1 m, a wall at x = 10 with a 3-cell door (y = 4, 5, 6).
BinaryGrid door_map() {
  BinaryGrid b(GridGeometry{21, 11, 0.1, {}}, 0);
  for (int y = 0; y < 11; ++y)
    if (y < 4 || y > 6) b[Cell{10, y}] = 1;
  return b;
}

TEST(FailureHint, StartInsideTheRadiusGetsTheNearestCellThatKeepsIt) {
  BinaryGrid b(GridGeometry{20, 20, 0.1, {}}, 0);
  for (int y = 0; y < 20; ++y)
    b[Cell{5, y}] = 1;  // a wall at x = 5
  // Start at x = 6: 0.1 m from the wall; radius 0.25 m blocks cells closer than 2.5 cells.
  const FailureHint h = explain_failure(b, b.geometry(), {6, 10}, {15, 10}, 0.25);
  ASSERT_TRUE(h.nearest_free.has_value());
  EXPECT_EQ(*h.nearest_free, (Cell{8, 10}));  // 3 cells from the wall: the first that keeps 2.5
  EXPECT_NE(h.text.find("start"), std::string::npos) << h.text;
  EXPECT_NE(h.text.find("0.10 m from an obstacle"), std::string::npos) << h.text;
  EXPECT_NE(h.text.find("0.20 m away"), std::string::npos) << h.text;
  // The planner agrees that the start is blocked with the radius and free at the hinted cell.
  AStarPlanner a;
  const BinaryGrid g = make_planning_grid(b, 0.25);
  EXPECT_EQ(a.plan(g, {6, 10}, {15, 10}).status, PlanStatus::kStartOccupied);
  EXPECT_TRUE(a.plan(g, *h.nearest_free, {15, 10}).ok());
}

TEST(FailureHint, DoorTooNarrowForTheRadiusNamesItsWidth) {
  const BinaryGrid b = door_map();
  // Door cells y = 4..6: the middle one is 2 cells from the wall ends at y = 3 and 7 -> clearance
  // 0.2 m, passage about 0.4 m; a robot of radius 0.25 m (0.5 m wide) cannot pass.
  AStarPlanner a;
  ASSERT_EQ(a.plan(make_planning_grid(b, 0.25), {2, 5}, {18, 5}).status, PlanStatus::kUnreachable);
  const FailureHint h = explain_failure(b, b.geometry(), {2, 5}, {18, 5}, 0.25);
  EXPECT_NEAR(h.narrowest_passage_m, 0.4, 1e-6) << h.text;
  EXPECT_NE(h.text.find("(1.05, 0.55) m"), std::string::npos) << h.text;  // the door's middle
  EXPECT_NE(h.text.find("diameter 0.50 m"), std::string::npos) << h.text;
  EXPECT_FALSE(h.nearest_free.has_value());
}

TEST(FailureHint, NoWayEvenForAPointAndObstacleEndsAreSaidPlainly) {
  BinaryGrid b = door_map();
  for (int y = 4; y <= 6; ++y)
    b[Cell{10, y}] = 1;  // the door closes
  EXPECT_NE(explain_failure(b, b.geometry(), {2, 5}, {18, 5}, 0.0).text.find("even for a point"),
            std::string::npos);
  EXPECT_NE(explain_failure(b, b.geometry(), {10, 5}, {18, 5}, 0.0).text.find("on an obstacle"),
            std::string::npos);
  EXPECT_TRUE(explain_failure(b, b.geometry(), {-1, 5}, {18, 5}, 0.0).text.empty());
}

}  // namespace
}  // namespace voronav::planning
