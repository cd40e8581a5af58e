// The GA operators over priority orders of seed 002, section 4.2.2 (not installed), shared by the
// delay GA (priority_search.cpp) and the GA over SIPP orders (sipp_ga.cpp):
//  - dpx(): DPX crossover, the parents' common edges kept, the fragments reconnected greedily;
//  - mutate(): removes mutation_min..max random edges and reconnects without them;
//  - reconnect(): the greedy reconnection, always appending the fragment whose head has the
//    largest weight (M + D) with the current tail, random among ties and for the first fragment;
//    with no weights every fragment ties, i.e. a random reconnection;
//  - segment_move(): a random 3-opt move for the asymmetric case (a segment moved elsewhere, not
//    reversed: the only 3-opt move that keeps every edge's direction).
// Orders are sequences of local indices 0..n-1; node n is the virtual start of the TSP path.
#pragma once

#include <random>
#include <vector>

namespace voronav::coordination::internal {

using GaRng = std::mt19937_64;

/// Uniform integer in [lo, hi].
[[nodiscard]] inline int uniform(GaRng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

class GaOperators {
 public:
  /// `weight`: n x n row-major reconnection weights (weight[a * n + b] for edge a -> b), or empty
  /// for a random reconnection.
  GaOperators(int n, std::vector<double> weight) : n_(n), weight_(std::move(weight)) {}

  /// succ[v] = the node after v (-1 for the last), succ[n] = the first node.
  [[nodiscard]] std::vector<int> successors(const std::vector<int>& seq) const;
  /// DPX: keeps the edges common to both parents, reconnects the fragments greedily without
  /// edges of either parent where possible.
  [[nodiscard]] std::vector<int> dpx(const std::vector<int>& pa, const std::vector<int>& pb,
                                     GaRng& rng) const;
  /// Removes a random number of edges in [min_edges, max_edges] and reconnects without them.
  [[nodiscard]] std::vector<int> mutate(const std::vector<int>& seq, int min_edges, int max_edges,
                                        GaRng& rng) const;

  /// A random segment move of `seq` (n >= 3): the segment [i, j] moved to position k of the rest.
  /// Returns false (after drawing) when the draw is not a move. Else `cand` is the new order and
  /// only its positions [from, to) differ from `seq`'s.
  static bool segment_move(const std::vector<int>& seq, GaRng& rng, std::vector<int>& cand,
                           int& from, int& to);

 private:
  /// forbidden(a, b): edge a -> b must not be created; forbidden(-1, b): b must not be first.
  template <class Forbidden>
  std::vector<int> reconnect(std::vector<std::vector<int>> frags, Forbidden forbidden,
                             GaRng& rng) const;

  int n_;
  std::vector<double> weight_;
};

}  // namespace voronav::coordination::internal
