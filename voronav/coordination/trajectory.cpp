#include "voronav/coordination/trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

namespace {

/// A stationary piece at p, valid for any time.
Piece still(Vec2 p, double t) {
  return {t, t, p, {0.0, 0.0}, {0.0, 0.0}};
}

/// The piece that describes `tr` around time t (stationary outside its pieces).
Piece piece_at(const Trajectory& tr, double t) {
  if (tr.pieces.empty()) return still({0.0, 0.0}, t);
  if (t <= tr.pieces.front().t0) return still(tr.pieces.front().p0, t);
  if (t >= tr.pieces.back().t1) return still(tr.end_point(), t);
  const auto it = std::lower_bound(tr.pieces.begin(), tr.pieces.end(), t,
                                   [](const Piece& p, double x) { return p.t1 < x; });
  return it == tr.pieces.end() ? still(tr.end_point(), t) : *it;
}

/// Real roots in [lo, hi] of c3 x^3 + c2 x^2 + c1 x + c0 with c3 != 0: the derivative's roots
/// split [lo, hi] into monotone pieces, each sign change is bisected to machine precision.
void cubic_roots(double c3, double c2, double c1, double c0, double lo, double hi,
                 std::vector<double>& out) {
  auto g = [&](double x) { return ((c3 * x + c2) * x + c1) * x + c0; };
  std::array<double, 4> cuts{lo, hi, lo, lo};
  int n = 2;
  const double qa = 3.0 * c3, qb = 2.0 * c2, qc = c1;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc >= 0.0) {
    const double s = std::sqrt(disc);
    for (const double r : {(-qb - s) / (2.0 * qa), (-qb + s) / (2.0 * qa)}) {
      if (r > lo && r < hi) cuts[static_cast<std::size_t>(n++)] = r;
    }
  }
  std::sort(cuts.begin(), cuts.begin() + n);
  for (int k = 0; k + 1 < n; ++k) {
    double x0 = cuts[static_cast<std::size_t>(k)], x1 = cuts[static_cast<std::size_t>(k + 1)];
    double g0 = g(x0), g1 = g(x1);
    if (g0 == 0.0) out.push_back(x0);
    if (g1 == 0.0) out.push_back(x1);
    if ((g0 < 0.0) == (g1 < 0.0) || g0 == 0.0 || g1 == 0.0) continue;
    for (int it = 0; it < 200 && x1 - x0 > 0.0; ++it) {
      const double xm = 0.5 * (x0 + x1);
      if (xm <= x0 || xm >= x1) break;
      const double gm = g(xm);
      if ((gm < 0.0) == (g0 < 0.0)) {
        x0 = xm;
        g0 = gm;
      } else {
        x1 = xm;
      }
    }
    out.push_back(0.5 * (x0 + x1));
  }
}

}  // namespace

Vec2 Trajectory::end_point() const {
  if (pieces.empty()) return {0.0, 0.0};
  const Piece& p = pieces.back();
  return p.at(p.t1);
}

Vec2 Trajectory::position(double t) const {
  return piece_at(*this, t).at(t);
}

Trajectory trajectory_of(const TimedPath& path, double delay, AtStart at_start, AtGoal at_goal) {
  Trajectory tr;
  const double travel = path.travel_time();
  tr.present_from = at_start == AtStart::kWait ? 0.0 : delay;
  tr.present_to = at_goal == AtGoal::kStay ? kInfinity : delay + travel;
  tr.half_open = at_start == AtStart::kAppear || at_goal == AtGoal::kLeave;
  const auto& cum = path.cumulative();
  const auto& nodes = path.nodes();
  const double amax = path.limits().a_max;
  std::vector<double> cuts;
  for (const double s : cum)
    cuts.push_back(path.time_at_arc(s));
  double ta = 0.0;  // duration of the acceleration phase
  if (std::isfinite(amax) && travel > 0.0) {
    const double v = path.limits().v_max;
    ta = path.length() >= v * v / amax ? v / amax : 0.5 * travel;
    cuts.push_back(ta);
    cuts.push_back(travel - ta);
  }
  cuts.push_back(0.0);
  cuts.push_back(travel);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double t0 = std::clamp(cuts[k], 0.0, travel), t1 = std::clamp(cuts[k + 1], 0.0, travel);
    if (!(t1 > t0)) continue;
    const double mid = 0.5 * (t0 + t1);
    const double s_mid = path.arc_at(mid);
    auto it = std::upper_bound(cum.begin(), cum.end(), s_mid);
    std::size_t i = static_cast<std::size_t>(it - cum.begin());
    i = std::clamp<std::size_t>(i, 1, nodes.size() - 1);
    const Vec2 seg = nodes[i] - nodes[i - 1];
    const double seg_len = seg.norm();
    const Vec2 u = seg_len > 0.0 ? seg / seg_len : Vec2{0.0, 0.0};
    double acc = 0.0, v0 = path.limits().v_max;
    if (std::isfinite(amax)) {
      if (mid < ta) {
        acc = amax;
        v0 = amax * t0;
      } else if (mid > travel - ta) {
        acc = -amax;
        v0 = amax * (travel - t0);
      } else {
        v0 = amax * ta;
      }
    }
    tr.pieces.push_back({t0 + delay, t1 + delay, path.position(t0), u * v0, u * acc});
  }
  if (tr.pieces.empty()) tr.pieces.push_back(still(nodes.front(), delay));
  return tr;
}

Trajectory trajectory_of(std::span<const TimedWaypoint> w, AtStart at_start, AtGoal at_goal) {
  if (w.empty()) throw Error("waypoints", 0, "a trajectory needs at least one waypoint");
  Trajectory tr;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!std::isfinite(w[i].t) || !w[i].p.is_finite() || w[i].t < 0.0)
      throw Error("waypoints", 0,
                  "waypoint " + std::to_string(i) + ": expected a finite time >= 0 and point");
    if (i > 0 && !(w[i].t > w[i - 1].t))
      throw Error("waypoints", 0,
                  "waypoint " + std::to_string(i) + ": times must increase strictly, got " +
                      std::to_string(w[i - 1].t) + " then " + std::to_string(w[i].t));
  }
  for (std::size_t i = 0; i + 1 < w.size(); ++i) {
    const double dt = w[i + 1].t - w[i].t;
    tr.pieces.push_back({w[i].t, w[i + 1].t, w[i].p, (w[i + 1].p - w[i].p) / dt, {0.0, 0.0}});
  }
  if (tr.pieces.empty()) tr.pieces.push_back(still(w.front().p, w.front().t));
  tr.present_from = at_start == AtStart::kWait ? 0.0 : w.front().t;
  tr.present_to = at_goal == AtGoal::kStay ? kInfinity : w.back().t;
  tr.half_open = at_start == AtStart::kAppear || at_goal == AtGoal::kLeave;
  return tr;
}

MinDistance min_distance(const Piece& a, const Piece& b, double lo, double hi) {
  const Vec2 D = a.at(lo) - b.at(lo);
  const Vec2 V = (a.v + a.a * (lo - a.t0)) - (b.v + b.a * (lo - b.t0));
  const Vec2 A = a.a - b.a;
  const double T = std::max(0.0, hi - lo);
  auto f = [&](double x) { return (D + V * x + A * (0.5 * x * x)).norm(); };
  MinDistance best{f(0.0), lo};
  auto consider = [&](double x) {
    if (!(x >= 0.0 && x <= T)) return;
    const double d = f(x);
    if (d < best.distance) best = {d, lo + x};
  };
  consider(T);
  // d/dx |d|^2 / 2 = (D + V x + A x^2/2) . (V + A x)
  const double c3 = 0.5 * dot(A, A), c2 = 1.5 * dot(A, V), c1 = dot(V, V) + dot(D, A),
               c0 = dot(D, V);
  if (c3 == 0.0) {
    if (c1 > 0.0) consider(-c0 / c1);
  } else {
    std::vector<double> roots;
    cubic_roots(c3, c2, c1, c0, 0.0, T, roots);
    for (const double r : roots)
      consider(r);
  }
  return best;
}

namespace {

template <class Stop>
MinDistance scan(const Trajectory& a, const Trajectory& b, double lo, double hi, Stop stop) {
  if (std::isinf(hi)) hi = std::max({lo, a.end_time(), b.end_time()});
  std::vector<double> cuts{lo, hi};
  for (const Trajectory* tr : {&a, &b}) {
    for (const Piece& p : tr->pieces) {
      if (p.t0 > lo && p.t0 < hi) cuts.push_back(p.t0);
      if (p.t1 > lo && p.t1 < hi) cuts.push_back(p.t1);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  MinDistance best{(a.position(lo) - b.position(lo)).norm(), lo};
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double x = cuts[k], y = cuts[k + 1];
    if (!(y > x)) continue;
    const double m = 0.5 * (x + y);
    const MinDistance d = min_distance(piece_at(a, m), piece_at(b, m), x, y);
    if (d.distance < best.distance) best = d;
    if (stop(d)) return d;
  }
  return best;
}

}  // namespace

MinDistance min_distance(const Trajectory& a, const Trajectory& b, double lo, double hi) {
  return scan(a, b, lo, hi, [](const MinDistance&) { return false; });
}

MinDistance first_below(const Trajectory& a, const Trajectory& b, double lo, double hi,
                        double limit) {
  return scan(a, b, lo, hi, [limit](const MinDistance& d) { return d.distance < limit; });
}

}  // namespace voronav::coordination
