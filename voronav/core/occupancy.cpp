#include "voronav/core/occupancy.hpp"

namespace voronav {

BinaryGrid binarize(const OccupancyGrid& grid, const BinarizeOptions& options) {
  BinaryGrid out(grid.geometry(), 0);
  const auto in = grid.data();
  auto dst = out.data();
  for (std::size_t i = 0; i < in.size(); ++i) {
    const int v = in[i];
    dst[i] = v < 0 ? (options.unknown_is_blocked ? 1 : 0) : (v >= options.occupied_threshold ? 1 : 0);
  }
  return out;
}

}  // namespace voronav
