// Tests of the runner's right of way (internal/right_of_way.hpp) and of the goalless robot's
// unstick (ExplorationOptions::idle_unstick): the two jams traced on lab_intel with 8 robots
// (issue 14, stop 19), each of which stalled a robot for 60 s; and the two kinds of stall the
// result tells apart (ExplorationResult::stalled_without_target, stop 25).
#include <gtest/gtest.h>

#include "voronav/exploration/explorer.hpp"
#include "voronav/exploration/internal/right_of_way.hpp"

namespace voronav::exploration {
namespace {

constexpr double kContact = 2.0 * 0.12 + 0.3;  // the runner: two body radii + 0.3 m

// lab_intel, 8 robots, frontier, seed 4, t = 130 s (the trace): robot 2 stood at a door corner
// at (11.60, 31.43) m, stopped by its guard (the corner), and robot 1 stood 0.31 m behind it,
// heading the same way into the same door, stopped by robot 2.
const Pose2 kRobot1{{11.84, 31.62}, -2.58};
const Pose2 kRobot2{{11.60, 31.43}, -1.97};

TEST(RightOfWay, TailgatingRobotBacksOffFromAHeldUpRobotOfHigherIndex) {
  const internal::RightOfWayPeer held2{2, kRobot2.position, true};
  EXPECT_TRUE(internal::backs_off_for(1, kRobot1, held2, kContact, true));
  // Before the fix (only the higher index backs off) neither moved: robot 1 stayed, robot 2
  // had no room to turn away from the corner, and robot 2 was stalled at 175.7 s.
  EXPECT_FALSE(internal::backs_off_for(1, kRobot1, held2, kContact, false));
}

TEST(RightOfWay, HeadOnPairStillResolvesByIndexAlone) {
  // Head-on: 0.3 m apart, facing each other. The higher index backs off at once; it is then
  // not "held" (it is backing off), so the lower index keeps going.
  const Pose2 a{{0.0, 0.0}, 0.0}, b{{0.3, 0.0}, 3.14159};
  EXPECT_TRUE(internal::backs_off_for(3, b, {0, a.position, false}, kContact, true));
  EXPECT_FALSE(internal::backs_off_for(0, a, {3, b.position, false}, kContact, true));
}

TEST(RightOfWay, NoBackOffForARobotBehindFarAwayOrMoving) {
  const internal::RightOfWayPeer behind{5, {-0.3, 0.0}, true};
  EXPECT_FALSE(internal::backs_off_for(1, {{0.0, 0.0}, 0.0}, behind, kContact, true));
  const internal::RightOfWayPeer far{5, {0.6, 0.0}, true};
  EXPECT_FALSE(internal::backs_off_for(1, {{0.0, 0.0}, 0.0}, far, kContact, true));
  const internal::RightOfWayPeer moving{5, {0.3, 0.0}, false};
  EXPECT_FALSE(internal::backs_off_for(1, {{0.0, 0.0}, 0.0}, moving, kContact, true));
  EXPECT_FALSE(internal::backs_off_for(5, {{0.3, 0.0}, 0.0}, {5, {0.0, 0.0}, true}, kContact,
                                       true));  // itself
}

// ExplorationOptions::unstick_right_of_way (stop 28): willow, 16 robots, tree, seed 9 with
// unstick_retry: robot 15 on an unstick route out of a crowd at (53.4, 20.7) m, robot 7 on its
// tree leg 0.37 m ahead of it (t = 482 s). By index robot 15 backs off and robot 7 goes on;
// robot 15 backed off from every robot it met and stayed 60 s.
TEST(RightOfWay, ARobotOnAnUnstickRouteGoesFirst) {
  const Pose2 r15{{53.23, 20.81}, -2.46}, r7{{53.17, 20.44}, -2.62};
  const internal::RightOfWayPeer leg7{7, r7.position, false, false};
  const internal::RightOfWayPeer unstick15{15, r15.position, false, true};
  // Without the option: the higher index backs off, whatever either is doing.
  EXPECT_TRUE(internal::backs_off_for(15, r15, leg7, kContact, true, true, false));
  // With it: the robot on the unstick route goes on and the other backs off for it.
  EXPECT_FALSE(internal::backs_off_for(15, r15, leg7, kContact, true, true, true));
  EXPECT_TRUE(internal::backs_off_for(7, r7, unstick15, kContact, true, false, true));
  // Both on unstick routes, or neither: by index as before.
  const internal::RightOfWayPeer unstick7{7, r7.position, false, true};
  EXPECT_TRUE(internal::backs_off_for(15, r15, unstick7, kContact, true, true, true));
  EXPECT_FALSE(internal::backs_off_for(7, r7, unstick15, kContact, true, true, true));
  const internal::RightOfWayPeer leg15{15, r15.position, false, false};
  EXPECT_TRUE(internal::backs_off_for(15, r15, leg7, kContact, true, false, true));
  EXPECT_FALSE(internal::backs_off_for(7, r7, leg15, kContact, true, false, true));
  // Out of contact (1.06 m apart): nobody backs off.
  const internal::RightOfWayPeer far15{15, {53.23, 21.5}, false, true};
  EXPECT_FALSE(internal::backs_off_for(7, r7, far15, kContact, true, false, true));
}

// Room A (3 x 3 m) and room B (6 x 3 m) joined by a 0.2 m slit: ground truth joins them (the
// coverage counts room B), but no robot fits through, so once the frontiers at the slit are
// banned the robot has no goal and searches reactively in room A.
OccupancyGrid rooms_with_a_slit() {
  OccupancyGrid w(100, 34, kOccupied, 0.1);
  for (int y = 2; y < 32; ++y) {
    for (int x = 2; x < 32; ++x)
      w[Cell{x, y}] = kFree;  // room A
    for (int x = 34; x < 94; ++x)
      w[Cell{x, y}] = kFree;  // room B
  }
  for (int x = 32; x < 34; ++x)
    for (int y = 16; y < 18; ++y)
      w[Cell{x, y}] = kFree;  // the slit, 2 cells
  return w;
}

// The runs below: one robot of the coordinated method, starting in room A's lower-left corner.
ExplorationOptions one_robot_in_room_a(double time_limit) {
  ExplorationOptions o;
  o.method = ExplorationMethod::kCoordinated;
  o.robots = 1;
  o.start = Vec2{1.0, 1.0};
  o.time_limit = time_limit;
  return o;
}

// lab_intel, 8 robots, coordinated, seed 1: every frontier left was banned by every robot, and a
// goalless robot turned on the spot in a corner (rule 2 found no clear front) for 52 s: stalled.
// Here the reactive search's obs_dist is raised so that rule 2 never finds a clear front in room
// A (the turn on the spot of the trace, every time the robot has no goal).
TEST(IdleUnstick, GoallessRobotTurningOnTheSpotIsMovedBeforeItStalls) {
  ExplorationOptions o = one_robot_in_room_a(200.0);
  o.frontier_controller.obs_dist = 4.5;  // every front sector always "occupied" in room A
  o.frontier_controller.approach_dist = 4.5;
  // The lab_intel trace's case: the unknown room is reachable in the ground truth (a centre
  // with 0.05 m clearance passes the 0.2 m slit) but off the team's planning grid.
  o.stall_reach_radius = 0.05;
  const ExplorationResult on = run_exploration(rooms_with_a_slit(), o);
  EXPECT_LT(on.coverage, 0.99);  // room B stays unknown: the stall rule is armed
  EXPECT_GT(on.idle_unsticks, 0);
  EXPECT_EQ(on.stalled_robots, 0);
  o.idle_unstick = false;  // before the fix
  o.stall_reach_radius = 0.0;
  // No robot fits through the slit, so room B is not reachable unknown space: the robot
  // turning on the spot in room A, which it has mapped, is idle with its work done, not
  // stalled (the stall rule of stop 26; until stop 25 coverage < 0.99 counted it).
  const ExplorationResult done = run_exploration(rooms_with_a_slit(), o);
  EXPECT_LT(done.coverage, 0.99);
  EXPECT_EQ(done.idle_unsticks, 0);
  EXPECT_EQ(done.stalled_robots, 0);
  EXPECT_EQ(done.idle_when_explored, 1);
  // The replay says so: one "idle" event, after stall_time on one spot, and no "stalled" one.
  int idle_events = 0, stalled_events = 0;
  for (const ExplorationEvent& e : done.recording.events) {
    idle_events += e.kind == "idle" ? 1 : 0;
    stalled_events += e.kind == "stalled" ? 1 : 0;
    if (e.kind == "idle") {
      EXPECT_GT(e.t, o.stall_time);
    }
  }
  EXPECT_EQ(idle_events, 1);
  EXPECT_EQ(stalled_events, 0);
  o.stall_reach_radius = 0.05;
  const ExplorationResult off = run_exploration(rooms_with_a_slit(), o);
  EXPECT_LT(off.coverage, 0.99);
  EXPECT_EQ(off.idle_unsticks, 0);
  EXPECT_EQ(off.stalled_robots, 1);
  EXPECT_EQ(off.idle_when_explored, 0);
  // Room B's frontier lies behind the slit, off the planning grid: the stall came with no
  // target any robot could reach (ExplorationResult::stalled_without_target, stop 25).
  EXPECT_EQ(off.stalled_without_target, 1);
}

// The other kind: a stall declared while the allocation had a reachable target. A stall time
// shorter than the robot's first turn and drive to its goal makes the stall watch fire at once.
TEST(StallKind, AStallWithAReachableTargetIsNotCountedAsWithout) {
  ExplorationOptions o = one_robot_in_room_a(20.0);
  o.stall_time = 1.5;
  o.stall_reach_radius = 0.05;  // room B is reachable unknown space for the stall rule
  const ExplorationResult r = run_exploration(rooms_with_a_slit(), o);
  EXPECT_GE(r.frontier_goals, 1);
  EXPECT_EQ(r.stalled_robots, 1);
  EXPECT_EQ(r.stalled_without_target, 0);
}

}  // namespace
}  // namespace voronav::exploration
