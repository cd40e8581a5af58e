#include "voronav/exploration/unstick.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "voronav/field/distance_transform.hpp"

namespace voronav::exploration {

std::optional<Cell> unstick_target(const BinaryGrid& grid, const planning::BfsFlood& flood,
                                   const field::DistanceField& clear, const UnstickOptions& o) {
  const double res = grid.geometry().resolution;
  const auto lo = static_cast<std::int32_t>(std::ceil(o.min_path / res - 1e-9));
  const auto hi = static_cast<std::int32_t>(std::floor(o.max_path / res + 1e-9));
  std::optional<Cell> best;
  double best_clear = -1.0;
  std::int32_t best_steps = 0;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Cell c = grid.cell_at(k);
    const std::int32_t st = flood.steps(grid, c);
    if (st < lo || st > hi) continue;
    const double cl = std::min(o.clearance_cap, clear.distance_m(c));
    if (cl > best_clear + 1e-9 || (std::abs(cl - best_clear) <= 1e-9 && st < best_steps)) {
      best = c;
      best_clear = cl;
      best_steps = st;
    }
  }
  return best;
}

}  // namespace voronav::exploration
