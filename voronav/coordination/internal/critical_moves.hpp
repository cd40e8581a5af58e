// The critical-first 3-opt neighbourhood of the delay GA (issue #16; not installed).
//
// The makespan J = max T^completed (seed 002, eq. 8) is set by the critical robot c (the last to
// arrive). c's delay is the sum of the shifts of its colliding boxes with higher robots (section
// 3.2.2): its "blockers". A move lowers c's completion only if it changes the set of higher
// neighbours of c or of a robot whose delay c depends on (see can_lower_makespan()). So instead of
// the paper's uniform random segment moves, critical_moves() lists the moves that lift the critical
// robot (and the robots delaying it) above a blocker, or drop a blocker below it, most shifting
// blocker first.
#pragma once

#include <random>
#include <vector>

#include "voronav/coordination/md_network.hpp"

namespace voronav::coordination::internal {

/// A segment move of a sequence: the segment [i, j] moved to position k of the sequence without
/// it (GaOperators::segment_move's encoding).
struct SegmentMove {
  int i = 0;
  int j = 0;
  int k = 0;
  friend bool operator==(const SegmentMove&, const SegmentMove&) = default;
};

/// Builds the moved sequence: cand = seq with [m.i, m.j] at position m.k of the rest; from/to = the
/// positions that differ. Requires 0 <= i <= j < n and 0 <= k <= n - (j - i + 1), k != i.
void apply_segment_move(const std::vector<int>& seq, const SegmentMove& m, std::vector<int>& cand,
                        int& from, int& to);

/// Draws a uniform random segment move of a sequence of n >= 2 (the distribution of
/// GaOperators::segment_move); false when the draw is not a move.
[[nodiscard]] bool random_segment_move(int n, std::mt19937_64& rng, SegmentMove& m);

/// The blocks a segment move swaps, as positions of the old sequence: A = [a_begin, a_end) above
/// B = [a_end, b_end) before the move, B above A after it.
struct SwappedBlocks {
  int a_begin, a_end, b_end;
};
[[nodiscard]] SwappedBlocks swapped_blocks(const SegmentMove& m);

/// The critical robot of a resolution: the largest completion (ties: the lowest in the order),
/// or the blocked robot of an order no delay resolves; -1 if none.
[[nodiscard]] int critical_robot(const Resolution& res, const std::vector<int>& rank);

struct Blocker {
  int robot = 0;       ///< the higher robot
  double shift = 0.0;  ///< how much its boxes delayed the robot in the resolution
};

/// The robots whose boxes shifted robot x when `res` was resolved for the order with ranks `rank`
/// (rank[robot] = position), the largest total shift first (ties: the higher robot first).
/// Repeats resolve()'s passes for x alone, so the shifts sum to res.delays[x].
[[nodiscard]] std::vector<Blocker> blockers(const MdNetwork& net, const std::vector<int>& rank,
                                            const Resolution& res, int x);

/// The critical-first candidate moves of a sequence whose robots take the first n positions of the
/// full order (the robots below do not move), for the resolution `res` of the full order with
/// ranks `rank`: for the critical robot c (largest completion, or the blocked robot of an order no
/// delay resolves) and, to `depth` levels, the robots that delay it, each robot x and each of its
/// blockers b in `seq` gives "x just above b" and "b just below x". No move is listed twice.
[[nodiscard]] std::vector<SegmentMove> critical_moves(const MdNetwork& net, int n,
                                                      const std::vector<int>& rank,
                                                      const Resolution& res, int depth);

/// A delayed robot x and one of its blockers b (the sum-of-arrivals side of the neighbourhood):
/// the moves "x just above b" and "b just below x", by robot, so that they stay meaningful while
/// a sweep changes the order.
struct DelayedPair {
  int x = 0;
  int b = 0;
  friend bool operator==(const DelayedPair&, const DelayedPair&) = default;
};

/// For every robot x in the first n positions with a positive delay, the latest completion first,
/// each of its blockers b (blockers(), largest shift first). Empty unless res is kOk.
[[nodiscard]] std::vector<DelayedPair> delayed_pairs(const MdNetwork& net, int n,
                                                     const std::vector<int>& rank,
                                                     const Resolution& res);

/// The exact cut: false only when the move cannot lower the makespan. Let S be the critical robot
/// c with, recursively, every higher neighbour of a robot in S (all that c's delay depends on;
/// `in_support` marks S by robot). A segment move swaps two adjacent blocks A (above) and B; it
/// changes the set of higher neighbours only of robots in a neighbouring pair (a in A, b in B).
/// If no robot of A in S has a neighbour in B, every robot of S keeps its higher neighbours, so
/// (by induction down the order) its delay, bitwise: c's completion, and so J, cannot drop.
/// `order` is the full order (global robots); the move's blocks are given by positions
/// [a_begin, a_end) and [a_end, b_end).
[[nodiscard]] bool can_lower_makespan(const MdNetwork& net, const std::vector<int>& order,
                                      const std::vector<char>& in_support, int a_begin, int a_end,
                                      int b_end, std::vector<char>& scratch);

/// Marks S (see can_lower_makespan()) for the robot c in the order with ranks `rank`.
void support_of(const MdNetwork& net, const std::vector<int>& rank, int c,
                std::vector<char>& in_support);

}  // namespace voronav::coordination::internal
