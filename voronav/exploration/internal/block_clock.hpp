// The exploration runner's block clock (issue 14; not installed): how long a robot that wants to
// drive forward has taken no forward step. The front guard stopping it, or the footprint check
// refusing its step, adds the step's dt; only a forward step actually taken ends a block. A new
// route (same goal re-routed, or a new goal) deliberately does not: resetting on it, or on a step
// the guard let through but the footprint check refused, kept robots standing still with the
// rule never firing (willow, 16 robots; commit 6e9e5e9). When the clock exceeds its threshold
// the runner drops the goal (or skips the waypoint) and the clock starts again from zero.
#pragma once

namespace voronav::exploration::internal {

class BlockClock {
 public:
  static constexpr double kDefaultThreshold = 3.0;  ///< [s] the runner's 3 s block rule

  explicit BlockClock(double threshold = kDefaultThreshold) : threshold_(threshold) {}

  /// The guard stopped the robot, or the footprint check refused its step: dt [s] without a step.
  void on_step_refused(double dt) { blocked_ += dt; }
  /// A forward step was taken (the footprint check let a v > 0 command through): the block ends.
  void on_forward_step_taken() { blocked_ = 0.0; }
  /// A new route: not progress, the clock goes on (no-op, kept so the call sites say so).
  void on_new_route() {}
  /// True when the robot has been blocked for longer than the threshold (the rule fires).
  [[nodiscard]] bool fires() const { return blocked_ > threshold_; }
  /// The rule fired and the runner acted on it: the clock starts again.
  void on_fired() { blocked_ = 0.0; }
  /// [s] time blocked so far.
  [[nodiscard]] double blocked_for() const { return blocked_; }
  [[nodiscard]] double threshold() const { return threshold_; }

 private:
  double threshold_;
  double blocked_ = 0.0;
};

}  // namespace voronav::exploration::internal
