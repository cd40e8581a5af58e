// Tests of the exploration runner (seed 004 method and the frontier baselines).
#include <gtest/gtest.h>

#include <cmath>

#include "voronav/core/error.hpp"
#include "voronav/exploration/explorer.hpp"

namespace voronav::exploration {
namespace {

TEST(Explorer, PaperWorldTreeMethodFourRobots) {
  const OccupancyGrid world = paper_world(0.05);
  ExplorationOptions o;
  o.robots = 4;
  o.start = kPaperWorldStart;
  o.time_limit = 600.0;
  const ExplorationResult r = run_exploration(world, o);
  std::cerr << to_json(r) << "\n";
  EXPECT_EQ(r.collisions, 0);
  EXPECT_GT(r.feature_points, 10);
  EXPECT_GT(r.leaves, 0);
  EXPECT_GT(r.coverage, 0.5);
}

}  // namespace
}  // namespace voronav::exploration
