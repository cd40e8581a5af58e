#include "voronav/coordination/sipp.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

namespace {

using Interval = std::pair<double, double>;

/// Smallest x in [lo, hi] with a x^2 + b x + c < 0 ... returns the open root interval of
/// a x^2 + b x + c < 0 (a >= 0), or nothing.
std::optional<Interval> negative_part(double a, double b, double c) {
  if (a <= 0.0) {
    if (b == 0.0) return c < 0.0 ? std::optional<Interval>({-kInfinity, kInfinity}) : std::nullopt;
    const double x = -c / b;
    return b > 0.0 ? Interval{-kInfinity, x} : Interval{x, kInfinity};
  }
  const double disc = b * b - 4.0 * a * c;
  if (!(disc > 0.0)) return std::nullopt;
  const double s = std::sqrt(disc);
  return Interval{(-b - s) / (2.0 * a), (-b + s) / (2.0 * a)};
}

/// Sorted, merged union of open intervals.
std::vector<Interval> merge(std::vector<Interval> v) {
  std::sort(v.begin(), v.end());
  std::vector<Interval> out;
  for (const auto& iv : v) {
    if (!out.empty() && iv.first < out.back().second) {
      out.back().second = std::max(out.back().second, iv.second);
    } else {
      out.push_back(iv);
    }
  }
  return out;
}

}  // namespace

Reservations::Reservations(const GridGeometry& geometry, double max_radius)
    : geometry_(geometry), max_radius_(max_radius), cells_(geometry.size()) {}

void Reservations::add(const Trajectory& tr, double radius) {
  if (tr.pieces.empty()) return;
  const Piece& first = tr.pieces.front();
  if (tr.present_from < first.t0) {
    add_segment({tr.present_from, first.t0, first.p0, {0.0, 0.0}, radius});
  }
  for (const Piece& p : tr.pieces) {
    if (p.a.x != 0.0 || p.a.y != 0.0)
      throw Error("a_max", 0, "SIPP plans among constant-velocity robots only (a_max: infinity)");
    if (p.t1 <= tr.present_from || p.t0 >= tr.present_to) continue;
    const double s0 = std::max(p.t0, tr.present_from), s1 = std::min(p.t1, tr.present_to);
    if (s1 > s0) add_segment({s0, s1, p.at(s0), p.v, radius});
  }
  if (tr.present_to > tr.end_time()) {
    add_segment({tr.end_time(), tr.present_to, tr.end_point(), {0.0, 0.0}, radius});
  }
}

void Reservations::add_soft(Vec2 p, double radius, double s0, double s1, int owner) {
  add_segment({s0, s1, p, {0.0, 0.0}, radius, owner});
}

void Reservations::add_segment(const Segment& s) {
  const int id = static_cast<int>(segments_.size());
  segments_.push_back(s);
  const Vec2 a = s.p0;
  const Vec2 b = std::isfinite(s.s1) ? s.p0 + s.z * (s.s1 - s.s0) : s.p0;
  // A move reaches at most half a cell diagonal from the cell it starts or ends at.
  const double reach = s.radius + max_radius_ + 0.75 * geometry_.resolution;
  const Vec2 ga = geometry_.world_to_grid(a), gb = geometry_.world_to_grid(b);
  const double rc = reach / geometry_.resolution;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min(ga.x, gb.x) - rc)));
  const int x1 =
      std::min(geometry_.width - 1, static_cast<int>(std::floor(std::max(ga.x, gb.x) + rc)));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min(ga.y, gb.y) - rc)));
  const int y1 =
      std::min(geometry_.height - 1, static_cast<int>(std::floor(std::max(ga.y, gb.y) + rc)));
  const Vec2 ab = b - a;
  const double l2 = dot(ab, ab);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Vec2 c = geometry_.cell_center({x, y});
      const double t = l2 > 0.0 ? std::clamp(dot(c - a, ab) / l2, 0.0, 1.0) : 0.0;
      if ((c - (a + ab * t)).norm() <= reach) cells_[geometry_.index({x, y})].push_back(id);
    }
  }
}

std::optional<std::pair<double, double>> bad_departures(Vec2 from, Vec2 to, double v, double radius,
                                                        const Reservations::Segment& s,
                                                        double slack) {
  const double R = radius + s.radius - slack;
  const double tau = distance(from, to) / v;
  const Vec2 w = tau > 0.0 ? (to - from) / tau : Vec2{0.0, 0.0};
  // d(t_d, sigma) = C + a t_d + b sigma, sigma in [0, tau], t_d + sigma in [s0, s1].
  const Vec2 C = from - s.p0 + s.z * s.s0;
  const Vec2 a = s.z * -1.0;
  const Vec2 b = w - s.z;
  if (s.z.x == 0.0 && s.z.y == 0.0) {
    // Stationary disc: the bad part of the move is an interval of sigma.
    const auto neg = negative_part(dot(b, b), 2.0 * dot(C, b), dot(C, C) - R * R);
    if (!neg) return std::nullopt;
    const double sa = std::max(0.0, neg->first), sb = std::min(tau, neg->second);
    if (!(sb > sa) && !(tau == 0.0 && neg->first < 0.0 && neg->second > 0.0)) return std::nullopt;
    const double lo = s.s0 - sb, hi = s.s1 - sa;
    if (!(hi > lo)) return std::nullopt;
    return Interval{lo, hi};
  }
  // Moving disc (finite s1): extremes of t_d over {Q <= 0} within the parallelogram.
  const Vec2 P[4] = {{s.s0, 0.0}, {s.s1, 0.0}, {s.s1 - tau, tau}, {s.s0 - tau, tau}};
  auto Q = [&](double td, double sg) { return (C + a * td + b * sg).squared_norm() - R * R; };
  double lo = kInfinity, hi = -kInfinity;
  auto take = [&](double td) {
    lo = std::min(lo, td);
    hi = std::max(hi, td);
  };
  for (int k = 0; k < 4; ++k) {
    const Vec2 V = P[k], E = P[(k + 1) % 4] - P[k];
    if (Q(V.x, V.y) <= 0.0) take(V.x);
    const Vec2 e = a * E.x + b * E.y, c0 = C + a * V.x + b * V.y;
    const double qa = dot(e, e), qb = 2.0 * dot(c0, e), qc = dot(c0, c0) - R * R;
    if (qa <= 0.0) continue;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0) continue;
    const double sq = std::sqrt(disc);
    for (const double lam : {(-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)}) {
      if (lam >= 0.0 && lam <= 1.0) take(V.x + E.x * lam);
    }
  }
  const double cab = cross(a, b), bb = dot(b, b);
  if (std::abs(cab) > 1e-12 && bb > 0.0) {
    for (const double sign : {-1.0, 1.0}) {
      const double td = (sign * R * std::sqrt(bb) - cross(C, b)) / cab;
      const double sg = -dot(C + a * td, b) / bb;
      if (sg >= 0.0 && sg <= tau && td + sg >= s.s0 && td + sg <= s.s1) take(td);
    }
  }
  if (!(hi > lo)) return std::nullopt;
  return Interval{lo, hi};
}

namespace {

struct State {
  int cell = 0;      // grid index
  int interval = 0;  // index into the cell's safe intervals
};

class Search {
 public:
  Search(const BinaryGrid& free, double radius, double v, const Reservations& res,
         const SippOptions& o)
      : free_(free),
        g_(free.geometry()),
        radius_(radius),
        v_(v),
        res_(res),
        o_(o),
        safe_slot_(free.geometry().size(), -1) {}

  const std::vector<Interval>& safe(std::size_t cell) {
    // Tables are computed on demand: a search touches few cells of a large map.
    if (safe_slot_[cell] >= 0) return safe_pool_[static_cast<std::size_t>(safe_slot_[cell])];
    const Vec2 c = g_.cell_center(g_.cell_at(cell));
    std::vector<Interval> unsafe;
    for (const int id : res_.near(g_.cell_at(cell))) {
      const auto& s = res_.segments()[static_cast<std::size_t>(id)];
      if (inactive(s)) continue;
      const double R = radius_ + s.radius - o_.slack;
      const Vec2 d0 = s.p0 - c;
      const auto neg = negative_part(dot(s.z, s.z), 2.0 * dot(d0, s.z), dot(d0, d0) - R * R);
      if (!neg) continue;
      const double lo = std::max(s.s0, s.s0 + neg->first);
      const double hi = std::min(s.s1, s.s0 + neg->second);
      if (hi > lo) unsafe.push_back({lo, hi});
    }
    unsafe = merge(std::move(unsafe));
    safe_slot_[cell] = static_cast<int>(safe_pool_.size());
    std::vector<Interval>& out = safe_pool_.emplace_back();
    double t = 0.0;
    for (const auto& [lo, hi] : unsafe) {
      if (lo > t) out.push_back({t, lo});
      t = std::max(t, hi);
    }
    if (std::isfinite(t)) out.push_back({t, kInfinity});
    return out;
  }

  /// Bad departure intervals of the move a -> b, merged, as far as they matter for departures in
  /// [lo, hi]: reserved segments that end before lo or begin after hi + the move's duration
  /// cannot touch such a move and are skipped (the search asks again for later departures).
  std::vector<Interval> bad(std::size_t a, std::size_t b, double lo, double hi, double tau) {
    const Vec2 pa = g_.cell_center(g_.cell_at(a)), pb = g_.cell_center(g_.cell_at(b));
    ++stamp_;
    if (seen_.size() < res_.segments().size()) seen_.resize(res_.segments().size(), 0);
    std::vector<Interval> out;
    for (const std::size_t c : {a, b}) {
      for (const int id : res_.near(g_.cell_at(c))) {
        if (seen_[static_cast<std::size_t>(id)] == stamp_) continue;
        seen_[static_cast<std::size_t>(id)] = stamp_;
        const auto& seg = res_.segments()[static_cast<std::size_t>(id)];
        if (seg.s1 <= lo || seg.s0 >= hi + tau) continue;
        if (inactive(seg)) continue;
        const auto iv = bad_departures(pa, pb, v_, radius_, seg, o_.slack);
        if (iv) out.push_back(*iv);
      }
    }
    return merge(std::move(out));
  }

  std::optional<std::vector<TimedWaypoint>> run(Cell start, Cell goal, SippStats* stats) {
    const std::size_t s = g_.index(start), gl = g_.index(goal);
    const Vec2 goal_p = g_.cell_center(goal);
    auto h = [&](std::size_t c) {
      const Cell p = g_.cell_at(c);
      const double dx = std::abs(p.x - goal.x), dy = std::abs(p.y - goal.y);
      return (std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy)) * g_.resolution / v_;
    };
    (void)goal_p;
    struct Node {
      std::size_t cell;
      int interval;
      double g;
      int parent;
    };
    std::vector<Node> nodes;
    using Entry = std::pair<double, int>;  // f, node
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    // best arrival per (cell, interval)
    std::vector<int> best_slot(g_.size(), -1);
    std::vector<std::vector<double>> best_pool;
    auto best = [&](std::size_t cell) -> std::vector<double>& {
      if (best_slot[cell] < 0) {
        best_slot[cell] = static_cast<int>(best_pool.size());
        best_pool.emplace_back();
      }
      return best_pool[static_cast<std::size_t>(best_slot[cell])];
    };
    auto push = [&](std::size_t cell, int iv, double g, int parent) {
      auto& b = best(cell);
      if (b.size() <= static_cast<std::size_t>(iv))
        b.resize(static_cast<std::size_t>(iv) + 1, kInfinity);
      if (g >= b[static_cast<std::size_t>(iv)]) return;
      b[static_cast<std::size_t>(iv)] = g;
      nodes.push_back({cell, iv, g, parent});
      open.push({g + h(cell), static_cast<int>(nodes.size()) - 1});
      if (stats) ++stats->generated;
    };
    if (free_[s] != 0 || free_[gl] != 0) return std::nullopt;
    const auto& ss = safe(s);
    for (std::size_t k = 0; k < ss.size(); ++k) {
      if (o_.at_start == AtStart::kWait) {
        if (ss[k].first <= 0.0 && ss[k].second > 0.0) push(s, static_cast<int>(k), 0.0, -1);
      } else {
        push(s, static_cast<int>(k), ss[k].first, -1);
      }
    }
    std::size_t expansions = 0;
    static constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
    static constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
    while (!open.empty()) {
      const auto [f, ni] = open.top();
      open.pop();
      const Node n = nodes[static_cast<std::size_t>(ni)];
      if (n.g > best(n.cell)[static_cast<std::size_t>(n.interval)]) continue;
      if (++expansions > o_.max_expansions) break;
      if (stats) ++stats->expansions;
      const auto& here = safe(n.cell)[static_cast<std::size_t>(n.interval)];
      if (n.cell == gl && (o_.at_goal == AtGoal::kLeave || std::isinf(here.second))) {
        // Reconstruct.
        std::vector<TimedWaypoint> out;
        int k = ni;
        std::vector<int> chain;
        while (k >= 0) {
          chain.push_back(k);
          k = nodes[static_cast<std::size_t>(k)].parent;
        }
        std::reverse(chain.begin(), chain.end());
        for (std::size_t i = 0; i < chain.size(); ++i) {
          const Node& m = nodes[static_cast<std::size_t>(chain[i])];
          const Vec2 p = g_.cell_center(g_.cell_at(m.cell));
          if (i > 0) {
            const Node& prev = nodes[static_cast<std::size_t>(chain[i - 1])];
            const double tau = distance(g_.cell_center(g_.cell_at(prev.cell)), p) / v_;
            const double depart = m.g - tau;
            if (depart > out.back().t + 1e-12) out.push_back({depart, out.back().p});
          }
          if (out.empty() || m.g > out.back().t) out.push_back({m.g, p});
        }
        // Drop waypoints inside a straight constant-velocity run (fewer pieces to check).
        std::vector<TimedWaypoint> merged;
        for (const TimedWaypoint& w : out) {
          if (merged.size() >= 2) {
            const TimedWaypoint& a = merged[merged.size() - 2];
            const TimedWaypoint& b = merged.back();
            const Vec2 v1 = (b.p - a.p) / (b.t - a.t), v2 = (w.p - b.p) / (w.t - b.t);
            if ((v1 - v2).norm() < 1e-12) merged.pop_back();
          }
          merged.push_back(w);
        }
        return merged;
      }
      const Cell c = g_.cell_at(n.cell);
      for (int d = 0; d < 8; ++d) {
        const Cell q{c.x + kDx[d], c.y + kDy[d]};
        if (!g_.contains(q) || free_[q] != 0) continue;
        if (d >= 4 && (free_[Cell{c.x + kDx[d], c.y}] != 0 || free_[Cell{c.x, c.y + kDy[d]}] != 0))
          continue;  // no corner cutting
        const std::size_t qi = g_.index(q);
        const double tau = (d >= 4 ? std::sqrt(2.0) : 1.0) * g_.resolution / v_;
        const auto& targets = safe(qi);
        if (targets.empty()) continue;
        // Departures that can matter: from n.g to the end of this interval or of v's last one.
        const double hi_dep = std::min(here.second, targets.back().second - tau);
        if (n.g > hi_dep) continue;
        const std::vector<Interval> bads = bad(n.cell, qi, n.g, hi_dep, tau);
        for (std::size_t k = 0; k < targets.size(); ++k) {
          const double lo = std::max(n.g, targets[k].first - tau);
          const double hi = std::min(here.second, targets[k].second - tau);
          if (lo > hi) continue;
          // earliest departure in [lo, hi] outside the open bad intervals
          double t = lo;
          for (const auto& [blo, bhi] : bads) {
            if (bhi <= t) continue;
            if (blo >= t) break;
            t = bhi;
          }
          if (t > hi || (t == hi && std::isinf(hi))) continue;
          if (std::isinf(t)) continue;
          push(qi, static_cast<int>(k), t + tau, ni);
        }
      }
    }
    return std::nullopt;
  }

 private:
  bool inactive(const Reservations::Segment& s) const {
    const auto* v = o_.inactive_owners;
    return s.owner >= 0 && v != nullptr && static_cast<std::size_t>(s.owner) < v->size() &&
           (*v)[static_cast<std::size_t>(s.owner)] != 0;
  }
  const BinaryGrid& free_;
  const GridGeometry& g_;
  double radius_, v_;
  const Reservations& res_;
  const SippOptions& o_;
  std::vector<int> safe_slot_;  // per cell: index into safe_pool_, -1 = not yet
  std::vector<std::vector<Interval>> safe_pool_;
  std::vector<unsigned> seen_;
  unsigned stamp_ = 0;
};

}  // namespace

std::optional<std::vector<TimedWaypoint>> sipp_plan(const BinaryGrid& free, Cell start, Cell goal,
                                                    double radius, double v_max,
                                                    const Reservations& reserved,
                                                    const SippOptions& options, SippStats* stats) {
  const GridGeometry& g = free.geometry();
  if (!g.contains(start) || !g.contains(goal))
    throw Error("sipp", 0, "start or goal outside the map");
  if (!(v_max > 0.0) || !std::isfinite(v_max)) throw Error("v_max", 0, "expected > 0 and finite");
  if (!(radius > 0.0)) throw Error("radius", 0, "expected > 0");
  Search s(free, radius, v_max, reserved, options);
  return s.run(start, goal, stats);
}

}  // namespace voronav::coordination
