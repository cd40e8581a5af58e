// Frontier-based exploration baselines in the same simulator as seed 004's method:
//  * nearest frontier (Yamauchi 1997; ROS explore_lite): every robot independently drives to the
//    frontier with the lowest cost = path distance - gain_scale * frontier size;
//  * coordinated (Burgard et al. 2005, "Coordinated multi-robot exploration"): targets start with
//    utility 1; repeatedly the (robot, target) pair with the largest utility - beta * cost is
//    assigned, and the utility of targets near an assigned one is reduced by
//    P(d) = 1 - d / utility_radius (the probability that it is seen from there).
// A frontier cell is a known free cell with an unknown 4-neighbour; frontiers are 8-connected
// clusters of such cells.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "voronav/core/cell.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"

namespace voronav::exploration {

struct FrontierOptions {
  int min_frontier_cells = 5;   ///< smaller clusters are ignored (noise)
  double gain_scale = 0.0;      ///< explore_lite gain_scale [m per cell of frontier size]
  double beta = 1.0;            ///< Burgard's cost weight (costs normalised to [0, 1])
  double utility_radius = 3.0;  ///< [m] utility reduction range (the sensor range)

  void validate() const;
};

struct Frontier {
  std::vector<Cell> cells;
  Vec2 centroid;  ///< [m]
  Cell target;    ///< traversable frontier-adjacent cell nearest the centroid
};

/// Frontier clusters of `map` (ROS values) whose target is a free cell of `traversable`
/// (0 = free). The target is the traversable cell within 3 cells of the cluster nearest its
/// centroid; clusters without one are dropped.
[[nodiscard]] std::vector<Frontier> find_frontiers(const OccupancyGrid& map,
                                                   const BinaryGrid& traversable,
                                                   const FrontierOptions& options = {});

/// costs[r][f]: path cost [m] of robot r to frontier f (negative = unreachable).
/// Nearest frontier: each robot picks its own best frontier; -1 when none is reachable.
[[nodiscard]] std::vector<int> assign_nearest(std::span<const Frontier> frontiers,
                                              const std::vector<std::vector<double>>& costs,
                                              const FrontierOptions& options = {});
/// Coordinated assignment (Burgard 2005). Robots that get nothing (more robots than targets)
/// get the best target anyway, after utility reduction; -1 when none is reachable.
/// `gains` (optional, one per frontier, >= 0): information-gain ranking (ours, used by
/// tree-frontier): a target's initial utility is its gain / the largest gain instead of 1.
[[nodiscard]] std::vector<int> assign_coordinated(std::span<const Frontier> frontiers,
                                                  const std::vector<std::vector<double>>& costs,
                                                  const FrontierOptions& options = {},
                                                  std::span<const double> gains = {});

/// Robot-aware planning (ours, not Burgard's): sets to 1 (blocked) the free cells of `grid`
/// within `radius` [m] of every position in `others` that lies within `range` [m] of `self`, so
/// a flood from `self` goes around robots in its way. Returns the indices of the changed cells
/// for restore_free_cells(). The runner uses radius = two body radii + 5 cm and range = 3 m.
[[nodiscard]] std::vector<std::size_t> block_robot_discs(BinaryGrid& grid, Vec2 self,
                                                         std::span<const Vec2> others,
                                                         double radius, double range);
/// Undoes block_robot_discs: the cells at `indices` become free (0) again.
void restore_free_cells(BinaryGrid& grid, std::span<const std::size_t> indices);

}  // namespace voronav::exploration
