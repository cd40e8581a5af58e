// run_netsim steps through the Stepper (core/stepper.hpp): the step count covers the time limit,
// every recorded step is stamped t_k = k * dt, and a limit over 1e9 steps is refused naming the
// option.
#include <gtest/gtest.h>

#include <string>

#include "voronav/core/error.hpp"
#include "voronav/sim/netsim.hpp"
#include "voronav/sim/test_halls.hpp"

namespace voronav::sim {
namespace {

TEST(NetSimSteps, StepsCoverTheLimitAndAreStampedKTimesDt) {
  const NetSimScenario sc = testing::two_row_hall(40, std::nullopt);
  NetSimOptions o;
  o.time_limit_s = 1.1;  // 5.5 steps of 0.2 s: 6 steps (the source is 27 m from its goal)
  o.record = true;
  const NetSimResult r = run_netsim(sc, o);
  ASSERT_EQ(r.recording.steps.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_EQ(r.recording.steps[k].t_s, static_cast<double>(k + 1) * 0.2) << k;
  EXPECT_EQ(r.metrics.simulated_s, 6 * 0.2);
  EXPECT_FALSE(r.metrics.success);
}

TEST(NetSimSteps, OverABillionStepsIsRefused) {
  NetSimOptions o;
  o.dt_s = 1e-7;  // 900 s: 9e9 steps
  try {
    o.validate();
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.source(), "netsim.time_limit_s");
    EXPECT_NE(e.reason().find("1e9"), std::string::npos) << e.reason();
  }
  o.dt_s = 0.0;
  EXPECT_THROW(o.validate(), Error);
}

}  // namespace
}  // namespace voronav::sim
