#include "voronav/coordination/collision_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

std::optional<std::pair<double, double>> collision_interval(Vec2 p1, Vec2 a, Vec2 b, double r) {
  // eq. 5: lambda^2 |b-a|^2 - 2 lambda (p1-a).(b-a) + |p1-a|^2 - r^2 < 0
  const Vec2 ab = b - a;
  const Vec2 ap = p1 - a;
  const double qa = ab.squared_norm();
  const double qb = dot(ap, ab);
  const double qc = ap.squared_norm() - r * r;
  if (qa <= 0.0) {
    if (qc < 0.0) return std::pair{0.0, 1.0};
    return std::nullopt;
  }
  const double disc = qb * qb - qa * qc;
  if (!(disc > 0.0)) return std::nullopt;
  const double root = std::sqrt(disc);
  const double lo = std::max(0.0, (qb - root) / qa);
  const double hi = std::min(1.0, (qb + root) / qa);
  if (!(lo < hi)) return std::nullopt;
  return std::pair{lo, hi};
}

BoxCase classify(double m, double d) {
  if (m > 0.0 && d > 0.0) return BoxCase::kCollision;
  if (m > 0.0) return BoxCase::kHighFirst;
  return BoxCase::kLowFirst;
}

double effective_node_spacing(const std::vector<Agent>& agents,
                              const CollisionMapOptions& options) {
  if (options.node_spacing < 0.0 || !std::isfinite(options.node_spacing)) {
    throw Error("node_spacing", 0,
                "expected a finite spacing >= 0, got " + std::to_string(options.node_spacing));
  }
  if (options.node_spacing > 0.0) return options.node_spacing;
  double r = kInfinity;
  for (const auto& a : agents)
    r = std::min(r, a.radius);
  if (!std::isfinite(r) || r <= 0.0) return 0.25;
  return 0.5 * r;
}

namespace {

struct Resampled {
  std::vector<Vec2> nodes;
  std::vector<double> arcs;
};

std::int64_t key(std::int64_t x, std::int64_t y) {
  return (x << 32) ^ (y & 0xffffffffLL);
}

}  // namespace

std::vector<CollisionPoint> collision_points(const Agent& high, const Agent& low, double spacing,
                                             double margin) {
  Resampled h, l;
  h.nodes = resample(high.path, spacing, &h.arcs);
  l.nodes = resample(low.path, spacing, &l.arcs);
  const double thr = std::max(1e-9, high.radius + low.radius + margin);
  const double thr2 = thr * thr;
  // Spatial hash of the high robot's nodes with cell size thr.
  std::unordered_map<std::int64_t, std::vector<int>> hash;
  auto cell_of = [thr](Vec2 p) {
    return std::pair{static_cast<std::int64_t>(std::floor(p.x / thr)),
                     static_cast<std::int64_t>(std::floor(p.y / thr))};
  };
  for (int n = 0; n < static_cast<int>(h.nodes.size()); ++n) {
    const auto [cx, cy] = cell_of(h.nodes[static_cast<std::size_t>(n)]);
    hash[key(cx, cy)].push_back(n);
  }
  const double low_len = low.path.length();
  std::vector<CollisionPoint> out;
  for (int m = 0; m < static_cast<int>(l.nodes.size()); ++m) {
    const Vec2 pm = l.nodes[static_cast<std::size_t>(m)];
    const auto [cx, cy] = cell_of(pm);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = hash.find(key(cx + dx, cy + dy));
        if (it == hash.end()) continue;
        for (const int n : it->second) {
          if ((h.nodes[static_cast<std::size_t>(n)] - pm).squared_norm() < thr2) {
            const double lm = low_len > 0.0 ? l.arcs[static_cast<std::size_t>(m)] / low_len : 0.0;
            out.push_back({m, n, high.path.time_at_arc(h.arcs[static_cast<std::size_t>(n)]), lm});
          }
        }
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const CollisionPoint& a, const CollisionPoint& b) {
    return a.m != b.m ? a.m < b.m : a.n < b.n;
  });
  return out;
}

std::vector<CollisionBox> collision_boxes(const Agent& high, int high_index, const Agent& low,
                                          int low_index, double spacing,
                                          const CollisionMapOptions& options) {
  const double margin = options.paper_literal ? 0.0 : spacing;
  const auto points = collision_points(high, low, spacing, margin);
  if (points.empty()) return {};
  std::vector<double> h_arcs, l_arcs;
  const auto h_nodes = resample(high.path, spacing, &h_arcs);
  const auto l_nodes = resample(low.path, spacing, &l_arcs);
  const int h_last = static_cast<int>(h_nodes.size()) - 1;
  const int l_last = static_cast<int>(l_nodes.size()) - 1;

  std::unordered_map<std::int64_t, int> index;
  index.reserve(points.size() * 2);
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    index[key(points[static_cast<std::size_t>(i)].m, points[static_cast<std::size_t>(i)].n)] = i;
  }
  std::vector<int> component(points.size(), -1);
  std::vector<CollisionBox> boxes;
  std::vector<int> stack;
  const double half = options.paper_literal ? 0.0 : 0.5 * spacing;
  for (int seed = 0; seed < static_cast<int>(points.size()); ++seed) {
    if (component[static_cast<std::size_t>(seed)] >= 0) continue;
    const int c = static_cast<int>(boxes.size());
    CollisionBox box;
    box.high = high_index;
    box.low = low_index;
    box.high_first = box.low_first = 1 << 30;
    box.high_last = box.low_last = -1;
    component[static_cast<std::size_t>(seed)] = c;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const auto& p = points[static_cast<std::size_t>(stack.back())];
      stack.pop_back();
      box.high_first = std::min(box.high_first, p.n);
      box.high_last = std::max(box.high_last, p.n);
      box.low_first = std::min(box.low_first, p.m);
      box.low_last = std::max(box.low_last, p.m);
      for (int dm = -1; dm <= 1; ++dm) {
        for (int dn = -1; dn <= 1; ++dn) {
          const auto it = index.find(key(p.m + dm, p.n + dn));
          if (it == index.end() || component[static_cast<std::size_t>(it->second)] >= 0) continue;
          component[static_cast<std::size_t>(it->second)] = c;
          stack.push_back(it->second);
        }
      }
    }
    const auto hf = static_cast<std::size_t>(box.high_first);
    const auto hl = static_cast<std::size_t>(box.high_last);
    const auto lf = static_cast<std::size_t>(box.low_first);
    const auto ll = static_cast<std::size_t>(box.low_last);
    const bool appear = options.at_start == AtStart::kAppear;
    const bool leave = options.at_goal == AtGoal::kLeave;
    box.t1 =
        (box.high_first == 0 && !appear) ? -kInfinity : high.path.time_at_arc(h_arcs[hf] - half);
    box.t4 =
        (box.high_last == h_last && !leave) ? kInfinity : high.path.time_at_arc(h_arcs[hl] + half);
    box.t2 = (box.low_first == 0 && !appear) ? -kInfinity : low.path.time_at_arc(l_arcs[lf] - half);
    box.t3 =
        (box.low_last == l_last && !leave) ? kInfinity : low.path.time_at_arc(l_arcs[ll] + half);
    const double len = low.path.length();
    box.l_s = len > 0.0 ? std::max(0.0, l_arcs[lf] - half) / len : 0.0;
    box.l_e = len > 0.0 ? std::min(len, l_arcs[ll] + half) / len : 1.0;
    boxes.push_back(box);
  }
  return boxes;
}

std::vector<RegionSample> collision_region(const Agent& high, const Agent& low, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw Error("dt", 0, "expected a positive finite time step, got " + std::to_string(dt));
  }
  const double r = high.radius + low.radius;
  const auto& nodes = low.path.nodes();
  const auto& cum = low.path.cumulative();
  const double len = low.path.length();
  std::vector<RegionSample> out;
  const double t_end = high.path.travel_time();
  const auto steps = static_cast<int>(std::ceil(t_end / dt));
  for (int k = 0; k <= steps; ++k) {
    RegionSample s;
    s.t = std::min(t_end, k * dt);
    const Vec2 p1 = high.path.position(s.t);
    if (nodes.size() == 1 || len <= 0.0) {
      if (distance(p1, nodes.front()) < r) s.intervals.emplace_back(0.0, 1.0);
    }
    for (std::size_t i = 1; i < nodes.size() && len > 0.0; ++i) {
      const auto iv = collision_interval(p1, nodes[i - 1], nodes[i], r);
      if (!iv) continue;
      const double seg = cum[i] - cum[i - 1];
      const double lo = (cum[i - 1] + iv->first * seg) / len;
      const double hi = (cum[i - 1] + iv->second * seg) / len;
      if (!s.intervals.empty() && lo <= s.intervals.back().second + 1e-12) {
        s.intervals.back().second = std::max(s.intervals.back().second, hi);
      } else {
        s.intervals.emplace_back(lo, hi);
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace voronav::coordination
