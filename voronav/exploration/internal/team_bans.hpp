// The exploration runner's team bans (ExplorationOptions::share_bans, issue 14 stop 22; ours, not
// in seed 004; not installed). A frontier goal that a robot reached is banned for the whole team
// when, at an allocation at least one scan later, its frontier is still there and no unknown cell
// next to it is in sight of its target cell (a straight line through known free cells within the
// laser's range): no robot standing there can observe it, since the robots share the map and the
// laser. Before, only the robot that stood there banned it, so every robot went to see for itself
// (willow, 16 robots, frontier seed 1: up to 12 robots herded into a dead-end pocket). A ban ends
// when the team map within kWatch of the goal gains or loses known cells: new information.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/core/vec2.hpp"
#include "voronav/exploration/frontier.hpp"

namespace voronav::exploration::internal {

class TeamBans {
 public:
  static constexpr double kWatch = 1.0;  ///< [m] the map around a ban that lifts it when changed
  static constexpr double kSame = 0.5;   ///< [m] a target this near a ban is banned

  /// A robot reached its frontier goal `at` at time `t` [s]; judged by a later update().
  void reached(Vec2 at, double t) { pending_.push_back({at, 0, t}); }

  /// At an allocation at time `t`: lifts the bans whose surroundings changed in the team map
  /// (`log_odds`: 0 = unknown), then judges the goals reached at least `scan_period` ago against
  /// `frontiers` on `map` (the team map, ROS values). Returns how many bans it added.
  int update(const OccupancyGrid& map, const GridMap<float>& log_odds,
             std::span<const Frontier> frontiers, double laser_range, double t,
             double scan_period) {
    const GridGeometry& g = map.geometry();
    std::erase_if(bans_, [&](const Ban& b) { return known_near(log_odds, g, b.at) != b.known; });
    int added = 0;
    std::erase_if(pending_, [&](const Ban& p) {
      if (t - p.t < scan_period) return false;  // no scan from there yet
      for (const Frontier& f : frontiers)
        if (distance(g.cell_center(f.target), p.at) < kSame &&
            !observable_from_target(map, f, laser_range) && !banned(p.at)) {
          bans_.push_back({p.at, known_near(log_odds, g, p.at), t});
          ++added;
          break;
        }
      return true;
    });
    return added;
  }

  /// True when `p` is within kSame of a ban.
  [[nodiscard]] bool banned(Vec2 p) const {
    for (const Ban& b : bans_)
      if (distance(b.at, p) < kSame) return true;
    return false;
  }

  /// True when an unknown cell 4-adjacent to a cell of `f` lies within `range` [m] of f's target
  /// cell on a straight line of known free cells from it.
  [[nodiscard]] static bool observable_from_target(const OccupancyGrid& map, const Frontier& f,
                                                   double range) {
    const GridGeometry& g = map.geometry();
    const Vec2 tp = g.cell_center(f.target);
    for (const Cell c : f.cells)
      for (int k = 0; k < 4; ++k) {
        const Cell u = c + kNeighbours8[k];
        if (!map.contains(u) || map[u] != kUnknown) continue;
        if (distance(g.cell_center(u), tp) > range) continue;
        if (for_each_line_cell(f.target, u, [&](Cell q) { return q == u || map[q] == kFree; }))
          return true;
      }
    return false;
  }

 private:
  struct Ban {
    Vec2 at;
    std::size_t known = 0;  // known cells of the team map within kWatch of `at`
    double t = 0.0;         // [s] when the goal was reached
  };

  static std::size_t known_near(const GridMap<float>& log_odds, const GridGeometry& g, Vec2 p) {
    const auto c = g.world_to_cell(p);
    std::size_t n = 0;
    if (!c) return n;
    const int r = static_cast<int>(std::ceil(kWatch / g.resolution));
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const Cell q{c->x + dx, c->y + dy};
        if (dx * dx + dy * dy <= r * r && g.contains(q) && log_odds[q] != 0.0F) ++n;
      }
    return n;
  }

  std::vector<Ban> pending_;  // reached, not yet judged
  std::vector<Ban> bans_;
};

}  // namespace voronav::exploration::internal
