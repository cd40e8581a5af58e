// Planning on the team map during an exploration run (run_exploration; not installed): the
// team map as a ROS-valued grid, its traversable cells for a robot centre, the free cell nearest
// a point, paths by descending a BFS flood, and their line-of-sight simplification. Every method
// plans its routes with these (frontier allocation, tree legs, unstick routes).
#pragma once

#include <optional>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/planning/bfs.hpp"

namespace voronav::exploration::internal {

/// The team's log-odds map as ROS values (kOccupied / kFree / kUnknown).
[[nodiscard]] OccupancyGrid team_grid(const mapping::OccupancyMap& m);

/// Known free cells, inflated by `radius` [m]: 0 = a robot centre may go there.
[[nodiscard]] BinaryGrid traversable_of(const OccupancyGrid& map, double radius);

/// The free (0) cell of `g` nearest `p` within `search` cells in x and y; none when there is none.
[[nodiscard]] std::optional<Cell> nearest_free(const BinaryGrid& g, Vec2 p, int search = 8);

/// Line-of-sight simplification of a cell path on `g` (looks at most 40 points ahead).
[[nodiscard]] std::vector<Vec2> simplify(const BinaryGrid& g, const std::vector<Vec2>& pts);

/// Path from the flood's start to `goal` by descending the BFS step counts (8-neighbours); empty
/// when the flood did not reach `goal`.
[[nodiscard]] std::vector<Vec2> descend(const BinaryGrid& g, const planning::BfsFlood& flood,
                                        Cell goal);

}  // namespace voronav::exploration::internal
