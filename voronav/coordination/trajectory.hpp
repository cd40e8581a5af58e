// Trajectory: a robot's motion in continuous time as pieces of constant acceleration along straight
// lines, p(t) = p0 + v (t - t0) + a (t - t0)^2 / 2 on [t0, t1], plus the window in which the robot
// is in the world. Both kinds of schedule map onto it: a fixed path with a start delay (seed 002,
// the trapezoid profile of TimedPath: cruise pieces have a = 0, the acceleration phases a != 0) and
// timed waypoints (SIPP, constant speed between waypoints, waits as pieces with v = 0).
//
// min_distance() is the exact minimum of |p_a(t) - p_b(t)| over a common time interval: for two
// constant-velocity pieces the closed form of the quadratic |d(t)|^2; with acceleration the
// quartic's stationary points are the roots of a cubic, isolated between the roots of its
// derivative and bisected to machine precision. This is what the continuous-time checker uses.
#pragma once

#include <span>
#include <vector>

#include "voronav/coordination/timed_path.hpp"

namespace voronav::coordination {

struct Piece {
  double t0 = 0.0, t1 = 0.0;  ///< [s], t0 <= t1
  Vec2 p0;                    ///< position at t0 [m]
  Vec2 v;                     ///< velocity at t0 [m/s]
  Vec2 a;                     ///< constant acceleration [m/s^2]
  [[nodiscard]] Vec2 at(double t) const {
    const double s = t - t0;
    return p0 + v * s + a * (0.5 * s * s);
  }
};

/// Pieces sorted by time and contiguous; before the first piece the robot is at its first point,
/// after the last at its last point. It is in the world on [present_from, present_to]
/// (present_to = infinity: stays forever).
struct Trajectory {
  std::vector<Piece> pieces;
  double present_from = 0.0;
  double present_to = kInfinity;
  /// Half-open presence: the robot appears at present_from or leaves at present_to, so two robots
  /// whose windows only touch do not meet.
  bool half_open = false;
  [[nodiscard]] Vec2 position(double t) const;
  [[nodiscard]] double end_time() const { return pieces.empty() ? 0.0 : pieces.back().t1; }
  [[nodiscard]] Vec2 end_point() const;
};

/// A fixed path with a start delay under the presence conventions (seed 002).
[[nodiscard]] Trajectory trajectory_of(const TimedPath& path, double delay, AtStart at_start,
                                       AtGoal at_goal);

/// A timed waypoint: the robot is at `p` at time `t`; between waypoints it moves at constant
/// velocity (equal positions = a wait).
struct TimedWaypoint {
  double t = 0.0;
  Vec2 p;
};
/// Timed waypoints (strictly increasing t) under the presence conventions: with kWait the robot
/// is at its first waypoint from time 0, with kAppear from the first waypoint's time; with kStay it
/// stays at the last one, with kLeave it leaves at the last waypoint's time.
[[nodiscard]] Trajectory trajectory_of(std::span<const TimedWaypoint> waypoints, AtStart at_start,
                                       AtGoal at_goal);

struct MinDistance {
  double distance = kInfinity;  ///< [m]
  double time = 0.0;            ///< [s] where it is attained
};
/// Exact minimum of |a(t) - b(t)| for t in [lo, hi] (both pieces evaluated by their formula).
[[nodiscard]] MinDistance min_distance(const Piece& a, const Piece& b, double lo, double hi);
/// Exact minimum of the distance between two trajectories over [lo, hi].
[[nodiscard]] MinDistance min_distance(const Trajectory& a, const Trajectory& b, double lo,
                                       double hi);
/// Stops at the first piece pair (in time) whose minimum is below `limit`, returning it; else the
/// overall minimum.
[[nodiscard]] MinDistance first_below(const Trajectory& a, const Trajectory& b, double lo,
                                      double hi, double limit);

}  // namespace voronav::coordination
