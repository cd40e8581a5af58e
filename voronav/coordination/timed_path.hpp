// TimedPath: a robot's fixed path (a polyline through path nodes) travelled with a trapezoidal
// velocity profile, |p'| <= v_max and |p''| <= a_max, always at the highest speed the profile
// allows (seed 002, section 2.1, eq. 2). The robot starts and ends at rest and does not slow
// down at the corners of the polyline (the paper assumes the offline path planner shapes paths so
// that curvature never limits speed). a_max = infinity is the paper's "instantaneous
// acceleration" special case (sections 3.2.1 and 5.1).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "voronav/core/vec2.hpp"

namespace voronav::coordination {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Kinematic limits of one robot (seed 002, eq. 2).
struct MotionLimits {
  double v_max = 1.0;        ///< maximum speed [m/s], > 0 and finite
  double a_max = kInfinity;  ///< maximum acceleration [m/s^2], > 0; infinity = instantaneous
};

/// One robot: a disc of `radius` [m] moving along `path` (seed 002, eq. 1).
class TimedPath {
 public:
  TimedPath() = default;
  /// Throws voronav::Error for an empty path, non-finite points or invalid limits.
  TimedPath(std::vector<Vec2> nodes, MotionLimits limits);

  [[nodiscard]] const std::vector<Vec2>& nodes() const { return nodes_; }
  [[nodiscard]] const MotionLimits& limits() const { return limits_; }
  /// Total path length [m].
  [[nodiscard]] double length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
  /// T^traveled: time from departure to arrival [s] (seed 002, eq. 9).
  [[nodiscard]] double travel_time() const { return travel_time_; }
  /// Arc length [m] travelled `t` seconds after departure (clamped to [0, length]).
  [[nodiscard]] double arc_at(double t) const;
  /// Time [s] after departure at which arc length `s` is reached (clamped to [0, length]).
  [[nodiscard]] double time_at_arc(double s) const;
  /// Point on the polyline at arc length `s` (clamped).
  [[nodiscard]] Vec2 point_at_arc(double s) const;
  /// Position `t` seconds after departure (start before, goal after).
  [[nodiscard]] Vec2 position(double t) const { return point_at_arc(arc_at(t)); }
  /// Speed [m/s] `t` seconds after departure.
  [[nodiscard]] double speed(double t) const;
  /// Cumulative arc length at each node [m].
  [[nodiscard]] const std::vector<double>& cumulative() const { return cumulative_; }

 private:
  std::vector<Vec2> nodes_;
  std::vector<double> cumulative_;
  MotionLimits limits_;
  double travel_time_ = 0.0;
  double t_accel_ = 0.0;  // duration of the acceleration (= deceleration) phase
  double v_peak_ = 0.0;   // peak speed reached (v_max or less for a triangular profile)
};

/// What a robot does before its delayed departure (seed 002 assumes it waits at its start).
enum class AtStart { kWait, kAppear };
/// What a robot does after arrival: stays on its goal (default) or leaves the world (the MAPF
/// continuous variant's "disappear at goal").
enum class AtGoal { kStay, kLeave };

/// One robot of a coordination problem: a disc of `radius` [m] on a timed path.
struct Agent {
  int id = 0;  ///< user-visible id (e.g. 1-based as in the paper, or the .scen row)
  TimedPath path;
  double radius = 0.5;  ///< [m], > 0
};

/// Path nodes of `path` resampled so that consecutive nodes are at most `spacing` [m] apart
/// along the path (original vertices are kept). Used by the extended collision map (seed 002,
/// section 2.4.1). Returns the arc length of each node in `arcs`.
[[nodiscard]] std::vector<Vec2> resample(const TimedPath& path, double spacing,
                                         std::vector<double>* arcs);

}  // namespace voronav::coordination
