// ExplorationOptions::unstick_retry (issue 14, stop 28): a robot the progress watchdog found on
// one spot plans its unstick route again, every unstick_retry_period, while it has none and has
// not left the spot, until the next watchdog. The jam it is meant for, traced on willow (16
// robots, the paper's tree, seeds 1 and 12): a robot in a dead-end pocket 1.3 m wide and 1.5 m
// deep whose way out the robots of the random search block at the mouth; its one attempt per
// watchdog (every 20 s) was stopped or found no route, and it stayed 60 s. Here the same pocket,
// cut into a small room, with six robots of the paper's random search starting in it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "voronav/exploration/explorer.hpp"

namespace voronav::exploration {
namespace {

// A room of 5 x 4 m with a dead-end pocket of 1.3 x 1.5 m below it (0.1 m cells): pocket x
// 1.2-2.5 m, y 0.2-1.7 m; room x 0.2-5.2 m, y 1.7-5.7 m.
OccupancyGrid room_with_pocket() {
  OccupancyGrid w(54, 59, kOccupied, 0.1);
  for (int y = 17; y < 57; ++y)
    for (int x = 2; x < 52; ++x)
      w[Cell{x, y}] = kFree;
  for (int y = 2; y < 17; ++y)
    for (int x = 12; x < 25; ++x)
      w[Cell{x, y}] = kFree;
  return w;
}

// The longest time [s] robot k stayed within stall_distance of one spot, by the stall watch's rule
// (the spot moves when the robot leaves its circle), read from the recorded frames (1 s apart).
double longest_stay(const ExplorationResult& r, std::size_t k, double stall_distance) {
  double best = 0.0, since = 0.0;
  Vec2 at = r.recording.frames.front().poses[k].position;
  for (const ExplorationFrame& f : r.recording.frames) {
    if (distance(f.poses[k].position, at) > stall_distance) {
      at = f.poses[k].position;
      since = f.t;
    }
    best = std::max(best, f.t - since);
  }
  return best;
}

ExplorationOptions six_in_the_pocket(int seed, bool retry) {
  ExplorationOptions o;
  o.method = ExplorationMethod::kTree;
  o.robots = 6;
  o.seed = static_cast<std::uint64_t>(seed);
  o.start = Vec2{1.85, 0.95};  // the spiral puts all six in the pocket
  o.tree_start_time = 1000.0;  // the paper's random search the whole run
  o.time_limit = 150.0;
  o.stop_at_coverage = 1.01;
  o.unstick_retry = retry;
  o.unstick_right_of_way = false;  // the retry alone (the right of way is tested apart)
  return o;
}

TEST(UnstickRetry, RobotsLeaveADeadEndPocketBeforeTheSecondWatchdog) {
  const OccupancyGrid world = room_with_pocket();
  int long_stays_without = 0;
  // Seeds where, without the retry, a robot needed the second watchdog (> 33 s on one spot).
  for (const int seed : {1, 8, 11, 12}) {
    const ExplorationResult off = run_exploration(world, six_in_the_pocket(seed, false));
    const ExplorationResult on = run_exploration(world, six_in_the_pocket(seed, true));
    EXPECT_EQ(off.unstick_retries, 0) << "seed " << seed;
    EXPECT_GT(on.unstick_retries, 0) << "seed " << seed;
    EXPECT_EQ(on.collisions, 0) << "seed " << seed;
    double stay_off = 0.0, stay_on = 0.0;
    for (std::size_t k = 0; k < 6; ++k) {
      stay_off = std::max(stay_off, longest_stay(off, k, 0.5));
      stay_on = std::max(stay_on, longest_stay(on, k, 0.5));
    }
    if (stay_off > 33.0) ++long_stays_without;
    // With the retry every robot leaves each spot within 30 s: one watchdog (20 s) and the
    // retries after it, not the next watchdog at 40 s.
    EXPECT_LE(stay_on, 30.0) << "seed " << seed << " (without the retry " << stay_off << " s)";
  }
  EXPECT_GE(long_stays_without, 3);
}

}  // namespace
}  // namespace voronav::exploration
