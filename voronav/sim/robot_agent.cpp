#include "voronav/sim/robot_agent.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/sim/agent_internal.hpp"

namespace voronav::sim {

using namespace network;
using namespace agent_detail;

std::string_view to_string(RouteFoundBy b) {
  switch (b) {
    case RouteFoundBy::kRelays:
      return "relays";
    case RouteFoundBy::kSourceAlone:
      return "source_alone";
    case RouteFoundBy::kNone:
      break;
  }
  return "none";
}

RouteFoundBy parse_route_found_by(std::string_view s) {
  if (s == "relays") return RouteFoundBy::kRelays;
  if (s == "source_alone") return RouteFoundBy::kSourceAlone;
  if (s == "none") return RouteFoundBy::kNone;
  throw Error("route_found_by", 0,
              "expected 'relays', 'source_alone' or 'none', got '" + std::string(s) + "'");
}

NetSimMetrics aggregate_metrics(const std::vector<AgentReport>& robots, std::size_t source,
                                Method method) {
  NetSimMetrics M;
  std::array<TrafficCounter, kMessageTypeCount> by_type{};
  for (const auto& a : robots) {
    const auto& rm = a.metrics;
    M.travel_m += rm.travel_m;
    M.computation += rm.work;
    M.max_robot_computation = std::max(M.max_robot_computation, rm.work);
    M.cpu_s += rm.cpu_s;
    M.max_robot_cpu_s = std::max(M.max_robot_cpu_s, rm.cpu_s);
    M.traffic_bytes += rm.sent_bytes;
    M.messages += rm.sent_messages;
    M.search_attempts += a.search_attempts;
    M.repairs += a.repairs;
    M.replans += a.replans;
    M.corrupt_packets += a.corrupt_packets;
    M.paths_lost += a.paths_lost;
    M.paths_unacknowledged += a.paths_unacknowledged;
    M.paths_late += a.paths_late;
    M.repairs_executed += a.repairs_executed;
    M.repair_requests += a.repair_requests;
    M.repair_answers += a.repair_answers;
    M.point_searches += static_cast<std::uint64_t>(a.point_searches);
    M.search_copies_ignored += static_cast<std::uint64_t>(a.search_copies_ignored);
    M.sensing_walks += a.sensing_walks;
    M.sensing_walk_m += a.sensing_walk_m;
    M.route_used_sensing = M.route_used_sensing || a.route_used_sensing;
    M.repair_sense_walks += a.repair_sense_walks;
    M.repair_sense_walk_m += a.repair_sense_walk_m;
    M.repair_sense_answers += a.repair_sense_answers;
    for (std::size_t t = 0; t < by_type.size(); ++t) {
      by_type[t].messages += rm.sent_by_type[t].messages;
      by_type[t].bytes += rm.sent_by_type[t].bytes;
    }
    M.robots.push_back(rm);
  }
  for (int t = 1; t < kMessageTypeCount; ++t)
    if (by_type[static_cast<std::size_t>(t)].messages > 0)
      M.by_type[std::string(to_string(static_cast<MessageType>(t)))] =
          by_type[static_cast<std::size_t>(t)];
  auto mean = [&](MessageType t) {
    const auto& c = by_type[static_cast<std::size_t>(t)];
    return c.messages ? static_cast<double>(c.bytes) / static_cast<double>(c.messages) : 0.0;
  };
  if (method == Method::kCentralized) {
    M.alpha_bytes = mean(MessageType::kRequest);
    M.beta_bytes = mean(MessageType::kAck);
  } else {
    M.alpha_bytes = mean(MessageType::kSearch);
    M.gamma_bytes = mean(MessageType::kPath);
  }
  if (source < robots.size()) {
    const auto& s = robots[source];
    M.success = s.arrived;
    M.route_time_s = s.route_time_s;
    M.arrival_time_s = s.arrival_time_s;
    M.route_length_m = s.route_length_m;
    M.source_travel_m = s.metrics.travel_m;
    M.relay_travel_m = M.travel_m - s.metrics.travel_m;
    M.route_found_by = s.found_by;
    M.route_robots = s.route_robots;
    M.changes_on_route = s.changes_on_route;
    M.source_repair_requests = s.repair_requests;
    static_cast<SourceRepairTrace&>(M) = s;
  }
  return M;
}

RobotAgent::RobotAgent(const AgentContext& context, RobotId id, Vec2 position, Transport& transport)
    : ctx_(context), transport_(transport) {
  if (!ctx_.scenario || !ctx_.options || !ctx_.truth)
    throw Error("RobotAgent", 0, "scenario, options and truth are required");
  r_.id = id;
  r_.pos = position;
  const auto& g = scen().world.geometry();
  sweep_ = DiscSweep(opt().robot_radius_m / g.resolution - 0.01);
  r_.map = LocalMap(g);
  if (opt().method == Method::kCentralized && is_source())
    r_.map.ensure(Cell{0, 0}, Cell{g.width - 1, g.height - 1});
}

bool RobotAgent::is_source() const {
  return r_.id.value == scen().source;
}
RobotId RobotAgent::source_id() const {
  return RobotId{static_cast<std::uint32_t>(scen().source)};
}

AgentReport RobotAgent::report() const {
  return report_;
}

std::vector<VoronoiPoint> RobotAgent::open_points() const {
  // An observer's look (recordings): computed aside when stale, so it neither adds to the robot's
  // work (eq. 8-9) nor changes when the robot itself recomputes; a recorded run then counts the
  // same work as an unrecorded one and as the same run over DDS.
  if (r_.points_dirty) return make_voronoi_points(r_.map.grid(), points_opts()).open;
  return r_.pts.open;
}

std::vector<Vec2> RobotAgent::route() const {
  if (opt().method == Method::kCentralized) return r_.waypoints;
  std::vector<Vec2> out;
  for (const auto& p : route_)
    out.push_back(p.position);
  return out;
}

// ---- step phases ------------------------------------------------------------------------------
void RobotAgent::begin() {
  transport_.update_position(r_.id, r_.pos);
  do_sense();
}

void RobotAgent::start() {
  if (!is_source()) return;
  if (opt().method == Method::kDecentralized) {
    start_search();
  } else {
    start_request();
  }
}

void RobotAgent::flush() {
  transport_.update_position(r_.id, r_.pos);  // every step: a robot process publishes its pose
  auto held = std::move(held_);
  held_.clear();
  for (auto& h : held)
    transmit(h.to, std::move(h.bytes));
}

void RobotAgent::communicate(double now_s) {
  now_ = now_s;
  for (auto& p : transport_.receive(r_.id))
    handle_packet(p);
  timers();
}

void RobotAgent::world_changed(double now_s, Vec2 lo, Vec2 hi) {
  now_ = now_s;
  count_change_on_route(lo, hi);
  // A robot whose sensing disc touches the change sees it now.
  const Vec2 q{std::clamp(r_.pos.x, lo.x, hi.x), std::clamp(r_.pos.y, lo.y, hi.y)};
  if (distance(q, r_.pos) > opt().sensing_range_m + 0.5) return;
  do_sense();
  if (last_sense_changed_) on_map_changed();
}

void RobotAgent::do_sense() {
  const auto s = sense(*ctx_.truth, r_.pos, opt().sensing_range_m, r_.map);
  report_.metrics.work += s.cells;
  if (s.changed) r_.points_dirty = true;
  last_sense_changed_ = s.changed;
}

const VoronoiPoints& RobotAgent::points() {
  if (r_.points_dirty) {
    r_.pts = timed([&] { return make_voronoi_points(r_.map.grid(), points_opts()); });
    report_.metrics.work += r_.pts.cells_processed;
    r_.points_dirty = false;
  }
  return r_.pts;
}

VoronoiPointsOptions RobotAgent::points_opts() const {
  VoronoiPointsOptions p = opt().points;
  p.robot_radius_m = opt().robot_radius_m;
  return p;
}

// ---- messaging --------------------------------------------------------------------------------
void RobotAgent::log_repair(bool executed, std::string what) {
  if (ctx_.repair_log) ctx_.repair_log->push_back({now_, r_.id.value, executed, std::move(what)});
}

void RobotAgent::transmit(RobotId to, std::vector<std::uint8_t> bytes) {
  if (holding_) {
    held_.push_back({to, std::move(bytes)});
    return;
  }
  const std::uint8_t type = peek_type(bytes);
  report_.metrics.sent_bytes += bytes.size();
  report_.metrics.sent_messages += 1;
  if (type < kMessageTypeCount) {
    report_.metrics.sent_by_type[type].messages += 1;
    report_.metrics.sent_by_type[type].bytes += bytes.size();
  }
  if (ctx_.message_log)
    ctx_.message_log->push_back(
        {now_, r_.id.value, to.value, static_cast<MessageType>(type), bytes.size()});
  if (to == kBroadcast) {
    transport_.broadcast(r_.id, bytes);
    return;
  }
  // A Path sent while its addressee is a radio neighbour reaches it (the radio's range rule, at
  // send time): remembered, so an unacknowledged Path is not counted lost (timers()).
  if (type == static_cast<std::uint8_t>(MessageType::kPath) && neighbour_position(to))
    for (auto& g : outbox_)
      if (g.to == to && !g.reached && g.bytes == bytes) g.reached = true;
  transport_.send(r_.id, to, bytes);
}

void RobotAgent::broadcast(Payload p, std::uint8_t hops) {
  Envelope e{Header{r_.id, kBroadcast, r_.id, r_.next_msg++, hops}, std::move(p)};
  r_.seen.insert(key_of(r_.id, e.header.msg_id));
  transmit(kBroadcast, encode(e));
}

void RobotAgent::send_reliable(RobotId to, Payload p) {
  Envelope e{Header{r_.id, to, r_.id, r_.next_msg++, 0}, std::move(p)};
  auto b = encode(e);
  outbox_.push_back({to, b, key_of(r_.id, e.header.msg_id), 1, now_ + opt().link_timeout_s});
  transmit(to, std::move(b));
}

void RobotAgent::link_ack(const Header& h) {
  Envelope e{Header{r_.id, h.sender, r_.id, r_.next_msg++, 0}, LinkAckMessage{h.origin, h.msg_id}};
  transmit(h.sender, encode(e));
}

void RobotAgent::handle_packet(const Packet& p) {
  Envelope e;
  try {
    e = decode(p.bytes);
  } catch (const Error&) {
    ++report_.corrupt_packets;
    return;
  }
  if (e.type() == MessageType::kLinkAck) {
    const auto& a = std::get<LinkAckMessage>(e.payload);
    const auto k = key_of(a.acked_origin, a.acked_id);
    std::erase_if(outbox_, [&](const Outgoing& g) { return g.key == k; });
    return;
  }
  if (e.header.receiver != kBroadcast) link_ack(e.header);
  if (!r_.seen.insert(key_of(e.header.origin, e.header.msg_id)).second) return;  // duplicate
  std::visit([&](const auto& m) { on(e.header, m); }, e.payload);
}

void RobotAgent::timers() {
  for (std::size_t i = 0; i < outbox_.size();) {
    auto& g = outbox_[i];
    if (now_ + 1e-9 >= g.next_at) {
      if (g.tries > opt().link_retries) {
        // A Path whose next hop never acknowledged it goes to the multi-hop fallback of Table 3
        // (path_fallback_after_retries); when that cannot take it, it is lost: counted.
        Outgoing failed = std::move(g);
        outbox_.erase(outbox_.begin() + static_cast<std::ptrdiff_t>(i));
        if (peek_type(failed.bytes) == static_cast<std::uint8_t>(MessageType::kPath)) {
          ++report_.paths_unacknowledged;
          // Sent while the addressee was in range of a lossless radio: it was received, only
          // its LinkAck failed (s2r3, s2r7: 25.0-25.5 m apart one step later). Nothing to carry.
          const bool received = failed.reached && opt().radio.loss <= 0.0;
          NS_DEBUG("t=%.1f robot %u: path to %u unacknowledged (in range when sent %d)\n", now_,
                   r_.id.value, failed.to.value, failed.reached ? 1 : 0);
          if (!received && !path_after_retries(failed.bytes)) ++report_.paths_lost;
        }
        continue;
      }
      ++g.tries;
      g.next_at = now_ + opt().link_timeout_s;
      transmit(g.to, g.bytes);
    }
    ++i;
  }
  if (opt().method == Method::kDecentralized) {
    if (r_.path_deadline >= 0.0 && now_ + 1e-9 >= r_.path_deadline) select_path();
    if (r_.bridge_at >= 0.0 && now_ + 1e-9 >= r_.bridge_at) start_bridge();
    pending_step();
    if (repair_walk_ && (r_.walk != Walk::kRepair || now_ + 1e-9 >= repair_walk_until_))
      end_repair_walk();  // taken over by a new Search, or the source no longer waits
    if (!is_source()) return;
    if (!route_.empty()) boxed_in_ = false;
    if (route_.empty() && boxed_in_ && r_.walk == Walk::kIdle && now_ + 1e-9 >= search_deadline_) {
      // Boxed in, and the Search sent at the gap got no answer: sense the next gap.
      if (!start_sensing_walk()) boxed_in_ = false;
    }
    if (route_.empty() && now_ + 1e-9 >= search_deadline_ &&
        report_.search_attempts < opt().max_search_attempts)
      retry_search();
    repair_timers();
    // repair_sense_walk: a relay said it walks to sense the break; wait for it.
    const bool sensing = sense_wait_until_ >= 0.0 && now_ + 1e-9 < sense_wait_until_;
    if (!route_.empty() && blocked_since_ >= 0.0 && !sensing &&
        now_ - blocked_since_ >= opt().repair_timeout_s && !expand_repair_ring()) {
      repair_done();
      // No Repair answer: the source plans a way on its own map to the first route point past
      // the break (counted in replans); only when there is none it starts a new Search.
      const bool rp = replan_to_route();
      NS_DEBUG("t=%.1f source repair timeout at (%.1f,%.1f): replan %d\n", now_, r_.pos.x, r_.pos.y,
               rp ? 1 : 0);
      if (!rp) {
        route_.clear();
        r_.waypoints.clear();
        // Boxed in (the Search sent after the last block got it nowhere): sense the gap first
        // (figure 18), then search from there.
        const bool boxed = searched_after_block_ &&
                           distance(*searched_after_block_, r_.pos) <= opt().sensing_range_m;
        searched_after_block_ = r_.pos;
        if (!boxed || !start_sensing_walk()) start_search();
      }
    }
  } else if (is_source() && collecting_ && now_ - last_ack_ >= opt().collect_s) {
    collecting_ = false;
    plan_central();
  }
}

void RobotAgent::on_map_changed() {
  if (opt().method == Method::kCentralized) {
    if (is_source()) {
      check_central_path();
    } else if (r_.parent != kBroadcast) {
      send_reliable(r_.parent, NotifyMessage{source_id(), r_.id, r_.pos});
    }
    return;
  }
  if (is_source()) {
    check_source_route();
  } else if (r_.saved) {
    check_relay_route();
  }
}

// ---- motion -----------------------------------------------------------------------------------
void RobotAgent::move(double now_s) {
  now_ = now_s;
  auto& r = r_;
  if (r.wp >= r.waypoints.size()) return;
  if (is_source() && blocked_since_ >= 0.0) return;  // waiting for a repair
  holding_ = true;
  walk_prev = r.pos;
  double budget = opt().speed_mps * opt().dt_s;
  double moved = 0.0;
  while (budget > 1e-12 && r.wp < r.waypoints.size()) {
    const Vec2 t = r.waypoints[r.wp];
    const double d = distance(r.pos, t);
    if (d <= budget) {
      r.pos = t;
      budget -= d;
      moved += d;
      ++r.wp;
    } else {
      r.pos = r.pos + (t - r.pos) * (budget / d);
      moved += budget;
      budget = 0.0;
    }
  }
  report_.metrics.travel_m += moved;
  if (is_source() && moved > 0.0) trail_.push_back(r.pos);
  if (is_source() && r.walk == Walk::kSense) report_.sensing_walk_m += moved;
  if (r.walk == Walk::kRepair) report_.repair_sense_walk_m += moved;
  if (!is_source() && (r.walk == Walk::kBridge || r.walk == Walk::kDestination ||
                       (r.walk == Walk::kRepair && repair_walk_phase_ == 1))) {
    // Trail points every 2 m, and before any corner: each straight step between two of them is
    // known free (the robot drove it and sensed around it).
    if (r.walk_trail.empty()) {
      r.walk_trail.push_back(r.pos);
    } else if (distance(r.walk_trail.back(), r.pos) >= 2.0 ||
               !segment_known_free(r.walk_trail.back(), r.pos)) {
      if (distance(r.walk_trail.back(), walk_prev) > 1e-6) r.walk_trail.push_back(walk_prev);
      if (!segment_known_free(r.walk_trail.back(), r.pos)) r.walk_trail.clear();
      r.walk_trail.push_back(r.pos);
    }
  }
  do_sense();
  const bool changed = last_sense_changed_;
  if (is_source() && r.wp >= r.waypoints.size() && distance(r.pos, scen().destination) < 0.35) {
    report_.arrived = true;
    report_.arrival_time_s = now_;
    note_route_used_sensing();
    // It walked there by itself without ever getting a route.
    if (report_.found_by == RouteFoundBy::kNone) report_.found_by = RouteFoundBy::kSourceAlone;
    holding_ = false;
    return;
  }
  if (opt().method == Method::kCentralized) {
    if (is_source() && changed) check_central_path();
  } else if (is_source() && r.walk == Walk::kIdle) {
    if (changed) check_source_route();
  } else if (r.walk != Walk::kIdle) {
    if (is_source() && r.walk == Walk::kDestination && route_.empty()) {
      source_walk_since_ += moved;
      if (source_walk_since_ >= 1.0) {
        source_walk_since_ = 0.0;
        if (source_walk_check()) {
          holding_ = false;
          return;
        }
      }
    }
    r.walk_since_check += moved;
    r.walk_map_changed |= changed;
    bool done = r.wp >= r.waypoints.size();
    if (changed && !done && walk_blocked() && !plan_walk(r.waypoints.back()) &&
        !source_walk_on_whole_map()) {
      r.waypoints.clear();  // no way on: stop here
      done = true;
    }
    // The points are recomputed (walk_progress) only when the map changed, at most once a metre.
    if ((r.walk_since_check >= 1.0 && r.walk_map_changed) || done) {
      r.walk_since_check = 0.0;
      r.walk_map_changed = false;
      walk_progress(done);
    }
  }
  holding_ = false;
}

/// Whether a straight robot move a->b crosses an occupied cell of the map (inflated by r).
bool RobotAgent::segment_blocked(Vec2 a, Vec2 b) const {
  const auto& map = r_.map;
  const auto& g = map.world();
  const auto ca = g.world_to_cell(a), cb = g.world_to_cell(b);
  if (!ca || !cb) return true;
  // Strictly closer than r, as field::inflate (so planned paths are not flagged as blocked).
  const double rad = opt().robot_radius_m / g.resolution - 0.01;
  bool blocked = false;
  for_each_line_cell(*ca, *cb, [&](Cell c) {
    for_each_disc_cell(c, rad, [&](Cell d) {
      if (map.at(d) == kOccupied) blocked = true;
      return !blocked;
    });
    return !blocked;
  });
  return blocked;
}

/// Whether every cell within r of the straight move a->b is known free in the map.
bool RobotAgent::segment_known_free(Vec2 a, Vec2 b) const {
  const auto& map = r_.map;
  const auto& g = map.world();
  const auto ca = g.world_to_cell(a), cb = g.world_to_cell(b);
  if (!ca || !cb) return false;
  // The union of the robot's discs (radius r / resolution - 0.01 cells, sweep_) along the line.
  // A disc cell outside the map's window is unknown, so the move is then not known free; the
  // union reaches exactly sweep_.reach() cells beyond the line's bounding box (in x and in y).
  if (sweep_.disc().empty()) return true;
  const auto& grid = map.grid();
  const Cell off = map.offset();
  const Cell k = sweep_.reach();
  if (std::min(ca->x, cb->x) - k.x < off.x || std::min(ca->y, cb->y) - k.y < off.y ||
      std::max(ca->x, cb->x) + k.x >= off.x + grid.width() ||
      std::max(ca->y, cb->y) + k.y >= off.y + grid.height())
    return false;
  return sweep_.visit(*ca - off, *cb - off, [&](Cell d) { return grid[d] == kFree; });
}

// ---- walking on the robot's own (optimistic) map ----------------------------------------------
/// The source's own walk to the destination is blocked and cannot be planned again in the window
/// around its two ends: before it stops, it plans once more on a window holding its whole local
/// map (as walk_replan_whole_map does for every walk). Without this the window can cut off the
/// only way its map holds, and a source that has spent its last Search stands still to the time
/// limit (scenario 4, run 15: stopped at 484 s, 0.4 m short of the way; issue #13, stop 26 in
/// docs/reproductions/networked.md). Only that walk: relays' walks keep the option's setting.
bool RobotAgent::source_walk_on_whole_map() {
  if (!is_source() || r_.walk != Walk::kDestination || opt().walk_replan_whole_map) return false;
  return plan_walk(r_.waypoints.back(), nullptr, true);
}

/// A* on the robot's own map from its position to `target`; unknown cells count as free
/// (optimistic). With `whole_map` (or walk_replan_whole_map), a failed plan is tried again on a
/// window holding the whole local map. With `seen`, only cells it knows free or that lie inside the
/// free disc of a point of `seen` (space that point's maker sensed free) may be used
/// (repair_fix_seen_only).
bool RobotAgent::plan_walk(Vec2 target, const std::vector<VoronoiPoint>* seen, bool whole_map) {
  auto& r = r_;
  const auto& wg = scen().world.geometry();
  const auto a = wg.world_to_cell(r.pos), b = wg.world_to_cell(target);
  if (!a || !b) return false;
  // Plan on a window of the world around both ends; unknown = free (optimistic). When that
  // fails (known walls close the window), plan once more on a window that also holds the whole
  // local map (outside it everything is unknown, so that window is as good as the world).
  const int margin = static_cast<int>(std::ceil(10.0 / wg.resolution));
  Cell lo{std::max(0, std::min(a->x, b->x) - margin), std::max(0, std::min(a->y, b->y) - margin)};
  Cell hi{std::min(wg.width - 1, std::max(a->x, b->x) + margin),
          std::min(wg.height - 1, std::max(a->y, b->y) + margin)};
  planning::PlanResult result;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      if (!opt().walk_replan_whole_map && !whole_map) break;
      const Cell mlo = r.map.offset();
      const Cell mhi{mlo.x + r.map.grid().width() - 1, mlo.y + r.map.grid().height() - 1};
      const Cell lo2{std::max(0, std::min(lo.x, mlo.x - 2)),
                     std::max(0, std::min(lo.y, mlo.y - 2))};
      const Cell hi2{std::min(wg.width - 1, std::max(hi.x, mhi.x + 2)),
                     std::min(wg.height - 1, std::max(hi.y, mhi.y + 2))};
      if (lo2 == lo && hi2 == hi) break;  // the first window was already that large
      lo = lo2;
      hi = hi2;
    }
    BinaryGrid win(GridGeometry{hi.x - lo.x + 1, hi.y - lo.y + 1, wg.resolution, {}}, 0);
    for (int y = 0; y < win.height(); ++y)
      for (int x = 0; x < win.width(); ++x) {
        const auto v = r.map.at(Cell{x, y} + lo);
        win[Cell{x, y}] = v == kOccupied || (seen && v != kFree) ? 1 : 0;
      }
    if (seen) {
      for (const auto& p : *seen) {
        const auto c = wg.world_to_cell(p.position);
        if (!c || !(p.clearance > 0.0f)) continue;
        for_each_disc_cell(*c, p.clearance / wg.resolution, [&](Cell d) {
          const Cell w = d - lo;
          if (win.contains(w) && r.map.at(d) != kOccupied) win[w] = 0;
          return true;
        });
      }
      report_.metrics.work += seen->size();
    }
    result = timed([&] {
      BinaryGrid pg = planning::make_planning_grid(win, opt().robot_radius_m);
      pg[*a - lo] = 0;
      pg[*b - lo] = 0;
      planning::AStarPlanner planner;
      return planner.plan(pg, *a - lo, *b - lo);
    });
    report_.metrics.work += win.size() * 2 + result.expanded;
    if (result.ok()) break;
  }
  if (!result.ok()) return false;
  r.waypoints.clear();
  for (std::size_t i = 1; i < result.path.size(); ++i)
    r.waypoints.push_back(wg.cell_center(result.path[i] + lo));
  r.waypoints.push_back(target);
  r.wp = 0;
  return true;
}

bool RobotAgent::walk_blocked() const {
  const auto& r = r_;
  for (std::size_t i = r.wp; i < r.waypoints.size(); ++i) {
    if (distance(r.waypoints[i], r.pos) > opt().sensing_range_m + 0.5) break;
    const Vec2 from = i == r.wp ? r.pos : r.waypoints[i - 1];
    if (segment_blocked(from, r.waypoints[i])) return true;
  }
  return false;
}

}  // namespace voronav::sim
