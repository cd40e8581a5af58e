// ExplorationOptions::retry_banned (issue 14, stop 19): depot, 2 robots, coordinated, seed 3
// ended at 69.1 % coverage after 900 s without a stall: by 360 s both robots had banned every
// frontier left (most after the 3 s block rule fired at clutter next to their routes), had no
// goal and wandered reactively for the remaining 540 s. A goalless robot that may take again
// the goals it gave up when blocked explores the rest. The blocks were the cone guard stopping
// robots at clutter beside their routes (FrontGuard::kCone, the default until stop 21); with
// the corridor guard the same run needs no reset.
#include <gtest/gtest.h>

#include <string>

#include "voronav/exploration/explorer.hpp"
#include "voronav/io/map_loader.hpp"

namespace voronav::exploration {
namespace {

TEST(RetryBanned, GoallessRobotsTakeTheirBlockedGoalsAgainOnDepot) {
  const OccupancyGrid depot =
      io::load_map(std::string(VORONAV_SOURCE_DIR) + "/data/ros_maps/depot/depot.yaml").grid;
  ExplorationOptions o;
  o.method = ExplorationMethod::kCoordinated;
  o.robots = 2;
  o.time_limit = 900.0;
  o.seed = 3;
  o.stop_at_coverage = 0.995;
  o.guard = FrontGuard::kCone;  // the guard of the traced run
  o.margin_escape = false;      // the traced run had no margin escape (default since stop 25)
  const ExplorationResult on = run_exploration(depot, o);
  EXPECT_GT(on.ban_resets, 0);
  EXPECT_GE(on.coverage, 0.99);
  EXPECT_EQ(on.stalled_robots, 0);
  o.retry_banned = false;  // before: every frontier banned, coverage frozen at 69.1 %
  const ExplorationResult off = run_exploration(depot, o);
  EXPECT_EQ(off.ban_resets, 0);
  EXPECT_LT(off.coverage, 0.75);
  // Stop 25: the blocked robots stood inside the planning margin of that clutter; the margin
  // escape drives them out of it, so no goal is banned for good even without retry_banned.
  o.margin_escape = true;
  const ExplorationResult escape = run_exploration(depot, o);
  EXPECT_GT(escape.margin_escapes, 0);
  EXPECT_GE(escape.coverage, 0.99);
  EXPECT_EQ(escape.stalled_robots, 0);
  o.margin_escape = false;
  // Stop 21: the corridor guard does not stop the robots at that clutter; no goal is banned
  // for good, even without retry_banned.
  o.guard = FrontGuard::kCorridor;
  const ExplorationResult corridor = run_exploration(depot, o);
  EXPECT_GE(corridor.coverage, 0.99);
  EXPECT_EQ(corridor.stalled_robots, 0);
}

}  // namespace
}  // namespace voronav::exploration
