// The decentralized method of seed 000, Table 3: Path messages travel back along the Relay Robots
// list. A relay waits a little, selects the shortest answer, saves it, deletes itself from Relay
// Robots and prepends its piece (from its sender's exit point to where the answer joins its
// points). Added for a real radio (issue #13): when the next relay is out of range the Path is
// carried hop by hop by the neighbour closest to where that relay was (loop guard: no robot
// carries it twice); when no neighbour is closer, the holder walks back until the relay is in
// range. A Path that still cannot be delivered is counted (paths_lost), never dropped silently.
// The source joins the route from where it stands.
#include <algorithm>
#include <cmath>
#include <set>

#include "voronav/core/error.hpp"
#include "voronav/sim/agent_internal.hpp"
#include "voronav/sim/robot_agent.hpp"

namespace voronav::sim {

using namespace network;
using namespace agent_detail;

namespace {

/// How long a robot holds an undeliverable Path (walking back toward its next relay) before it
/// counts it lost [s].
constexpr double kHoldPathS = 120.0;

bool contains(const std::vector<RobotId>& v, RobotId id) {
  return std::find(v.begin(), v.end(), id) != v.end();
}

}  // namespace

std::optional<Vec2> RobotAgent::neighbour_position(RobotId id) {
  for (const auto& n : transport_.nearby(r_.id))
    if (n.id == id) return n.position;
  return std::nullopt;
}

// ---- delivery ----------------------------------------------------------------------------------
void RobotAgent::deliver_path(PathMessage p, RobotId to, Vec2 toward,
                              [[maybe_unused]] bool carrier) {
  auto& r = r_;
  NS_DEBUG("t=%.1f robot %u delivers path to %u (in range %d, carrier %d)\n", now_, r.id.value,
           to.value, neighbour_position(to) ? 1 : 0, carrier ? 1 : 0);
  if (neighbour_position(to)) {
    send_reliable(to, p);
    return;
  }
  // Multi-hop fallback: hand the Path to the neighbour closest to where `to` was, if that is
  // at least 0.5 m closer than this robot (greedy progress; every carrier is recorded).
  p.toward = toward;
  if (!contains(p.carriers, r.id)) p.carriers.push_back(r.id);
  const double mine = distance(r.pos, toward);
  RobotId best = kBroadcast;
  double bd = mine - 0.5;
  for (const auto& n : transport_.nearby(r.id)) {
    if (contains(p.carriers, n.id)) continue;
    const double d = distance(n.position, toward);
    if (d < bd) {
      bd = d;
      best = n.id;
    }
  }
  if (best != kBroadcast) {
    send_reliable(best, p);
    return;
  }
  if (!r.pending) {
    // The holder (or carrier) walks back toward the relay until it is in range (pending_step).
    r.pending = p;
    r.pending_since = now_;
    return;
  }
  NS_DEBUG("t=%.1f robot %u loses a path (already holds one, carrier %d)\n", now_, r.id.value,
           carrier ? 1 : 0);
  ++report_.paths_lost;
}

/// A Path (Table 3) sent to a robot that never acknowledged it within the link retries (it left
/// radio range, s2r3 and s2r4 of the fourth pass): handed to the multi-hop fallback toward its
/// next relay (path_fallback_after_retries). Returns false when it is not taken (the option is
/// off, a repaired path, or no relay to go to): the caller counts it lost.
bool RobotAgent::path_after_retries(const std::vector<std::uint8_t>& bytes) {
  if (!opt().path_fallback_after_retries || opt().method != Method::kDecentralized) return false;
  Envelope e;
  try {
    e = decode(bytes);
  } catch (const Error&) {
    return false;
  }
  if (e.type() != MessageType::kPath) return false;
  PathMessage p = std::get<PathMessage>(e.payload);
  if ((p.num & kRepairFlag) || p.relays.empty() || p.relays.back() == r_.id) return false;
  NS_DEBUG("t=%.1f robot %u: path to %u unacknowledged, to the fallback\n", now_, r_.id.value,
           p.relays.back().value);
  const int lost = report_.paths_lost;
  deliver_path(p, p.relays.back(), p.toward, true);
  return report_.paths_lost == lost;
}

/// Each step while a Path waits: deliver it when its relay (or a closer carrier) is in range,
/// else keep walking back toward where the relay was; count it lost after kHoldPathS.
void RobotAgent::pending_step() {
  auto& r = r_;
  if (!r.pending) return;
  const RobotId to = r.pending->relays.back();
  const Vec2 toward = r.pending->toward;
  const double mine = distance(r.pos, toward);
  RobotId via = kBroadcast;
  double bd = mine - 0.5;
  for (const auto& n : transport_.nearby(r.id)) {
    if (n.id == to) {
      via = to;
      break;
    }
    if (contains(r.pending->carriers, n.id)) continue;
    const double d = distance(n.position, toward);
    if (d < bd) {
      bd = d;
      via = n.id;
    }
  }
  if (via != kBroadcast) {
    PathMessage p = std::move(*r.pending);
    r.pending.reset();
    if (r.walk == Walk::kBack) {
      r.walk = Walk::kIdle;
      r.waypoints.clear();
    }
    send_reliable(via, p);
    return;
  }
  if (now_ - r.pending_since > kHoldPathS) {
    NS_DEBUG("t=%.1f robot %u loses a path (held too long)\n", now_, r.id.value);
    r.pending.reset();
    ++report_.paths_lost;
    return;
  }
  if (r.walk == Walk::kIdle && r.wp >= r.waypoints.size() && distance(r.pos, toward) > 1.0) {
    if (plan_walk(toward)) {
      r.walk = Walk::kBack;
    } else {
      r.pending.reset();
      ++report_.paths_lost;
    }
  }
}

// ---- Table 3 -----------------------------------------------------------------------------------
void RobotAgent::on(const Header& h, const PathMessage& m) {
  auto& r = r_;
  if (m.num & kRepairFlag) {
    on_repair_path(m, h.sender);
    return;
  }
  if (m.relays.empty() || m.whole_path.empty()) {
    ++report_.paths_lost;
    return;
  }
  if (m.relays.back() != r.id) {
    // Carried toward the next relay (multi-hop fallback). Loop guard: a robot that already
    // carried this Path does not take it again.
    if (contains(m.carriers, r.id)) {
      NS_DEBUG("t=%.1f robot %u loses a path (loop guard, from %u)\n", now_, r.id.value,
               h.sender.value);
      ++report_.paths_lost;
      return;
    }
    deliver_path(m, m.relays.back(), m.toward, true);
    return;
  }
  NS_DEBUG("t=%.1f robot %u got path num %u (s_num %u)\n", now_, r.id.value, m.num, r.s_num);
  if (m.num != r.s_num) {  // an answer to a search this robot no longer runs
    NS_DEBUG("t=%.1f robot %u: a path of an old search (num %u)\n", now_, r.id.value, m.num);
    // The source received it, after a new Search: late, not lost (s2r8). A relay cannot send it
    // on (it no longer knows that search's senders): lost.
    ++(is_source() ? report_.paths_late : report_.paths_lost);
    return;
  }
  if (is_source() && !route_.empty()) return;  // delivered; the source already drives a route
  PathMessage got = m;
  got.carriers.clear();
  r.got_paths.push_back(std::move(got));
  r.path_forwarded = false;  // a later answer is selected again (and sent on if shorter)
  if (r.path_deadline < 0.0) r.path_deadline = now_ + opt().path_wait_s;
}

void RobotAgent::select_path() {
  auto& r = r_;
  r.path_deadline = -1.0;
  if (r.got_paths.empty() || r.path_forwarded) return;
  r.path_forwarded = true;
  // Select the shortest: cost to the exit point + the rest of the whole path.
  double best = kInf;
  std::size_t bi = 0, best_ci = r.s_comb.size();
  for (std::size_t k = 0; k < r.got_paths.size(); ++k) {
    const auto& p = r.got_paths[k];
    const std::size_t ci = own_index_at(p.whole_path.front().position);
    double c = kInf;
    if (ci < r.s_comb.size() && std::isfinite(r.s_search.cost[ci])) {
      c = r.s_search.cost[ci] + route_length(p.whole_path);
    } else if (is_source()) {
      // The source moved since it sent its points: it joins the route from where it stands.
      c = distance(r.pos, p.whole_path.front().position) + route_length(p.whole_path);
    }
    if (c < best) {
      best = c;
      bi = k;
      best_ci = ci;
    }
  }
  NS_DEBUG("t=%.1f robot %u selects: best %.1f (joins %d)\n", now_, r.id.value, best,
           best_ci < r.s_comb.size() ? 1 : 0);
  if (!std::isfinite(best)) {
    report_.paths_lost += static_cast<int>(r.got_paths.size());  // nowhere to join them
    r.got_paths.clear();
    return;
  }
  PathMessage got = r.got_paths[bi];
  r.got_paths.clear();
  if (!is_source() && r.saved && r.saved->num == got.num && best >= r.saved_cost - 1e-6)
    return;  // this relay already sent a shorter answer on
  if (got.owners.size() != got.whole_path.size())
    got.owners.assign(got.whole_path.size(), kBroadcast);
  PathMessage out = got;
  std::size_t sender = 0;
  if (best_ci < r.s_comb.size()) {
    // Prepend the own piece (it ends with the exit point the answer starts with).
    auto pc = own_piece(best_ci);
    sender = pc.sender;
    out.whole_path = pc.points;
    out.whole_path.insert(out.whole_path.end(), got.whole_path.begin() + 1, got.whole_path.end());
    out.owners.assign(pc.points.size(), r.id);
    out.owners.front() = r.s_senders[pc.sender].id;
    out.owners.insert(out.owners.end(), got.owners.begin() + 1, got.owners.end());
    out.exit_index = pc.exit;
  }
  if (is_source()) {
    finish_route(out, false);
    return;
  }
  out.relays = r.s_senders[sender].relays;  // delete oneself: continue toward the source
  out.toward = r.s_senders[sender].pos;     // where the next relay was (for the fallback)
  r.saved = out;
  r.saved_cost = best;
  deliver_path(out, r.s_senders[sender].id, r.s_senders[sender].pos, false);
}

/// The source has an answer: it joins the route from where it stands (the route point it can
/// reach straight through known free space leaving the shortest way; else a walk planned on its
/// own map to the best route point), then drives the open points.
void RobotAgent::finish_route(const PathMessage& p, bool own_answer) {
  auto& s = r_;
  const bool first = report_.route_time_s < 0.0;
  bool sees_way = own_answer;
  if (first && !own_answer) sees_way = source_sees_way();
  s.walk = Walk::kIdle;
  s.s_done = true;
  std::vector<VoronoiPoint> w = p.whole_path;
  std::vector<RobotId> owners = p.owners;
  if (owners.size() != w.size()) owners.assign(w.size(), kBroadcast);
  if (w.empty() || distance(w.back().position, scen().destination) > 1e-3) {
    w.push_back(VoronoiPoint{scen().destination, 1.0f, 0.0f});
    owners.push_back(owners.empty() ? s.id : owners.back());
  }
  std::vector<double> rest(w.size() + 1, 0.0);
  for (std::size_t j = w.size() - 1; j-- > 0;)
    rest[j] = rest[j + 1] + distance(w[j].position, w[j + 1].position);
  std::size_t join = w.size();
  double best = kInf;
  for (std::size_t j = 0; j < w.size(); ++j) {
    const double c = distance(s.pos, w[j].position) + rest[j];
    if (c < best &&
        (distance(s.pos, w[j].position) < 1e-6 || segment_known_free(s.pos, w[j].position))) {
      best = c;
      join = j;
    }
  }
  std::vector<Vec2> prefix;  // the way to the join point (ends at it)
  if (join == w.size()) {
    // Back along its own trail (driven, so known free) only as far as needed: to the trail point
    // from which a route point is a straight known-free move (<= 6 m), leaving the shortest way.
    double back = 0.0;
    Vec2 prev = s.pos, checked{kInf, kInf};
    std::size_t tk = trail_.size(), tj = w.size();
    double tbest = kInf;
    for (std::size_t k = trail_.size(); k-- > 0;) {
      back += distance(prev, trail_[k]);
      prev = trail_[k];
      if (back >= tbest) break;
      if (k > 0 && distance(checked, trail_[k]) < 0.5) continue;
      checked = trail_[k];
      for (std::size_t j = 0; j < w.size(); ++j) {
        const double d = distance(trail_[k], w[j].position);
        if (d > 6.0 || back + d + rest[j] >= tbest) continue;
        if (d < 1e-6 || segment_known_free(trail_[k], w[j].position)) {
          tbest = back + d + rest[j];
          tk = k;
          tj = j;
        }
      }
    }
    if (tj < w.size()) {
      for (std::size_t k = trail_.size(); k-- > tk;)
        prefix.push_back(trail_[k]);
      prefix.push_back(w[tj].position);
      join = tj;
    }
  }
  if (join == w.size()) {
    for (std::size_t j = 0; j < w.size(); ++j) {
      const double c = distance(s.pos, w[j].position) + rest[j];
      if (c < best) {
        best = c;
        join = j;
      }
    }
    if (plan_walk(w[join].position)) {
      prefix = s.waypoints;
    } else {
      // No way on its map: go back along its own (known free) trail to where it sent the
      // Search, then drive the whole route.
      prefix.assign(trail_.rbegin(), trail_.rend());
      join = 0;
      prefix.push_back(w[0].position);
    }
  } else if (prefix.empty()) {
    prefix = {w[join].position};
  }
  NS_DEBUG(
      "t=%.1f source at (%.1f,%.1f) joins route point %zu of %zu at (%.1f,%.1f), prefix %zu, route "
      "from (%.1f,%.1f)\n",
      now_, s.pos.x, s.pos.y, join, w.size(), w[join].position.x, w[join].position.y, prefix.size(),
      w[0].position.x, w[0].position.y);
  route_.assign(1, VoronoiPoint{s.pos, 1.0f, 0.0f});
  route_.insert(route_.end(), w.begin() + static_cast<std::ptrdiff_t>(join), w.end());
  route_owners_.assign(1, s.id);
  route_owners_.insert(route_owners_.end(), owners.begin() + static_cast<std::ptrdiff_t>(join),
                       owners.end());
  s.waypoints = prefix;
  for (std::size_t i = 2; i < route_.size(); ++i)
    s.waypoints.push_back(route_[i].position);
  s.wp = 0;
  route_base_ = 1;
  back_steps_ = prefix.size() - 1;
  if (first) {
    report_.route_time_s = now_;
    report_.route_length_m = path_len(s.pos, s.waypoints);
    std::set<std::uint32_t> robots;
    bool others = false;
    for (std::size_t i = 1; i < route_owners_.size(); ++i) {
      if (route_owners_[i] == kBroadcast) continue;
      robots.insert(route_owners_[i].value);
      others |= route_owners_[i] != s.id;
    }
    report_.route_robots = static_cast<int>(robots.size());
    report_.found_by = others && !sees_way ? RouteFoundBy::kRelays : RouteFoundBy::kSourceAlone;
  }
}

/// route_ index of the source's next waypoint (waypoints may start with a way to the route).
std::size_t RobotAgent::next_route_index() const {
  const std::size_t wp = r_.wp;
  return route_base_ + (wp >= back_steps_ ? wp - back_steps_ : 0);
}

void RobotAgent::set_source_waypoints(std::size_t from) {
  back_steps_ = 0;
  auto& s = r_;
  s.waypoints.clear();
  for (std::size_t i = from; i < route_.size(); ++i)
    s.waypoints.push_back(route_[i].position);
  s.wp = 0;
  route_base_ = from;
}

/// Source: whether an obstacle change inside [lo, hi] touches the route ahead of it (issue #13:
/// the change runs must really test the repair of a route in use).
void RobotAgent::count_change_on_route(Vec2 lo, Vec2 hi) {
  auto& s = r_;
  if (!is_source() || report_.route_time_s < 0.0 || report_.arrived) return;
  if (s.wp >= s.waypoints.size()) return;
  const double m = opt().robot_radius_m + scen().world.resolution();
  auto inside = [&](Vec2 q) {
    return q.x >= lo.x - m && q.x <= hi.x + m && q.y >= lo.y - m && q.y <= hi.y + m;
  };
  Vec2 a = s.pos;
  for (std::size_t i = s.wp; i < s.waypoints.size(); ++i) {
    const Vec2 b = s.waypoints[i];
    const double len = distance(a, b);
    const int n = std::max(1, static_cast<int>(std::ceil(len / 0.05)));
    for (int k = 0; k <= n; ++k)
      if (inside(a + (b - a) * (static_cast<double>(k) / n))) {
        ++report_.changes_on_route;
        return;
      }
    a = b;
  }
}

}  // namespace voronav::sim
