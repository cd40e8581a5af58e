// Tests of the exploration runner (seed 004 method and the frontier baselines).
#include <gtest/gtest.h>

#include <cmath>

#include "voronav/core/error.hpp"
#include "voronav/exploration/explorer.hpp"

namespace voronav::exploration {
namespace {

// The paper's world at 0.1 m cells keeps the tests fast; the bench uses 0.05 m.
const OccupancyGrid& world() {
  static const OccupancyGrid w = paper_world(0.1);
  return w;
}

ExplorationOptions quick(ExplorationMethod m, int robots, double time) {
  ExplorationOptions o;
  o.method = m;
  o.robots = robots;
  o.start = kPaperWorldStart;
  o.time_limit = time;
  o.tree_start_time = time / 2;
  return o;
}

TEST(Explorer, PaperWorldTreeMethodHasNoCollisions) {
  const ExplorationResult r = run_exploration(world(), quick(ExplorationMethod::kTree, 4, 300));
  EXPECT_EQ(r.collisions, 0);
  EXPECT_GT(r.feature_points, 10);
  EXPECT_GT(r.leaves, 0);
  EXPECT_GE(r.trees, 1);
  EXPECT_GT(r.coverage, 0.3);
  EXPECT_LE(r.coverage, 1.0);
  EXPECT_GT(r.distance_m, 4 * 300 * 0.3 * 0.3);  // robots keep moving
  // The first tree obeys the invariants and every robot got a route starting where it was.
  const VoronoiTree& t = r.recording.tree;
  ASSERT_FALSE(t.empty());
  for (const TreeNode& n : t.nodes) {
    if (n.right >= 0) {
      EXPECT_GE(n.left, 0);
    }
  }
  EXPECT_EQ(r.recording.routes.size(), 4u);
  EXPECT_EQ(static_cast<int>(t.leaves_by_distance().size()), r.leaves);
  // Frames: one per second, coverage never decreases (cells once known stay known).
  ASSERT_EQ(r.recording.frames.size(), 300u);
  for (std::size_t k = 1; k < r.recording.frames.size(); ++k)
    ASSERT_GE(r.recording.frames[k].coverage, r.recording.frames[k - 1].coverage);
}

TEST(Explorer, FrontierBaselinesCoverTheWorld) {
  for (ExplorationMethod m : {ExplorationMethod::kFrontier, ExplorationMethod::kCoordinated}) {
    ExplorationOptions o = quick(m, 4, 400);
    o.stop_at_coverage = 0.95;  // keeps the test short
    const ExplorationResult r = run_exploration(world(), o);
    EXPECT_EQ(r.collisions, 0) << to_string(m);
    EXPECT_GT(r.coverage, 0.9) << to_string(m);
    ASSERT_TRUE(r.t90_s.has_value()) << to_string(m);
    EXPECT_LE(*r.t90_s, 400.0);
    EXPECT_EQ(r.leaves, 0);
    EXPECT_EQ(r.stalled_robots, 0) << to_string(m);
  }
}

TEST(Explorer, TreeFrontierAllocatesTreeLeavesAndCoversTheWorld) {
  // Ours: coordinated allocation over frontiers + Voronoi-tree leaves from the start; the tree is
  // rebuilt from the feature points and some of its leaves are taken as goals.
  ExplorationOptions o = quick(ExplorationMethod::kTreeFrontier, 4, 400);
  o.stop_at_coverage = 0.95;
  const ExplorationResult r = run_exploration(world(), o);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_GT(r.coverage, 0.95);
  EXPECT_GE(r.trees, 1);
  EXPECT_GT(r.feature_points, 10);
  EXPECT_GT(r.leaf_goals, 0);
  EXPECT_GT(r.frontier_goals, 0);
  EXPECT_EQ(r.dispatches, 0);  // no figure-9 dispatch in this method
  EXPECT_EQ(r.stalled_robots, 0);
}

TEST(Explorer, DeterministicForAGivenSeed) {
  ExplorationOptions o = quick(ExplorationMethod::kTree, 2, 120);
  o.start.reset();  // seeded start spot
  o.seed = 9;
  const ExplorationResult a = run_exploration(world(), o), b = run_exploration(world(), o);
  EXPECT_EQ(to_json(a, true), to_json(b, true));
  o.seed = 10;
  EXPECT_NE(to_json(run_exploration(world(), o), true), to_json(a, true));
}

TEST(Explorer, StopsEarlyAtTheRequestedCoverage) {
  ExplorationOptions o = quick(ExplorationMethod::kCoordinated, 4, 600);
  o.stop_at_coverage = 0.5;
  const ExplorationResult r = run_exploration(world(), o);
  EXPECT_GE(r.coverage, 0.5);
  EXPECT_LT(r.sim_time_s, 600.0);
}

TEST(Explorer, BadInputIsAnError) {
  ExplorationOptions o = quick(ExplorationMethod::kTree, 0, 10);
  EXPECT_THROW((void)run_exploration(world(), o), Error);
  o = quick(ExplorationMethod::kTree, 2, std::nan(""));
  EXPECT_THROW((void)run_exploration(world(), o), Error);
  o = quick(ExplorationMethod::kTree, 2, 10);
  o.start = Vec2{0.05, 0.05};  // inside the outer wall
  EXPECT_THROW((void)run_exploration(world(), o), Error);
  o.start = Vec2{std::nan(""), 1.0};
  EXPECT_THROW((void)run_exploration(world(), o), Error);
  EXPECT_THROW((void)run_exploration(OccupancyGrid{}, quick(ExplorationMethod::kTree, 1, 10)),
               Error);
  EXPECT_THROW((void)parse_exploration_method("random"), Error);
  EXPECT_EQ(parse_exploration_method("coordinated"), ExplorationMethod::kCoordinated);
  EXPECT_THROW((void)paper_world(0.0), Error);
}

TEST(Explorer, FineWorldsAreResampled) {
  // The 0.05 m paper world runs on 0.1 m cells: the recording has the coarse geometry and the
  // reachable free area is (about) the same 20 x 20 m minus obstacles.
  ExplorationOptions o = quick(ExplorationMethod::kCoordinated, 1, 5);
  const ExplorationResult fine = run_exploration(paper_world(0.05), o);
  const ExplorationResult coarse = run_exploration(world(), o);
  EXPECT_DOUBLE_EQ(fine.recording.geometry.resolution, 0.1);
  EXPECT_EQ(fine.recording.geometry.width, 200);
  // A coarse cell is blocked when any fine cell is: slightly less free area than drawing at 0.1.
  EXPECT_LE(fine.reachable_free_cells, coarse.reachable_free_cells);
  EXPECT_GT(fine.reachable_free_cells, coarse.reachable_free_cells * 99 / 100);
  o.min_cell_size = 0.05;
  const ExplorationResult kept = run_exploration(paper_world(0.05), o);
  EXPECT_DOUBLE_EQ(kept.recording.geometry.resolution, 0.05);
  EXPECT_NEAR(static_cast<double>(kept.reachable_free_cells) * 0.0025,
              static_cast<double>(coarse.reachable_free_cells) * 0.01, 0.03 * 400);
}

TEST(Explorer, JsonHasTheDocumentedFields) {
  ExplorationResult r;
  r.coverage = 0.5;
  r.t90_s = 12.5;
  const std::string j = to_json(r);
  for (const char* key : {"\"coverage\":0.5", "\"t90_s\":12.5", "\"t99_s\":null", "\"distance_m\":",
                          "\"collisions\":", "\"feature_points\":", "\"leaves\":"})
    EXPECT_NE(j.find(key), std::string::npos) << key << " in " << j;
  for (const char* key : {"\"leg_replans\":0", "\"escapes\":0", "\"unsticks\":0"})
    EXPECT_NE(j.find(key), std::string::npos) << key << " in " << j;
}

// Issue 14: the tree's reactive search drives straight while its sectors are clear (Table 1:
// CLEAR -> F) and escapes clutter; the frontier methods' reactive windows keep the controller
// their stall fixes were measured with.
TEST(Explorer, TreeSearchDrivesStraightWhenClearFrontierWindowsKeepTheirController) {
  const ExplorationOptions o;
  EXPECT_EQ(o.controller.random_turn_rate, 0.0);
  EXPECT_EQ(o.controller.avoid_escape, robot::AvoidEscape::kCorridor);
  EXPECT_EQ(o.frontier_controller.random_turn_rate, 0.4);
  EXPECT_EQ(o.frontier_controller.avoid_escape, robot::AvoidEscape::kSpin);
  EXPECT_EQ(o.tree_leg_replan, TreeLegReplan::kAroundRobots);
  robot::ReactiveController c(o.controller);
  robot::LaserScan clear;
  clear.angle_min = -3.14159;
  clear.angle_increment = 2 * 3.14159 / 360;
  clear.range_max = 3.0;
  clear.ranges.assign(360, 3.0F);
  for (int k = 0; k < 100; ++k) {  // 10 s: longer than the 4 s random period
    const robot::BodyVelocity cmd = c.update(clear, 0.1);
    EXPECT_DOUBLE_EQ(cmd.v, o.controller.drive_velocity);
    EXPECT_DOUBLE_EQ(cmd.omega, 0.0);
  }
  EXPECT_EQ(parse_tree_leg_replan("none"), TreeLegReplan::kNone);
  EXPECT_THROW((void)parse_tree_leg_replan("sometimes"), Error);
}

}  // namespace
}  // namespace voronav::exploration
