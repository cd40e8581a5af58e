#include "voronav/exploration/internal/information_gain.hpp"

#include <cmath>
#include <vector>

#include "voronav/core/cell.hpp"

namespace voronav::exploration::internal {

double information_gain(const OccupancyGrid& map, Vec2 p, double radius, bool through_free) {
  const auto c = map.geometry().world_to_cell(p);
  if (!c) return 0.0;
  const int r = static_cast<int>(std::ceil(radius / map.resolution()));
  const auto in_disc = [&](int dx, int dy) { return dx * dx + dy * dy <= r * r; };
  int all = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      all += in_disc(dx, dy) ? 1 : 0;
  if (all == 0) return 0.0;
  int unknown = 0;
  if (!through_free) {
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const Cell n{c->x + dx, c->y + dy};
        if (in_disc(dx, dy) && (!map.contains(n) || map[n] == kUnknown)) ++unknown;
      }
    return static_cast<double>(unknown) / all;
  }
  // A 4-connected flood from p's cell over the disc's cells that are on the map and not occupied.
  if (!map.contains(*c)) return 0.0;  // no walk starts off the map
  const int side = 2 * r + 1;
  std::vector<char> seen(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
  const auto slot = [&](Cell n) {
    return static_cast<std::size_t>(n.y - c->y + r) * static_cast<std::size_t>(side) +
           static_cast<std::size_t>(n.x - c->x + r);
  };
  std::vector<Cell> stack{*c};
  seen[slot(*c)] = 1;
  while (!stack.empty()) {
    const Cell n = stack.back();
    stack.pop_back();
    if (map[n] == kUnknown) ++unknown;
    for (int k = 0; k < 4; ++k) {
      const Cell m = n + kNeighbours8[k];
      if (!in_disc(m.x - c->x, m.y - c->y) || !map.contains(m) || seen[slot(m)] || map[m] >= 50)
        continue;
      seen[slot(m)] = 1;
      stack.push_back(m);
    }
  }
  return static_cast<double>(unknown) / all;
}

}  // namespace voronav::exploration::internal
