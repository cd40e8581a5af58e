// The (M,D) network of seed 002, section 3.2, and the delay resolution of section 3.2.2.
//
// Nodes are robots (start delay, pure travel time T^traveled); every collision box between two
// robots is an arc from the higher- to the lower-priority robot with cost (M, D) (Table 2).
// The network is stored once, for the reference priority "lower index first"; the network of any
// other order follows from the symmetry rule (swapping the priority of two robots swaps M and D,
// section 3.3.2), and start delays shift M and D (section 3.1.2): delaying the low robot by T2d
// gives M' = M + T2d, D' = D - T2d; delaying the high robot by T1d gives M' = M - T1d,
// D' = D + T1d. So M + D = k0 is constant.
//
// Resolution (section 3.2.2): robots are processed in priority order; each is delayed by the max D
// over its colliding incoming arcs (M > 0 and D > 0). The paper stops there; we repeat the step
// until no incoming arc collides, because the delay can push an arc that was "low passes first"
// (M <= 0) into collision. The repeated step yields the smallest delay >= the minimum for which no
// incoming arc collides. An arc with D = infinity (the low robot waits at its start inside the
// high robot's segment, or the high robot stays on its goal inside the low robot's segment) cannot
// be resolved by a start delay: the order then has status kNoDelaySchedule.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "voronav/coordination/collision_map.hpp"

namespace voronav::coordination {

/// Times closer than this [s] count as equal when deciding whether an arc collides (M > eps and
/// D > eps), so that rounding cannot make the resolution loop add ever smaller delays.
inline constexpr double kTimeEpsilon = 1e-9;

/// One collision box between robots a < b: (M, D) when a has priority over b and nobody is
/// delayed.
struct MdBox {
  int a = 0;
  int b = 0;
  double m = 0.0;
  double d = 0.0;
};

class MdNetwork {
 public:
  MdNetwork() = default;
  /// Robots with travel times T^traveled [s] (>= 0, finite) and no boxes yet.
  explicit MdNetwork(std::vector<double> travel_times);

  [[nodiscard]] int size() const { return static_cast<int>(travel_.size()); }
  [[nodiscard]] const std::vector<double>& travel_times() const { return travel_; }
  [[nodiscard]] const std::vector<MdBox>& boxes() const { return boxes_; }
  /// Indices into boxes() of the boxes that involve robot i.
  [[nodiscard]] const std::vector<int>& incident(int i) const {
    return incident_[static_cast<std::size_t>(i)];
  }
  /// Adds a box between robots i != j with (M, D) given for "i has priority over j".
  void add_box(int i, int j, double m, double d);
  /// (M, D) of box k when robot `high` has priority over the other robot of the box, with start
  /// delays of the high and the low robot (symmetry rule + delay update rules).
  [[nodiscard]] std::pair<double, double> oriented(int k, int high, double high_delay = 0.0,
                                                   double low_delay = 0.0) const;
  /// k0 = M + D summed over the boxes between i and j (the greedy reconnection weight of the GA).
  [[nodiscard]] double shared_time(int i, int j) const;

 private:
  std::vector<double> travel_;
  std::vector<MdBox> boxes_;
  std::vector<std::vector<int>> incident_;
};

/// Builds the network of `agents` from their collision boxes (seed 002, sections 2.4-3.2).
[[nodiscard]] MdNetwork build_network(const std::vector<Agent>& agents,
                                      const CollisionMapOptions& options = {});

enum class ResolveStatus {
  kOk,
  kNoDelaySchedule,  ///< some arc has D = infinity: no start delay resolves this order
};
[[nodiscard]] std::string_view to_string(ResolveStatus s);

/// Delays and arrival times of one priority order.
struct Resolution {
  ResolveStatus status = ResolveStatus::kOk;
  std::vector<double> delays;      ///< T^delayed per robot [s] (by robot index)
  std::vector<double> completion;  ///< T^completed = T^traveled + T^delayed (eq. 9)
  double makespan = 0.0;           ///< J = max T^completed (eq. 8)
  double sum_of_arrivals = 0.0;
  int blocked = -1;     ///< with kNoDelaySchedule: the robot that cannot be delayed out of it
  int blocked_by = -1;  ///< ... and the higher-priority robot of that arc
  bool cut = false;     ///< MoveEvaluator::resolve_move stopped early (makespan above the cutoff)
};

/// Resolves `order` (a permutation of 0..N-1, highest priority first). `min_delays`, when given,
/// are lower bounds on the delays (used to repair conflicts the boxes missed).
[[nodiscard]] Resolution resolve(const MdNetwork& net, std::span<const int> order,
                                 std::span<const double> min_delays = {});

/// Incremental resolve() for local search over orders (the GA's 3-opt, issue #16). Built once per
/// network: per robot its boxes as arcs oriented "the other robot above" (in incident order) and
/// its distinct neighbours.
///
/// resolve_move(): `order` equals `base_order` outside the positions [from, to) (a segment move
/// permutes only those); `base` = resolve(net, base_order). A robot's delay is a function of the
/// set of its higher neighbours and their delays (resolve() visits its boxes in incident order,
/// filtered by rank), so a robot is resolved again only when
///  - it lies in [from, to) and some neighbour changed sides (above <-> below) with it, or
///  - a higher neighbour's delay differs from its delay in `base` (bitwise);
/// every other robot keeps its delay from `base`. Stops (Resolution::cut, makespan infinity) as
/// soon as a completion time exceeds `cutoff`: such an order cannot beat one of makespan <= cutoff.
/// Otherwise the result equals resolve(net, order) bitwise (tested). Throws voronav::Error when
/// an order is not a permutation of the robots.
class MoveEvaluator {
 public:
  explicit MoveEvaluator(const MdNetwork& net);
  [[nodiscard]] Resolution resolve_move(std::span<const int> base_order, const Resolution& base,
                                        std::span<const int> order, int from, int to,
                                        double cutoff);
  /// Robots resolved again by the last resolve_move() (the others kept their delay).
  [[nodiscard]] int last_resolved() const { return last_resolved_; }

 private:
  struct Arc {
    int j;     ///< the other robot (above)
    double m;  ///< (M, D) with j above, no delays
    double d;
  };
  const MdNetwork& net_;
  std::vector<Arc> arcs_;                 ///< per robot, in incident order
  std::vector<int> arc_begin_;            ///< robot i: arcs_[arc_begin_[i], arc_begin_[i+1])
  std::vector<int> nbrs_, nbr_begin_;     ///< distinct neighbours, same layout
  std::vector<int> rank_old_, rank_new_;  ///< scratch
  std::vector<char> dirty_;               ///< scratch
  struct Active {
    double m, d, hd;  ///< hd: the higher robot's delay
    int j;
  };
  std::vector<Active> act_;  ///< scratch: the boxes with higher robots
  int last_resolved_ = 0;
};

/// An arc of the network of a given order: from `high` to `low`, (M, D) after the delays.
struct OrientedArc {
  int high = 0;
  int low = 0;
  double m = 0.0;
  double d = 0.0;
};
/// The (M,D) network of `order` (symmetry rule), with the given delays applied (empty = none).
[[nodiscard]] std::vector<OrientedArc> network_for_order(const MdNetwork& net,
                                                         std::span<const int> order,
                                                         std::span<const double> delays = {});

/// Throws voronav::Error unless `order` is a permutation of 0..n-1.
void check_order(std::span<const int> order, int n);

}  // namespace voronav::coordination
