// The world ends at the map's edge for the laser as for the body (issue 14, lab_intel seed 3):
// a map whose free space runs to its edge must not let a robot drive at an edge its laser cannot
// see, stop there on the footprint check and stay (stalled).
#include <gtest/gtest.h>

#include <algorithm>

#include "voronav/exploration/explorer.hpp"

namespace voronav::exploration {
namespace {

// 12 x 2 m, every cell free: no wall anywhere, only the map's edge.
OccupancyGrid open_world() {
  return OccupancyGrid(120, 20, kFree, 0.1);
}

// The longest time [s] robot k stayed within 0.5 m of one spot (the stall watch's measure; the
// run's stall count also needs reachable unknown space, which a small open world soon has not).
double longest_stay(const ExplorationResult& r, std::size_t k) {
  const auto& f = r.recording.frames;
  double longest = 0.0, since = f.front().t;
  Vec2 anchor = f.front().poses[k].position;
  for (const ExplorationFrame& fr : f) {
    if (distance(fr.poses[k].position, anchor) > 0.5) {
      anchor = fr.poses[k].position;
      since = fr.t;
    }
    longest = std::max(longest, fr.t - since);
  }
  return longest;
}

TEST(WorldEdge, ReactiveSearchInAnOpenWorldDoesNotStallAtTheEdge) {
  for (const ExplorationMethod m : {ExplorationMethod::kTree, ExplorationMethod::kCoordinated}) {
    ExplorationOptions o;
    o.method = m;
    o.robots = 1;
    o.start = Vec2{0.35, 0.35};
    o.time_limit = 150.0;
    o.stop_at_coverage = 1.01;  // keep driving: the stall watch runs the whole time
    const ExplorationResult r = run_exploration(open_world(), o);
    EXPECT_EQ(r.stalled_robots, 0) << "method " << static_cast<int>(m);
    // Before the edge was a wall for the laser, the robot stood 38 s and more at the edge
    // (coordinated: the laser saw open space ahead, the footprint check refused every step).
    EXPECT_LT(longest_stay(r, 0), 20.0) << "method " << static_cast<int>(m);
  }
}

}  // namespace
}  // namespace voronav::exploration
