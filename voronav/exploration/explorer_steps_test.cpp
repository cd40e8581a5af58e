// run_exploration steps through the Stepper (core/stepper.hpp): the step count covers the time
// limit, frames are stamped at the end of their step (t = k * dt), and a limit over 1e9 steps is
// refused.
#include <gtest/gtest.h>

#include <string>

#include "voronav/core/error.hpp"
#include "voronav/exploration/explorer.hpp"

namespace voronav::exploration {
namespace {

TEST(ExplorerSteps, StepsCoverTheLimitAndFramesAreStampedAtStepEnds) {
  const OccupancyGrid world = paper_world(0.1);
  ExplorationOptions o;
  o.method = ExplorationMethod::kFrontier;
  o.robots = 2;
  o.start = kPaperWorldStart;
  o.time_limit = 2.34;    // 23.4 steps of 0.1 s: 24 steps (rounding to nearest would run 23)
  o.record_period = 0.7;  // 7 steps: frames after steps 7, 14, 21 and the last (24)
  const ExplorationResult r = run_exploration(world, o);
  const auto& f = r.recording.frames;
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0].t, 7 * 0.1);
  EXPECT_EQ(f[1].t, 14 * 0.1);
  EXPECT_EQ(f[2].t, 21 * 0.1);
  EXPECT_EQ(f[3].t, 24 * 0.1);
  EXPECT_EQ(r.sim_time_s, 24 * 0.1);
  EXPECT_GT(f[0].coverage, 0.0);  // the scans of step 0 are in the first frame
}

TEST(ExplorerSteps, OverABillionStepsIsRefused) {
  ExplorationOptions o;
  o.dt = 1e-6;
  o.time_limit = 1e4;  // 1e10 steps
  try {
    o.validate();
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.source(), "ExplorationOptions.time_limit");
    EXPECT_NE(e.reason().find("1e9"), std::string::npos) << e.reason();
  }
}

}  // namespace
}  // namespace voronav::exploration
