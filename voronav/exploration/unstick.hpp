// Stall recovery (ours, issue 14; not in seed 004): where a robot that has stayed on one spot
// drives to. The runner calls it when its progress watchdog fires (ExplorationOptions::unstick):
// the most open known-free place a short path away, reached around the other robots, so a robot
// dithering in clutter or boxed in among robots gets out before it stalls. margin_exit
// (ExplorationOptions::margin_escape, stop 23): where a robot standing too near a wall for its
// routes' first legs to clear it drives first. robots_in_way (ExplorationOptions::clear_way_out,
// stop 27): which robots stand in a stuck robot's way out.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"
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

/// ExplorationOptions::margin_escape (ours, issue 14, stop 23): where a robot that stands inside
/// the planning margin (nearer than `margin` = body radius + clearance to a wall) drives first.
/// `grid`: 0 = free for a robot centre (the team map's known obstacles inflated by the body radius
/// + clearance, traversable_of); `world`: the walls the robot's disc must clear (its front
/// guard's). When p's cell is free on `grid`, nullopt (not in the margin) when also the walls of
/// `world` (what the robot's front guard senses) are at least `margin` [m] from p. Else the centre
/// of the cell nearest to p within `search` [m] that is free on `grid`, at least `margin` +
/// internal::kCornerReach from the walls of `world` (the runner ends the escape that near the exit,
/// so the robot is out of the margin then), and reached by the straight line along which the disc
/// of radius `body` keeps clear of `world` by the front guard's wall rule (internal::line_clear);
/// nullopt when there is none. A route is planned from the free cell nearest the robot and then
/// joined to the robot's own position, so from inside the margin its first leg is one the planner
/// never checked: in willow (16 robots, coordinated, seeds 5 and 15) it clipped a wall corner 0.14
/// m from the robot's centre (map speckle the team map had as free) and the guard stopped every new
/// route for 600 s.
[[nodiscard]] std::optional<Vec2> margin_exit(const BinaryGrid& grid, const BinaryGrid& world,
                                              Vec2 p, double body, double margin,
                                              double search = 1.0);

/// ExplorationOptions::clear_way_out (ours, issue 14, stop 27): the indices (ascending) of the
/// points of `robots` [m] whose distance to the polyline `way` [m] (a stuck robot's way out, from
/// its position) is less than `reach` [m] (two body radii + 5 cm: their discs touch the disc
/// that drives along it). A way of one point is that point.
[[nodiscard]] std::vector<std::size_t> robots_in_way(const std::vector<Vec2>& way,
                                                     const std::vector<Vec2>& robots, double reach);

}  // namespace voronav::exploration
