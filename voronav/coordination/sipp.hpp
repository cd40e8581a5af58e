// Safe interval path planning (SIPP, Phillips & Likhachev, ICRA 2011) for one disc robot among
// moving discs of higher priority, and prioritized planning with it (issue #21).
//
// Graph: the grid's cells, 8-connected without corner cutting (as the library's grid planners),
// on the map already inflated for the robot (make_planning_grid). Motion: constant speed v_max
// between cell centres, instantaneous stops and starts (a_max = infinity; SIPP refuses finite
// a_max, see docs/coordination.md). Time is continuous. The higher-priority robots are
// trajectories (trajectory.hpp) with disc radii, including their presence before departure and
// after arrival (--at-start wait|appear, --at-goal stay|leave).
//
//  - Safe intervals of a cell: the complement of the times at which some higher-priority disc is
//    closer than r + r_j to the cell centre (a quadratic per constant-velocity piece).
//  - An edge move u -> v departing at t_d conflicts with a piece when the two discs overlap during
//    the move; the departures that conflict form an open interval (the projection of a convex
//    set: an ellipse in (t_d, s) clipped by the parallelogram where move and piece overlap in
//    time), computed in closed form. The search departs at the earliest time that is inside u's
//    safe interval, outside every such interval, and lands in a safe interval of v.
//  - Touching (distance exactly r + r_j) is allowed, as in the checker.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "voronav/coordination/trajectory.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::coordination {

/// Higher-priority robots as moving discs, indexed by the grid cells they come near.
class Reservations {
 public:
  /// `max_radius`: the largest radius of a robot that will plan against these reservations.
  Reservations(const GridGeometry& geometry, double max_radius);
  /// Adds a robot (its pieces must have zero acceleration). Presence before the first piece and
  /// after the last one (trajectory.present_from / present_to) is a stationary disc.
  void add(const Trajectory& trajectory, double radius);
  /// A stationary disc at `p` on [s0, s1] that belongs to robot `owner`: the search ignores it
  /// when SippOptions::inactive_owners marks the owner (used for the starts and goals of robots not
  /// planned yet, which prioritized planning avoids when it can).
  void add_soft(Vec2 p, double radius, double s0, double s1, int owner);

  struct Segment {
    double s0 = 0.0, s1 = 0.0;  ///< [s], s1 may be infinity (stationary then)
    Vec2 p0, z;                 ///< position at s0, velocity
    double radius = 0.0;
    int owner = -1;  ///< -1: always active
  };
  [[nodiscard]] const std::vector<Segment>& segments() const { return segments_; }
  [[nodiscard]] const std::vector<int>& near(Cell c) const { return cells_[geometry_.index(c)]; }
  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }

 private:
  void add_segment(const Segment& s);
  GridGeometry geometry_;
  double max_radius_ = 0.0;
  std::vector<Segment> segments_;
  std::vector<std::vector<int>> cells_;
};

struct SippOptions {
  AtStart at_start = AtStart::kWait;
  AtGoal at_goal = AtGoal::kStay;
  std::size_t max_expansions = 200'000;  ///< give up after this many state expansions
  /// Accepted overlap [m] in the safety tests (floating point slack; the checker accepts 1e-6).
  double slack = 1e-7;
  /// Owners whose soft discs are ignored (index = owner; empty or missing = active).
  const std::vector<char>* inactive_owners = nullptr;
};

struct SippStats {
  std::size_t expansions = 0;
  std::size_t generated = 0;
};

/// Plans `radius`/`v_max` robot from `start` to `goal` on `free` (0 = free, inflated already)
/// against `reserved`. Returns timed waypoints (cell centres; waits are repeated points) or nothing
/// when no plan exists within the expansion limit. Under kStay the robot must be able to stay at
/// its goal forever; under kWait it is at its start from time 0.
[[nodiscard]] std::optional<std::vector<TimedWaypoint>> sipp_plan(
    const BinaryGrid& free, Cell start, Cell goal, double radius, double v_max,
    const Reservations& reserved, const SippOptions& options = {}, SippStats* stats = nullptr);

/// Open intervals of departure times t_d at which moving from `from` to `to` at speed `v`
/// (duration |to - from| / v) brings a disc of radius `radius` closer than radius + s.radius -
/// slack to segment `s`; empty when never. Exposed for tests.
[[nodiscard]] std::optional<std::pair<double, double>> bad_departures(
    Vec2 from, Vec2 to, double v, double radius, const Reservations::Segment& s, double slack);

}  // namespace voronav::coordination
