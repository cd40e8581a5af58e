// Exact Euclidean distance transform of a binary grid (Felzenszwalb & Huttenlocher, "Distance
// Transforms of Sampled Functions", 2012): for every cell, the squared distance [cells^2] to the
// nearest blocked cell and which cell that is. Linear time; used for robot-radius clearance in the
// planners and as the basis of the generalized Voronoi diagram.
#pragma once

#include <cstdint>
#include <limits>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::field {

/// Index (row-major) of the nearest blocked cell; kNoSite when the grid has no blocked cell.
inline constexpr std::int32_t kNoSite = -1;

struct DistanceField {
  /// Squared Euclidean distance [cells^2] from each cell centre to the nearest blocked cell
  /// centre (0 on blocked cells). std::numeric_limits<float>::infinity() when nothing is blocked.
  GridMap<float> squared_distance;
  /// Row-major index of the nearest blocked cell, or kNoSite.
  GridMap<std::int32_t> nearest;

  /// Distance [m] from the cell centre to the nearest blocked cell centre.
  [[nodiscard]] double distance_m(Cell c) const;
};

struct DistanceTransformOptions {
  /// Whether cells outside the grid count as blocked (a wall around the map).
  bool border_is_blocked = false;
};

/// Exact EDT of `blocked` (non-zero = blocked cell, the sites).
[[nodiscard]] DistanceField distance_transform(const BinaryGrid& blocked,
                                               const DistanceTransformOptions& options = {});

/// Blocks every cell whose centre is closer than `radius_m` [m] to a blocked cell centre
/// (distance < radius). radius <= 0 returns a copy. Throws voronav::Error for NaN or negative radius.
[[nodiscard]] BinaryGrid inflate(const BinaryGrid& blocked, double radius_m);

}  // namespace voronav::field
