// Continuous-time verification of a schedule: no two robot discs ever overlap, and (when a map is
// given) no disc enters a blocked cell. This is the correctness net beyond seed 002: the collision
// boxes are an approximation (section 2.4.2), so every schedule the library returns is checked
// here before it is called valid, whatever produced it (start delays or SIPP's timed waypoints).
//
// Method: every robot's motion is a Trajectory (pieces of constant acceleration). For each pair of
// robots, on the time window where both are in the world, the exact minimum of the centre distance
// is computed per pair of pieces (trajectory.hpp: closed form for constant velocity, the roots of
// a cubic with acceleration). A pair conflicts when that minimum is below r_a + r_b - tolerance;
// discs that only touch (distance == r_a + r_b) are accepted, however long they touch.
// min_clearance is the exact minimum of d - (r_a + r_b) over all pairs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "voronav/coordination/trajectory.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::coordination {

/// With kAppear / kLeave a robot is in the world on [delay, delay + travel) (half-open), so one
/// that appears at the instant another leaves does not meet it.
struct VerifyOptions {
  AtStart at_start = AtStart::kWait;
  AtGoal at_goal = AtGoal::kStay;
  double tolerance = 1e-6;  ///< overlaps shallower than this [m] are accepted (touching discs)
};

struct Conflict {
  int a = 0;  ///< robot indices
  int b = 0;
  double time = 0.0;      ///< [s], where the pair's distance is smallest in its first overlap
  double distance = 0.0;  ///< centre distance at that time [m] (< r_a + r_b)
};

/// A robot disc that overlaps a blocked map cell.
struct WallHit {
  int robot = 0;          ///< robot index
  double time = 0.0;      ///< [s], start of the motion piece that enters the cell
  Cell cell;              ///< the blocked cell
  double distance = 0.0;  ///< distance from the centre's path to the cell [m] (< radius)
};

struct Verification {
  bool valid = true;
  std::vector<Conflict> conflicts;   ///< at most one per pair, sorted by time
  std::vector<WallHit> wall_hits;    ///< at most one per robot (when a map was checked)
  int undecided_pairs = 0;           ///< always 0 (the minimum is exact); kept for the JSON
  double min_clearance = kInfinity;  ///< min over pairs of d - (r_a + r_b) [m]; exact when valid
};

/// Checks robots `agents` departing after `delays` [s] (one per robot, >= 0, finite).
[[nodiscard]] Verification verify_schedule(const std::vector<Agent>& agents,
                                           std::span<const double> delays,
                                           const VerifyOptions& options = {});

/// Checks trajectories with disc radii (one per trajectory); overlaps shallower than `tolerance`.
[[nodiscard]] Verification verify_trajectories(std::span<const Trajectory> trajectories,
                                               std::span<const double> radii,
                                               double tolerance = 1e-6);

/// Adds to `v` the robots whose disc overlaps a blocked cell of `blocked` (1 = blocked; the cells
/// are squares of the grid's resolution) by more than `tolerance`; sets v.valid accordingly.
void check_map(Verification& v, std::span<const Trajectory> trajectories,
               std::span<const double> radii, const BinaryGrid& blocked, double tolerance = 1e-6);

}  // namespace voronav::coordination
