// Tests of the exploration runner's block clock (internal/block_clock.hpp): only a forward step
// taken ends a block; a new route or a refused step does not; the 3 s rule fires past 3 s.
#include <gtest/gtest.h>

#include "voronav/exploration/internal/block_clock.hpp"

namespace voronav::exploration::internal {
namespace {

constexpr double kDt = 0.1;  // the runner's default step (ExplorationOptions::dt)

// n refused steps of dt each.
void refuse(BlockClock& c, int n, double dt = kDt) {
  for (int k = 0; k < n; ++k)
    c.on_step_refused(dt);
}

TEST(BlockClock, StartsUnblockedWithTheRunnersThreshold) {
  const BlockClock c;
  EXPECT_EQ(c.blocked_for(), 0.0);
  EXPECT_EQ(c.threshold(), 3.0);
  EXPECT_FALSE(c.fires());
}

TEST(BlockClock, RefusedStepsAddUpAndFireAfterThreeSeconds) {
  BlockClock c;
  refuse(c, 29);  // 2.9 s
  EXPECT_NEAR(c.blocked_for(), 2.9, 1e-9);
  EXPECT_FALSE(c.fires());
  refuse(c, 2);  // 3.1 s
  EXPECT_NEAR(c.blocked_for(), 3.1, 1e-9);
  EXPECT_TRUE(c.fires());
}

TEST(BlockClock, NewRouteWhileNotSteppingDoesNotResetTheBlock) {
  // A robot re-routed every 2 s in a jam (willow, 16 robots): the rule must still fire at 3 s.
  BlockClock c;
  refuse(c, 20);  // 2.0 s
  c.on_new_route();
  EXPECT_NEAR(c.blocked_for(), 2.0, 1e-9);
  refuse(c, 11);  // 3.1 s in all
  EXPECT_TRUE(c.fires());
  c.on_new_route();
  EXPECT_TRUE(c.fires());
}

TEST(BlockClock, RefusedStepDoesNotResetTheBlock) {
  // A step the front guard let through but the footprint check refused is no progress.
  BlockClock c;
  refuse(c, 25);  // 2.5 s
  c.on_step_refused(0.6);
  EXPECT_NEAR(c.blocked_for(), 3.1, 1e-9);
  EXPECT_TRUE(c.fires());
}

TEST(BlockClock, ForwardStepTakenEndsTheBlock) {
  BlockClock c;
  refuse(c, 29);  // 2.9 s
  c.on_forward_step_taken();
  EXPECT_EQ(c.blocked_for(), 0.0);
  refuse(c, 29);  // 2.9 s again: 5.8 s blocked in all, but never 3 s in a row
  EXPECT_FALSE(c.fires());
  refuse(c, 2);
  EXPECT_TRUE(c.fires());
}

TEST(BlockClock, FiresStrictlyPastItsThresholdAndStartsAgainAfterFiring) {
  // dt = 0.5 s sums exactly: 6 steps are 3 s (not past the threshold), 7 are 3.5 s.
  BlockClock c;
  refuse(c, 6, 0.5);
  EXPECT_EQ(c.blocked_for(), 3.0);
  EXPECT_FALSE(c.fires());
  refuse(c, 1, 0.5);
  EXPECT_TRUE(c.fires());
  c.on_fired();
  EXPECT_EQ(c.blocked_for(), 0.0);
  EXPECT_FALSE(c.fires());

  BlockClock one_second(1.0);
  refuse(one_second, 2, 0.5);
  EXPECT_FALSE(one_second.fires());
  refuse(one_second, 1, 0.5);
  EXPECT_TRUE(one_second.fires());
}

}  // namespace
}  // namespace voronav::exploration::internal
