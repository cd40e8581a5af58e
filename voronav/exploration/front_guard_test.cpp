// Tests of the runner's front guard (internal/front_guard.hpp, ExplorationOptions::guard): a
// route the planner accepts past a wall corner is driven with the corridor rule and was stopped
// by the cone rule (issue 14, stop 21: the root of the lab_intel door jam, the depot bans and the
// willow crowd of stop 19); a robot on the route still stops the robot with both rules; the
// runner does not cut a route's corner where the body would not clear the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "voronav/exploration/internal/front_guard.hpp"
#include "voronav/exploration/voronoi_tree.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/robot/diff_drive.hpp"
#include "voronav/robot/laser.hpp"

namespace voronav::exploration {
namespace {

using internal::GuardRule;

constexpr double kBody = 0.12;              // robot::DiffDriveOptions::body_radius
constexpr double kPlanRadius = 0.12 + 0.1;  // body + ExplorationOptions::clearance

// 5 x 3 m of free space (0.1 m cells) with a block over x 3.0-4.0 m, y 0-1.5 m: its up-left
// corner is at (3.0, 1.5) m.
BinaryGrid world_with_corner() {
  BinaryGrid w(50, 30, 0, 0.1);
  for (int y = 0; y < 15; ++y)
    for (int x = 30; x < 40; ++x)
      w[Cell{x, y}] = 1;
  return w;
}

// The runner's guard laser: 13 beams over 1.4 rad, 1 m, no noise.
robot::LaserOptions guard_laser() {
  robot::LaserOptions l;
  l.beams = 13;
  l.field_of_view = 1.4;
  l.range_max = 1.0;
  l.noise_stddev = 0.0;
  return l;
}

// A diagonal route through cell centres (x, x - 13) past the corner cell (30, 14): every cell it
// crosses keeps more than 0.22 m (centre to centre) from the block, so the planner accepts it;
// it passes the corner 0.141 m from its surface (0.2 / sqrt 2), 0.021 m more than the body.
const Vec2 kFrom{2.05, 0.75}, kTo{3.45, 2.15};

struct DriveResult {
  bool reached = false;
  int collisions = 0;
  Vec2 end;
};

// The runner's route following (steer to the waypoint, the guard, the footprint check), for
// `seconds`; `others`: robots standing still.
DriveResult drive(GuardRule rule, const BinaryGrid& w, std::vector<robot::Disc> others,
                  double seconds = 20.0) {
  robot::DiffDriveOptions d;
  const double dt = 0.1;
  robot::DiffDriveRobot bot(d, Pose2{kFrom, std::atan2(kTo.y - kFrom.y, kTo.x - kFrom.x)}, 1);
  const std::vector<Vec2> route{kFrom, kTo};
  DriveResult out;
  for (double t = 0.0; t < seconds; t += dt) {
    const Pose2 pose = bot.true_pose();
    if (distance(pose.position, kTo) < 0.3) {
      out.reached = true;
      break;
    }
    const double e =
        wrap_angle(std::atan2(kTo.y - pose.position.y, kTo.x - pose.position.x) - pose.yaw);
    robot::BodyVelocity cmd{std::abs(e) > 0.6 ? 0.0 : 0.3 * std::cos(e),
                            std::clamp(1.5 * e, -1.0, 1.0)};
    if (cmd.v > 0.0 &&
        internal::front_guard(rule, w, pose, route, 1, others, kBody, guard_laser()).stop)
      cmd.v = 0.0;
    if (cmd.v > 0.0) {
      const Vec2 next = pose.position + Vec2{std::cos(pose.yaw), std::sin(pose.yaw)} * 0.09;
      if (robot::disc_collides(w, next, kBody + 0.01, others)) cmd.v = 0.0;
    }
    bot.command(cmd);
    bot.step(dt, w, others);
  }
  out.collisions = bot.collisions();
  out.end = bot.true_pose().position;
  return out;
}

TEST(FrontGuard, ThePlannerAcceptsTheRoutePastTheCorner) {
  const BinaryGrid w = world_with_corner();
  const BinaryGrid trav = planning::make_planning_grid(w, kPlanRadius);
  EXPECT_TRUE(segment_free(trav, kFrom, kTo));
  // Beside the corner the body keeps clear of it, but less than the cone's 0.24 m.
  const Vec2 beside{2.9, 1.6};  // on the route, nearest the corner
  const double c = internal::wall_clearance(w, beside, 1.0);
  EXPECT_NEAR(c, 0.2 / std::sqrt(2.0), 1e-9);
  EXPECT_GT(c, kBody + internal::kCorridorMargin);
  EXPECT_LT(c, kBody + internal::kGuardReach);
}

TEST(FrontGuard, CorridorDrivesTheLegalRoutePastTheCornerTheConeStoppedOn) {
  const BinaryGrid w = world_with_corner();
  const DriveResult corridor = drive(GuardRule::kCorridor, w, {});
  EXPECT_TRUE(corridor.reached);
  EXPECT_EQ(corridor.collisions, 0);
  // Before stop 21: the cone saw the corner beside the route within 0.24 m and the robot stood
  // there (in the runner: the 3 s block rule, the goal banned).
  const DriveResult cone = drive(GuardRule::kCone, w, {});
  EXPECT_FALSE(cone.reached);
  EXPECT_LT(distance(cone.end, {3.0, 1.5}), 0.3);
}

TEST(FrontGuard, ARobotStandingOnTheRouteStillStopsTheRobot) {
  const BinaryGrid w = world_with_corner();
  // Another robot on the route 1 m from the start, before the corner.
  const Vec2 dir = (kTo - kFrom) / distance(kFrom, kTo);
  const robot::Disc other{kFrom + dir * 1.0, kBody};
  for (const GuardRule rule : {GuardRule::kCorridor, GuardRule::kCone}) {
    const DriveResult r = drive(rule, w, {other});
    EXPECT_FALSE(r.reached);
    EXPECT_EQ(r.collisions, 0);
    // Stopped by the guard, within the cone's reach of the other robot's surface.
    const double gap = distance(r.end, other.center) - 2.0 * kBody;
    EXPECT_GT(gap, 0.0);
    EXPECT_LT(gap, internal::kGuardReach + 0.03);
    // The verdict names the robot, so the right of way applies.
    const Pose2 at{r.end, std::atan2(dir.y, dir.x)};
    const std::vector<Vec2> route{kFrom, kTo};
    const std::vector<robot::Disc> others{other};
    const internal::GuardVerdict v =
        internal::front_guard(rule, w, at, route, 1, others, kBody, guard_laser());
    EXPECT_TRUE(v.stop);
    EXPECT_TRUE(v.by_robot);
  }
}

TEST(FrontGuard, AWallOnTheRouteStopsTheCorridorGuard) {
  const BinaryGrid w = world_with_corner();
  // Straight at the block's left face (x = 3.0 m) along y = 0.75 m.
  const std::vector<Vec2> route{{1.0, 0.75}, {3.5, 0.75}};
  const Pose2 near{{3.0 - kBody - 0.08, 0.75}, 0.0}, far{{2.4, 0.75}, 0.0};
  const auto verdict = [&](const Pose2& p) {
    return internal::front_guard(GuardRule::kCorridor, w, p, route, 1, {}, kBody, guard_laser());
  };
  EXPECT_TRUE(verdict(near).stop);
  EXPECT_FALSE(verdict(near).by_robot);
  EXPECT_FALSE(verdict(far).stop);
  // Along the block's top face at 0.125 m (inside the margin, not nearing it): no stop.
  const std::vector<Vec2> along{{3.2, 1.625}, {4.5, 1.625}};
  EXPECT_FALSE(internal::front_guard(GuardRule::kCorridor, w, {{3.2, 1.625}, 0.0}, along, 1, {},
                                     kBody, guard_laser())
                   .stop);
}

TEST(FrontGuard, NoCornerCutWhereTheBodyWouldNotClearTheWall) {
  // A route up along x = 2.8 m, then right along y = 1.75 m over the block. 0.25 m before the
  // corner waypoint (within the 0.3 m waypoint tolerance) the straight line to the next waypoint
  // would graze the block's corner (3.0, 1.5) m: the runner (kCorridor) drives on to the
  // waypoint; from the waypoint the line is clear.
  const BinaryGrid w = world_with_corner();
  const Vec2 corner_wp{2.8, 1.75}, next_wp{3.8, 1.75};
  EXPECT_FALSE(internal::line_clear(w, {2.8, 1.5}, next_wp, kBody));
  EXPECT_TRUE(internal::line_clear(w, corner_wp, next_wp, kBody));
  EXPECT_TRUE(internal::line_clear(w, {2.8, 0.5}, corner_wp, kBody));
}

TEST(FrontGuard, RouteAheadFollowsTheRouteRoundItsCorners) {
  const std::vector<Vec2> route{{0.0, 0.0}, {0.05, 0.0}, {0.05, 1.0}};
  const std::vector<Vec2> pts = internal::route_ahead({0.0, 0.0}, route, 1, 0.12, 0.02);
  ASSERT_EQ(pts.size(), 6U);
  EXPECT_NEAR(pts[1].x, 0.04, 1e-9);
  EXPECT_NEAR(pts[2].x, 0.05, 1e-9);
  EXPECT_NEAR(pts[2].y, 0.01, 1e-9);
  EXPECT_NEAR(pts.back().y, 0.07, 1e-9);
  // A route that ends within the reach: its end is the last point.
  const std::vector<Vec2> shortr{{0.0, 0.0}, {0.05, 0.0}};
  const std::vector<Vec2> s = internal::route_ahead({0.0, 0.0}, shortr, 1, 0.12, 0.02);
  ASSERT_EQ(s.size(), 3U);
  EXPECT_NEAR(s.back().x, 0.05, 1e-9);
  EXPECT_TRUE(internal::route_ahead({0.0, 0.0}, shortr, 2, 0.12, 0.02).empty());
}

}  // namespace
}  // namespace voronav::exploration
