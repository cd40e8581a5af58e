#include "voronav/exploration/unstick.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "voronav/exploration/internal/front_guard.hpp"
#include "voronav/field/distance_transform.hpp"

namespace voronav::exploration {
std::vector<std::size_t> robots_in_way(const std::vector<Vec2>& way,
                                       const std::vector<Vec2>& robots, double reach) {
  std::vector<std::size_t> out;
  if (way.empty()) return out;
  for (std::size_t j = 0; j < robots.size(); ++j) {
    bool in = distance(robots[j], way.front()) < reach;
    for (std::size_t k = 1; k < way.size() && !in; ++k)
      in = distance_to_segment(robots[j], way[k - 1], way[k]) < reach;
    if (in) out.push_back(j);
  }
  return out;
}

std::optional<Cell> unstick_target(const BinaryGrid& grid, const planning::BfsFlood& flood,
                                   const field::DistanceField& clear, const UnstickOptions& o) {
  const double res = grid.geometry().resolution;
  const auto lo = static_cast<std::int32_t>(std::ceil(o.min_path / res - 1e-9));
  const auto hi = static_cast<std::int32_t>(std::floor(o.max_path / res + 1e-9));
  std::optional<Cell> best;
  double best_clear = -1.0;
  std::int32_t best_steps = 0;
  std::int32_t best_index = 0;
  // Only the cells the flood reached, in its order (steps never decrease): stop past max_path.
  for (const std::int32_t k : flood.reached()) {
    const Cell c = grid.cell_at(static_cast<std::size_t>(k));
    const std::int32_t st = flood.steps(grid, c);
    if (st > hi) break;
    if (st < lo) continue;
    const double cl = std::min(o.clearance_cap, clear.distance_m(c));
    const bool tie = std::abs(cl - best_clear) <= 1e-9;
    if (cl > best_clear + 1e-9 ||
        (tie && (st < best_steps || (st == best_steps && k < best_index)))) {
      best = c;
      best_clear = cl;
      best_steps = st;
      best_index = k;
    }
  }
  return best;
}

std::optional<Vec2> margin_exit(const BinaryGrid& grid, const BinaryGrid& world, Vec2 p,
                                double body, double margin, double search) {
  const GridGeometry& g = grid.geometry();
  const auto c = g.world_to_cell(p);
  if (!c) return std::nullopt;
  // The runner ends the escape within kCornerReach of the exit: the exit keeps that much more.
  const double need = margin + internal::kCornerReach, cap = need + 0.01;
  if (grid[*c] == 0 && internal::wall_clearance(world, p, cap) >= margin) return std::nullopt;
  const int r = static_cast<int>(std::ceil(search / g.resolution));
  std::vector<std::pair<double, Cell>> free_cells;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const Cell n{c->x + dx, c->y + dy};
      if (!grid.contains(n) || grid[n] != 0) continue;
      const double d = distance(g.cell_center(n), p);
      if (d <= search && internal::wall_clearance(world, g.cell_center(n), cap) >= need)
        free_cells.emplace_back(d, n);
    }
  std::sort(free_cells.begin(), free_cells.end(), [&](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && grid.index(a.second) < grid.index(b.second));
  });
  for (const auto& [d, n] : free_cells)
    if (internal::line_clear(world, p, g.cell_center(n), body)) return g.cell_center(n);
  return std::nullopt;
}

}  // namespace voronav::exploration
