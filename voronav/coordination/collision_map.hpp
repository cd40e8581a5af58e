// The (extended) collision map of two robots, seed 002 sections 2.2-2.4 and 3.1.
//
// The higher-priority robot (A1, "high") never changes its motion; the lower one (A2, "low") is
// a point and A1 a disc of radius r1 + r2. The collision map is the plane (servo time of A1) x
// (normalized travelled length of A2); A2's TLVSTC (travelled length vs servo time curve) must not
// enter the collision region.
//  - collision_interval(): the exact straight-segment test, the quadratic in lambda of eq. 5.
//  - collision_region(): the exact region, sampled in time with eq. 5 (for pictures, fig. 3).
//  - collision_points(): the extended collision map, node pairs closer than r_i + r_j (fig. 5, 6).
//  - collision_boxes(): path segments of conflicting nodes and their collision boxes with the
//    variables T1..T4, M = T3 - T1 and D = T4 - T2 (Table 2), classified as in Table 3.
//
// Conservativeness (our addition; the paper does not discuss node spacing): paths are resampled
// every h = node_spacing metres and node pairs closer than r_i + r_j + h count as collision
// points; box times are widened by h/2 of travel on each side. Then every real overlap of the two
// discs lies inside a box, so resolving all boxes gives a collision-free schedule.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "voronav/coordination/timed_path.hpp"

namespace voronav::coordination {

/// Options shared by the collision map, the (M,D) network and the verifier.
struct CollisionMapOptions {
  /// Path node spacing h [m] for the extended collision map; 0 = automatic
  /// (half the smallest robot radius).
  double node_spacing = 0.0;
  AtStart at_start = AtStart::kWait;
  AtGoal at_goal = AtGoal::kStay;
  /// The paper's literal rule: node pairs closer than r_i + r_j, box times at the segment's
  /// first and last node, no margin. Faster boxes, but conflicts between nodes can be missed
  /// (the verifier then repairs them).
  bool paper_literal = false;
};

/// Eq. 5: the range [lambda_lo, lambda_hi] within [0, 1] of the points a + lambda (b - a) that are
/// strictly closer than r to p1, or nothing. A zero-length segment gives [0, 1] or nothing.
[[nodiscard]] std::optional<std::pair<double, double>> collision_interval(Vec2 p1, Vec2 a, Vec2 b,
                                                                          double r);

/// A collision point cp(t_n, l_m) of the extended collision map (seed 002, fig. 6).
struct CollisionPoint {
  int m = 0;         ///< node index on the low robot's resampled path
  int n = 0;         ///< node index on the high robot's resampled path
  double t_n = 0.0;  ///< time [s] after departure at which the high robot reaches node n
  double l_m = 0.0;  ///< normalized travelled length [0, 1] of the low robot at node m
};

/// Collision box of one path segment (seed 002, Table 2). Times are in each robot's own clock
/// (0 = its departure, i.e. before any start delay). A segment containing the start of a robot
/// that waits there has T_enter = -infinity; one containing the goal of a robot that stays there
/// has T_leave = +infinity. M and D are then infinite: M = inf never blocks, D = inf means no start
/// delay of the low robot can resolve the box.
struct CollisionBox {
  int high = 0;                       ///< index of the higher-priority robot (A1)
  int low = 0;                        ///< index of the lower-priority robot (A2)
  int high_first = 0, high_last = 0;  ///< the high robot's path segment (resampled node indices)
  int low_first = 0, low_last = 0;    ///< the low robot's path segment PS_{i,k}
  double t1 = 0.0;                    ///< A1 enters its segment
  double t2 = 0.0;                    ///< A2 enters its segment
  double t3 = 0.0;                    ///< A2 leaves its segment
  double t4 = 0.0;                    ///< A1 leaves its segment
  double l_s = 0.0, l_e = 0.0;        ///< the low robot's segment as normalized length (box height)

  /// Max start delay of A2 that keeps the box collision-free: M = T3 - T1.
  [[nodiscard]] double m() const { return t3 - t1; }
  /// Min start delay of A2 that avoids the collision: D = T4 - T2.
  [[nodiscard]] double d() const { return t4 - t2; }
};

/// Table 3, by the signs of M and D after start delays of the high and low robot.
enum class BoxCase {
  kHighFirst,  ///< M > 0, D <= 0: A2 enters after A1 has left (T1 < T4 <= T2 < T3)
  kCollision,  ///< M > 0, D > 0: the robots share the segment at the same time
  kLowFirst,   ///< M <= 0, D > 0: A2 has left before A1 enters (T2 < T3 <= T1 < T4)
};
[[nodiscard]] BoxCase classify(double m, double d);
[[nodiscard]] inline BoxCase classify(const CollisionBox& b, double high_delay = 0.0,
                                      double low_delay = 0.0) {
  return classify(b.m() + low_delay - high_delay, b.d() - low_delay + high_delay);
}

/// The node spacing h actually used for `agents` with `options`.
[[nodiscard]] double effective_node_spacing(const std::vector<Agent>& agents,
                                            const CollisionMapOptions& options);

/// Extended collision map of `low` against `high`: node pairs closer than r1 + r2 + margin
/// (margin = spacing by default, 0 with paper_literal).
[[nodiscard]] std::vector<CollisionPoint> collision_points(const Agent& high, const Agent& low,
                                                           double spacing, double margin);
[[nodiscard]] inline std::vector<CollisionPoint> collision_points(const Agent& high,
                                                                  const Agent& low,
                                                                  double spacing) {
  return collision_points(high, low, spacing, spacing);
}

/// Collision boxes of `low` (index low_index) against `high` (index high_index): one box per
/// 8-connected group of collision points, i.e. per pair of conflicting path segments.
[[nodiscard]] std::vector<CollisionBox> collision_boxes(const Agent& high, int high_index,
                                                        const Agent& low, int low_index,
                                                        double spacing,
                                                        const CollisionMapOptions& options);

/// The exact collision region (eq. 5) sampled every `dt` seconds of the high robot's clock:
/// for each sample, the normalized-length intervals of the low robot's path inside the disc
/// r1 + r2 around the high robot (fig. 3).
struct RegionSample {
  double t = 0.0;
  std::vector<std::pair<double, double>> intervals;
};
[[nodiscard]] std::vector<RegionSample> collision_region(const Agent& high, const Agent& low,
                                                         double dt);

}  // namespace voronav::coordination
