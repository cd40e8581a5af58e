// Stall recovery (ours, issue 14; not in seed 004): where a robot that has stayed on one spot
// drives to. The runner calls it when its progress watchdog fires (ExplorationOptions::unstick):
// the most open known-free place a short path away, reached around the other robots, so a robot
// dithering in clutter or boxed in among robots gets out before it stalls.
#pragma once

#include <optional>

#include "voronav/core/occupancy.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/planning/bfs.hpp"

namespace voronav::exploration {

struct UnstickOptions {
  double min_path = 1.0;       ///< [m] the target is at least this far along the path ...
  double max_path = 4.0;       ///< [m] ... and at most this far
  double clearance_cap = 1.0;  ///< [m] clearances above this count as equal (then: the nearer)
};

/// The target cell: among the cells `flood` reached on `grid` (0 = free for a robot centre; the
/// other robots' discs already blocked, block_robot_discs) with min_path <= path length <=
/// max_path, the one with the largest `clearance` (the distance field of the obstacles, without
/// the robots; capped at clearance_cap; ties: the shorter path, then the lower cell index).
/// Path length = BFS steps x resolution. nullopt when no reached cell is in that range (e.g. the
/// robot is boxed in).
[[nodiscard]] std::optional<Cell> unstick_target(const BinaryGrid& grid,
                                                 const planning::BfsFlood& flood,
                                                 const field::DistanceField& clearance,
                                                 const UnstickOptions& options = {});

}  // namespace voronav::exploration
