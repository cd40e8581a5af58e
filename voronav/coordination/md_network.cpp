#include "voronav/coordination/md_network.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "voronav/core/error.hpp"

namespace voronav::coordination {

MdNetwork::MdNetwork(std::vector<double> travel_times)
    : travel_(std::move(travel_times)), incident_(travel_.size()) {
  for (std::size_t i = 0; i < travel_.size(); ++i) {
    if (!(travel_[i] >= 0.0) || !std::isfinite(travel_[i])) {
      throw Error("travel_time", 0,
                  "robot " + std::to_string(i) + ": expected a finite travel time >= 0, got " +
                      std::to_string(travel_[i]));
    }
  }
}

void MdNetwork::add_box(int i, int j, double m, double d) {
  if (i < 0 || j < 0 || i >= size() || j >= size() || i == j) {
    throw Error("box", 0,
                "robots " + std::to_string(i) + ", " + std::to_string(j) + " are not a valid pair");
  }
  if (std::isnan(m) || std::isnan(d) || (m <= 0.0 && d <= 0.0)) {
    throw Error("box", 0,
                "expected M + D > 0 (the time both robots spend in the box), got M=" +
                    std::to_string(m) + " D=" + std::to_string(d));
  }
  if (i > j) {  // store for a < b: swapping the priority swaps M and D
    std::swap(i, j);
    std::swap(m, d);
  }
  const int k = static_cast<int>(boxes_.size());
  boxes_.push_back({i, j, m, d});
  incident_[static_cast<std::size_t>(i)].push_back(k);
  incident_[static_cast<std::size_t>(j)].push_back(k);
}

std::pair<double, double> MdNetwork::oriented(int k, int high, double high_delay,
                                              double low_delay) const {
  const MdBox& b = boxes_[static_cast<std::size_t>(k)];
  double m = b.m, d = b.d;
  if (high == b.b) std::swap(m, d);
  return {m + low_delay - high_delay, d - low_delay + high_delay};
}

double MdNetwork::shared_time(int i, int j) const {
  double s = 0.0;
  const auto& inc = incident(i);
  for (const int k : inc) {
    const MdBox& b = boxes_[static_cast<std::size_t>(k)];
    if (b.a == j || b.b == j) s += b.m + b.d;
  }
  return s;
}

MdNetwork build_network(const std::vector<Agent>& agents, const CollisionMapOptions& options) {
  std::vector<double> travel;
  travel.reserve(agents.size());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const double r = agents[i].radius;
    if (!(r > 0.0) || !std::isfinite(r)) {
      throw Error("radius", 0,
                  "robot " + std::to_string(agents[i].id) + ": expected a positive radius, got " +
                      std::to_string(r));
    }
    travel.push_back(agents[i].path.travel_time());
  }
  MdNetwork net(std::move(travel));
  const double h = effective_node_spacing(agents, options);
  // Axis-aligned bounds to skip far-apart pairs quickly.
  struct Bounds {
    Vec2 lo, hi;
  };
  std::vector<Bounds> bounds;
  for (const auto& a : agents) {
    Bounds b{a.path.nodes().front(), a.path.nodes().front()};
    for (const Vec2 p : a.path.nodes()) {
      b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
      b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
    }
    bounds.push_back(b);
  }
  const int n = static_cast<int>(agents.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const auto& bi = bounds[static_cast<std::size_t>(i)];
      const auto& bj = bounds[static_cast<std::size_t>(j)];
      const double thr = agents[static_cast<std::size_t>(i)].radius +
                         agents[static_cast<std::size_t>(j)].radius + h;
      if (bi.lo.x - thr > bj.hi.x || bj.lo.x - thr > bi.hi.x || bi.lo.y - thr > bj.hi.y ||
          bj.lo.y - thr > bi.hi.y) {
        continue;
      }
      for (const auto& box : collision_boxes(agents[static_cast<std::size_t>(i)], i,
                                             agents[static_cast<std::size_t>(j)], j, h, options)) {
        if (!(box.m() + box.d() > 0.0)) continue;  // zero-duration box (paper_literal only)
        net.add_box(i, j, box.m(), box.d());
      }
    }
  }
  return net;
}

std::string_view to_string(ResolveStatus s) {
  switch (s) {
    case ResolveStatus::kOk:
      return "ok";
    case ResolveStatus::kNoDelaySchedule:
      return "no_delay_schedule";
  }
  return "?";
}

void check_order(std::span<const int> order, int n) {
  if (static_cast<int>(order.size()) != n) {
    throw Error("order", 0,
                "expected " + std::to_string(n) + " robots, got " + std::to_string(order.size()));
  }
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (const int i : order) {
    if (i < 0 || i >= n || seen[static_cast<std::size_t>(i)]) {
      throw Error("order", 0, "not a permutation: robot " + std::to_string(i));
    }
    seen[static_cast<std::size_t>(i)] = 1;
  }
}

namespace {

/// resolve() starting at position `from` with the delays of order[0..from) taken from `base`;
/// stops (cut = true) as soon as a completion time exceeds `cutoff`.
Resolution resolve_impl(const MdNetwork& net, std::span<const int> order,
                        std::span<const double> min_delays, const Resolution* base, int from,
                        double cutoff, int to = -1) {
  const int n = net.size();
  Resolution r;
  r.delays.assign(static_cast<std::size_t>(n), 0.0);
  r.completion.assign(static_cast<std::size_t>(n), 0.0);
  std::vector<int> rank(static_cast<std::size_t>(n), 0);
  for (int p = 0; p < n; ++p)
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(p)])] = p;
  for (int p = 0; p < from; ++p) {
    const auto i = static_cast<std::size_t>(order[static_cast<std::size_t>(p)]);
    r.delays[i] = base->delays[i];
    r.completion[i] = base->completion[i];
  }
  // With `to`: differs[j] = robot j's delay is not base's (bitwise).
  std::vector<char> differs;
  if (base != nullptr && to > from) differs.assign(static_cast<std::size_t>(n), 0);
  const auto& boxes = net.boxes();
  struct Arc {
    double m, d, hd;
    int j;
  };
  std::vector<Arc> act;
  for (int p = from; p < n; ++p) {
    const int i = order[static_cast<std::size_t>(p)];
    if (!differs.empty()) {
      if (p < to) {
        differs[static_cast<std::size_t>(i)] = 1;  // its set of higher robots may have changed
      } else {
        bool stale = false;
        for (const int k : net.incident(i)) {
          const MdBox& b = boxes[static_cast<std::size_t>(k)];
          const int j = b.a == i ? b.b : b.a;
          if (rank[static_cast<std::size_t>(j)] < p && differs[static_cast<std::size_t>(j)]) {
            stale = true;
            break;
          }
        }
        if (!stale) {
          r.delays[static_cast<std::size_t>(i)] = base->delays[static_cast<std::size_t>(i)];
          r.completion[static_cast<std::size_t>(i)] = base->completion[static_cast<std::size_t>(i)];
          if (r.completion[static_cast<std::size_t>(i)] > cutoff) {
            r.cut = true;
            r.makespan = kInfinity;
            r.sum_of_arrivals = kInfinity;
            return r;
          }
          continue;
        }
      }
    }
    double delay =
        min_delays.empty() ? 0.0 : std::max(0.0, min_delays[static_cast<std::size_t>(i)]);
    // The boxes shared with higher robots, in incident order: (M, D) oriented with j above i
    // (MdNetwork::oriented, inlined with the same arithmetic), j's delay.
    act.clear();
    for (const int k : net.incident(i)) {
      const MdBox& b = boxes[static_cast<std::size_t>(k)];
      const int j = b.a == i ? b.b : b.a;
      if (rank[static_cast<std::size_t>(j)] > p) continue;  // j has lower priority
      act.push_back(
          {j == b.b ? b.d : b.m, j == b.b ? b.m : b.d, r.delays[static_cast<std::size_t>(j)], j});
    }
    // Passes until no box moves i (the delay only grows). A box whose D after the delays is
    // <= epsilon stays so for every larger delay: it is dropped from later passes (it could
    // never fire again, so the sequence of shifts, and the result, are unchanged).
    bool changed = true;
    while (changed && r.status == ResolveStatus::kOk) {
      changed = false;
      std::size_t keep = 0;
      for (std::size_t q = 0; q < act.size(); ++q) {
        const Arc& e = act[q];
        const double m = e.m + delay - e.hd;
        const double d = e.d - delay + e.hd;
        if (!(d > kTimeEpsilon)) continue;
        act[keep++] = e;
        if (m > kTimeEpsilon) {
          if (std::isinf(d)) {
            r.status = ResolveStatus::kNoDelaySchedule;
            r.blocked = i;
            r.blocked_by = e.j;
            break;
          }
          delay += d;
          changed = true;
        }
      }
      if (r.status == ResolveStatus::kOk) act.resize(keep);
    }
    r.delays[static_cast<std::size_t>(i)] = delay;
    r.completion[static_cast<std::size_t>(i)] =
        net.travel_times()[static_cast<std::size_t>(i)] + delay;
    if (!differs.empty() && p >= to)
      differs[static_cast<std::size_t>(i)] = delay != base->delays[static_cast<std::size_t>(i)];
    if (r.status != ResolveStatus::kOk) break;
    if (r.completion[static_cast<std::size_t>(i)] > cutoff) {
      r.cut = true;
      r.makespan = kInfinity;
      r.sum_of_arrivals = kInfinity;
      return r;
    }
  }
  r.makespan = 0.0;
  r.sum_of_arrivals = 0.0;
  for (int i = 0; i < n; ++i) {
    r.makespan = std::max(r.makespan, r.completion[static_cast<std::size_t>(i)]);
    r.sum_of_arrivals += r.completion[static_cast<std::size_t>(i)];
  }
  if (r.status != ResolveStatus::kOk) {
    r.makespan = kInfinity;
    r.sum_of_arrivals = kInfinity;
  }
  return r;
}

}  // namespace

Resolution resolve(const MdNetwork& net, std::span<const int> order,
                   std::span<const double> min_delays) {
  const int n = net.size();
  check_order(order, n);
  if (!min_delays.empty() && static_cast<int>(min_delays.size()) != n) {
    throw Error("min_delays", 0, "expected one delay per robot");
  }
  return resolve_impl(net, order, min_delays, nullptr, 0, kInfinity);
}

Resolution resolve_incremental(const MdNetwork& net, std::span<const int> order,
                               const Resolution& base, int from, double cutoff, int to) {
  if (base.status != ResolveStatus::kOk || base.delays.size() != order.size())
    return resolve_impl(net, order, {}, nullptr, 0, cutoff);
  return resolve_impl(net, order, {}, &base, std::clamp<int>(from, 0, net.size()), cutoff,
                      to > from ? std::min<int>(to, net.size()) : -1);
}

std::vector<OrientedArc> network_for_order(const MdNetwork& net, std::span<const int> order,
                                           std::span<const double> delays) {
  const int n = net.size();
  check_order(order, n);
  std::vector<int> rank(static_cast<std::size_t>(n), 0);
  for (int p = 0; p < n; ++p)
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(p)])] = p;
  auto delay_of = [&](int i) { return delays.empty() ? 0.0 : delays[static_cast<std::size_t>(i)]; };
  std::vector<OrientedArc> arcs;
  for (int k = 0; k < static_cast<int>(net.boxes().size()); ++k) {
    const MdBox& b = net.boxes()[static_cast<std::size_t>(k)];
    const bool a_high = rank[static_cast<std::size_t>(b.a)] < rank[static_cast<std::size_t>(b.b)];
    const int high = a_high ? b.a : b.b;
    const int low = a_high ? b.b : b.a;
    const auto [m, d] = net.oriented(k, high, delay_of(high), delay_of(low));
    arcs.push_back({high, low, m, d});
  }
  return arcs;
}

}  // namespace voronav::coordination
