#include "voronav/exploration/internal/stall_rule.hpp"

#include "voronav/core/cell.hpp"
#include "voronav/core/error.hpp"
#include "voronav/exploration/internal/plan_grid.hpp"
#include "voronav/planning/grid_planner.hpp"

namespace voronav::exploration::internal {

std::vector<char> robot_reach(const BinaryGrid& blocked, double radius,
                              std::span<const Vec2> starts) {
  const BinaryGrid fits = planning::make_planning_grid(blocked, radius);
  std::vector<char> reach(fits.size(), 0);
  std::vector<Cell> stack;
  for (const Vec2& s : starts)
    if (const auto c = nearest_free(fits, s); c && !reach[fits.index(*c)]) {
      reach[fits.index(*c)] = 1;
      stack.push_back(*c);
    }
  while (!stack.empty()) {
    const Cell c = stack.back();
    stack.pop_back();
    for (const Cell d : kNeighbours8) {
      const Cell n = c + d;
      if (!fits.contains(n) || fits[n] != 0 || reach[fits.index(n)]) continue;
      reach[fits.index(n)] = 1;
      stack.push_back(n);
    }
  }
  return reach;
}

bool unknown_patch_in_reach(const GridGeometry& geometry, std::span<const char> reach,
                            std::span<const float> log_odds) {
  if (reach.size() != geometry.size() || log_odds.size() != geometry.size())
    throw Error("unknown_patch_in_reach: the grids differ in size");
  const int w = geometry.width, h = geometry.height;
  const auto at = [w](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
  };
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      if (!reach[at(x, y)] || log_odds[at(x, y)] != 0.0F) continue;
      bool patch = true;
      for (const Cell d : kNeighbours8)
        patch = patch && log_odds[at(x + d.x, y + d.y)] == 0.0F;
      if (patch) return true;
    }
  return false;
}

}  // namespace voronav::exploration::internal
