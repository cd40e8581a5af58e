// Tests of the shared stepping loop (stepper.hpp): step counts, period rounding, the order and
// times of the phases, the stop condition and the errors, all hand-computed.
#include "voronav/core/stepper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav {
namespace {

long steps(double dt, double limit) {
  return step_count(dt, limit, "t.dt", "t.limit");
}

TEST(Stepper, StepCountCoversTheLimit) {
  EXPECT_EQ(steps(0.2, 900.0), 4500);
  EXPECT_EQ(steps(0.1, 600.0), 6000);
  // Ratios a rounding error off an integer are that integer.
  EXPECT_EQ(steps(0.2, 1.2), 6);  // 5.999999999999999
  EXPECT_EQ(steps(0.1, 0.7), 7);  // 6.999999999999999
  EXPECT_EQ(steps(0.1, 0.3), 3);  // 2.9999999999999996
  // Otherwise the fewest steps that cover the limit (rounding to nearest would give 33).
  EXPECT_EQ(steps(0.3, 10.0), 34);
  EXPECT_EQ(steps(0.3, 9.1), 31);  // 30.33...
  // A limit shorter than one step is one step.
  EXPECT_EQ(steps(0.5, 0.1), 1);
  // 1e9 steps is the most.
  EXPECT_EQ(steps(1e-3, 1e6), 1000000000L);
  const Stepper s(0.3, 10.0, "t.dt", "t.limit");
  EXPECT_EQ(s.steps(), 34);
  EXPECT_DOUBLE_EQ(s.dt(), 0.3);
}

TEST(Stepper, BadInputIsAnErrorNamingTheOption) {
  const auto source_of = [](double dt, double limit) {
    try {
      (void)steps(dt, limit);
    } catch (const Error& e) {
      return e.source() + ": " + e.reason();
    }
    return std::string("no error");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(source_of(0.0, 10.0).rfind("t.dt: expected a positive finite number", 0), 0u);
  EXPECT_EQ(source_of(-0.1, 10.0).rfind("t.dt: ", 0), 0u);
  EXPECT_EQ(source_of(nan, 10.0).rfind("t.dt: ", 0), 0u);
  EXPECT_EQ(source_of(inf, 10.0).rfind("t.dt: ", 0), 0u);
  EXPECT_EQ(source_of(0.1, 0.0).rfind("t.limit: expected a positive finite number", 0), 0u);
  EXPECT_EQ(source_of(0.1, nan).rfind("t.limit: ", 0), 0u);
  EXPECT_EQ(source_of(0.1, inf).rfind("t.limit: ", 0), 0u);
  // 1e10 steps: refused before anything runs, naming the limit, the values and the bound.
  const std::string big = source_of(1e-9, 10.0);
  EXPECT_EQ(big.rfind("t.limit: ", 0), 0u) << big;
  EXPECT_NE(big.find("1e9"), std::string::npos) << big;
  EXPECT_NE(big.find("10 s / 1e-09 s"), std::string::npos) << big;
  EXPECT_THROW(Stepper(1e-9, 10.0, "t.dt", "t.limit"), Error);
  EXPECT_THROW((void)steps(1e-300, 1e300), Error);

  const Stepper s(0.1, 1.0, "t.dt", "t.limit");
  EXPECT_THROW((void)s.every(0.0, "t.period"), Error);
  EXPECT_THROW((void)s.every(-1.0, "t.period"), Error);
  EXPECT_THROW((void)s.every(nan, "t.period"), Error);
  EXPECT_THROW((void)s.every(1e300, "t.period"), Error);
  try {
    (void)s.every(0.0, "t.period");
  } catch (const Error& e) {
    EXPECT_EQ(e.source(), "t.period");
  }
  Stepper::Phases p;
  p.sense_every = 0;
  EXPECT_THROW((void)s.run(p), Error);
  p.sense_every = 1;
  p.record_every = -2;
  EXPECT_THROW((void)s.run(p), Error);
}

TEST(Stepper, PeriodsRoundToTheNearestWholeStep) {
  const Stepper s(0.1, 10.0, "t.dt", "t.limit");
  EXPECT_EQ(s.every(0.5, "p"), 5);
  EXPECT_EQ(s.every(1.0, "p"), 10);
  EXPECT_EQ(s.every(0.15, "p"), 1);  // 1.4999999999999998 steps
  EXPECT_EQ(s.every(0.17, "p"), 2);  // 1.7 steps: nearest, not floor
  EXPECT_EQ(s.every(0.04, "p"), 1);  // shorter than a step: every step
  const Stepper h(0.5, 10.0, "t.dt", "t.limit");
  EXPECT_EQ(h.every(1.25, "p"), 3);  // 2.5 steps: halves round up
  EXPECT_EQ(h.every(0.74, "p"), 1);  // 1.48 steps
}

// Every phase appends "<phase><k>@<time>" so that order, periods and times are checked at once.
struct Log {
  std::string text;
  void add(const char* what, long k, double t) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%ld@%g ", what, k, t);
    text += buf;
  }
};

Stepper::Phases logging_phases(Log& log) {
  Stepper::Phases p;
  p.sense = [&log](const Stepper::Step& s) { log.add("S", s.k, s.t); };
  p.decide = [&log](const Stepper::Step& s) { log.add("D", s.k, s.t); };
  p.move = [&log](const Stepper::Step& s) { log.add("M", s.k, s.t_end); };
  p.record = [&log](const Stepper::Step& s) { log.add("R", s.k, s.t_end); };
  p.finish = [&log](double t) { log.add("F", -1, t); };
  return p;
}

TEST(Stepper, PhasesRunInOrderAtTheirTimes) {
  // 4 steps of 0.5 s; sensing every 1 s (2 steps) from t = 0, a frame every 1.5 s (3 steps)
  // at the step's end, and one at the end of the run.
  const Stepper s(0.5, 2.0, "t.dt", "t.limit");
  Log log;
  Stepper::Phases p = logging_phases(log);
  p.sense_every = s.every(1.0, "sense");
  p.record_every = s.every(1.5, "record");
  const Stepper::Outcome out = s.run(p);
  EXPECT_EQ(log.text,
            "S0@0 D0@0 M0@0.5 "
            "D1@0.5 M1@1 "
            "S2@1 D2@1 M2@1.5 R2@1.5 "
            "D3@1.5 M3@2 R3@2 "
            "F-1@2 ");
  EXPECT_EQ(out.steps, 4);
  EXPECT_EQ(out.t_end, 2.0);
  EXPECT_FALSE(out.stopped);
}

TEST(Stepper, DoneStopsAfterTheStepsRecordThenFinishes) {
  const Stepper s(0.5, 10.0, "t.dt", "t.limit");
  Log log;
  Stepper::Phases p = logging_phases(log);
  int checks = 0;
  p.done = [&] {
    log.add("?", checks, 0.0);
    return ++checks == 2;  // true after the second step
  };
  const Stepper::Outcome out = s.run(p);
  EXPECT_EQ(log.text,
            "S0@0 D0@0 M0@0.5 R0@0.5 ?0@0 "
            "S1@0.5 D1@0.5 M1@1 R1@1 ?1@0 "
            "F-1@1 ");
  EXPECT_EQ(out.steps, 2);
  EXPECT_EQ(out.t_end, 1.0);
  EXPECT_TRUE(out.stopped);
}

TEST(Stepper, TheClockIsComputedNotAccumulated) {
  // Ten additions of 0.1 give 0.9999999999999999; t_10 must be 10 * 0.1 = 1 exactly.
  const Stepper s(0.1, 1.0, "t.dt", "t.limit");
  ASSERT_EQ(s.steps(), 10);
  double sum = 0.0;
  long seen = 0;
  Stepper::Phases p;
  p.move = [&](const Stepper::Step& st) {
    EXPECT_EQ(st.t, static_cast<double>(st.k) * 0.1);
    EXPECT_EQ(st.t_end, static_cast<double>(st.k + 1) * 0.1);
    EXPECT_EQ(st.k, seen++);
    sum += 0.1;
  };
  double end = -1.0;
  p.finish = [&](double t) { end = t; };
  EXPECT_EQ(s.run(p).t_end, 1.0);
  EXPECT_EQ(end, 1.0);
  EXPECT_EQ(seen, 10);
  EXPECT_NE(sum, 1.0);  // what an accumulated clock would have said
  EXPECT_EQ(s.time(3), 3 * 0.1);
}

}  // namespace
}  // namespace voronav
