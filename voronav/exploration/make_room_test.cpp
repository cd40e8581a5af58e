// Making room for a stuck robot of the paper's tree method, when the progress watchdog fires for
// it: ExplorationOptions::disperse_neighbours (issue 14, stop 26: the robots without a route
// within disperse_range of it drive unstick routes to open space first) and clear_way_out (stop
// 27: the robots whose discs touch its way out to open space, planned as if no robot were there,
// do). Which robots are in the way is tested by hand in unstick_test.cpp
// (ClearWayOut.RobotsWhoseDiscsTouchTheWay); here: the runner moves them, at the watchdog's time,
// and only with the option.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "voronav/exploration/explorer.hpp"

namespace voronav::exploration {
namespace {

// A closed room of 4 x 1.2 m (0.1 m cells): robots of the random search meet in it.
OccupancyGrid narrow_room() {
  OccupancyGrid w(44, 16, kOccupied, 0.1);
  for (int y = 2; y < 14; ++y)
    for (int x = 2; x < 42; ++x)
      w[Cell{x, y}] = kFree;
  return w;
}

// The pose of robot k in the recorded frame nearest t (frames every second).
Vec2 pose_at(const ExplorationResult& r, double t, int k) {
  const ExplorationFrame* best = &r.recording.frames.front();
  for (const ExplorationFrame& f : r.recording.frames)
    if (std::abs(f.t - t) < std::abs(best->t - t)) best = &f;
  return best->poses[static_cast<std::size_t>(k)].position;
}

// How far robot k got from where it stood at t within the next 10 s [m].
double farthest_in_10s(const ExplorationResult& r, double t, int k) {
  const Vec2 before = pose_at(r, t, k);
  double moved = 0.0;
  for (double dt = 1.0; dt <= 10.0; dt += 1.0)
    moved = std::max(moved, distance(pose_at(r, t + dt, k), before));
  return moved;
}

// The (watchdog event, "unstick" event of another robot at the same time) pairs of a run: the
// robots sent away for a stuck robot.
std::vector<std::pair<const ExplorationEvent*, const ExplorationEvent*>> moved_at_watchdogs(
    const ExplorationResult& r) {
  std::vector<std::pair<const ExplorationEvent*, const ExplorationEvent*>> out;
  for (const ExplorationEvent& w : r.recording.events) {
    if (w.kind != "watchdog") continue;
    for (const ExplorationEvent& u : r.recording.events)
      if (u.kind == "unstick" && u.robot != w.robot && u.t == w.t) out.emplace_back(&w, &u);
  }
  return out;
}

// Three robots of the paper's random search (no tree) for 120 s from the room's corner.
ExplorationOptions random_search_of_three(int seed) {
  ExplorationOptions o;
  o.method = ExplorationMethod::kTree;
  o.robots = 3;
  o.seed = static_cast<std::uint64_t>(seed);
  o.start = Vec2{0.8, 0.8};
  o.tree_start_time = 1000.0;  // the paper's random search the whole run
  o.time_limit = 120.0;
  return o;
}

TEST(Disperse, RobotsBesideAStuckRobotDriveAway) {
  int dispersed = 0, drove_away = 0;
  for (int seed = 1; seed <= 4; ++seed) {
    ExplorationOptions o = random_search_of_three(seed);
    o.stop_at_coverage = 1.01;
    o.disperse_neighbours = true;
    const ExplorationResult r = run_exploration(narrow_room(), o);
    EXPECT_EQ(r.collisions, 0);
    // A dispersal is an "unstick" event of another robot at the time of a watchdog event.
    const auto moved = moved_at_watchdogs(r);
    for (const auto& [w, u] : moved) {
      // It was within disperse_range (+ 1 s of driving between frames) and drove away.
      const Vec2 stuck = pose_at(r, w->t, w->robot), before = pose_at(r, w->t, u->robot);
      EXPECT_LT(distance(stuck, before), o.disperse_range + 0.5) << "seed " << seed;
      if (farthest_in_10s(r, w->t, u->robot) > 0.5) ++drove_away;
    }
    EXPECT_EQ(static_cast<int>(moved.size()), r.dispersals) << "seed " << seed;
    dispersed += r.dispersals;
    o.disperse_neighbours = false;
    EXPECT_EQ(run_exploration(narrow_room(), o).dispersals, 0);
  }
  EXPECT_GT(dispersed, 8);
  // Most drive 0.5 m or more from where they stood within 10 s (an unstick route may still be
  // stopped by the front guard, as in seed 2 once).
  EXPECT_GE(4 * drove_away, 3 * dispersed) << drove_away << " of " << dispersed;
}

TEST(ClearWayOut, RobotsInAStuckRobotsWayDriveAway) {
  int cleared = 0, drove_away = 0;
  for (int seed = 1; seed <= 4; ++seed) {
    ExplorationOptions o = random_search_of_three(seed);
    o.clear_way_out = true;
    const ExplorationResult r = run_exploration(narrow_room(), o);
    EXPECT_EQ(r.collisions, 0);
    EXPECT_EQ(r.dispersals, 0);  // disperse_neighbours stays off
    // A robot moved out of the way is an "unstick" event of another robot at the time of a
    // watchdog event.
    const auto moved = moved_at_watchdogs(r);
    for (const auto& [w, u] : moved)
      if (farthest_in_10s(r, w->t, u->robot) > 0.3) ++drove_away;
    EXPECT_EQ(static_cast<int>(moved.size()), r.way_clearances) << "seed " << seed;
    cleared += r.way_clearances;
    o.clear_way_out = false;
    EXPECT_EQ(run_exploration(narrow_room(), o).way_clearances, 0);
  }
  EXPECT_GE(cleared, 4);  // over the four runs
  EXPECT_GE(4 * drove_away, 3 * cleared) << drove_away << " of " << cleared;
}

}  // namespace
}  // namespace voronav::exploration
