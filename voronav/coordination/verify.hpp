// Continuous-time verification of a schedule: no two robot discs ever overlap. This is the
// correctness net beyond seed 002: the collision boxes are an approximation (section 2.4.2), so
// every schedule the library returns is simulated here before it is called valid.
//
// Method: for each pair of robots, on the time window where both are in the world, the distance
// d(t) between the centres is Lipschitz with constant v_i + v_j, so on [t0, t1]
//   min d >= (d(t0) + d(t1) - (v_i + v_j)(t1 - t0)) / 2.
// Intervals whose bound is at least r_i + r_j - tolerance are cleared; the others are split until
// a sample shows an overlap deeper than the tolerance or the bound clears. This is exact up to the
// tolerance (no fixed sampling step that could miss a short overlap).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "voronav/coordination/timed_path.hpp"

namespace voronav::coordination {

/// With kAppear / kLeave a robot is in the world on [delay, delay + travel) (half-open), so one
/// that appears at the instant another leaves does not meet it.
struct VerifyOptions {
  AtStart at_start = AtStart::kWait;
  AtGoal at_goal = AtGoal::kStay;
  double tolerance = 1e-6;  ///< overlaps shallower than this [m] are accepted (touching discs)
  /// Work limit per pair (interval splits); a pair that hits it is reported as undecided.
  std::size_t max_splits_per_pair = 2'000'000;
};

struct Conflict {
  int a = 0;  ///< robot indices
  int b = 0;
  double time = 0.0;      ///< [s], the earliest overlap found for this pair
  double distance = 0.0;  ///< centre distance at that time [m] (< r_a + r_b)
};

struct Verification {
  bool valid = true;
  std::vector<Conflict> conflicts;   ///< at most one per pair, sorted by time
  int undecided_pairs = 0;           ///< pairs that hit the work limit (valid is then false)
  double min_clearance = kInfinity;  ///< smallest sampled d - (r_a + r_b) [m]
};

/// Checks robots `agents` departing after `delays` [s] (one per robot, >= 0, finite).
[[nodiscard]] Verification verify_schedule(const std::vector<Agent>& agents,
                                           std::span<const double> delays,
                                           const VerifyOptions& options = {});

}  // namespace voronav::coordination
