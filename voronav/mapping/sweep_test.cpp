#include "voronav/mapping/sweep.hpp"

#include <gtest/gtest.h>

#include "voronav/core/error.hpp"

namespace voronav::mapping {
namespace {

BinaryGrid box_world() {
  BinaryGrid g(GridGeometry{60, 40, 0.1, {}}, 0);
  for (int x = 0; x < 60; ++x)
    g[Cell{x, 0}] = g[Cell{x, 39}] = 1;
  for (int y = 0; y < 40; ++y)
    g[Cell{0, y}] = g[Cell{59, y}] = 1;
  for (int y = 15; y < 25; ++y)
    for (int x = 25; x < 35; ++x)
      g[Cell{x, y}] = 1;  // a pillar
  return g;
}

TEST(Sweep, LaserSweepRebuildsTheWorld) {
  const BinaryGrid truth = box_world();
  const SweepResult r = simulate_sweep(truth, {.poses = 30, .seed = 3});
  EXPECT_EQ(r.poses.size(), 30u);
  for (const Pose2& p : r.poses) {
    const auto c = truth.geometry().world_to_cell(p.position);
    ASSERT_TRUE(c && truth.contains(*c));
    EXPECT_EQ(truth[*c], 0) << "poses are on free cells";
  }
  EXPECT_GT(r.agreement.observed, 0.9);
  EXPECT_GT(r.agreement.agreement, 0.95);
  // Same seed, same map.
  const SweepResult again = simulate_sweep(truth, {.poses = 30, .seed = 3});
  EXPECT_EQ(again.map.threshold(), r.map.threshold());
}

TEST(Sweep, SonarSweepObservesLess) {
  const BinaryGrid truth = box_world();
  const SweepResult r = simulate_sweep(truth, {.sensor = SweepSensor::kSonar, .poses = 30});
  EXPECT_GT(r.agreement.agreement, 0.6);
  EXPECT_GT(r.agreement.compared, 0u);
}

TEST(Sweep, BadOptions) {
  const BinaryGrid truth = box_world();
  EXPECT_THROW((void)simulate_sweep(truth, {.poses = 0}), Error);
  EXPECT_THROW((void)simulate_sweep(truth, {.clearance = 100.0}), Error);
  EXPECT_THROW((void)simulate_sweep(truth, {.range = -1.0}), Error);
  EXPECT_THROW((void)simulate_sweep(BinaryGrid(GridGeometry{5, 5, 0.1, {}}, 1)), Error);
}

}  // namespace
}  // namespace voronav::mapping
