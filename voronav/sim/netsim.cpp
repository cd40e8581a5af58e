#include "voronav/sim/netsim.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/sim/world.hpp"

// Trace points of the protocol (compiled out; the library does no I/O).
#define NS_DEBUG(...) ((void)0)

namespace voronav::sim {

using namespace network;

std::string_view to_string(Method m) {
  return m == Method::kCentralized ? "centralized" : "decentralized";
}

Method parse_method(std::string_view s) {
  if (s == "centralized") return Method::kCentralized;
  if (s == "decentralized") return Method::kDecentralized;
  throw Error("method", 0,
              "expected 'centralized' or 'decentralized', got '" + std::string(s) + "'");
}

void NetSimScenario::validate() const {
  if (world.empty()) throw Error("scenario.world", 0, "the world map is empty");
  if (robots.empty()) throw Error("scenario.robots", 0, "at least one robot is needed");
  if (source >= robots.size()) throw Error("scenario.source", 0, "source index out of range");
  auto check = [&](Vec2 p, const std::string& what) {
    const auto c = world.geometry().world_to_cell(p);
    if (!p.is_finite() || !c || !world.contains(*c))
      throw Error(what, 0, "position is outside the map");
    if (world[*c] != kFree) throw Error(what, 0, "position is inside an obstacle");
  };
  for (std::size_t i = 0; i < robots.size(); ++i)
    check(robots[i], "scenario.robots[" + std::to_string(i) + "]");
  check(destination, "scenario.destination");
  for (const auto& ch : changes) {
    if (!(ch.after_route_s >= 0.0) || !std::isfinite(ch.after_route_s))
      throw Error("scenario.changes", 0, "after_route_s must be a finite number >= 0");
    for (Cell c : ch.cells)
      if (!world.contains(c)) throw Error("scenario.changes", 0, "change cell outside the map");
  }
}

void NetSimOptions::validate() const {
  auto pos = [](double v, const char* n) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw Error(std::string("netsim.") + n, 0,
                  "expected a positive finite number, got " + std::to_string(v));
  };
  pos(sensing_range_m, "sensing_range_m");
  pos(speed_mps, "speed_mps");
  pos(dt_s, "dt_s");
  pos(time_limit_s, "time_limit_s");
  pos(search_timeout_s, "search_timeout_s");
  pos(link_timeout_s, "link_timeout_s");
  pos(collect_s, "collect_s");
  pos(repair_timeout_s, "repair_timeout_s");
  if (!(robot_radius_m >= 0.0) || !std::isfinite(robot_radius_m))
    throw Error("netsim.robot_radius_m", 0, "expected a finite number >= 0");
  if (!(path_wait_s >= 0.0) || !std::isfinite(path_wait_s))
    throw Error("netsim.path_wait_s", 0, "expected a finite number >= 0");
  if (max_search_attempts < 1 || link_retries < 0 || hop_limit < 1 || hop_limit > 255 ||
      repair_hops < 1)
    throw Error("netsim", 0, "attempts/retries/hop limits out of range");
  radio.validate();
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kRepairFlag = 0x80000000u;
constexpr double kUnreached = 1e8;  // cost sent for an open point the Search has not reached

struct Robot {
  RobotId id;
  Vec2 pos;
  LocalMap map;
  std::vector<Vec2> waypoints;
  std::size_t wp = 0;
  RobotMetrics m;
  bool points_dirty = true;
  VoronoiPoints pts;
  std::unordered_set<std::uint64_t> seen;
  std::uint32_t next_msg = 1;
  // Decentralized search state (one search at a time: the latest Num).
  std::uint32_t s_num = kNone;
  bool s_done = false;
  SearchMessage s_in;  // what the senders told us: all their points, concatenated
  RobotId s_sender;
  struct SenderInfo {
    RobotId id;
    std::vector<RobotId> relays;
    std::size_t offset = 0;  // first of its points in s_in.open_points
    std::size_t count = 0;
  };
  std::vector<SenderInfo> s_senders;
  int reforwards = 0;
  std::vector<VoronoiPoint> s_comb;  // sender points + own points (+ destination)
  PointSearch s_search;
  std::size_t s_na = 0;             // number of sender points in s_comb
  std::vector<std::size_t> s_sent;  // sent point index -> s_comb index
  enum class Walk { kIdle, kBridge, kDestination } walk = Walk::kIdle;
  double walk_since_check = 0.0;
  double bridge_at = -1.0;  // when to start bridging if no continuable Search came
  std::vector<PathMessage> got_paths;
  double path_deadline = -1.0;
  bool path_forwarded = false;
  std::optional<PathMessage> saved;
  std::unordered_set<std::uint32_t> repairs_seen;
  std::uint32_t repair_counter = 0;
  // Centralized.
  RobotId parent = kBroadcast;
  std::uint32_t req_num = kNone;
};

struct Outgoing {
  RobotId from, to;
  std::vector<std::uint8_t> bytes;
  std::uint64_t key;
  int tries;
  double next_at;
};

std::uint64_t key_of(RobotId origin, std::uint32_t id) {
  return (static_cast<std::uint64_t>(origin.value) << 32) | id;
}

class Runner {
 public:
  Runner(const NetSimScenario& sc, const NetSimOptions& o)
      : sc_(sc), o_(o), radio_(radio_opts(o)), truth_(binarize(sc.world)) {
    const auto& g = sc.world.geometry();
    for (std::size_t i = 0; i < sc.robots.size(); ++i) {
      Robot r;
      r.id = RobotId{static_cast<std::uint32_t>(i)};
      r.pos = sc.robots[i];
      r.map = LocalMap(g);
      robots_.push_back(std::move(r));
    }
    if (o.method == Method::kCentralized) {
      auto& s = src();
      s.map.ensure(Cell{0, 0}, Cell{g.width - 1, g.height - 1});
    }
  }

  NetSimResult run() {
    const auto wall0 = std::chrono::steady_clock::now();
    for (auto& r : robots_) {
      radio_.update_position(r.id, r.pos);
      do_sense(r);
    }
    if (o_.record) res_.recording.world = sc_.world.geometry();
    start_method();
    const int steps = static_cast<int>(std::ceil(o_.time_limit_s / o_.dt_s));
    for (int k = 1; k <= steps && !arrived_; ++k) {
      now_ = k * o_.dt_s;
      apply_changes();
      for (auto& r : robots_)
        move(r);
      radio_.set_time(now_);
      for (auto& r : robots_) {
        for (auto& p : radio_.receive(r.id))
          handle_packet(r, p);
      }
      timers();
      if (o_.record) {
        RecordedStep st{now_, {}};
        for (const auto& r : robots_)
          st.positions.push_back(r.pos);
        res_.recording.steps.push_back(std::move(st));
      }
    }
    auto& M = res_.metrics;
    M.simulated_s = now_;
    M.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    M.success = arrived_;
    const auto& st = radio_.stats();
    M.traffic_bytes = st.total.bytes;
    M.messages = st.total.messages;
    for (int t = 1; t < kMessageTypeCount; ++t)
      if (st.by_type[static_cast<std::size_t>(t)].messages > 0)
        M.by_type[std::string(to_string(static_cast<MessageType>(t)))] =
            st.by_type[static_cast<std::size_t>(t)];
    auto mean = [&](MessageType t) {
      const auto& c = st.by_type[static_cast<std::size_t>(t)];
      return c.messages ? static_cast<double>(c.bytes) / static_cast<double>(c.messages) : 0.0;
    };
    if (o_.method == Method::kCentralized) {
      M.alpha_bytes = mean(MessageType::kRequest);
      M.beta_bytes = mean(MessageType::kAck);
    } else {
      M.alpha_bytes = mean(MessageType::kSearch);
      M.gamma_bytes = mean(MessageType::kPath);
    }
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      auto rm = robots_[i].m;
      if (i < st.sent_by_robot.size()) {
        rm.sent_bytes = st.sent_by_robot[i].bytes;
        rm.sent_messages = st.sent_by_robot[i].messages;
      }
      M.travel_m += rm.travel_m;
      M.computation += rm.work;
      M.max_robot_computation = std::max(M.max_robot_computation, rm.work);
      M.cpu_s += rm.cpu_s;
      M.max_robot_cpu_s = std::max(M.max_robot_cpu_s, rm.cpu_s);
      M.robots.push_back(rm);
    }
    M.source_travel_m = src().m.travel_m;
    if (o_.record) {
      for (auto& r : robots_) {
        res_.recording.final_local_maps.push_back(r.map.grid());
        res_.recording.open_points.push_back(points(r).open);
      }
      for (const auto& p : route_)
        res_.recording.route.push_back(p.position);
      if (o_.method == Method::kCentralized) res_.recording.route = src().waypoints;
    }
    return std::move(res_);
  }

 private:
  static RadioOptions radio_opts(const NetSimOptions& o) {
    RadioOptions r = o.radio;
    r.seed = o.radio.seed ^ (o.seed * 0x9E3779B97F4A7C15ull);
    return r;
  }
  Robot& src() { return robots_[sc_.source]; }
  [[nodiscard]] bool is_source(const Robot& r) const { return r.id.value == sc_.source; }

  // ---- timing of computation --------------------------------------------------------------
  template <typename F>
  auto timed(Robot& r, F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    auto out = f();
    r.m.cpu_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }

  void do_sense(Robot& r) {
    const auto s = sense(truth_, r.pos, o_.sensing_range_m, r.map);
    r.m.work += s.cells;
    if (s.changed) r.points_dirty = true;
    last_sense_changed_ = s.changed;
  }

  const VoronoiPoints& points(Robot& r) {
    if (r.points_dirty) {
      r.pts = timed(r, [&] { return make_voronoi_points(r.map.grid(), points_opts()); });
      r.m.work += r.pts.cells_processed;
      r.points_dirty = false;
    }
    return r.pts;
  }
  [[nodiscard]] VoronoiPointsOptions points_opts() const {
    VoronoiPointsOptions p = o_.points;
    p.robot_radius_m = o_.robot_radius_m;
    return p;
  }

  // ---- messaging ----------------------------------------------------------------------------
  void record_msg(RobotId from, RobotId to, const std::vector<std::uint8_t>& b) {
    if (!o_.record) return;
    res_.recording.messages.push_back(
        {now_, from.value, to.value, static_cast<MessageType>(peek_type(b)), b.size()});
  }
  void broadcast(Robot& r, Payload p, std::uint8_t hops) {
    Envelope e{Header{r.id, kBroadcast, r.id, r.next_msg++, hops}, std::move(p)};
    const auto b = encode(e);
    r.seen.insert(key_of(r.id, e.header.msg_id));
    radio_.broadcast(r.id, b);
    record_msg(r.id, kBroadcast, b);
  }
  void send_reliable(Robot& r, RobotId to, Payload p) {
    Envelope e{Header{r.id, to, r.id, r.next_msg++, 0}, std::move(p)};
    auto b = encode(e);
    radio_.send(r.id, to, b);
    record_msg(r.id, to, b);
    outbox_.push_back(
        {r.id, to, std::move(b), key_of(r.id, e.header.msg_id), 1, now_ + o_.link_timeout_s});
  }
  void link_ack(Robot& r, const Header& h) {
    Envelope e{Header{r.id, h.sender, r.id, r.next_msg++, 0}, LinkAckMessage{h.origin, h.msg_id}};
    const auto b = encode(e);
    radio_.send(r.id, h.sender, b);
    record_msg(r.id, h.sender, b);
  }

  void handle_packet(Robot& r, const Packet& p) {
    Envelope e;
    try {
      e = decode(p.bytes);
    } catch (const Error&) {
      ++res_.metrics.corrupt_packets;
      return;
    }
    if (e.type() == MessageType::kLinkAck) {
      const auto& a = std::get<LinkAckMessage>(e.payload);
      const auto k = key_of(a.acked_origin, a.acked_id);
      std::erase_if(outbox_, [&](const Outgoing& g) { return g.key == k && g.from == r.id; });
      return;
    }
    if (e.header.receiver != kBroadcast) link_ack(r, e.header);
    if (!r.seen.insert(key_of(e.header.origin, e.header.msg_id)).second) return;  // duplicate
    std::visit([&](const auto& m) { on(r, e.header, m); }, e.payload);
  }

  void timers() {
    for (std::size_t i = 0; i < outbox_.size();) {
      auto& g = outbox_[i];
      if (now_ + 1e-9 >= g.next_at) {
        if (g.tries > o_.link_retries) {
          outbox_.erase(outbox_.begin() + static_cast<std::ptrdiff_t>(i));
          continue;
        }
        ++g.tries;
        g.next_at = now_ + o_.link_timeout_s;
        radio_.send(g.from, g.to, g.bytes);
        record_msg(g.from, g.to, g.bytes);
      }
      ++i;
    }
    if (o_.method == Method::kDecentralized) {
      for (auto& r : robots_) {
        if (r.path_deadline >= 0.0 && now_ + 1e-9 >= r.path_deadline) select_path(r);
        if (r.bridge_at >= 0.0 && now_ + 1e-9 >= r.bridge_at) start_bridge(r);
      }
      auto& s = src();
      if (route_.empty() && now_ - search_started_ >= o_.search_timeout_s &&
          res_.metrics.search_attempts < o_.max_search_attempts)
        start_search();
      if (!route_.empty() && blocked_since_ >= 0.0 &&
          now_ - blocked_since_ >= o_.repair_timeout_s) {
        route_.clear();
        s.waypoints.clear();
        blocked_since_ = -1.0;
        start_search();
      }
    } else {
      if (collecting_ && now_ - last_ack_ >= o_.collect_s) {
        collecting_ = false;
        plan_central();
      }
    }
  }

  // ---- world changes ------------------------------------------------------------------------
  void apply_changes() {
    if (first_route_ < 0.0) return;
    while (next_change_ < sc_.changes.size() &&
           now_ + 1e-9 >= first_route_ + sc_.changes[next_change_].after_route_s) {
      const auto& ch = sc_.changes[next_change_++];
      Vec2 lo{kInf, kInf}, hi{-kInf, -kInf};
      for (Cell c : ch.cells) {
        truth_[c] = ch.value >= 50 ? 1 : 0;
        const Vec2 w = truth_.geometry().cell_center(c);
        lo = {std::min(lo.x, w.x), std::min(lo.y, w.y)};
        hi = {std::max(hi.x, w.x), std::max(hi.y, w.y)};
      }
      // Robots whose sensing disc touches the change see it now.
      for (auto& r : robots_) {
        const Vec2 q{std::clamp(r.pos.x, lo.x, hi.x), std::clamp(r.pos.y, lo.y, hi.y)};
        if (distance(q, r.pos) > o_.sensing_range_m + 0.5) continue;
        do_sense(r);
        if (last_sense_changed_) on_map_changed(r);
      }
    }
  }

  void on_map_changed(Robot& r) {
    if (o_.method == Method::kCentralized) {
      if (is_source(r)) {
        check_central_path(r);
      } else if (r.parent != kBroadcast) {
        send_reliable(r, r.parent, NotifyMessage{src().id, r.id, r.pos});
      }
      return;
    }
    if (is_source(r)) {
      check_source_route();
    } else if (r.saved) {
      check_relay_route(r);
    }
  }

  // ---- motion --------------------------------------------------------------------------------
  void move(Robot& r) {
    if (r.wp >= r.waypoints.size()) return;
    if (is_source(r) && blocked_since_ >= 0.0) return;  // waiting for a repair
    double budget = o_.speed_mps * o_.dt_s;
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
    r.m.travel_m += moved;
    if (is_source(r) && moved > 0.0) trail_.push_back(r.pos);
    radio_.update_position(r.id, r.pos);
    do_sense(r);
    const bool changed = last_sense_changed_;
    if (is_source(r) && r.wp >= r.waypoints.size() && distance(r.pos, sc_.destination) < 0.35) {
      arrived_ = true;
      res_.metrics.arrival_time_s = now_;
      return;
    }
    if (o_.method == Method::kCentralized) {
      if (is_source(r) && changed) check_central_path(r);
      return;
    }
    if (is_source(r) && r.walk == Robot::Walk::kIdle) {
      if (changed) check_source_route();
      return;
    }
    if (r.walk != Robot::Walk::kIdle) {
      r.walk_since_check += moved;
      bool done = r.wp >= r.waypoints.size();
      if (changed && !done && walk_blocked(r) && !plan_walk(r, r.waypoints.back())) {
        r.waypoints.clear();  // no way on: stop here
        done = true;
      }
      if (r.walk_since_check >= 1.0 || done) {
        r.walk_since_check = 0.0;
        walk_progress(r, done);
      }
    }
  }

  /// Whether a straight robot move a->b crosses an occupied cell of `map` (inflated by r).
  bool segment_blocked(const LocalMap& map, Vec2 a, Vec2 b) {
    const auto& g = map.world();
    const auto ca = g.world_to_cell(a), cb = g.world_to_cell(b);
    if (!ca || !cb) return true;
    // Strictly closer than r, as field::inflate (so planned paths are not flagged as blocked).
    const double rad = o_.robot_radius_m / g.resolution - 0.01;
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

  /// Whether every cell within r of the straight move a->b is known free in `map`.
  bool segment_known_free(const LocalMap& map, Vec2 a, Vec2 b) {
    const auto& g = map.world();
    const auto ca = g.world_to_cell(a), cb = g.world_to_cell(b);
    if (!ca || !cb) return false;
    const double rad = o_.robot_radius_m / g.resolution - 0.01;
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

  // ---- walking on a robot's own (optimistic) map ---------------------------------------------
  bool plan_walk(Robot& r, Vec2 target) {
    const auto& wg = sc_.world.geometry();
    const auto a = wg.world_to_cell(r.pos), b = wg.world_to_cell(target);
    if (!a || !b) return false;
    // Plan on a window of the world around both ends; unknown = free (optimistic).
    const int margin = static_cast<int>(std::ceil(10.0 / wg.resolution));
    Cell lo{std::max(0, std::min(a->x, b->x) - margin), std::max(0, std::min(a->y, b->y) - margin)};
    Cell hi{std::min(wg.width - 1, std::max(a->x, b->x) + margin),
            std::min(wg.height - 1, std::max(a->y, b->y) + margin)};
    BinaryGrid win(GridGeometry{hi.x - lo.x + 1, hi.y - lo.y + 1, wg.resolution, {}}, 0);
    for (int y = 0; y < win.height(); ++y)
      for (int x = 0; x < win.width(); ++x)
        win[Cell{x, y}] = r.map.at(Cell{x, y} + lo) == kOccupied ? 1 : 0;
    const auto result = timed(r, [&] {
      BinaryGrid pg = planning::make_planning_grid(win, o_.robot_radius_m);
      pg[*a - lo] = 0;
      pg[*b - lo] = 0;
      planning::AStarPlanner planner;
      return planner.plan(pg, *a - lo, *b - lo);
    });
    r.m.work += win.size() * 2 + result.expanded;
    if (!result.ok()) return false;
    r.waypoints.clear();
    for (std::size_t i = 1; i < result.path.size(); ++i)
      r.waypoints.push_back(wg.cell_center(result.path[i] + lo));
    r.waypoints.push_back(target);
    r.wp = 0;
    return true;
  }

  bool walk_blocked(Robot& r) {
    for (std::size_t i = r.wp; i < r.waypoints.size(); ++i) {
      if (distance(r.waypoints[i], r.pos) > o_.sensing_range_m + 0.5) break;
      const Vec2 from = i == r.wp ? r.pos : r.waypoints[i - 1];
      if (segment_blocked(r.map, from, r.waypoints[i])) return true;
    }
    return false;
  }

  // ---- decentralized: Search (Tables 1–2) ---------------------------------------------------
  void start_method() {
    if (o_.method == Method::kDecentralized) {
      start_search();
    } else {
      start_request();
    }
  }

  void start_search() {
    auto& s = src();
    ++res_.metrics.search_attempts;
    search_started_ = now_;
    trail_ = {s.pos};
    const std::uint32_t num = ++search_num_;
    SearchMessage pseudo;
    pseudo.source = s.id;
    pseudo.num = num;
    pseudo.destination = sc_.destination;
    const double cl = clearance_at(s.map.grid(), s.pos);
    pseudo.open_points = {
        VoronoiPoint{s.pos, static_cast<float>(std::max(cl, o_.robot_radius_m + 0.05)), 0.0f}};
    s.got_paths.clear();
    s.path_deadline = -1.0;
    s.path_forwarded = false;
    process_search(s, s.id, pseudo, 0);
  }

  /// Runs the point search from the sender's open points through r's open points (and the
  /// destination when it is in r's area). Returns true when r continues the sender.
  bool try_continue(Robot& r) {
    const auto& own = points(r).open;
    r.s_comb = r.s_in.open_points;
    r.s_na = r.s_comb.size();
    r.s_comb.insert(r.s_comb.end(), own.begin(), own.end());
    const double dcl = clearance_at(r.map.grid(), sc_.destination);
    const bool has_dest = dcl > o_.robot_radius_m;
    if (has_dest) r.s_comb.push_back(VoronoiPoint{sc_.destination, static_cast<float>(dcl), 0.0f});
    std::vector<double> start(r.s_comb.size(), kInf);
    for (std::size_t i = 0; i < r.s_na; ++i)
      start[i] = r.s_comb[i].cost < kUnreached ? r.s_comb[i].cost : kInf;
    // Within its own map a robot may also move straight between its own points when the move is
    // known free (it checks the cells itself; at most 6 m apart to bound the work).
    const std::size_t own_end = r.s_na + own.size();
    std::size_t los_cells = 0;
    auto own_edge = [&](std::size_t i, std::size_t j) {
      if (i < r.s_na || j < r.s_na || i >= own_end || j >= own_end) return false;
      const Vec2 a = r.s_comb[i].position, b = r.s_comb[j].position;
      if (distance(a, b) > 6.0) return false;
      los_cells += static_cast<std::size_t>(distance(a, b) / sc_.world.resolution()) + 1;
      return segment_known_free(r.map, a, b);
    };
    r.s_search =
        timed(r, [&] { return search_points(r.s_comb, start, o_.robot_radius_m, own_edge); });
    r.m.work += los_cells;
    r.m.work += r.s_search.work;
    if (has_dest && !std::isfinite(r.s_search.cost.back())) {
      // The destination is not an open point: join it to the best reached own point it can be
      // driven to in a straight line through known free space.
      const std::size_t d = r.s_comb.size() - 1;
      for (std::size_t i = r.s_na; i < d; ++i) {
        if (!std::isfinite(r.s_search.cost[i])) continue;
        const double c = r.s_search.cost[i] + distance(r.s_comb[i].position, sc_.destination);
        if (c < r.s_search.cost[d] &&
            segment_known_free(r.map, r.s_comb[i].position, sc_.destination)) {
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
  [[nodiscard]] bool dest_reached(const Robot& r) const {
    const double dcl = clearance_at(r.map.grid(), sc_.destination);
    return dcl > o_.robot_radius_m && r.s_comb.size() > r.s_na &&
           std::isfinite(r.s_search.cost.back()) && r.s_comb.back().position == sc_.destination;
  }

  void on(Robot& r, const Header& h, const SearchMessage& m) {
    if (is_source(r) || m.source.value != sc_.source) return;
    if (r.s_num != kNone && m.num < r.s_num) return;  // stale search
    if (r.s_num == m.num) {
      // Same search from another robot: only useful while this robot has not continued yet.
      if (r.walk == Robot::Walk::kDestination || r.path_forwarded) return;
      // Merge the new sender's points with those already received (distributed shortest path:
      // a robot that already forwarded re-forwards when its costs improve, at most 3 times).
      r.s_senders.push_back({h.sender, m.relays, r.s_in.open_points.size(), m.open_points.size()});
      r.s_in.open_points.insert(r.s_in.open_points.end(), m.open_points.begin(),
                                m.open_points.end());
      if (r.s_done) {
        std::vector<double> before;
        for (std::size_t i : r.s_sent)
          before.push_back(r.s_search.cost[i]);
        if (!try_continue(r) || r.reforwards >= 3) return;
        bool better = before.size() != r.s_sent.size();
        for (std::size_t k = 0; k < before.size() && !better; ++k)
          better = r.s_search.cost[r.s_sent[k]] < before[k] - 1e-6;
        if (better) {
          ++r.reforwards;
          forward_search(r, h.hops);
        }
        return;
      }
      if (try_continue(r)) {
        NS_DEBUG("t=%.1f robot %u continues search %u from %u\n", now_, r.id.value, m.num,
                 h.sender.value);
        r.walk = Robot::Walk::kIdle;
        r.waypoints.clear();
        r.bridge_at = -1.0;
        after_continue(r, h.hops);
      }
      return;
    }
    process_search(r, h.sender, m, h.hops);
  }

  void process_search(Robot& r, RobotId sender, const SearchMessage& m, std::uint8_t hops) {
    r.s_num = m.num;
    r.s_done = false;
    r.s_in = m;
    r.s_sender = sender;
    r.s_senders = {{sender, m.relays, 0, m.open_points.size()}};
    r.reforwards = 0;
    if (r.walk != Robot::Walk::kDestination) r.walk = Robot::Walk::kIdle;  // stay committed
    r.bridge_at = -1.0;
    r.got_paths.clear();
    r.path_deadline = -1.0;
    r.path_forwarded = false;
    search_hops_ = hops;
    const bool cont = try_continue(r);
    NS_DEBUG("t=%.1f robot %u search %u from %u: continues=%d own=%zu sent=%zu pos=(%.1f,%.1f)\n",
             now_, r.id.value, m.num, sender.value, cont ? 1 : 0, points(r).open.size(),
             r.s_sent.size(), r.pos.x, r.pos.y);
    if (cont) {
      after_continue(r, hops);
      return;
    }
    if (is_source(r)) return;
    // Cannot continue: walk over and sense the gap on the source's behalf (figure 18) when this
    // robot is closer to the destination than the sender's points.
    double d_sender = kInf, d_near = kInf;
    Vec2 near{};
    for (const auto& p : m.open_points) {
      d_sender = std::min(d_sender, distance(p.position, sc_.destination));
      if (distance(p.position, r.pos) < d_near) {
        d_near = distance(p.position, r.pos);
        near = p.position;
      }
    }
    (void)near;
    if (distance(r.pos, sc_.destination) < d_sender - 1.0) {
      // Wait a little for a Search this robot can continue; bridge the gap only if none comes.
      r.bridge_at = now_ + o_.bridge_wait_s;
      return;
    }
    r.s_done = true;
  }

  void start_bridge(Robot& r) {
    r.bridge_at = -1.0;
    if (r.s_done || r.walk != Robot::Walk::kIdle) return;
    double d_near = kInf;
    Vec2 near{};
    for (const auto& p : r.s_in.open_points)
      if (distance(p.position, r.pos) < d_near) {
        d_near = distance(p.position, r.pos);
        near = p.position;
      }
    if (std::isfinite(d_near) && plan_walk(r, near)) {
      NS_DEBUG("t=%.1f robot %u bridges to (%.1f,%.1f)\n", now_, r.id.value, near.x, near.y);
      r.walk = Robot::Walk::kBridge;
      r.walk_since_check = 0.0;
      return;
    }
    r.s_done = true;
  }

  void after_continue(Robot& r, std::uint8_t hops) {
    if (dest_reached(r)) {
      r.s_done = true;
      r.walk = Robot::Walk::kIdle;
      r.waypoints.clear();
      answer_path(r);
      return;
    }
    // Walk toward the destination and sense it on the source's behalf (figure 18) when no radio
    // neighbour is closer to it (this robot is the frontier); otherwise forward the Search.
    bool frontier = true;
    const double my_d = distance(r.pos, sc_.destination);
    for (RobotId n : radio_.neighbours(r.id))
      if (distance(robots_[n.value].pos, sc_.destination) < my_d) frontier = false;
    // The source also walks toward the destination itself from its second attempt on (as the
    // centralized source does), while it keeps searching.
    const bool source_walks = is_source(r) && res_.metrics.search_attempts >= 2;
    if (frontier || source_walks || r.walk == Robot::Walk::kDestination) {
      bool walking = r.walk == Robot::Walk::kDestination;
      if (!walking && plan_walk(r, sc_.destination)) {
        NS_DEBUG("  robot %u walks to destination\n", r.id.value);
        r.walk = Robot::Walk::kDestination;
        r.walk_since_check = 0.0;
        walking = true;
      }
      if (walking && !is_source(r)) return;
    }
    if (!is_source(r) || r.walk != Robot::Walk::kDestination) {
      r.walk = Robot::Walk::kIdle;
      r.waypoints.clear();
      r.s_done = true;
    }
    forward_search(r, hops);
  }

  /// Table 2 line 8-9: add oneself to Relay Robots and send the Search with one's open points.
  void forward_search(Robot& r, std::uint8_t hops) {
    if (hops + 1 >= o_.hop_limit) return;
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
                     ? r.s_senders[sender_of(r, trace_points(r.s_search, best_i).front())].relays
                     : r.s_senders.front().relays;
    out.relays.push_back(r.id);
    out.close_points = points(r).close;
    broadcast(r, out, static_cast<std::uint8_t>(hops + 1));
  }

  /// Which sender a point of s_comb (index < s_na) came from.
  static std::size_t sender_of(const Robot& r, std::size_t i) {
    for (std::size_t k = 0; k < r.s_senders.size(); ++k)
      if (i >= r.s_senders[k].offset && i < r.s_senders[k].offset + r.s_senders[k].count) return k;
    return 0;
  }

  void walk_progress(Robot& r, bool arrived) {
    if (r.s_done) return;
    r.points_dirty = true;
    if (is_source(r)) {
      // Is the destination reachable from where the source stands now? (The search state of the
      // broadcast Search is kept for the Path answers.)
      const auto keep_in = r.s_in;
      const auto keep_comb = r.s_comb;
      const auto keep_search = r.s_search;
      const auto keep_na = r.s_na;
      const auto keep_sent = r.s_sent;
      const double cl = clearance_at(r.map.grid(), r.pos);
      r.s_in.open_points = {
          VoronoiPoint{r.pos, static_cast<float>(std::max(cl, o_.robot_radius_m + 0.05)), 0.0f}};
      if (try_continue(r) && dest_reached(r)) {
        trail_ = {r.pos};
        r.walk = Robot::Walk::kIdle;
        r.waypoints.clear();
        answer_path(r);
        return;
      }
      r.s_in = keep_in;
      r.s_comb = keep_comb;
      r.s_search = keep_search;
      r.s_na = keep_na;
      r.s_sent = keep_sent;
      if (arrived) r.walk = Robot::Walk::kIdle;
      return;
    }
    const bool cont = try_continue(r);
    NS_DEBUG("t=%.1f robot %u walk check cont=%d dest=%d arrived=%d dcl=%.2f\n", now_, r.id.value,
             cont ? 1 : 0, dest_reached(r) ? 1 : 0, arrived ? 1 : 0,
             clearance_at(r.map.grid(), sc_.destination));
    if (r.walk == Robot::Walk::kBridge) {
      if (cont) {
        r.walk = Robot::Walk::kIdle;
        r.waypoints.clear();
        after_continue(r, search_hops_);
      } else if (arrived) {
        r.walk = Robot::Walk::kIdle;
        r.s_done = true;
      }
    } else if (r.walk == Robot::Walk::kDestination) {
      if (cont && dest_reached(r)) {
        r.walk = Robot::Walk::kIdle;
        r.waypoints.clear();
        r.s_done = true;
        answer_path(r);
      } else if (arrived) {
        r.walk = Robot::Walk::kIdle;
        r.s_done = true;
      }
    }
  }

  /// The chain of s_comb indices ending at `last`, split into the sender's exit point and r's
  /// piece.
  struct Piece {
    std::size_t sender = 0;  // index into s_senders
    std::uint32_t exit = 0;  // index into that sender's points
    std::vector<VoronoiPoint> points;
  };
  Piece own_piece(const Robot& r, std::size_t last) {
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
    const std::size_t k = sender_of(r, exit);
    return {k, static_cast<std::uint32_t>(exit - r.s_senders[k].offset), piece};
  }

  void answer_path(Robot& r) {
    NS_DEBUG("t=%.1f robot %u answers path\n", now_, r.id.value);
    auto pc = own_piece(r, r.s_comb.size() - 1);
    PathMessage p;
    p.source = r.s_in.source;
    p.num = r.s_in.num;
    p.relays = r.s_senders[pc.sender].relays;
    p.whole_path = pc.points;
    p.exit_index = pc.exit;
    if (is_source(r)) {
      finish_route(r, p);
      return;
    }
    r.saved = p;
    send_reliable(r, r.s_senders[pc.sender].id, p);
  }

  // ---- decentralized: Path (Table 3) --------------------------------------------------------
  void on(Robot& r, const Header&, const PathMessage& m) {
    if (m.num & kRepairFlag) {
      on_repair_path(r, m);
      return;
    }
    NS_DEBUG("t=%.1f robot %u got path num %u exit %u (s_num %u fwd %d sent %zu)\n", now_,
             r.id.value, m.num, m.exit_index, r.s_num, r.path_forwarded ? 1 : 0, r.s_sent.size());
    if (m.num != r.s_num || r.path_forwarded || m.exit_index >= r.s_sent.size()) return;
    r.got_paths.push_back(m);
    if (r.path_deadline < 0.0) r.path_deadline = now_ + o_.path_wait_s;
  }

  void select_path(Robot& r) {
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
      if (!p.whole_path.empty())
        c += distance(r.s_comb[ci].position, p.whole_path.front().position);
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
    auto pc = own_piece(r, r.s_sent[got.exit_index]);
    PathMessage out = got;
    out.whole_path = pc.points;  // add the path to the sender (own piece) to the whole path
    out.whole_path.insert(out.whole_path.end(), got.whole_path.begin(), got.whole_path.end());
    out.exit_index = pc.exit;
    if (is_source(r)) {
      finish_route(r, out);
      return;
    }
    out.relays = r.s_senders[pc.sender].relays;  // delete oneself: continue toward the source
    r.saved = out;
    send_reliable(r, r.s_senders[pc.sender].id, out);
  }

  void finish_route(Robot& s, const PathMessage& p) {
    s.walk = Robot::Walk::kIdle;
    s.s_done = true;
    route_.clear();
    route_.push_back(VoronoiPoint{s.pos, 1.0f, 0.0f});
    route_.insert(route_.end(), p.whole_path.begin(), p.whole_path.end());
    if (distance(route_.back().position, sc_.destination) > 1e-3)
      route_.push_back(VoronoiPoint{sc_.destination, 1.0f, 0.0f});
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
    if (first_route_ < 0.0) {
      first_route_ = now_;
      res_.metrics.route_time_s = now_;
      res_.metrics.route_length_m = route_length(route_);
      if (o_.record) {
        for (auto& r : robots_) {
          res_.recording.maps_at_route.push_back(r.map.grid());
          res_.recording.open_points_at_route.push_back(points(r).open);
        }
      }
    }
  }

  /// route_ index of the source's next waypoint (waypoints may start with a way back).
  std::size_t next_route_index() {
    const std::size_t wp = src().wp;
    return route_base_ + (wp >= back_steps_ ? wp - back_steps_ : 0);
  }

  void set_source_waypoints(std::size_t from) {
    back_steps_ = 0;
    auto& s = src();
    s.waypoints.clear();
    for (std::size_t i = from; i < route_.size(); ++i)
      s.waypoints.push_back(route_[i].position);
    s.wp = 0;
    route_base_ = from;
  }

  // ---- decentralized: Repair (Tables 4–5) ---------------------------------------------------
  /// Broken segments of `path` as seen in r's map: [first broken point, first good point after).
  std::optional<std::pair<std::uint32_t, std::uint32_t>> find_break(
      Robot& r, const std::vector<VoronoiPoint>& path, std::size_t from) {
    std::optional<std::pair<std::uint32_t, std::uint32_t>> br;
    for (std::size_t i = from; i + 1 < path.size(); ++i) {
      if (segment_blocked(r.map, path[i].position, path[i + 1].position)) {
        if (!br) br = std::pair{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)};
        br->second = static_cast<std::uint32_t>(i + 1);
      }
    }
    r.m.work += path.size();
    return br;
  }

  /// A detour through r's open points joining path[0..from] to path[to..]; empty when none.
  std::vector<VoronoiPoint> detour(Robot& r, const std::vector<VoronoiPoint>& path,
                                   std::uint32_t from, std::uint32_t to) {
    const auto& own = points(r).open;
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
    // Segments that are now blocked must not be used: drop prefix/suffix points whose own
    // move would cross the change by requiring the detour to pass through r's points.
    const auto s = timed(r, [&] { return search_points(comb, start, o_.robot_radius_m); });
    r.m.work += s.work;
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
    // The chain must use at least one own point and its moves must be free in r's map.
    bool uses_own = false;
    for (std::size_t i : chain)
      uses_own |= (i >= n_pre && i < n_own_end);
    if (!uses_own) return {};
    for (std::size_t k = 1; k < chain.size(); ++k)
      if (segment_blocked(r.map, comb[chain[k - 1]].position, comb[chain[k]].position)) return {};
    std::vector<VoronoiPoint> out(path.begin(),
                                  path.begin() + static_cast<std::ptrdiff_t>(chain.front() + 1));
    for (std::size_t k = 1; k < chain.size(); ++k)
      out.push_back(comb[chain[k]]);
    const std::size_t pi = to + (bi - n_own_end);
    out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(pi + 1), path.end());
    return out;
  }

  void check_relay_route(Robot& r) {
    const auto& path = r.saved->whole_path;
    const auto br = find_break(r, path, 0);
    if (!br) return;
    ++res_.metrics.repairs;
    auto fixed = detour(r, path, br->first, br->second);
    if (!fixed.empty()) {
      PathMessage p = *r.saved;
      p.num = kRepairFlag | (++repair_seq_);
      p.whole_path = fixed;
      r.saved->whole_path = fixed;
      if (!p.relays.empty()) send_reliable(r, p.relays.back(), p);
      return;
    }
    RepairMessage m;
    m.source = src().id;
    m.num = (r.id.value << 16) | (++r.repair_counter & 0xFFFFu);
    m.relays = r.saved->relays;
    m.relays.push_back(r.id);
    m.whole_path = path;
    m.broken_from = br->first;
    m.broken_to = br->second;
    r.repairs_seen.insert(m.num);
    broadcast(r, m, 1);
  }

  void on(Robot& r, const Header& h, const RepairMessage& m) {
    if (!r.repairs_seen.insert(m.num).second) return;
    if (m.broken_to >= m.whole_path.size()) return;
    auto fixed = detour(r, m.whole_path, m.broken_from, m.broken_to);
    if (!fixed.empty()) {
      PathMessage p;
      p.source = m.source;
      p.num = kRepairFlag | (++repair_seq_);
      p.relays = m.relays;
      p.whole_path = fixed;
      if (is_source(r)) {
        on_repair_path(r, p);
      } else {
        send_reliable(r, h.sender, p);
      }
      return;
    }
    if (h.hops < o_.repair_hops) broadcast(r, m, static_cast<std::uint8_t>(h.hops + 1));  // relay
  }

  void on_repair_path(Robot& r, PathMessage m) {
    if (is_source(r)) {
      splice_route(m.whole_path);
      return;
    }
    if (!m.relays.empty() && m.relays.back() == r.id) m.relays.pop_back();
    if (r.saved) r.saved->whole_path = m.whole_path;
    if (!m.relays.empty()) send_reliable(r, m.relays.back(), m);
  }

  void splice_route(const std::vector<VoronoiPoint>& whole) {
    if (whole.empty() || route_.empty()) return;
    auto& s = src();
    const std::size_t done = next_route_index();
    for (std::size_t i = route_.size(); i-- > 0;) {
      if (distance(route_[i].position, whole.front().position) < 1e-3) {
        if (i + 1 < done) break;  // already passed: the splice point is behind the source
        std::vector<VoronoiPoint> n(route_.begin(),
                                    route_.begin() + static_cast<std::ptrdiff_t>(i));
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

  void check_source_route() {
    auto& s = src();
    if (route_.empty()) return;
    // Only the part within sensing range matters; find_break checks the remaining route.
    std::vector<VoronoiPoint> rest{VoronoiPoint{s.pos, 1.0f, 0.0f}};
    const std::size_t next = next_route_index();
    rest.insert(rest.end(),
                route_.begin() + static_cast<std::ptrdiff_t>(std::min(next, route_.size())),
                route_.end());
    const auto br = find_break(s, rest, 0);
    if (!br) return;
    if (blocked_since_ < 0.0) blocked_since_ = now_;
    ++res_.metrics.repairs;
    auto fixed = detour(s, rest, br->first, br->second);
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
    broadcast(s, m, 1);
  }

  // ---- centralized baseline -----------------------------------------------------------------
  void start_request() {
    auto& s = src();
    ++res_.metrics.search_attempts;
    const std::uint32_t num = ++search_num_;
    s.req_num = num;
    collecting_ = true;
    last_ack_ = now_;
    broadcast(s, RequestMessage{s.id, num}, 0);
  }

  void on(Robot& r, const Header& h, const RequestMessage& m) {
    if (is_source(r) || m.source.value != sc_.source) return;
    if (r.req_num != kNone && m.num <= r.req_num) return;
    r.req_num = m.num;
    r.parent = h.sender;
    if (h.hops + 1 < o_.hop_limit) broadcast(r, m, static_cast<std::uint8_t>(h.hops + 1));
    r.m.work += r.map.grid().size();  // serialising the map
    send_reliable(r, r.parent, AckMessage{m.source, m.num, r.id, r.map.grid()});
  }

  void on(Robot& r, const Header&, const AckMessage& m) {
    if (!is_source(r)) {
      if (r.parent != kBroadcast) send_reliable(r, r.parent, m);  // relay toward the source
      return;
    }
    // Merge the received local map into the source's map.
    const auto& g = m.local_map.geometry();
    const auto off = sc_.world.geometry().world_to_cell(g.cell_center(Cell{0, 0}));
    if (!off) return;
    timed(r, [&] {
      for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
          const std::int8_t v = m.local_map[Cell{x, y}];
          const Cell w = *off + Cell{x, y};
          if (v != kUnknown && sc_.world.contains(w) && r.map.at(w) != v) r.map.set(w, v);
        }
      return 0;
    });
    r.m.work += m.local_map.size();
    last_ack_ = now_;
  }

  void on(Robot& r, const Header&, const NotifyMessage& m) {
    if (!is_source(r)) {
      if (r.parent != kBroadcast) send_reliable(r, r.parent, m);
      return;
    }
    ++res_.metrics.repairs;
    if (!collecting_) start_request();
  }

  void on(Robot&, const Header&, const LinkAckMessage&) {}

  void plan_central() {
    auto& s = src();
    const auto& wg = sc_.world.geometry();
    const auto a = wg.world_to_cell(s.pos), b = wg.world_to_cell(sc_.destination);
    ++res_.metrics.replans;
    const auto result = timed(s, [&] {
      BinaryGrid bin = binarize(s.map.grid(), BinarizeOptions{.unknown_is_blocked = false});
      BinaryGrid pg = planning::make_planning_grid(bin, o_.robot_radius_m);
      const Cell la = *a - s.map.offset(), lb = *b - s.map.offset();
      pg[la] = 0;
      pg[lb] = 0;
      planning::AStarPlanner planner;
      auto r = planner.plan(pg, la, lb);
      for (auto& c : r.path)
        c = c + s.map.offset();
      return r;
    });
    s.m.work += s.map.grid().size() * 3 + result.expanded;
    if (!result.ok()) {
      s.waypoints.clear();
      return;
    }
    s.waypoints.clear();
    for (std::size_t i = 1; i < result.path.size(); ++i)
      s.waypoints.push_back(wg.cell_center(result.path[i]));
    s.waypoints.push_back(sc_.destination);
    s.wp = 0;
    if (first_route_ < 0.0) {
      first_route_ = now_;
      res_.metrics.route_time_s = now_;
      res_.metrics.route_length_m = path_len(s.pos, s.waypoints);
    }
  }
  static double path_len(Vec2 from, const std::vector<Vec2>& w) {
    double l = 0.0;
    for (Vec2 p : w) {
      l += distance(from, p);
      from = p;
    }
    return l;
  }

  void check_central_path(Robot& s) {
    if (collecting_ || s.waypoints.empty()) return;
    for (std::size_t i = s.wp; i < s.waypoints.size(); ++i) {
      if (distance(s.waypoints[i], s.pos) > o_.sensing_range_m + 0.5) break;
      const Vec2 from = i == s.wp ? s.pos : s.waypoints[i - 1];
      if (segment_blocked(s.map, from, s.waypoints[i])) {
        plan_central();
        return;
      }
    }
  }

  const NetSimScenario& sc_;
  NetSimOptions o_;
  SimRadio radio_;
  BinaryGrid truth_;
  std::vector<Robot> robots_;
  std::vector<Outgoing> outbox_;
  NetSimResult res_;
  double now_ = 0.0;
  bool arrived_ = false;
  bool last_sense_changed_ = false;
  double first_route_ = -1.0;
  std::size_t next_change_ = 0;
  std::uint32_t search_num_ = 0;
  double search_started_ = 0.0;
  std::uint8_t search_hops_ = 0;
  std::vector<VoronoiPoint> route_;
  std::size_t route_base_ = 0;
  std::vector<Vec2> trail_;     // source positions since its latest Search
  std::size_t back_steps_ = 0;  // waypoints of the way back along the trail
  double blocked_since_ = -1.0;
  std::uint32_t repair_seq_ = 0;
  bool collecting_ = false;
  double last_ack_ = 0.0;
};

}  // namespace

NetSimResult run_netsim(const NetSimScenario& scenario, const NetSimOptions& options) {
  scenario.validate();
  options.validate();
  Runner runner(scenario, options);
  return runner.run();
}

}  // namespace voronav::sim
