#include "voronav/topology/edge_route.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace voronav::topology {
namespace {

// Dijkstra from `from` to `to` over the cells whose region is a or b (plus `to` itself).
std::vector<Cell> leg(const TopologicalMap& m, int a, int b, Cell from, Cell to) {
  const GridGeometry& geo = m.geometry;
  if (!geo.contains(from) || !geo.contains(to)) return {};
  const auto allowed = [&](Cell c) {
    if (!geo.contains(c) || m.blocked[c]) return false;
    if (c == to) return true;
    const int r = m.region[c];
    return r == a || r == b;
  };
  if (!allowed(from)) return {};
  const std::size_t n = static_cast<std::size_t>(geo.width) * static_cast<std::size_t>(geo.height);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> parent(n, -1);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  const std::size_t s = geo.index(from), t = geo.index(to);
  dist[s] = 0.0;
  open.push({0.0, s});
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[i]) continue;
    if (i == t) break;
    const Cell c{static_cast<int>(i % static_cast<std::size_t>(geo.width)),
                 static_cast<int>(i / static_cast<std::size_t>(geo.width))};
    for (int k = 0; k < 8; ++k) {
      const Cell dlt = kNeighbours8[k];
      const Cell q = c + dlt;
      if (!allowed(q)) continue;
      if (k >= 4 && (m.blocked[Cell{c.x + dlt.x, c.y}] || m.blocked[Cell{c.x, c.y + dlt.y}]))
        continue;  // no corner cutting
      const double len = k < 4 ? 1.0 : std::sqrt(2.0);
      const double nd = d + len * (m.diagram[q] ? 1.0 : kOffDiagramCost);
      const std::size_t j = geo.index(q);
      if (nd < dist[j]) {
        dist[j] = nd;
        parent[j] = static_cast<std::int64_t>(i);
        open.push({nd, j});
      }
    }
  }
  if (!std::isfinite(dist[t])) return {};
  std::vector<Cell> path;
  for (std::int64_t i = static_cast<std::int64_t>(t); i >= 0;
       i = parent[static_cast<std::size_t>(i)])
    path.push_back(
        Cell{static_cast<int>(static_cast<std::size_t>(i) % static_cast<std::size_t>(geo.width)),
             static_cast<int>(static_cast<std::size_t>(i) / static_cast<std::size_t>(geo.width))});
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

std::vector<Cell> edge_route(const TopologicalMap& m, const TopoEdge& e) {
  if (e.a < 0 || e.b < 0 || static_cast<std::size_t>(e.a) >= m.regions.size() ||
      static_cast<std::size_t>(e.b) >= m.regions.size())
    return {};
  const Cell ca = m.regions[static_cast<std::size_t>(e.a)].centre;
  const Cell cb = m.regions[static_cast<std::size_t>(e.b)].centre;
  std::vector<Cell> first = leg(m, e.a, e.b, ca, e.midpoint);
  if (first.empty()) return {};
  std::vector<Cell> second = leg(m, e.a, e.b, e.midpoint, cb);
  if (second.empty()) return {};
  first.insert(first.end(), second.begin() + 1, second.end());
  return first;
}

}  // namespace voronav::topology
