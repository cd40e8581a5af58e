// The information gain of a target in an exploration run (run_exploration; not installed): the
// fraction of the cells within a radius of it that the team map does not know. It ranks
// kTreeFrontier's targets, and min_leaf_gain filters tree leaves with it (TreeReplan::kFromRobots,
// skip_known_leaves). `through_free` (ExplorationOptions::gain_through_free, ours) counts only the
// unknown cells that connect to the target through cells not known to be occupied: the unknown
// inside a closed obstacle (a shelf's hollow, a pillar's core) can never be observed, and counted
// it kept targets beside shelves attractive for ever (depot, tree-frontier seed 14, stop 24).
#pragma once

#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::exploration::internal {

/// Unknown cells within `radius` [m] of p over all cells within it (0 when p is off the map
/// with `through_free`, or not a finite point).
/// Cells off the map count as unknown unless `through_free`; with `through_free` only the
/// unknown cells reached from p's cell by a 4-connected walk inside the disc over cells of the map
/// that are not occupied (value < 50) count.
[[nodiscard]] double information_gain(const OccupancyGrid& map, Vec2 p, double radius,
                                      bool through_free);

}  // namespace voronav::exploration::internal
