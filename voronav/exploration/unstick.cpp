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
  std::int32_t best_index = 0;
  // Only the cells the flood reached, in its order (steps never decrease): stop past max_path.
  for (const std::int32_t k : flood.reached()) {
    const Cell c = grid.cell_at(static_cast<std::size_t>(k));
    const std::int32_t st = flood.steps(grid, c);
    if (st > hi) break;
    if (st < lo) continue;
    const double cl = std::min(o.clearance_cap, clear.distance_m(c));
    const bool tie = std::abs(cl - best_clear) <= 1e-9;
    if (cl > best_clear + 1e-9 ||
        (tie && (st < best_steps || (st == best_steps && k < best_index)))) {
      best = c;
      best_clear = cl;
      best_steps = st;
      best_index = k;
    }
  }
  return best;
}

}  // namespace voronav::exploration
