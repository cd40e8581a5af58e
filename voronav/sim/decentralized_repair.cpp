// The decentralized method of seed 000, Tables 4–5: a robot that finds the saved path broken
// repairs it locally (own detour) or asks its neighbours with a Repair message.
#include "voronav/sim/robot_agent.hpp"

#include <algorithm>
#include <cmath>

#include "voronav/core/error.hpp"
#include "voronav/sim/agent_internal.hpp"

namespace voronav::sim {

using namespace network;
using namespace agent_detail;

// ---- decentralized: Repair (Tables 4–5) -------------------------------------------------------
/// Broken segments of `path` as seen in the robot's map: [first broken point, first good point
/// after).
std::optional<std::pair<std::uint32_t, std::uint32_t>> RobotAgent::find_break(
    const std::vector<VoronoiPoint>& path, std::size_t from) {
  std::optional<std::pair<std::uint32_t, std::uint32_t>> br;
  for (std::size_t i = from; i + 1 < path.size(); ++i) {
    if (segment_blocked(path[i].position, path[i + 1].position)) {
      if (!br) br = std::pair{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)};
      br->second = static_cast<std::uint32_t>(i + 1);
    }
  }
  report_.metrics.work += path.size();
  return br;
}

/// Shrinks the free disc of every point of `path` to the nearest cell this robot knows occupied:
/// route points keep the clearances of the older maps they were made from, so after an obstacle
/// change their discs may hold it, and the continuity rule would still join points across the
/// break (docs/reproductions/networked.md, "Repair").
void RobotAgent::shrink_to_map(std::vector<VoronoiPoint>& path) {
  const auto& g = r_.map.world();
  for (auto& p : path) {
    const auto c = g.world_to_cell(p.position);
    if (!c) continue;
    const int k = static_cast<int>(std::ceil(p.clearance / g.resolution)) + 1;
    double best = p.clearance;
    for (int dy = -k; dy <= k; ++dy)
      for (int dx = -k; dx <= k; ++dx) {
        const Cell d{c->x + dx, c->y + dy};
        if (r_.map.at(d) != kOccupied) continue;
        best = std::min(best, distance(g.cell_center(d), p.position) - 0.5 * g.resolution);
      }
    report_.metrics.work += static_cast<std::uint64_t>((2 * k + 1) * (2 * k + 1));
    p.clearance = static_cast<float>(std::max(best, 0.0));
  }
}

/// A detour through the robot's open points joining path[0..from] to path[to..]; empty when
/// none.
std::vector<VoronoiPoint> RobotAgent::detour(std::vector<VoronoiPoint> path, std::uint32_t from,
                                             std::uint32_t to) {
  const auto& own = points().open;
  shrink_to_map(path);  // this robot's own view of the change (the sender's is in the clearances)
  std::vector<VoronoiPoint> comb;
  std::vector<double> start;
  double along = 0.0;
  for (std::uint32_t i = 0; i <= from && i < path.size(); ++i) {
    if (i > 0) along += distance(path[i - 1].position, path[i].position);
    comb.push_back(path[i]);
    start.push_back(along);
  }
  const std::size_t n_pre = comb.size();
  for (const auto& p : own) {
    comb.push_back(p);
    start.push_back(kInf);
  }
  const std::size_t n_own_end = comb.size();
  for (std::size_t i = to; i < path.size(); ++i) {
    comb.push_back(path[i]);
    start.push_back(kInf);
  }
  // As in try_continue, the robot may also move straight where its own map knows the move is
  // free: here between its points and the route points (at most 6 m apart), never route point
  // to route point (that would be the broken route again).
  std::size_t los_cells = 0;
  auto own_edge = [&](std::size_t i, std::size_t j) {
    if ((i < n_pre || i >= n_own_end) && (j < n_pre || j >= n_own_end)) return false;
    const Vec2 a = comb[i].position, b = comb[j].position;
    if (distance(a, b) > 6.0) return false;
    los_cells += static_cast<std::size_t>(distance(a, b) / scen().world.resolution()) + 1;
    return segment_known_free(a, b);
  };
  const auto s = timed([&] { return search_points(comb, start, opt().robot_radius_m, own_edge); });
  report_.metrics.work += s.work + los_cells;
  double best = kInf;
  std::size_t bi = 0;
  for (std::size_t i = n_own_end; i < comb.size(); ++i) {
    if (!std::isfinite(s.cost[i])) continue;
    const std::size_t pi = to + (i - n_own_end);
    double rest = 0.0;
    for (std::size_t k = pi + 1; k < path.size(); ++k)
      rest += distance(path[k - 1].position, path[k].position);
    if (s.cost[i] + rest < best) {
      best = s.cost[i] + rest;
      bi = i;
    }
  }
  if (!std::isfinite(best)) return {};
  const auto chain = trace_points(s, bi);
  // The chain must use at least one own point and its moves must be free in the robot's map.
  bool uses_own = false;
  for (std::size_t i : chain)
    uses_own |= (i >= n_pre && i < n_own_end);
  if (!uses_own) return {};
  for (std::size_t k = 1; k < chain.size(); ++k)
    if (segment_blocked(comb[chain[k - 1]].position, comb[chain[k]].position)) return {};
  std::vector<VoronoiPoint> out(path.begin(),
                                path.begin() + static_cast<std::ptrdiff_t>(chain.front() + 1));
  for (std::size_t k = 1; k < chain.size(); ++k)
    out.push_back(comb[chain[k]]);
  const std::size_t pi = to + (bi - n_own_end);
  out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(pi + 1), path.end());
  return out;
}

std::uint32_t RobotAgent::next_repair_num() {
  return kRepairFlag | ((r_.id.value & 0x7FFFu) << 16) | (++repair_seq_ & 0xFFFFu);
}

void RobotAgent::check_relay_route() {
  auto& r = r_;
  auto path = r.saved->whole_path;
  const auto br = find_break(path, 0);
  if (!br) return;
  ++report_.repairs;
  shrink_to_map(path);  // so the Repair tells the others which free discs the change cut
  auto fixed = detour(path, br->first, br->second);
  if (!fixed.empty()) {
    ++report_.repairs_executed;
    log_repair(true, "repairs the route with its own detour (Repair executed)");
    PathMessage p = *r.saved;
    p.num = next_repair_num();
    p.whole_path = fixed;
    r.saved->whole_path = fixed;
    if (!p.relays.empty()) send_reliable(p.relays.back(), p);
    return;
  }
  RepairMessage m;
  m.source = source_id();
  m.num = (r.id.value << 16) | (++r.repair_counter & 0xFFFFu);
  m.relays = r.saved->relays;
  m.relays.push_back(r.id);
  m.whole_path = path;
  m.broken_from = br->first;
  m.broken_to = br->second;
  r.repairs_seen.insert(m.num);
  log_repair(false, "finds the route blocked and asks its neighbours (Repair message)");
  broadcast(m, 1);
}

void RobotAgent::on(const Header& h, const RepairMessage& m) {
  auto& r = r_;
  if (!r.repairs_seen.insert(m.num).second) return;
  if (m.broken_to >= m.whole_path.size()) return;
  auto fixed = detour(m.whole_path, m.broken_from, m.broken_to);
  NS_DEBUG("t=%.1f robot %u repair from %u: detour %zu\n", now_, r.id.value, h.sender.value,
           fixed.size());
  if (!fixed.empty()) {
    ++report_.repairs_executed;
    log_repair(true, "answers robot " + std::to_string(h.sender.value) +
                         "'s Repair with a detour (Repair executed)");
    PathMessage p;
    p.source = m.source;
    p.num = next_repair_num();
    p.relays = m.relays;
    p.whole_path = fixed;
    if (is_source()) {
      on_repair_path(p);
    } else {
      send_reliable(h.sender, p);
    }
    return;
  }
  if (h.hops < opt().repair_hops) broadcast(m, static_cast<std::uint8_t>(h.hops + 1));  // relay
}

void RobotAgent::on_repair_path(PathMessage m) {
  auto& r = r_;
  if (is_source()) {
    splice_route(m.whole_path);
    return;
  }
  if (!m.relays.empty() && m.relays.back() == r.id) m.relays.pop_back();
  if (r.saved && !m.whole_path.empty()) {
    // Keep this relay's own piece before the repaired part (the answer starts at a point of the
    // path the Repair carried, which may be a suffix of this relay's saved path).
    auto& w = r.saved->whole_path;
    auto at = std::find_if(w.begin(), w.end(), [&](const VoronoiPoint& p) {
      return distance(p.position, m.whole_path.front().position) < 1e-3;
    });
    if (at == w.end()) at = w.begin();  // not on it: the answer replaces it (as before)
    w.erase(at, w.end());
    w.insert(w.end(), m.whole_path.begin(), m.whole_path.end());
  }
  if (!m.relays.empty()) send_reliable(m.relays.back(), m);
}

void RobotAgent::splice_route(const std::vector<VoronoiPoint>& whole) {
  if (whole.empty() || route_.empty()) return;
  auto& s = r_;
  const std::size_t done = next_route_index();
  if (distance(whole.front().position, s.pos) < 1e-3) {
    // The answer to the source's own Repair: it starts where the source stands (it waits there
    // while blocked) and replaces the rest of the route.
    route_.erase(route_.begin() + static_cast<std::ptrdiff_t>(std::min(done, route_.size())),
                 route_.end());
    route_.insert(route_.end(), whole.begin() + 1, whole.end());
    set_source_waypoints(std::min(done, route_.size()));
    blocked_since_ = -1.0;
    NS_DEBUG("t=%.1f source splices a repaired route (%zu points)\n", now_, whole.size());
    return;
  }
  for (std::size_t i = route_.size(); i-- > 0;) {
    if (distance(route_[i].position, whole.front().position) < 1e-3) {
      if (i + 1 < done) break;  // already passed: the splice point is behind the source
      std::vector<VoronoiPoint> n(route_.begin(), route_.begin() + static_cast<std::ptrdiff_t>(i));
      n.insert(n.end(), whole.begin(), whole.end());
      route_ = std::move(n);
      set_source_waypoints(std::max<std::size_t>(done, 1) - 1);
      s.waypoints.insert(s.waypoints.begin(), s.pos);
      back_steps_ = 1;
      blocked_since_ = -1.0;
      return;
    }
  }
}

void RobotAgent::check_source_route() {
  auto& s = r_;
  if (route_.empty()) return;
  if (s.wp < back_steps_) {
    // Still on a planned way to the route (its own map): check what it drives, plan again if
    // that is blocked.
    if (walk_blocked() && !replan_to_route()) {
      NS_DEBUG("t=%.1f source way to the route blocked at (%.1f,%.1f)\n", now_, s.pos.x, s.pos.y);
      blocked_since_ = now_;
    }
    return;
  }
  // Only the part within sensing range matters; find_break checks the remaining route.
  std::vector<VoronoiPoint> rest{VoronoiPoint{s.pos, 1.0f, 0.0f}};
  const std::size_t next = next_route_index();
  rest.insert(rest.end(),
              route_.begin() + static_cast<std::ptrdiff_t>(std::min(next, route_.size())),
              route_.end());
  const auto br = find_break(rest, 0);
  if (!br) return;
  if (blocked_since_ < 0.0) blocked_since_ = now_;
  NS_DEBUG("t=%.1f source blocked at (%.1f,%.1f), break %u-%u of %zu\n", now_, s.pos.x, s.pos.y,
           br->first, br->second, rest.size());
  ++report_.repairs;
  shrink_to_map(rest);  // as in check_relay_route
  auto fixed = detour(rest, br->first, br->second);
  NS_DEBUG("t=%.1f source own detour %zu\n", now_, fixed.size());
  if (!fixed.empty()) {
    ++report_.repairs_executed;
    log_repair(true, "detours around the block on its own map (Repair executed)");
    route_.erase(route_.begin() + static_cast<std::ptrdiff_t>(std::min(next, route_.size())),
                 route_.end());
    route_.insert(route_.end(), fixed.begin() + 1, fixed.end());
    set_source_waypoints(std::min(next, route_.size()));
    blocked_since_ = -1.0;
    return;
  }
  RepairMessage m;
  m.source = s.id;
  m.num = (s.id.value << 16) | (++s.repair_counter & 0xFFFFu);
  m.relays = {s.id};
  m.whole_path = rest;
  m.broken_from = br->first;
  m.broken_to = br->second;
  s.repairs_seen.insert(m.num);
  log_repair(false, "is blocked and asks its neighbours (Repair message)");
  broadcast(m, 1);
}

/// Source, when no Repair answered in time: A* on its own map to the first route point past the
/// break that it can plan to, then the rest of the route.
bool RobotAgent::replan_to_route() {
  auto& s = r_;
  const std::size_t next = next_route_index();
  for (std::size_t i = std::max<std::size_t>(next, 1) + 1; i < route_.size(); ++i) {
    if (!plan_walk(route_[i].position)) continue;
    ++report_.replans;
    auto prefix = s.waypoints;
    route_.erase(route_.begin() + 1, route_.begin() + static_cast<std::ptrdiff_t>(i));
    route_[0] = VoronoiPoint{s.pos, 1.0f, 0.0f};
    for (std::size_t k = 2; k < route_.size(); ++k)
      prefix.push_back(route_[k].position);
    s.waypoints = std::move(prefix);
    s.wp = 0;
    back_steps_ = s.waypoints.size() - (route_.size() - 1);
    route_base_ = 1;
    return true;
  }
  return false;
}

}  // namespace voronav::sim
