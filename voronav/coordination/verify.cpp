#include "voronav/coordination/verify.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

namespace {

struct Box {
  double x0 = kInfinity, y0 = kInfinity, x1 = -kInfinity, y1 = -kInfinity;
  void add(Vec2 p) {
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
};

/// Bounding box of everything a trajectory visits (pieces move along straight lines without
/// reversing, so the piece ends bound them).
Box bounds(const Trajectory& tr) {
  Box b;
  for (const Piece& p : tr.pieces) {
    b.add(p.at(p.t0));
    b.add(p.at(p.t1));
  }
  return b;
}

double gap(const Box& a, const Box& b) {
  const double dx = std::max({0.0, a.x0 - b.x1, b.x0 - a.x1});
  const double dy = std::max({0.0, a.y0 - b.y1, b.y0 - a.y1});
  return std::hypot(dx, dy);
}

/// Distance from segment ab to the axis-aligned square [x, x+1] x [y, y+1] (grid units).
double segment_square(Vec2 a, Vec2 b, double x, double y) {
  auto inside = [&](Vec2 p) { return p.x >= x && p.x <= x + 1 && p.y >= y && p.y <= y + 1; };
  if (inside(a) || inside(b)) return 0.0;
  const Vec2 c[4] = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
  auto cross = [](Vec2 u, Vec2 v) { return u.x * v.y - u.y * v.x; };
  double best = kInfinity;
  for (int k = 0; k < 4; ++k) {
    const Vec2 p = c[k], q = c[(k + 1) % 4];
    // proper intersection of ab with edge pq
    const double d1 = cross(b - a, p - a), d2 = cross(b - a, q - a);
    const double d3 = cross(q - p, a - p), d4 = cross(q - p, b - p);
    if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) return 0.0;
    best = std::min({best, distance_to_segment(p, a, b), distance_to_segment(a, p, q),
                     distance_to_segment(b, p, q)});
  }
  return best;
}

}  // namespace

Verification verify_trajectories(std::span<const Trajectory> tr, std::span<const double> radii,
                                 double tolerance) {
  if (radii.size() != tr.size()) throw Error("radii", 0, "expected one radius per trajectory");
  if (!(tolerance >= 0.0)) throw Error("tolerance", 0, "expected >= 0");
  Verification out;
  const std::size_t n = tr.size();
  std::vector<Box> box(n);
  for (std::size_t i = 0; i < n; ++i)
    box[i] = bounds(tr[i]);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const double lo = std::max(tr[i].present_from, tr[j].present_from);
      const double hi = std::min(tr[i].present_to, tr[j].present_to);
      if (lo > hi || (lo == hi && (tr[i].half_open || tr[j].half_open))) continue;
      const double rsum = radii[i] + radii[j];
      // The pair cannot overlap or lower the minimum clearance: skip it.
      const double bound = gap(box[i], box[j]) - rsum;
      if (bound >= out.min_clearance && bound > -tolerance) continue;
      const MinDistance d = first_below(tr[i], tr[j], lo, hi, rsum - tolerance);
      out.min_clearance = std::min(out.min_clearance, d.distance - rsum);
      if (d.distance < rsum - tolerance) {
        out.conflicts.push_back({static_cast<int>(i), static_cast<int>(j), d.time, d.distance});
      }
    }
  }
  std::sort(out.conflicts.begin(), out.conflicts.end(),
            [](const Conflict& a, const Conflict& b) { return a.time < b.time; });
  out.valid = out.conflicts.empty();
  return out;
}

Verification verify_schedule(const std::vector<Agent>& agents, std::span<const double> delays,
                             const VerifyOptions& options) {
  if (delays.size() != agents.size()) {
    throw Error("delays", 0,
                "expected " + std::to_string(agents.size()) + " delays, got " +
                    std::to_string(delays.size()));
  }
  for (std::size_t i = 0; i < delays.size(); ++i) {
    if (!(delays[i] >= 0.0) || !std::isfinite(delays[i])) {
      throw Error("delays", 0,
                  "robot " + std::to_string(agents[i].id) + ": expected a finite delay >= 0, got " +
                      std::to_string(delays[i]));
    }
  }
  std::vector<Trajectory> tr;
  std::vector<double> radii;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    tr.push_back(trajectory_of(agents[i].path, delays[i], options.at_start, options.at_goal));
    radii.push_back(agents[i].radius);
  }
  return verify_trajectories(tr, radii, options.tolerance);
}

void check_map(Verification& v, std::span<const Trajectory> tr, std::span<const double> radii,
               const BinaryGrid& blocked, double tolerance) {
  const GridGeometry& g = blocked.geometry();
  for (std::size_t i = 0; i < tr.size(); ++i) {
    const double r = radii[i] / g.resolution, tol = tolerance / g.resolution;
    bool hit = false;
    for (const Piece& p : tr[i].pieces) {
      const Vec2 a = g.world_to_grid(p.at(p.t0)), b = g.world_to_grid(p.at(p.t1));
      const int x0 = static_cast<int>(std::floor(std::min(a.x, b.x) - r)) - 1;
      const int x1 = static_cast<int>(std::floor(std::max(a.x, b.x) + r)) + 1;
      const int y0 = static_cast<int>(std::floor(std::min(a.y, b.y) - r)) - 1;
      const int y1 = static_cast<int>(std::floor(std::max(a.y, b.y) + r)) + 1;
      for (int y = y0; y <= y1 && !hit; ++y) {
        for (int x = x0; x <= x1 && !hit; ++x) {
          const Cell c{x, y};
          // Outside the map counts as blocked.
          if (g.contains(c) && blocked[c] == 0) continue;
          const double d = segment_square(a, b, x, y);
          if (d < r - tol) {
            v.wall_hits.push_back({static_cast<int>(i), p.t0, c, d * g.resolution});
            hit = true;
          }
        }
      }
      if (hit) break;
    }
  }
  if (!v.wall_hits.empty()) v.valid = false;
}

}  // namespace voronav::coordination
