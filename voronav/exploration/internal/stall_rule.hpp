// The stall rule's "reachable unknown space remains" (issue 14's definition of stalled_robots,
// read from the ground truth since stop 26; run_exploration, not installed): where a robot centre
// fits in the world, connected to the team's starts, and whether the team map still has an
// unknown patch there that a robot standing on it would map.
#pragma once

#include <span>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::exploration::internal {

/// The cells of `blocked` (the ground truth, 1 = blocked) where a robot centre of clearance
/// `radius` [m] fits, 8-connected to the free cell nearest one of `starts` (within 8 cells):
/// 1 = reachable.
[[nodiscard]] std::vector<char> robot_reach(const BinaryGrid& blocked, double radius,
                                            std::span<const Vec2> starts);

/// True when some reachable cell is unknown (`log_odds` 0) and so are its 8 neighbours: a patch
/// of 3 x 3 cells. A gap between two laser rays in mapped space is one or two cells wide and
/// does not count. `reach` and `log_odds` are row-major over the same `geometry`.
[[nodiscard]] bool unknown_patch_in_reach(const GridGeometry& geometry, std::span<const char> reach,
                                          std::span<const float> log_odds);

}  // namespace voronav::exploration::internal
