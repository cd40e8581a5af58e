// ExplorationOptions::disperse_neighbours (issue 14, stop 26): when the progress watchdog fires
// for a robot of the paper's tree method, the robots without a route within disperse_range of
// it drive unstick routes to open space first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

TEST(Disperse, RobotsBesideAStuckRobotDriveAway) {
  int dispersed = 0, drove_away = 0;
  for (int seed = 1; seed <= 4; ++seed) {
    ExplorationOptions o;
    o.method = ExplorationMethod::kTree;
    o.robots = 3;
    o.seed = static_cast<std::uint64_t>(seed);
    o.start = Vec2{0.8, 0.8};
    o.tree_start_time = 1000.0;  // the paper's random search the whole run
    o.time_limit = 120.0;
    o.stop_at_coverage = 1.01;
    o.disperse_neighbours = true;
    const ExplorationResult r = run_exploration(narrow_room(), o);
    EXPECT_EQ(r.collisions, 0);
    // A dispersal is an "unstick" event of another robot at the time of a watchdog event.
    int found = 0;
    for (const ExplorationEvent& w : r.recording.events) {
      if (w.kind != "watchdog") continue;
      for (const ExplorationEvent& u : r.recording.events) {
        if (u.kind != "unstick" || u.robot == w.robot || u.t != w.t) continue;
        ++found;
        // It was within disperse_range (+ 1 s of driving between frames) and drove away.
        const Vec2 stuck = pose_at(r, w.t, w.robot), before = pose_at(r, w.t, u.robot);
        EXPECT_LT(distance(stuck, before), o.disperse_range + 0.5) << "seed " << seed;
        double moved = 0.0;
        for (double dt = 1.0; dt <= 10.0; dt += 1.0)
          moved = std::max(moved, distance(pose_at(r, w.t + dt, u.robot), before));
        if (moved > 0.5) ++drove_away;
      }
    }
    EXPECT_EQ(found, r.dispersals) << "seed " << seed;
    dispersed += r.dispersals;
    o.disperse_neighbours = false;
    EXPECT_EQ(run_exploration(narrow_room(), o).dispersals, 0);
  }
  EXPECT_GT(dispersed, 8);
  // Most drive 0.5 m or more from where they stood within 10 s (an unstick route may still be
  // stopped by the front guard, as in seed 2 once).
  EXPECT_GE(4 * drove_away, 3 * dispersed) << drove_away << " of " << dispersed;
}

}  // namespace
}  // namespace voronav::exploration
