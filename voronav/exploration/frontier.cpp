#include "voronav/exploration/frontier.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::exploration {

void FrontierOptions::validate() const {
  if (min_frontier_cells < 1) throw Error("FrontierOptions.min_frontier_cells", 0, "expected >= 1");
  if (!(gain_scale >= 0.0) || !std::isfinite(gain_scale))
    throw Error("FrontierOptions.gain_scale", 0, "expected a finite number >= 0");
  if (!(beta >= 0.0) || !std::isfinite(beta))
    throw Error("FrontierOptions.beta", 0, "expected a finite number >= 0");
  if (!(utility_radius > 0.0) || !std::isfinite(utility_radius))
    throw Error("FrontierOptions.utility_radius", 0, "expected a positive finite number");
}

std::vector<Frontier> find_frontiers(const OccupancyGrid& map, const BinaryGrid& traversable,
                                     const FrontierOptions& options) {
  options.validate();
  if (map.geometry() != traversable.geometry())
    throw Error("find_frontiers", 0, "map and traversable grid differ in geometry");
  const GridGeometry& g = map.geometry();
  const auto is_frontier = [&](Cell c) {
    if (map[c] != kFree) return false;
    for (int k = 0; k < 4; ++k) {
      const Cell n = c + kNeighbours8[k];
      if (map.contains(n) && map[n] == kUnknown) return true;
    }
    return false;
  };
  std::vector<char> seen(map.size(), 0);
  std::vector<Frontier> out;
  std::vector<Cell> stack;
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const Cell c0{x, y};
      if (seen[map.index(c0)] || !is_frontier(c0)) continue;
      Frontier f;
      stack.assign(1, c0);
      seen[map.index(c0)] = 1;
      while (!stack.empty()) {
        const Cell c = stack.back();
        stack.pop_back();
        f.cells.push_back(c);
        for (const Cell d : kNeighbours8) {
          const Cell n = c + d;
          if (!map.contains(n) || seen[map.index(n)] || !is_frontier(n)) continue;
          seen[map.index(n)] = 1;
          stack.push_back(n);
        }
      }
      if (static_cast<int>(f.cells.size()) < options.min_frontier_cells) continue;
      Vec2 sum;
      for (const Cell c : f.cells)
        sum += g.cell_center(c);
      f.centroid = sum / static_cast<double>(f.cells.size());
      double best = std::numeric_limits<double>::infinity();
      bool found = false;
      for (const Cell c : f.cells) {
        for (int dy = -3; dy <= 3; ++dy)
          for (int dx = -3; dx <= 3; ++dx) {
            const Cell t{c.x + dx, c.y + dy};
            if (!traversable.contains(t) || traversable[t] != 0) continue;
            const double d = distance(g.cell_center(t), f.centroid);
            if (d < best) {
              best = d;
              f.target = t;
              found = true;
            }
          }
      }
      if (found) out.push_back(std::move(f));
    }
  }
  return out;
}

std::vector<int> assign_nearest(std::span<const Frontier> frontiers,
                                const std::vector<std::vector<double>>& costs,
                                const FrontierOptions& options) {
  std::vector<int> out(costs.size(), -1);
  for (std::size_t r = 0; r < costs.size(); ++r) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < frontiers.size() && f < costs[r].size(); ++f) {
      if (costs[r][f] < 0.0) continue;
      const double c =
          costs[r][f] - options.gain_scale * static_cast<double>(frontiers[f].cells.size());
      if (c < best) {
        best = c;
        out[r] = static_cast<int>(f);
      }
    }
  }
  return out;
}

std::vector<int> assign_coordinated(std::span<const Frontier> frontiers,
                                    const std::vector<std::vector<double>>& costs,
                                    const FrontierOptions& options, std::span<const double> gains) {
  const std::size_t nr = costs.size(), nf = frontiers.size();
  if (!gains.empty() && gains.size() != nf)
    throw Error("assign_coordinated", 0,
                "expected one gain per frontier (" + std::to_string(nf) + "), got " +
                    std::to_string(gains.size()));
  std::vector<int> out(nr, -1);
  if (nf == 0) return out;
  double max_cost = 0.0;
  for (const auto& row : costs)
    for (double c : row)
      max_cost = std::max(max_cost, c);
  if (max_cost <= 0.0) max_cost = 1.0;
  std::vector<double> utility(nf, 1.0);
  if (!gains.empty()) {
    double most = 0.0;
    for (double v : gains)
      most = std::max(most, v);
    for (std::size_t f = 0; f < nf; ++f)
      utility[f] = most > 0.0 ? std::max(0.0, gains[f]) / most : 1.0;
  }
  std::vector<char> done(nr, 0);
  for (std::size_t round = 0; round < nr; ++round) {
    double best = -std::numeric_limits<double>::infinity();
    std::size_t br = nr, bf = nf;
    for (std::size_t r = 0; r < nr; ++r) {
      if (done[r]) continue;
      for (std::size_t f = 0; f < nf && f < costs[r].size(); ++f) {
        if (costs[r][f] < 0.0) continue;
        const double v = utility[f] - options.beta * costs[r][f] / max_cost;
        if (v > best) {
          best = v;
          br = r;
          bf = f;
        }
      }
    }
    if (br == nr) break;
    out[br] = static_cast<int>(bf);
    done[br] = 1;
    for (std::size_t f = 0; f < nf; ++f) {
      const double d = distance(frontiers[f].centroid, frontiers[bf].centroid);
      if (d < options.utility_radius) utility[f] -= 1.0 - d / options.utility_radius;
    }
  }
  return out;
}

std::vector<std::size_t> block_robot_discs(BinaryGrid& grid, Vec2 self,
                                           std::span<const Vec2> others, double radius,
                                           double range) {
  std::vector<std::size_t> changed;
  const GridGeometry& g = grid.geometry();
  const int rc = static_cast<int>(std::ceil(radius / g.resolution));
  for (const Vec2& p : others) {
    if (distance(p, self) > range) continue;
    const auto c = g.world_to_cell(p);
    if (!c) continue;
    for (int dy = -rc; dy <= rc; ++dy)
      for (int dx = -rc; dx <= rc; ++dx) {
        const Cell n{c->x + dx, c->y + dy};
        if (!grid.contains(n) || grid[n] != 0 || distance(g.cell_center(n), p) > radius) continue;
        grid[n] = 1;
        changed.push_back(grid.index(n));
      }
  }
  return changed;
}

void restore_free_cells(BinaryGrid& grid, std::span<const std::size_t> indices) {
  for (const std::size_t k : indices)
    grid[k] = 0;
}

}  // namespace voronav::exploration
