// Occupancy values as ROS nav_msgs/OccupancyGrid uses them: 0 = free, 100 = occupied,
// 1..99 = probability of occupancy in %, -1 = unknown. OccupancyGrid is what every map loader
// returns; planners and Voronoi work on the BinaryGrid derived from it.
#pragma once

#include <cstdint>

#include "voronav/core/grid_map.hpp"

namespace voronav {

inline constexpr std::int8_t kFree = 0;
inline constexpr std::int8_t kOccupied = 100;
inline constexpr std::int8_t kUnknown = -1;

using OccupancyGrid = GridMap<std::int8_t>;
/// 1 = blocked, 0 = free.
using BinaryGrid = GridMap<std::uint8_t>;

struct BinarizeOptions {
  /// A cell with value >= this is blocked [0..100].
  int occupied_threshold = 50;
  /// Whether unknown (-1) cells are blocked.
  bool unknown_is_blocked = true;
};

/// Thresholds an occupancy grid into blocked (1) / free (0) cells.
[[nodiscard]] BinaryGrid binarize(const OccupancyGrid& grid, const BinarizeOptions& options = {});

}  // namespace voronav
