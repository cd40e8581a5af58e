#include "voronav/exploration/internal/plan_grid.hpp"

#include <algorithm>
#include <limits>

#include "voronav/exploration/voronoi_tree.hpp"
#include "voronav/planning/grid_planner.hpp"

namespace voronav::exploration::internal {

OccupancyGrid team_grid(const mapping::OccupancyMap& m) {
  OccupancyGrid out(m.geometry(), kUnknown);
  const auto l = m.log_odds().data();
  auto o = out.data();
  for (std::size_t i = 0; i < l.size(); ++i)
    o[i] = l[i] > 0.0F ? kOccupied : (l[i] < 0.0F ? kFree : kUnknown);
  return out;
}

BinaryGrid traversable_of(const OccupancyGrid& map, double radius) {
  return planning::make_planning_grid(binarize(map, {50, true}), radius);
}

std::optional<Cell> nearest_free(const BinaryGrid& g, Vec2 p, int search) {
  const auto c = g.geometry().world_to_cell(p);
  if (!c) return std::nullopt;
  std::optional<Cell> best;
  double bd = std::numeric_limits<double>::infinity();
  for (int dy = -search; dy <= search; ++dy)
    for (int dx = -search; dx <= search; ++dx) {
      const Cell n{c->x + dx, c->y + dy};
      if (!g.contains(n) || g[n] != 0) continue;
      const double d = dx * dx + dy * dy;
      if (d < bd) {
        bd = d;
        best = n;
      }
    }
  return best;
}

std::vector<Vec2> simplify(const BinaryGrid& g, const std::vector<Vec2>& pts) {
  if (pts.size() <= 2) return pts;
  std::vector<Vec2> out{pts.front()};
  std::size_t i = 0;
  while (i + 1 < pts.size()) {
    std::size_t j = i + 1;
    for (std::size_t k = std::min(pts.size() - 1, i + 40); k > i + 1; --k)
      if (segment_free(g, pts[i], pts[k])) {
        j = k;
        break;
      }
    out.push_back(pts[j]);
    i = j;
  }
  return out;
}

std::vector<Vec2> descend(const BinaryGrid& g, const planning::BfsFlood& flood, Cell goal) {
  std::vector<Vec2> rev;
  std::int32_t s = flood.steps(g, goal);
  if (s < 0) return {};
  Cell c = goal;
  rev.push_back(g.geometry().cell_center(c));
  while (s > 0) {
    bool moved = false;
    for (const Cell d : kNeighbours8) {
      const Cell n = c + d;
      if (g.contains(n) && flood.steps(g, n) == s - 1) {
        c = n;
        --s;
        moved = true;
        break;
      }
    }
    if (!moved) return {};
    rev.push_back(g.geometry().cell_center(c));
  }
  return {rev.rbegin(), rev.rend()};
}

}  // namespace voronav::exploration::internal
