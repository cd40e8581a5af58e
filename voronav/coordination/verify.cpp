#include "voronav/coordination/verify.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

Verification verify_schedule(const std::vector<Agent>& agents, std::span<const double> delays,
                             const VerifyOptions& options) {
  if (delays.size() != agents.size()) {
    throw Error("delays", 0,
                "expected " + std::to_string(agents.size()) + " delays, got " +
                    std::to_string(delays.size()));
  }
  for (std::size_t i = 0; i < delays.size(); ++i) {
    if (!(delays[i] >= 0.0) || !std::isfinite(delays[i])) {
      throw Error("delays", 0,
                  "robot " + std::to_string(agents[i].id) + ": expected a finite delay >= 0, got " +
                      std::to_string(delays[i]));
    }
  }
  if (!(options.tolerance >= 0.0)) throw Error("tolerance", 0, "expected >= 0");
  Verification out;
  const std::size_t n = agents.size();
  double horizon = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    horizon = std::max(horizon, delays[i] + agents[i].path.travel_time());
  auto window = [&](std::size_t i) {
    const double lo = options.at_start == AtStart::kWait ? 0.0 : delays[i];
    const double hi =
        options.at_goal == AtGoal::kStay ? horizon : delays[i] + agents[i].path.travel_time();
    return std::pair{lo, hi};
  };
  struct Interval {
    double t0, t1, d0, d1;
  };
  std::vector<Interval> stack;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const auto [lo_i, hi_i] = window(i);
      const auto [lo_j, hi_j] = window(j);
      const double lo = std::max(lo_i, lo_j);
      const double hi = std::min(hi_i, hi_j);
      // Presence is half-open, [departure, arrival): a robot that appears at the instant another
      // leaves does not meet it.
      const bool half_open =
          options.at_start == AtStart::kAppear || options.at_goal == AtGoal::kLeave;
      if (lo > hi || (lo == hi && half_open)) continue;
      const Agent& A = agents[i];
      const Agent& B = agents[j];
      const double rsum = A.radius + B.radius;
      const double limit = rsum - options.tolerance;
      const double vrel = A.path.limits().v_max + B.path.limits().v_max;
      auto dist = [&](double t) {
        return distance(A.path.position(t - delays[i]), B.path.position(t - delays[j]));
      };
      auto note = [&](double d) { out.min_clearance = std::min(out.min_clearance, d - rsum); };
      const double d_lo = dist(lo), d_hi = dist(hi);
      note(d_lo);
      note(d_hi);
      std::size_t splits = 0;
      bool found = false;
      stack.clear();
      if (d_lo < limit) {
        out.conflicts.push_back({static_cast<int>(i), static_cast<int>(j), lo, d_lo});
        continue;
      }
      stack.push_back({lo, hi, d_lo, d_hi});
      while (!stack.empty()) {
        const Interval iv = stack.back();
        stack.pop_back();
        if (0.5 * (iv.d0 + iv.d1 - vrel * (iv.t1 - iv.t0)) >= limit) continue;
        if (iv.d1 < limit) {
          out.conflicts.push_back({static_cast<int>(i), static_cast<int>(j), iv.t1, iv.d1});
          found = true;
          break;
        }
        if (iv.t1 - iv.t0 <= 1e-12) continue;
        if (++splits > options.max_splits_per_pair) {
          ++out.undecided_pairs;
          break;
        }
        const double tm = 0.5 * (iv.t0 + iv.t1);
        const double dm = dist(tm);
        note(dm);
        if (dm < limit) {
          out.conflicts.push_back({static_cast<int>(i), static_cast<int>(j), tm, dm});
          found = true;
          break;
        }
        stack.push_back({tm, iv.t1, dm, iv.d1});  // later half below: earlier half first
        stack.push_back({iv.t0, tm, iv.d0, dm});
      }
      (void)found;
    }
  }
  std::sort(out.conflicts.begin(), out.conflicts.end(),
            [](const Conflict& a, const Conflict& b) { return a.time < b.time; });
  out.valid = out.conflicts.empty() && out.undecided_pairs == 0;
  return out;
}

}  // namespace voronav::coordination
