#include "voronav/planning/failure_hint.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <utility>

#include "voronav/field/distance_transform.hpp"
#include "voronav/planning/astar.hpp"

namespace voronav::planning {
namespace {

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f m", v);
  return buf;
}
std::string where(const GridGeometry& g, Cell c) {
  const Vec2 p = g.cell_center(c);
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.2f, %.2f) m", p.x, p.y);
  return buf;
}

}  // namespace

FailureHint explain_failure(const BinaryGrid& blocked, const GridGeometry& geometry, Cell start,
                            Cell goal, double radius_m) {
  FailureHint h;
  const auto inside = [&](Cell c) {
    return c.x >= 0 && c.y >= 0 && c.x < blocked.width() && c.y < blocked.height();
  };
  if (!inside(start) || !inside(goal) || blocked.empty()) return h;
  const double res = geometry.resolution;
  const BinaryGrid inflated = field::inflate(blocked, radius_m);
  const field::DistanceField df = field::distance_transform(blocked);
  for (const auto& [which, cell] : {std::pair{"start", start}, std::pair{"goal", goal}}) {
    if (blocked[cell] != 0) {
      h.text += std::string("The ") + which + " " + where(geometry, cell) +
                " lies on an obstacle of the map. ";
      continue;
    }
    if (inflated[cell] == 0) continue;
    // The nearest cell (Euclidean, cell centres) that keeps the radius.
    long best = std::numeric_limits<long>::max();
    Cell nearest{-1, -1};
    for (int y = 0; y < inflated.height(); ++y)
      for (int x = 0; x < inflated.width(); ++x)
        if (inflated[Cell{x, y}] == 0) {
          const long dx = x - cell.x, dy = y - cell.y, d = dx * dx + dy * dy;
          if (d < best) {
            best = d;
            nearest = {x, y};
          }
        }
    h.text += std::string("The ") + which + " " + where(geometry, cell) + " is free but only " +
              metres(df.distance_m(cell)) + " from an obstacle, closer than the robot radius " +
              metres(radius_m) + "; ";
    if (nearest.x >= 0) {
      h.nearest_free = nearest;
      h.text += "the nearest place that keeps the radius is " + where(geometry, nearest) + ", " +
                metres(std::sqrt(static_cast<double>(best)) * res) + " away. ";
    } else {
      h.text += "no cell of this map keeps that radius. ";
    }
  }
  if (!h.text.empty()) {
    h.text.pop_back();
    return h;
  }
  // Both ends keep the radius, yet no path: is it the radius that closes the way? The widest way
  // from start to goal (the path that maximises its smallest clearance, a bottleneck search over
  // 4-connected free cells) tells how wide the narrowest unavoidable passage is.
  AStarPlanner point_robot;
  const PlanResult r = point_robot.plan(blocked, start, goal);
  if (!r.ok()) {
    h.text = "No free path connects start and goal on this map, even for a point robot.";
    return h;
  }
  const GridGeometry& g = blocked.geometry();
  GridMap<float> widest(g, -1.0f);
  GridMap<std::int32_t> pinch(g, -1);  // index of the tightest cell on the widest way so far
  std::priority_queue<std::pair<float, std::int32_t>> open;
  const auto clearance = [&](Cell c) { return static_cast<float>(df.distance_m(c)); };
  widest[start] = clearance(start);
  pinch[start] = static_cast<std::int32_t>(g.index(start));
  open.push({widest[start], pinch[start]});
  while (!open.empty()) {
    const auto [w, i] = open.top();
    open.pop();
    const Cell u = g.cell_at(static_cast<std::size_t>(i));
    if (w < widest[u]) continue;
    if (u == goal) break;
    for (const Cell d : {Cell{1, 0}, Cell{-1, 0}, Cell{0, 1}, Cell{0, -1}}) {
      const Cell v = u + d;
      if (!inside(v) || blocked[v] != 0) continue;
      const float cv = clearance(v), cand = std::min(w, cv);
      if (cand > widest[v]) {
        widest[v] = cand;
        pinch[v] = cv < w ? static_cast<std::int32_t>(g.index(v)) : pinch[u];
        open.push({cand, static_cast<std::int32_t>(g.index(v))});
      }
    }
  }
  const Cell at = g.cell_at(static_cast<std::size_t>(pinch[goal]));
  h.narrowest_passage_m = 2.0 * widest[goal];
  h.text = "A point robot would get there (" + metres(r.length_cells * res) +
           "), but every way passes a gap about " + metres(h.narrowest_passage_m) +
           " wide (the narrowest at " + where(geometry, at) + "), less than the robot's diameter " +
           metres(2.0 * radius_m) + ". A smaller robot radius would pass.";
  return h;
}

}  // namespace voronav::planning
