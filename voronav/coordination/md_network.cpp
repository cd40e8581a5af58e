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

/// The delay of robot i given its higher-priority boxes `act` (M, D with the other robot above,
/// no delays; hd = the other robot's delay), starting from `delay` (section 3.2.2, repeated until
/// no box moves i). A box whose D after the delays is <= epsilon stays so for every larger delay:
/// it is dropped from later passes (it could never fire again, so the sequence of shifts, and the
/// result, are unchanged). On an unresolvable box (D infinite) sets r.status / blocked.
template <class ArcT>
double resolve_robot(double delay, ArcT* act, std::size_t count, int& blocked_by) {
  blocked_by = -1;
  // A pass after a shift can stop at the box that made the last shift, when nothing shifted the
  // robot before it: the boxes after that one were already checked at this delay in the previous
  // pass. The shifts, and so the result, are exactly those of complete passes.
  std::size_t stop = count;
  bool changed = true;
  while (changed) {
    changed = false;
    std::size_t keep = 0;
    std::size_t last = 0;
    for (std::size_t q = 0; q < count; ++q) {
      if (!changed && q == stop) return delay;
      const ArcT e = act[q];
      const double m = e.m + delay - e.hd;
      const double d = e.d - delay + e.hd;
      // Branch-free compaction: the box stays for the next pass iff D > epsilon.
      const bool live = d > kTimeEpsilon;
      act[keep] = e;
      keep += live ? 1U : 0U;
      if (live && m > kTimeEpsilon) {
        if (std::isinf(d)) {
          blocked_by = e.j;
          return delay;
        }
        delay += d;
        changed = true;
        last = keep - 1;
      }
    }
    count = keep;
    stop = last + 1;
  }
  return delay;
}

struct HdArc {
  double m, d, hd;
  int j;
};

/// resolve_robot() with branches instead of the branch-free compaction and without the early
/// stop (the shifts, and so the result, are the same; MoveEvaluatorEqualsFullResolveBitwise
/// compares the two). Used by the full resolve(): on sparse networks (BM_ResolveRandom/100,
/// 3 boxes per robot) it is 10-15 % faster, while on the dense MAPF networks of the GA's 3-opt
/// the two take the same time (issue #16).
double resolve_robot_sparse(double delay, HdArc* act, std::size_t count, int& blocked_by) {
  blocked_by = -1;
  bool changed = true;
  while (changed) {
    changed = false;
    std::size_t keep = 0;
    for (std::size_t q = 0; q < count; ++q) {
      const HdArc e = act[q];
      const double m = e.m + delay - e.hd;
      const double d = e.d - delay + e.hd;
      if (!(d > kTimeEpsilon)) continue;
      act[keep++] = e;
      if (m > kTimeEpsilon) {
        if (std::isinf(d)) {
          blocked_by = e.j;
          return delay;
        }
        delay += d;
        changed = true;
      }
    }
    count = keep;
  }
  return delay;
}

/// Makespan and sum of arrivals from the completions (infinite unless status is ok).
void finish(Resolution& r) {
  r.makespan = 0.0;
  r.sum_of_arrivals = 0.0;
  for (const double c : r.completion) {
    r.makespan = std::max(r.makespan, c);
    r.sum_of_arrivals += c;
  }
  if (r.status != ResolveStatus::kOk) {
    r.makespan = kInfinity;
    r.sum_of_arrivals = kInfinity;
  }
}

void cut(Resolution& r) {
  r.cut = true;
  r.makespan = kInfinity;
  r.sum_of_arrivals = kInfinity;
}

/// resolve(); stops (cut) as soon as a completion time exceeds `cutoff`.
Resolution resolve_impl(const MdNetwork& net, std::span<const int> order,
                        std::span<const double> min_delays, double cutoff) {
  const int n = net.size();
  Resolution r;
  r.delays.assign(static_cast<std::size_t>(n), 0.0);
  r.completion.assign(static_cast<std::size_t>(n), 0.0);
  std::vector<int> rank(static_cast<std::size_t>(n), 0);
  for (int p = 0; p < n; ++p)
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(p)])] = p;
  const auto& boxes = net.boxes();
  std::vector<HdArc> act;
  for (int p = 0; p < n; ++p) {
    const int i = order[static_cast<std::size_t>(p)];
    const double delay0 =
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
    int blocked_by = -1;
    const double delay = resolve_robot_sparse(delay0, act.data(), act.size(), blocked_by);
    if (blocked_by >= 0) {
      r.status = ResolveStatus::kNoDelaySchedule;
      r.blocked = i;
      r.blocked_by = blocked_by;
    }
    r.delays[static_cast<std::size_t>(i)] = delay;
    r.completion[static_cast<std::size_t>(i)] =
        net.travel_times()[static_cast<std::size_t>(i)] + delay;
    if (r.status != ResolveStatus::kOk) break;
    if (r.completion[static_cast<std::size_t>(i)] > cutoff) {
      cut(r);
      return r;
    }
  }
  finish(r);
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
  return resolve_impl(net, order, min_delays, kInfinity);
}

MoveEvaluator::MoveEvaluator(const MdNetwork& net) : net_(net) {
  const int n = net.size();
  const auto& boxes = net.boxes();
  std::vector<int> last_seen(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    arc_begin_.push_back(static_cast<int>(arcs_.size()));
    nbr_begin_.push_back(static_cast<int>(nbrs_.size()));
    for (const int k : net.incident(i)) {
      const MdBox& b = boxes[static_cast<std::size_t>(k)];
      const int j = b.a == i ? b.b : b.a;
      arcs_.push_back({j, j == b.b ? b.d : b.m, j == b.b ? b.m : b.d});
      if (last_seen[static_cast<std::size_t>(j)] != i) {
        last_seen[static_cast<std::size_t>(j)] = i;
        nbrs_.push_back(j);
      }
    }
  }
  arc_begin_.push_back(static_cast<int>(arcs_.size()));
  nbr_begin_.push_back(static_cast<int>(nbrs_.size()));
  rank_old_.assign(static_cast<std::size_t>(n), 0);
  rank_new_.assign(static_cast<std::size_t>(n), 0);
  dirty_.assign(static_cast<std::size_t>(n), 0);
  int most = 0;
  for (int i = 0; i < n; ++i)
    most = std::max(most, arc_begin_[static_cast<std::size_t>(i) + 1] -
                              arc_begin_[static_cast<std::size_t>(i)]);
  act_.resize(static_cast<std::size_t>(most) + 1);
}

Resolution MoveEvaluator::resolve_move(std::span<const int> base_order, const Resolution& base,
                                       std::span<const int> order, int from, int to,
                                       double cutoff) {
  const int n = net_.size();
  if (base.status != ResolveStatus::kOk || base.delays.size() != order.size() ||
      base_order.size() != order.size()) {
    last_resolved_ = n;
    return resolve_impl(net_, order, {}, cutoff);
  }
  from = std::clamp(from, 0, n);
  to = std::clamp(to, from, n);
  // Both orders must be permutations of 0..n-1 (a repeated robot leaves a rank that does not
  // point back to its position).
  for (int p = 0; p < n; ++p) {
    const int o = base_order[static_cast<std::size_t>(p)], c = order[static_cast<std::size_t>(p)];
    if (o < 0 || o >= n || c < 0 || c >= n)
      throw Error("order", 0,
                  "not a permutation: robot " + std::to_string(o < 0 || o >= n ? o : c));
    rank_old_[static_cast<std::size_t>(o)] = p;
    rank_new_[static_cast<std::size_t>(c)] = p;
  }
  for (int p = 0; p < n; ++p) {
    const int o = base_order[static_cast<std::size_t>(p)], c = order[static_cast<std::size_t>(p)];
    if (rank_old_[static_cast<std::size_t>(o)] != p || rank_new_[static_cast<std::size_t>(c)] != p)
      throw Error("order", 0, "not a permutation: a robot appears twice");
  }
  std::fill(dirty_.begin(), dirty_.end(), 0);
  // Robots in [from, to) with a neighbour on the other side than before.
  for (int p = from; p < to; ++p) {
    const auto i = static_cast<std::size_t>(order[static_cast<std::size_t>(p)]);
    const int ro = rank_old_[i];
    for (int q = nbr_begin_[i]; q < nbr_begin_[i + 1]; ++q) {
      const auto j = static_cast<std::size_t>(nbrs_[static_cast<std::size_t>(q)]);
      if ((rank_new_[j] < p) != (rank_old_[j] < ro)) {
        dirty_[i] = 1;
        break;
      }
    }
  }
  Resolution r;
  r.delays = base.delays;
  r.completion = base.completion;
  last_resolved_ = 0;
  // Raw pointers: the loop below is the GA's hot spot (no reloads through the members).
  const Arc* arcs = arcs_.data();
  const int* arc_begin = arc_begin_.data();
  const int* nbrs = nbrs_.data();
  const int* nbr_begin = nbr_begin_.data();
  const int* rank = rank_new_.data();
  char* dirty = dirty_.data();
  Active* act = act_.data();
  double* delays = r.delays.data();
  double* completion = r.completion.data();
  const double* travel = net_.travel_times().data();
  for (int p = from; p < n; ++p) {
    const int i = order[static_cast<std::size_t>(p)];
    const auto ui = static_cast<std::size_t>(i);
    if (!dirty[ui]) continue;
    ++last_resolved_;
    // The boxes shared with higher robots, in incident order (branch-free filter).
    std::size_t count = 0;
    for (int q = arc_begin[ui]; q < arc_begin[ui + 1]; ++q) {
      const Arc& a = arcs[q];
      const auto j = static_cast<std::size_t>(a.j);
      act[count] = {a.m, a.d, delays[j], a.j};
      count += rank[j] < p ? 1U : 0U;
    }
    int blocked_by = -1;
    const double delay = resolve_robot(0.0, act, count, blocked_by);
    delays[ui] = delay;
    completion[ui] = travel[ui] + delay;
    if (blocked_by >= 0) {
      r.status = ResolveStatus::kNoDelaySchedule;
      r.blocked = i;
      r.blocked_by = blocked_by;
      for (int q = p + 1; q < n; ++q) {  // as resolve(): nothing below is resolved
        const auto k = static_cast<std::size_t>(order[static_cast<std::size_t>(q)]);
        delays[k] = 0.0;
        completion[k] = 0.0;
      }
      break;
    }
    if (completion[ui] > cutoff) {
      cut(r);
      return r;
    }
    if (delay != base.delays[ui]) {
      for (int q = nbr_begin[ui]; q < nbr_begin[ui + 1]; ++q) {
        const auto j = static_cast<std::size_t>(nbrs[q]);
        dirty[j] = static_cast<char>(dirty[j] | (rank[j] > p ? 1 : 0));
      }
    }
  }
  finish(r);
  if (r.status == ResolveStatus::kOk && r.makespan > cutoff) cut(r);
  return r;
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
