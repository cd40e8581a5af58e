// Room-segmentation scores against a ground truth (Bormann et al., ICRA 2016, the metric the
// issue's floor-plan table uses): per ground-truth room, the largest overlap with one region over
// the room's area (recall); per region, the largest overlap with one room over the region's area
// (precision); each averaged without weights. Cells that are outside every room (walls, door
// lines drawn in the ground truth) or outside every region are ignored.
#pragma once

#include <cstdint>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::topology {

struct SegmentationScores {
  double recall = 0.0;     ///< mean over rooms of best overlap / room area (0..1)
  double precision = 0.0;  ///< mean over regions of best overlap / region area (0..1)
  int rooms = 0;           ///< ground-truth rooms
  int regions = 0;         ///< segmented regions (that overlap the rooms' cells)
};

/// 4-connected components of the free (0) cells; -1 on blocked cells.
[[nodiscard]] GridMap<std::int32_t> free_components(const BinaryGrid& blocked);

/// Scores `regions` (id >= 0 per cell, -1 none) against `rooms` (same). Rooms with fewer than
/// `min_room_cells` cells (specks of free pixels inside walls of drawn ground truths) are ignored
/// like walls. Throws voronav::Error when the sizes differ.
[[nodiscard]] SegmentationScores segmentation_scores(const GridMap<std::int32_t>& regions,
                                                     const GridMap<std::int32_t>& rooms,
                                                     std::size_t min_room_cells = 0);

}  // namespace voronav::topology
