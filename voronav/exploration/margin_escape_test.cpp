// ExplorationOptions::margin_escape (issue 14, stop 23): margin_exit, where a robot that stands
// inside the planning margin drives first. The hand-made case is the traced willow stall
// (16 robots, coordinated, seeds 5 and 15): a robot 0.14 m from the corner of a small block of
// wall cells (map speckle), its route's first leg leaving past that corner. Every route the
// allocation gave it from there started with such a leg, the front guard stopped it, and the
// robot stood on that spot for 600 s (stalled). From the exit the same leg is clear.
#include <gtest/gtest.h>

#include "voronav/exploration/explorer.hpp"
#include "voronav/exploration/internal/front_guard.hpp"
#include "voronav/exploration/unstick.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/robot/diff_drive.hpp"

namespace voronav::exploration {
namespace {

// The runner's defaults: the body radius, and the planning margin (body + clearance) = 0.22 m.
const double kBody = robot::DiffDriveOptions{}.body_radius;
const double kMargin = kBody + ExplorationOptions{}.clearance;

// A 4 x 4 m room of 0.1 m cells, walled at its edge, with a 2 x 3 cell block (the speckle) whose
// lower-left corner is at (2.0, 2.0) m.
BinaryGrid room(bool with_speckle) {
  BinaryGrid b(40, 40, 0, 0.1);
  for (int k = 0; k < 40; ++k) {
    b[Cell{k, 0}] = b[Cell{k, 39}] = 1;
    b[Cell{0, k}] = b[Cell{39, k}] = 1;
  }
  if (with_speckle)
    for (int y = 20; y < 23; ++y)
      for (int x = 20; x < 22; ++x)
        b[Cell{x, y}] = 1;
  return b;
}

// The robot where it stalled, relative to the corner, and its route's first waypoint.
constexpr Vec2 kRobot{2.0 - 0.14, 2.0 - 0.03};
constexpr Vec2 kFirstWaypoint{kRobot.x + 0.49, kRobot.y - 0.42};

TEST(MarginEscape, TheStalledRobotsFirstLegClipsTheCornerAndTheExitClearsIt) {
  const BinaryGrid world = room(true);
  const BinaryGrid grid = planning::make_planning_grid(world, kMargin);
  // The stall: inside the margin, and the front guard's wall rule refuses the first leg (the
  // disc swept along it comes within 0.13 m of the corner, nearer than it is now).
  EXPECT_LT(internal::wall_clearance(world, kRobot, 1.0), kMargin);
  EXPECT_FALSE(internal::line_clear(world, kRobot, kFirstWaypoint, kBody));
  const std::optional<Vec2> exit = margin_exit(grid, world, kRobot, kBody, kMargin);
  ASSERT_TRUE(exit.has_value());
  // The exit: near, reached by a straight drive the guard lets through, out of the margin by the
  // reach at which the runner ends the escape, and from there the same first leg is clear.
  EXPECT_LE(distance(*exit, kRobot), 1.0);
  EXPECT_GT(distance(*exit, kRobot), internal::kCornerReach);
  EXPECT_TRUE(internal::line_clear(world, kRobot, *exit, kBody));
  EXPECT_GE(internal::wall_clearance(world, *exit, 1.0), kMargin + internal::kCornerReach);
  EXPECT_EQ(grid[*grid.geometry().world_to_cell(*exit)], 0);
  EXPECT_TRUE(internal::line_clear(world, *exit, kFirstWaypoint, kBody));
}

TEST(MarginEscape, AMarginOnlyTheWallsShowIsAMarginToo) {
  // willow coordinated seed 15: the team map had the speckle's cells as free, so the planning
  // grid put the robot outside the margin; the walls the guard senses do not.
  const BinaryGrid world = room(true);
  const BinaryGrid grid = planning::make_planning_grid(room(false), kMargin);
  ASSERT_EQ(grid[*grid.geometry().world_to_cell(kRobot)], 0);
  const std::optional<Vec2> exit = margin_exit(grid, world, kRobot, kBody, kMargin);
  ASSERT_TRUE(exit.has_value());
  EXPECT_TRUE(internal::line_clear(world, kRobot, *exit, kBody));
  EXPECT_TRUE(internal::line_clear(world, *exit, kFirstWaypoint, kBody));
}

TEST(MarginEscape, NoEscapeOutsideTheMargin) {
  const BinaryGrid world = room(true);
  const BinaryGrid grid = planning::make_planning_grid(world, kMargin);
  // 0.5 m from the block and every wall: not in the margin, nothing to escape.
  EXPECT_FALSE(margin_exit(grid, world, Vec2{1.0, 1.0}, kBody, kMargin).has_value());
}

}  // namespace
}  // namespace voronav::exploration
