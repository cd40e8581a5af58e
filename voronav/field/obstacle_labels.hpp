// Obstacle labels: every blocked cell gets the id of its 8-connected obstacle component. The
// generalized Voronoi diagram (seed 003, section III) separates cells whose nearest obstacles are
// different components, which is what makes the labeled Voronoi diagram meaningful.
#pragma once

#include <cstdint>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::field {

/// Label of a free cell.
inline constexpr std::int32_t kNoLabel = -1;

struct ObstacleLabels {
  /// Component id (0..count-1, numbered in row-major order of their first cell) per blocked
  /// cell; kNoLabel on free cells.
  GridMap<std::int32_t> label;
  int count = 0;
};

/// 8-connected components of the blocked (non-zero) cells. Linear time.
[[nodiscard]] ObstacleLabels label_obstacles(const BinaryGrid& blocked);

}  // namespace voronav::field
