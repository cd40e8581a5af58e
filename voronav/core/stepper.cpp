#include "voronav/core/stepper.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "voronav/core/error.hpp"

namespace voronav {
namespace {

constexpr double kMaxSteps = 1e9;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void check_positive(double v, const std::string& option) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw Error(option, 0, "expected a positive finite number [s], got " + num(v));
}

}  // namespace

long step_count(double dt_s, double time_limit_s, const std::string& dt_option,
                const std::string& time_option) {
  check_positive(dt_s, dt_option);
  check_positive(time_limit_s, time_option);
  const double ratio = time_limit_s / dt_s;
  if (!(ratio <= kMaxSteps))
    throw Error(time_option, 0,
                "time limit / step is over 1e9 simulation steps: " + num(time_limit_s) + " s / " +
                    num(dt_s) + " s; give a shorter time limit or a longer step");
  // The fewest steps that cover the limit; a ratio a rounding error above an integer is that
  // integer (1.2 / 0.2 = 5.999999999999999, 0.7 / 0.1 = 7.000000000000001: 6 and 7 steps).
  const double whole = std::ceil(ratio - 1e-12 * std::max(1.0, ratio));
  return std::max(1L, static_cast<long>(whole));
}

Stepper::Stepper(double dt_s, double time_limit_s, const std::string& dt_option,
                 const std::string& time_option)
    : dt_(dt_s), steps_(step_count(dt_s, time_limit_s, dt_option, time_option)) {}

long Stepper::every(double period_s, const std::string& option) const {
  check_positive(period_s, option);
  const double ratio = period_s / dt_;
  if (!(ratio <= kMaxSteps))
    throw Error(option, 0, "period / step is over 1e9 steps: " + num(period_s) + " s");
  return std::max(1L, std::lround(ratio));
}

Stepper::Outcome Stepper::run(const Phases& p) const {
  if (p.sense_every < 1 || p.record_every < 1)
    throw Error("Stepper", 0,
                "sense_every and record_every must be >= 1 steps, got " +
                    std::to_string(p.sense_every) + " and " + std::to_string(p.record_every));
  Outcome out;
  for (long k = 0; k < steps_; ++k) {
    const Step s{k, time(k), time(k + 1)};
    if (p.sense && k % p.sense_every == 0) p.sense(s);
    if (p.decide) p.decide(s);
    if (p.move) p.move(s);
    out.steps = k + 1;
    if (p.record && ((k + 1) % p.record_every == 0 || k + 1 == steps_)) p.record(s);
    if (p.done && p.done()) {
      out.stopped = true;
      break;
    }
  }
  out.t_end = time(out.steps);
  if (p.finish) p.finish(out.t_end);
  return out;
}

}  // namespace voronav
