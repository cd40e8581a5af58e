// Room-segmentation scores against a ground truth (Bormann et al., ICRA 2016): per ground-truth
// room, the largest overlap with one region over the room's area (recall); per region, the
// largest overlap with one room over the region's area (precision); each averaged without
// weights. Two definitions:
//  - ipa (the ipa_room_segmentation evaluation, the common one): rooms are the 8-connected white
//    components of the ground truth over 100 pixels; regions of 100 pixels or less are dropped;
//    the areas are the full room and the full region (a region cell outside every room, e.g. on
//    a door line or furniture drawn in the ground truth, counts against precision);
//  - intersection (voronav's earlier score): rooms are 4-connected components of at least
//    min_room_cells, every region is kept, and both areas are cut to the cells inside both a room
//    and a region, so door lines and furniture are never errors (higher figures).
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

/// 4-connected (or 8-connected) components of the free (0) cells; -1 on blocked cells.
[[nodiscard]] GridMap<std::int32_t> free_components(const BinaryGrid& blocked, bool eight = false);

/// The ipa_room_segmentation score: rooms = 8-connected free components of `ground_truth` with
/// more than min_pixels cells, regions with more than min_pixels cells, full areas (see the file
/// comment). Throws voronav::Error when the sizes differ.
[[nodiscard]] SegmentationScores segmentation_scores_ipa(const GridMap<std::int32_t>& regions,
                                                         const BinaryGrid& ground_truth,
                                                         std::size_t min_pixels = 100);

/// Nearest-neighbour resampling of a grid to width x height (for ground truths drawn at another
/// scale than the map).
[[nodiscard]] BinaryGrid resample_nearest(const BinaryGrid& grid, int width, int height);

/// Scores `regions` (id >= 0 per cell, -1 none) against `rooms` (same). Rooms with fewer than
/// `min_room_cells` cells (specks of free pixels inside walls of drawn ground truths) are ignored
/// like walls. Throws voronav::Error when the sizes differ.
[[nodiscard]] SegmentationScores segmentation_scores(const GridMap<std::int32_t>& regions,
                                                     const GridMap<std::int32_t>& rooms,
                                                     std::size_t min_room_cells = 0);

}  // namespace voronav::topology
