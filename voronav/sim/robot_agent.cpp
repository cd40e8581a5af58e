#include "voronav/sim/robot_agent.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/planning/astar.hpp"

// Trace points of the protocol (compiled out; the library does no I/O).
#define NS_DEBUG(...) ((void)0)

namespace voronav::sim {

using namespace network;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kRepairFlag = 0x80000000u;
constexpr double kUnreached = 1e8;  // cost sent for an open point the Search has not reached

std::uint64_t key_of(RobotId origin, std::uint32_t id) {
  return (static_cast<std::uint64_t>(origin.value) << 32) | id;
}

double path_len(Vec2 from, const std::vector<Vec2>& w) {
  double l = 0.0;
  for (Vec2 p : w) {
    l += distance(from, p);
    from = p;
  }
  return l;
}

}  // namespace

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

std::vector<VoronoiPoint> RobotAgent::open_points() {
  return points().open;
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
  // A robot whose sensing disc touches the change sees it now.
  const Vec2 q{std::clamp(r_.pos.x, lo.x, hi.x), std::clamp(r_.pos.y, lo.y, hi.y)};
  if (distance(q, r_.pos) > opt().sensing_range_m + 0.5) return;
  do_sense();
  if (last_sense_changed_) on_map_changed();
}

// ---- timing of computation --------------------------------------------------------------------
template <typename F>
auto RobotAgent::timed(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  auto out = f();
  report_.metrics.cpu_s +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
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
  } else {
    transport_.send(r_.id, to, bytes);
  }
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
        outbox_.erase(outbox_.begin() + static_cast<std::ptrdiff_t>(i));
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
    if (!is_source()) return;
    if (route_.empty() && now_ + 1e-9 >= search_deadline_ &&
        report_.search_attempts < opt().max_search_attempts)
      start_search();
    if (!route_.empty() && blocked_since_ >= 0.0 &&
        now_ - blocked_since_ >= opt().repair_timeout_s) {
      route_.clear();
      r_.waypoints.clear();
      blocked_since_ = -1.0;
      start_search();
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
  do_sense();
  const bool changed = last_sense_changed_;
  if (is_source() && r.wp >= r.waypoints.size() && distance(r.pos, scen().destination) < 0.35) {
    report_.arrived = true;
    report_.arrival_time_s = now_;
    holding_ = false;
    return;
  }
  if (opt().method == Method::kCentralized) {
    if (is_source() && changed) check_central_path();
  } else if (is_source() && r.walk == Walk::kIdle) {
    if (changed) check_source_route();
  } else if (r.walk != Walk::kIdle) {
    r.walk_since_check += moved;
    bool done = r.wp >= r.waypoints.size();
    if (changed && !done && walk_blocked() && !plan_walk(r.waypoints.back())) {
      r.waypoints.clear();  // no way on: stop here
      done = true;
    }
    if (r.walk_since_check >= 1.0 || done) {
      r.walk_since_check = 0.0;
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
  const double rad = opt().robot_radius_m / g.resolution - 0.01;
  bool ok = true;
  for_each_line_cell(*ca, *cb, [&](Cell c) {
    for_each_disc_cell(c, rad, [&](Cell d) {
      if (map.at(d) != kFree) ok = false;
      return ok;
    });
    return ok;
  });
  return ok;
}

// ---- walking on the robot's own (optimistic) map ----------------------------------------------
bool RobotAgent::plan_walk(Vec2 target) {
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
      if (!opt().walk_replan_whole_map) break;
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
      for (int x = 0; x < win.width(); ++x)
        win[Cell{x, y}] = r.map.at(Cell{x, y} + lo) == kOccupied ? 1 : 0;
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

// ---- decentralized: Search (Tables 1–2) -------------------------------------------------------
void RobotAgent::start_search() {
  auto& s = r_;
  ++report_.search_attempts;
  // Retry timeout: fixed, or longer the farther the destination (every hop that must bridge a
  // gap costs bridge_wait_s plus a walk; see NetSimOptions::search_timeout_per_m).
  search_deadline_ =
      now_ + std::max(opt().search_timeout_s,
                      opt().search_timeout_per_m * distance(s.pos, scen().destination));
  trail_ = {s.pos};
  const std::uint32_t num = ++search_num_;
  SearchMessage pseudo;
  pseudo.source = s.id;
  pseudo.num = num;
  pseudo.destination = scen().destination;
  const double cl = clearance_at(s.map.grid(), s.pos);
  pseudo.open_points = {
      VoronoiPoint{s.pos, static_cast<float>(std::max(cl, opt().robot_radius_m + 0.05)), 0.0f}};
  s.got_paths.clear();
  s.path_deadline = -1.0;
  s.path_forwarded = false;
  process_search(s.id, pseudo, 0);
}

/// Runs the point search from the sender's open points through the robot's open points (and the
/// destination when it is in the robot's area). Returns true when the robot continues the sender.
bool RobotAgent::try_continue() {
  auto& r = r_;
  const Vec2 dest = scen().destination;
  const auto& own = points().open;
  r.s_comb = r.s_in.open_points;
  r.s_na = r.s_comb.size();
  r.s_comb.insert(r.s_comb.end(), own.begin(), own.end());
  const double dcl = clearance_at(r.map.grid(), dest);
  const bool has_dest = dcl > opt().robot_radius_m;
  if (has_dest) r.s_comb.push_back(VoronoiPoint{dest, static_cast<float>(dcl), 0.0f});
  std::vector<double> start(r.s_comb.size(), kInf);
  for (std::size_t i = 0; i < r.s_na; ++i)
    start[i] = r.s_comb[i].cost < kUnreached ? r.s_comb[i].cost : kInf;
  // Within its own map a robot may also move straight between its own points when the move is
  // known free (it checks the cells itself; at most 6 m apart to bound the work).
  // The source's start point (its position) is in its own map too (source_straight_start).
  const std::size_t own_end = r.s_na + own.size();
  const std::size_t own_begin = is_source() && opt().source_straight_start ? 0 : r.s_na;
  std::size_t los_cells = 0;
  auto own_edge = [&](std::size_t i, std::size_t j) {
    if (i < own_begin || j < own_begin || i >= own_end || j >= own_end) return false;
    if (i < r.s_na && j < r.s_na) return false;
    const Vec2 a = r.s_comb[i].position, b = r.s_comb[j].position;
    if (distance(a, b) > 6.0) return false;
    los_cells += static_cast<std::size_t>(distance(a, b) / scen().world.resolution()) + 1;
    return segment_known_free(a, b);
  };
  r.s_search =
      timed([&] { return search_points(r.s_comb, start, opt().robot_radius_m, own_edge); });
  report_.metrics.work += los_cells;
  report_.metrics.work += r.s_search.work;
  if (has_dest && !std::isfinite(r.s_search.cost.back())) {
    // The destination is not an open point: join it to the best reached own point it can be
    // driven to in a straight line through known free space.
    const std::size_t d = r.s_comb.size() - 1;
    for (std::size_t i = own_begin; i < d; ++i) {
      if (!std::isfinite(r.s_search.cost[i])) continue;
      const double c = r.s_search.cost[i] + distance(r.s_comb[i].position, dest);
      if (c < r.s_search.cost[d] && segment_known_free(r.s_comb[i].position, dest)) {
        r.s_search.cost[d] = c;
        r.s_search.parent[d] = static_cast<std::int32_t>(i);
      }
    }
  }
  // Every own point is sent, in a fixed order (so Path answers can name it by index); the
  // unreached ones with cost kUnreached.
  r.s_sent.clear();
  bool reached = false;
  for (std::size_t i = r.s_na; i < r.s_na + own.size(); ++i) {
    r.s_sent.push_back(i);
    reached |= std::isfinite(r.s_search.cost[i]);
  }
  return reached || (has_dest && std::isfinite(r.s_search.cost.back()));
}

bool RobotAgent::dest_reached() const {
  const auto& r = r_;
  const Vec2 dest = scen().destination;
  const double dcl = clearance_at(r.map.grid(), dest);
  return dcl > opt().robot_radius_m && r.s_comb.size() > r.s_na &&
         std::isfinite(r.s_search.cost.back()) && r.s_comb.back().position == dest;
}

void RobotAgent::on(const Header& h, const SearchMessage& m) {
  auto& r = r_;
  if (is_source() && m.source == r.id && m.num == search_num_ && opt().search_activity_s > 0.0)
    // A neighbour (re-)forwards the current Search: it is still spreading, wait for it.
    search_deadline_ = std::max(search_deadline_, now_ + opt().search_activity_s);
  if (is_source() || m.source != source_id()) return;
  if (r.s_num != kNone && m.num < r.s_num) return;  // stale search
  if (r.s_num == m.num) {
    // Same search from another robot: only useful while this robot has not continued yet.
    if (r.walk == Walk::kDestination || r.path_forwarded) return;
    // Merge the new sender's points with those already received (distributed shortest path:
    // a robot that already forwarded re-forwards when its costs improve, at most 3 times).
    r.s_senders.push_back({h.sender, m.relays, r.s_in.open_points.size(), m.open_points.size()});
    r.s_in.open_points.insert(r.s_in.open_points.end(), m.open_points.begin(), m.open_points.end());
    if (r.s_done) {
      std::vector<double> before;
      for (std::size_t i : r.s_sent)
        before.push_back(r.s_search.cost[i]);
      if (!try_continue() || r.reforwards >= 3) return;
      bool better = before.size() != r.s_sent.size();
      for (std::size_t k = 0; k < before.size() && !better; ++k)
        better = r.s_search.cost[r.s_sent[k]] < before[k] - 1e-6;
      if (better) {
        ++r.reforwards;
        forward_search(h.hops);
      }
      return;
    }
    if (try_continue()) {
      NS_DEBUG("t=%.1f robot %u continues search %u from %u\n", now_, r.id.value, m.num,
               h.sender.value);
      r.walk = Walk::kIdle;
      r.waypoints.clear();
      r.bridge_at = -1.0;
      after_continue(h.hops);
    }
    return;
  }
  process_search(h.sender, m, h.hops);
}

void RobotAgent::process_search(RobotId sender, const SearchMessage& m, std::uint8_t hops) {
  auto& r = r_;
  r.s_num = m.num;
  r.s_done = false;
  r.s_in = m;
  r.s_senders = {{sender, m.relays, 0, m.open_points.size()}};
  r.reforwards = 0;
  // A robot walking to the destination stays committed; one bridging a gap may keep walking
  // (the new Search's points are tried as it senses, walk_progress).
  const bool bridging = r.walk == Walk::kBridge && opt().keep_bridge_on_new_search;
  if (r.walk != Walk::kDestination && !bridging) r.walk = Walk::kIdle;
  r.bridge_at = -1.0;
  r.got_paths.clear();
  r.path_deadline = -1.0;
  r.path_forwarded = false;
  r.s_hops = hops;
  const bool cont = try_continue();
  if (cont) {
    after_continue(hops);
    return;
  }
  if (is_source() || bridging) return;
  // Cannot continue: walk over and sense the gap on the source's behalf (figure 18) when this
  // robot is closer to the destination than the sender's points.
  double d_sender = kInf;
  for (const auto& p : m.open_points)
    d_sender = std::min(d_sender, distance(p.position, scen().destination));
  if (distance(r.pos, scen().destination) < d_sender - 1.0) {
    // Wait a little for a Search this robot can continue; bridge the gap only if none comes.
    r.bridge_at = now_ + opt().bridge_wait_s;
    return;
  }
  r.s_done = true;
}

void RobotAgent::start_bridge() {
  auto& r = r_;
  r.bridge_at = -1.0;
  if (r.s_done || r.walk != Walk::kIdle) return;
  double d_near = kInf;
  Vec2 near{};
  for (const auto& p : r.s_in.open_points)
    if (distance(p.position, r.pos) < d_near) {
      d_near = distance(p.position, r.pos);
      near = p.position;
    }
  if (std::isfinite(d_near) && plan_walk(near)) {
    NS_DEBUG("t=%.1f robot %u bridges to (%.1f,%.1f)\n", now_, r.id.value, near.x, near.y);
    r.walk = Walk::kBridge;
    r.walk_since_check = 0.0;
    return;
  }
  r.s_done = true;
}

void RobotAgent::after_continue(std::uint8_t hops) {
  auto& r = r_;
  if (dest_reached()) {
    r.s_done = true;
    r.walk = Walk::kIdle;
    r.waypoints.clear();
    answer_path();
    return;
  }
  // Walk toward the destination and sense it on the source's behalf (figure 18) when no radio
  // neighbour is closer to it (this robot is the frontier); otherwise forward the Search.
  bool frontier = true;
  double my_d = distance(r.pos, scen().destination);
  if (opt().frontier_by_points) {
    // As a receiver decides whether to bridge (process_search): a neighbour takes the Search on
    // only when it is > 1 m closer to the destination than every point this robot sends.
    for (const auto& p : points().open)
      my_d = std::min(my_d, distance(p.position, scen().destination));
    my_d -= 1.0;
  }
  for (const auto& n : transport_.nearby(r.id))
    if (distance(n.position, scen().destination) < my_d) frontier = false;
  // The source also walks toward the destination itself from its second attempt on (as the
  // centralized source does), while it keeps searching.
  const bool source_walks = is_source() && report_.search_attempts >= 2;
  if (frontier || source_walks || r.walk == Walk::kDestination) {
    bool walking = r.walk == Walk::kDestination;
    if (!walking && plan_walk(scen().destination)) {
      r.walk = Walk::kDestination;
      r.walk_since_check = 0.0;
      walking = true;
    }
    if (walking && !is_source()) return;
  }
  if (!is_source() || r.walk != Walk::kDestination) {
    r.walk = Walk::kIdle;
    r.waypoints.clear();
    r.s_done = true;
  }
  forward_search(hops);
}

/// Table 2 line 8-9: add oneself to Relay Robots and send the Search with one's open points.
void RobotAgent::forward_search(std::uint8_t hops) {
  auto& r = r_;
  if (hops + 1 >= opt().hop_limit) return;
  SearchMessage out;
  out.source = r.s_in.source;
  out.num = r.s_in.num;
  out.destination = r.s_in.destination;
  double best = kInf;
  std::size_t best_i = 0;
  for (std::size_t i : r.s_sent) {
    VoronoiPoint p = r.s_comb[i];
    const double c = r.s_search.cost[i];
    p.cost = static_cast<float>(std::isfinite(c) ? c : kUnreached);
    out.open_points.push_back(p);
    if (c < best) {
      best = c;
      best_i = i;
    }
  }
  out.relays = std::isfinite(best)
                   ? r.s_senders[sender_of(trace_points(r.s_search, best_i).front())].relays
                   : r.s_senders.front().relays;
  out.relays.push_back(r.id);
  out.close_points = points().close;
  broadcast(out, static_cast<std::uint8_t>(hops + 1));
}

/// Which sender a point of s_comb (index < s_na) came from.
std::size_t RobotAgent::sender_of(std::size_t i) const {
  const auto& r = r_;
  for (std::size_t k = 0; k < r.s_senders.size(); ++k)
    if (i >= r.s_senders[k].offset && i < r.s_senders[k].offset + r.s_senders[k].count) return k;
  return 0;
}

void RobotAgent::walk_progress(bool arrived) {
  auto& r = r_;
  if (r.s_done) return;
  r.points_dirty = true;
  if (is_source()) {
    // Is the destination reachable from where the source stands now? (The search state of the
    // broadcast Search is kept for the Path answers.)
    const auto keep_in = r.s_in;
    const auto keep_comb = r.s_comb;
    const auto keep_search = r.s_search;
    const auto keep_na = r.s_na;
    const auto keep_sent = r.s_sent;
    const double cl = clearance_at(r.map.grid(), r.pos);
    r.s_in.open_points = {
        VoronoiPoint{r.pos, static_cast<float>(std::max(cl, opt().robot_radius_m + 0.05)), 0.0f}};
    if (try_continue() && dest_reached()) {
      trail_ = {r.pos};
      r.walk = Walk::kIdle;
      r.waypoints.clear();
      answer_path();
      return;
    }
    r.s_in = keep_in;
    r.s_comb = keep_comb;
    r.s_search = keep_search;
    r.s_na = keep_na;
    r.s_sent = keep_sent;
    if (arrived) r.walk = Walk::kIdle;
    return;
  }
  const bool cont = try_continue();
  if (r.walk == Walk::kBridge) {
    if (cont) {
      r.walk = Walk::kIdle;
      r.waypoints.clear();
      after_continue(r.s_hops);
    } else if (arrived) {
      r.walk = Walk::kIdle;
      r.s_done = true;
    }
  } else if (r.walk == Walk::kDestination) {
    if (cont && dest_reached()) {
      r.walk = Walk::kIdle;
      r.waypoints.clear();
      r.s_done = true;
      answer_path();
    } else if (arrived) {
      r.walk = Walk::kIdle;
      r.s_done = true;
    }
  }
}

/// The chain of s_comb indices ending at `last`, split into the sender's exit point and the
/// robot's own piece.
RobotAgent::Piece RobotAgent::own_piece(std::size_t last) const {
  const auto& r = r_;
  const auto chain = trace_points(r.s_search, last);
  std::uint32_t exit = 0;
  std::vector<VoronoiPoint> piece;
  for (std::size_t i : chain) {
    if (i < r.s_na) {
      exit = static_cast<std::uint32_t>(i);
      piece.clear();
    } else {
      VoronoiPoint p = r.s_comb[i];
      p.cost = 0.0f;
      piece.push_back(p);
    }
  }
  const std::size_t k = sender_of(exit);
  return {k, static_cast<std::uint32_t>(exit - r.s_senders[k].offset), piece};
}

void RobotAgent::answer_path() {
  auto& r = r_;
  auto pc = own_piece(r.s_comb.size() - 1);
  PathMessage p;
  p.source = r.s_in.source;
  p.num = r.s_in.num;
  p.relays = r.s_senders[pc.sender].relays;
  p.whole_path = pc.points;
  p.exit_index = pc.exit;
  if (is_source()) {
    finish_route(p);
    return;
  }
  r.saved = p;
  send_reliable(r.s_senders[pc.sender].id, p);
}

// ---- decentralized: Path (Table 3) ------------------------------------------------------------
void RobotAgent::on(const Header&, const PathMessage& m) {
  auto& r = r_;
  if (m.num & kRepairFlag) {
    on_repair_path(m);
    return;
  }
  if (m.num != r.s_num || r.path_forwarded || m.exit_index >= r.s_sent.size()) return;
  r.got_paths.push_back(m);
  if (r.path_deadline < 0.0) r.path_deadline = now_ + opt().path_wait_s;
}

void RobotAgent::select_path() {
  auto& r = r_;
  r.path_deadline = -1.0;
  if (r.got_paths.empty() || r.path_forwarded) return;
  r.path_forwarded = true;
  // Select the shortest: cost to the exit point + the rest of the whole path.
  double best = kInf;
  std::size_t bi = 0;
  for (std::size_t k = 0; k < r.got_paths.size(); ++k) {
    const auto& p = r.got_paths[k];
    const std::size_t ci = r.s_sent[p.exit_index];
    if (!std::isfinite(r.s_search.cost[ci])) continue;
    double c = r.s_search.cost[ci] + route_length(p.whole_path);
    if (!p.whole_path.empty()) c += distance(r.s_comb[ci].position, p.whole_path.front().position);
    if (c < best) {
      best = c;
      bi = k;
    }
  }
  if (!std::isfinite(best)) {
    r.got_paths.clear();
    return;
  }
  const PathMessage got = r.got_paths[bi];
  r.got_paths.clear();
  auto pc = own_piece(r.s_sent[got.exit_index]);
  PathMessage out = got;
  out.whole_path = pc.points;  // add the path to the sender (own piece) to the whole path
  out.whole_path.insert(out.whole_path.end(), got.whole_path.begin(), got.whole_path.end());
  out.exit_index = pc.exit;
  if (is_source()) {
    finish_route(out);
    return;
  }
  out.relays = r.s_senders[pc.sender].relays;  // delete oneself: continue toward the source
  r.saved = out;
  send_reliable(r.s_senders[pc.sender].id, out);
}

void RobotAgent::finish_route(const PathMessage& p) {
  auto& s = r_;
  s.walk = Walk::kIdle;
  s.s_done = true;
  route_.clear();
  route_.push_back(VoronoiPoint{s.pos, 1.0f, 0.0f});
  route_.insert(route_.end(), p.whole_path.begin(), p.whole_path.end());
  if (distance(route_.back().position, scen().destination) > 1e-3)
    route_.push_back(VoronoiPoint{scen().destination, 1.0f, 0.0f});
  set_source_waypoints(0);
  if (trail_.size() > 1) {
    // The source walked since it sent this Search: go back along its own (known free) trail.
    const auto back = std::vector<Vec2>(trail_.rbegin(), trail_.rend());
    s.waypoints.insert(s.waypoints.begin(), back.begin(), back.end());
    route_base_ = 0;
    back_steps_ = back.size();
  } else {
    back_steps_ = 0;
  }
  if (report_.route_time_s < 0.0) {
    report_.route_time_s = now_;
    report_.route_length_m = route_length(route_);
  }
}

/// route_ index of the source's next waypoint (waypoints may start with a way back).
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
  broadcast(m, 1);
}

void RobotAgent::on(const Header& h, const RepairMessage& m) {
  auto& r = r_;
  if (!r.repairs_seen.insert(m.num).second) return;
  if (m.broken_to >= m.whole_path.size()) return;
  auto fixed = detour(m.whole_path, m.broken_from, m.broken_to);
  if (!fixed.empty()) {
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
  // Only the part within sensing range matters; find_break checks the remaining route.
  std::vector<VoronoiPoint> rest{VoronoiPoint{s.pos, 1.0f, 0.0f}};
  const std::size_t next = next_route_index();
  rest.insert(rest.end(),
              route_.begin() + static_cast<std::ptrdiff_t>(std::min(next, route_.size())),
              route_.end());
  const auto br = find_break(rest, 0);
  if (!br) return;
  if (blocked_since_ < 0.0) blocked_since_ = now_;
  ++report_.repairs;
  shrink_to_map(rest);  // as in check_relay_route
  auto fixed = detour(rest, br->first, br->second);
  if (!fixed.empty()) {
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
  broadcast(m, 1);
}

// ---- centralized baseline ---------------------------------------------------------------------
void RobotAgent::start_request() {
  auto& s = r_;
  ++report_.search_attempts;
  const std::uint32_t num = ++search_num_;
  s.req_num = num;
  collecting_ = true;
  last_ack_ = now_;
  broadcast(RequestMessage{s.id, num}, 0);
}

void RobotAgent::on(const Header& h, const RequestMessage& m) {
  auto& r = r_;
  if (is_source() || m.source != source_id()) return;
  if (r.req_num != kNone && m.num <= r.req_num) return;
  r.req_num = m.num;
  r.parent = h.sender;
  if (h.hops + 1 < opt().hop_limit) broadcast(m, static_cast<std::uint8_t>(h.hops + 1));
  report_.metrics.work += r.map.grid().size();  // serialising the map
  send_reliable(r.parent, AckMessage{m.source, m.num, r.id, r.map.grid()});
}

void RobotAgent::on(const Header&, const AckMessage& m) {
  auto& r = r_;
  if (!is_source()) {
    if (r.parent != kBroadcast) send_reliable(r.parent, m);  // relay toward the source
    return;
  }
  // Merge the received local map into the source's map.
  const auto& wg = scen().world;
  const auto& g = m.local_map.geometry();
  const auto off = wg.geometry().world_to_cell(g.cell_center(Cell{0, 0}));
  if (!off) return;
  timed([&] {
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        const std::int8_t v = m.local_map[Cell{x, y}];
        const Cell w = *off + Cell{x, y};
        if (v != kUnknown && wg.contains(w) && r.map.at(w) != v) r.map.set(w, v);
      }
    return 0;
  });
  report_.metrics.work += m.local_map.size();
  last_ack_ = now_;
}

void RobotAgent::on(const Header&, const NotifyMessage& m) {
  auto& r = r_;
  if (!is_source()) {
    if (r.parent != kBroadcast) send_reliable(r.parent, m);
    return;
  }
  ++report_.repairs;
  if (!collecting_) start_request();
}

void RobotAgent::on(const Header&, const LinkAckMessage&) {}

void RobotAgent::plan_central() {
  auto& s = r_;
  const auto& wg = scen().world.geometry();
  const auto a = wg.world_to_cell(s.pos), b = wg.world_to_cell(scen().destination);
  ++report_.replans;
  const auto result = timed([&] {
    BinaryGrid bin = binarize(s.map.grid(), BinarizeOptions{.unknown_is_blocked = false});
    BinaryGrid pg = planning::make_planning_grid(bin, opt().robot_radius_m);
    const Cell la = *a - s.map.offset(), lb = *b - s.map.offset();
    pg[la] = 0;
    pg[lb] = 0;
    planning::AStarPlanner planner;
    auto r = planner.plan(pg, la, lb);
    for (auto& c : r.path)
      c = c + s.map.offset();
    return r;
  });
  report_.metrics.work += s.map.grid().size() * 3 + result.expanded;
  if (!result.ok()) {
    s.waypoints.clear();
    return;
  }
  s.waypoints.clear();
  for (std::size_t i = 1; i < result.path.size(); ++i)
    s.waypoints.push_back(wg.cell_center(result.path[i]));
  s.waypoints.push_back(scen().destination);
  s.wp = 0;
  if (report_.route_time_s < 0.0) {
    report_.route_time_s = now_;
    report_.route_length_m = path_len(s.pos, s.waypoints);
  }
}

void RobotAgent::check_central_path() {
  auto& s = r_;
  if (collecting_ || s.waypoints.empty()) return;
  for (std::size_t i = s.wp; i < s.waypoints.size(); ++i) {
    if (distance(s.waypoints[i], s.pos) > opt().sensing_range_m + 0.5) break;
    const Vec2 from = i == s.wp ? s.pos : s.waypoints[i - 1];
    if (segment_blocked(from, s.waypoints[i])) {
      plan_central();
      return;
    }
  }
}

}  // namespace voronav::sim
