// (M,D) networks given by numbers rather than geometry, for the reproductions of seed 002:
//  - table4_network(): a 5-robot network consistent with Table 4 (figure 16 is missing from the
//    paper; arc costs derived in docs/reproductions/coordination.md).
//  - random_network(): the random generator of section 5.1 (N robots, P collision points spread
//    over the N(N-1)/2 pairs, T^traveled ~ U[40, 80] s, shared time M + D ~ U[4, 20] s,
//    D ~ U[-8, 8] s for the reference order "lower index first").
#pragma once

#include <cstdint>

#include "voronav/coordination/md_network.hpp"

namespace voronav::coordination {

/// Table 4 under the default EDF reading (arc cost k0 = M + D, EdfCost::kSharedTime).
[[nodiscard]] MdNetwork table4_network();
/// Table 4 under the other reading (arc cost = delay below the other robot, EdfCost::kDelay).
[[nodiscard]] MdNetwork table4_network_delay_reading();

struct RandomNetworkOptions {
  double travel_min = 40.0, travel_max = 80.0;  ///< T^traveled range [s]
  double shared_min = 4.0, shared_max = 20.0;   ///< k0 = M + D range [s]
  double d_min = -8.0, d_max = 8.0;             ///< D range [s]
};

/// `agents` robots and `points` collision boxes between uniformly drawn pairs; seeded.
[[nodiscard]] MdNetwork random_network(int agents, int points, std::uint64_t seed,
                                       const RandomNetworkOptions& options = {});

}  // namespace voronav::coordination
