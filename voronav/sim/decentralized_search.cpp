// The decentralized method of seed 000, Tables 1–2: the source starts a Search (Num, its open
// points, the destination, Relay Robots) and waits for Path answers; a relay continues the Search
// through its open Voronoi points, or, when a gap in sensed space stops the chain, goes and senses
// it on the source's behalf (figure 18). One hand-off rule decides who walks (hands_off_to), used
// by the sender and the receiver alike, so the Search cannot stop where neither moves
// (docs/reproductions/networked.md, "Hand-off").
#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>

#include "voronav/core/error.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/sim/agent_internal.hpp"
#include "voronav/sim/robot_agent.hpp"

namespace voronav::sim {

using namespace network;
using namespace agent_detail;

namespace {

/// The hand-off margin [m]: a neighbour takes the Search on when it is this much closer to the
/// destination than the nearest point the sender sent.
constexpr double kHandOffM = 1.0;

/// A sensing walk that made fewer cells known free than this sends no Search (cells).
constexpr std::size_t kOpenedCells = 25;

/// A copy of a Search is new when it lowers a cost by more than this [m] (the re-forward test
/// below uses the same margin).
constexpr double kCopyImproveM = 1e-6;

double nearest_to(const std::vector<VoronoiPoint>& pts, Vec2 dest) {
  double d = kInf;
  for (const auto& p : pts)
    d = std::min(d, distance(p.position, dest));
  return d;
}

bool contains(const std::vector<RobotId>& v, RobotId id) {
  return std::find(v.begin(), v.end(), id) != v.end();
}

}  // namespace

/// The source's start point (its position) as the Search's only "sender point".
static VoronoiPoint start_point(const LocalMap& map, Vec2 pos, double radius) {
  const double cl = clearance_at(map.grid(), pos);
  return VoronoiPoint{pos, static_cast<float>(std::max(cl, radius + 0.05)), 0.0f};
}

// ---- Table 1: the source ----------------------------------------------------------------------
void RobotAgent::start_search() {
  auto& s = r_;
  ++report_.search_attempts;
  // Retry timeout: fixed, or longer the farther the destination.
  search_deadline_ =
      now_ + std::max(opt().search_timeout_s,
                      opt().search_timeout_per_m * distance(s.pos, scen().destination));
  trail_ = {s.pos};
  const std::uint32_t num = ++search_num_;
  NS_DEBUG("t=%.1f source starts search %u at (%.1f,%.1f)\n", now_, num, s.pos.x, s.pos.y);
  SearchMessage pseudo;
  pseudo.source = s.id;
  pseudo.num = num;
  pseudo.destination = scen().destination;
  pseudo.open_points = {start_point(s.map, s.pos, opt().robot_radius_m)};
  s.got_paths.clear();
  s.path_deadline = -1.0;
  s.path_forwarded = false;
  process_search(s.id, pseudo, 0);
}

/// No route by the deadline: the same search goes on (same Num, nothing is reset). The source
/// sends its Search again from where it stands, so robots that could not continue it reconsider
/// the hand-off; with source_walks_on_retry it also walks toward the destination itself (as the
/// centralized source does) while it keeps waiting for Path answers.
void RobotAgent::retry_search() {
  auto& s = r_;
  NS_DEBUG("t=%.1f source retries search at (%.1f,%.1f)\n", now_, s.pos.x, s.pos.y);
  ++report_.search_attempts;
  search_deadline_ =
      now_ + std::max(opt().search_timeout_s,
                      opt().search_timeout_per_m * distance(s.pos, scen().destination));
  s.s_in.open_points = {start_point(s.map, s.pos, opt().robot_radius_m)};
  s.s_senders = {{s.id, s.pos, {}, 0, 1}};
  s.s_done = false;
  if (try_continue()) after_continue(0);
}

/// Whether the source's own map holds a way from where it stands to the destination (the search
/// state of the Search it sent is kept when not).
bool RobotAgent::source_sees_way() {
  auto& r = r_;
  const auto keep_in = r.s_in;
  const auto keep_senders = r.s_senders;
  const auto keep_comb = r.s_comb;
  const auto keep_search = r.s_search;
  const auto keep_na = r.s_na;
  const auto keep_sent = r.s_sent;
  r.s_in.open_points = {start_point(r.map, r.pos, opt().robot_radius_m)};
  r.s_senders = {{r.id, r.pos, {}, 0, 1}};
  if (try_continue() && dest_reached()) return true;
  r.s_in = keep_in;
  r.s_senders = keep_senders;
  r.s_comb = keep_comb;
  r.s_search = keep_search;
  r.s_na = keep_na;
  r.s_sent = keep_sent;
  return false;
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
  // The robot's walk for this search: driven, so each step to the next is free.
  const std::size_t trail_begin = r.s_comb.size();
  for (Vec2 p : r.walk_trail)
    r.s_comb.push_back(start_point(r.map, p, opt().robot_radius_m));
  const std::size_t own_end = r.s_comb.size();
  const double dcl = clearance_at(r.map.grid(), dest);
  const bool has_dest = dcl > opt().robot_radius_m;
  if (has_dest) r.s_comb.push_back(VoronoiPoint{dest, static_cast<float>(dcl), 0.0f});
  std::vector<double> start(r.s_comb.size(), kInf);
  for (std::size_t i = 0; i < r.s_na; ++i)
    start[i] = r.s_comb[i].cost;
  // Within its own map a robot may also move straight between its own points when the move is
  // known free (it checks the cells itself; at most 6 m apart to bound the work).
  // The source's start point (its position) is in its own map too (source_straight_start).
  const std::size_t own_begin = is_source() && opt().source_straight_start ? 0 : r.s_na;
  std::size_t los_cells = 0;
  // Which pairs own_edge checks in the map: 0 = none (false), 1 = consecutive trail points
  // (true), 2 = a straight move to check.
  auto own_kind = [&](std::size_t i, std::size_t j) {
    if (i < own_begin || j < own_begin || i >= own_end || j >= own_end) return 0;
    if (i < r.s_na && j < r.s_na) return 0;
    if (i >= trail_begin && j >= trail_begin && (i + 1 == j || j + 1 == i)) return 1;
    const Vec2 a = r.s_comb[i].position, b = r.s_comb[j].position;
    if ((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) > 36.0) return 0;  // > 6 m
    return 2;
  };
  auto own_edge = [&](std::size_t i, std::size_t j) {
    const int kind = own_kind(i, j);
    if (kind != 2) return kind == 1;
    const Vec2 a = r.s_comb[i].position, b = r.s_comb[j].position;
    return r.own_moves.get(r.map.version(), a, b, [&] { return segment_known_free(a, b); });
  };
  // The work of a check counts every move the search asks about (eq. 8-9), also those whose
  // answer cannot change a cost, which the search then does not check (on_asked).
  auto own_asked = [&](std::size_t i, std::size_t j) {
    if (own_kind(i, j) != 2) return;
    los_cells += static_cast<std::size_t>(distance(r.s_comb[i].position, r.s_comb[j].position) /
                                          scen().world.resolution()) +
                 1;
  };
  // The same search on a grid of the points (identical result and work count): own_edge is
  // false outside [own_begin, own_end) and beyond 6 m, except between consecutive trail points.
  BoundedExtraEdges extra{own_edge, own_asked, 6.0, own_begin, own_end, {}};
  for (std::size_t i = trail_begin; i + 1 < own_end; ++i)
    extra.unbounded_pairs.emplace_back(i, i + 1);
  r.s_search =
      timed([&] { return search_points_bucketed(r.s_comb, start, opt().robot_radius_m, extra); });
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
  // Table 1 / 2: the Search carries the open points that continue the sender's (those the search
  // reached), nothing else.
  r.s_sent.clear();
  for (std::size_t i = r.s_na; i < own_end; ++i)
    if (std::isfinite(r.s_search.cost[i])) r.s_sent.push_back(i);
  // What this search was run on (copy_is_new compares).
  r.s_map_version = r.map.version();
  r.s_trail_size = r.walk_trail.size();
  r.s_check.reset();
  ++report_.point_searches;
  return !r.s_sent.empty() || (has_dest && std::isfinite(r.s_search.cost.back()));
}

bool RobotAgent::dest_reached() const {
  const auto& r = r_;
  const Vec2 dest = scen().destination;
  const double dcl = clearance_at(r.map.grid(), dest);
  return dcl > opt().robot_radius_m && r.s_comb.size() > r.s_na &&
         std::isfinite(r.s_search.cost.back()) && r.s_comb.back().position == dest;
}

/// s_comb index of the own reached point at `p` (the exit point a Path answer names), or
/// s_comb.size() when the robot has no such point any more.
std::size_t RobotAgent::own_index_at(Vec2 p) const {
  const auto& r = r_;
  std::size_t best = r.s_comb.size();
  double bd = 0.3;  // a point moves by less than a cell when the map is recomputed
  for (std::size_t i : r.s_sent) {
    const double d = distance(r.s_comb[i].position, p);
    if (d < bd) {
      bd = d;
      best = i;
    }
  }
  return best;
}

// ---- the hand-off rule --------------------------------------------------------------------------
/// The nearest distance to the destination of the points this robot sends on (what receivers
/// compare themselves with).
double RobotAgent::reference_distance() const {
  const auto& r = r_;
  double d = kInf;
  for (std::size_t i : r.s_sent)
    d = std::min(d, distance(r.s_comb[i].position, scen().destination));
  return d;
}

/// The one hand-off rule: a robot at `robot` takes the Search on (walks to sense the gap) when
/// it is kHandOffM closer to the destination than `sender_reference`. The sender applies it to
/// its neighbours' positions with slack 0 (if some neighbour qualifies, the sender does not walk
/// itself); a receiver applies it to its own position with slack 0.5 m (it moved at most that
/// since the sender looked), so a robot the sender counted on always takes the Search on.
bool RobotAgent::hands_off_to(Vec2 robot, double sender_reference, double slack) const {
  return distance(robot, scen().destination) < sender_reference - (kHandOffM - slack);
}

/// A robot that cannot continue a sender's points: if the hand-off rule names it, it waits a
/// little for a Search it can continue, then walks over to sense the gap (figure 18).
void RobotAgent::consider_bridge(const SearchMessage& m) {
  auto& r = r_;
  if (is_source() || r.s_done || r.walk != Walk::kIdle || r.bridge_at >= 0.0) return;
  if (hands_off_to(r.pos, nearest_to(m.open_points, scen().destination), 0.5))
    r.bridge_at = now_ + opt().bridge_wait_s;
  NS_DEBUG("t=%.1f robot %u cannot continue (d %.1f, ref %.1f, bridge %d)\n", now_, r.id.value,
           distance(r.pos, scen().destination), nearest_to(m.open_points, scen().destination),
           r.bridge_at >= 0.0 ? 1 : 0);
}

/// The source walks toward the destination only while no radio neighbour can take its Search
/// on (it is alone, or every neighbour is behind it): each metre it looks again; when the
/// hand-off rule names a neighbour it has not handed the Search to yet, it stops and sends the
/// same Search (same Num) from where it stands, and waits for the relays' Path. Returns true
/// when it stopped (or answered itself, having sensed a way to the destination).
bool RobotAgent::source_walk_check() {
  auto& s = r_;
  s.s_in.open_points = {start_point(s.map, s.pos, opt().robot_radius_m)};
  s.s_senders = {{s.id, s.pos, {}, 0, 1}};
  if (!try_continue()) return false;
  if (dest_reached()) {
    s.walk = Walk::kIdle;
    s.waypoints.clear();
    answer_path();
    return true;
  }
  const double ref = reference_distance();
  for (const auto& n : transport_.nearby(s.id)) {
    if (n.id == s.id || contains(handed_to_, n.id) || !hands_off_to(n.position, ref, 0.0)) continue;
    NS_DEBUG("t=%.1f source stops at (%.1f,%.1f): robot %u takes the search on\n", now_, s.pos.x,
             s.pos.y, n.id.value);
    for (const auto& m : transport_.nearby(s.id))
      if (hands_off_to(m.position, ref, 0.0)) handed_to_.push_back(m.id);
    s.walk = Walk::kIdle;
    s.waypoints.clear();
    s.wp = 0;
    s.s_done = true;
    forward_search(0);
    return true;
  }
  return false;
}

// ---- figure 18, the boxed-in source ------------------------------------------------------------
/// The source's route is blocked, no Repair answer it could take came and its own map holds no
/// way back to the route (timers): a new Search at once would be answered from the relays' maps,
/// which still hold the closed doors open (s2 runs 10 and 14: every answer was blocked at once).
/// Figure 18: a robot goes and senses the gap on the source's behalf. The gap is where the
/// source's own way to the destination leaves its known space: the first move of its walk planned
/// on its map (unknown = free, seen walls and closures blocked) that is not known free. No robot
/// in radio range can be told to go there (the messages of Tables 1-5 carry no such request), so
/// the source goes itself, as the "or the source itself when no one can"; on the way it
/// answers itself when its map shows a way, and where it reaches the gap it sends a new Search,
/// whose open points now reach across the gap (docs/reproductions/networked.md, "Sensing walk").
/// Returns false (nothing started) when the option is off or its map holds no way at all.
bool RobotAgent::start_sensing_walk() {
  auto& s = r_;
  if (!opt().sense_when_boxed_in) return false;
  // Dijkstra over the cells the source knows are free (unknown counts as blocked, inflated by
  // the robot radius, so it never drives into unseen space: a wall cell hidden behind the cell
  // it sees is unknown too). A gap is a reachable cell with an unknown 4-neighbour; it goes to
  // the one with the least way there plus straight distance on to the destination.
  const OccupancyGrid& g = s.map.grid();
  const Cell off = s.map.offset();
  const auto& wg = scen().world.geometry();
  const auto here = wg.world_to_cell(s.pos);
  if (!here || g.width() == 0) return false;
  const Cell start = *here - off;
  if (!g.contains(start)) return false;
  BinaryGrid blocked(g.geometry(), 0);
  for (std::size_t i = 0; i < g.size(); ++i)
    blocked[i] = g[i] == kFree ? 0 : 1;
  BinaryGrid pg =
      timed([&] { return planning::make_planning_grid(blocked, opt().robot_radius_m); });
  pg[start] = 0;
  const int w = g.width();
  std::vector<double> dist(g.size(), kInf);
  std::vector<std::int32_t> parent(g.size(), -1);
  using Item = std::pair<double, std::int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  // An unknown cell next to a seen wall cell is most likely wall hidden behind it (sense() sees
  // along Bresenham lines): a gap opens onto unknown cells away from seen walls.
  const auto next_to_wall = [&g](Cell n) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell m{n.x + dx, n.y + dy};
        if (g.contains(m) && g[m] == kOccupied) return true;
      }
    return false;
  };
  const auto idx = [w](Cell c) { return static_cast<std::int32_t>(c.y * w + c.x); };
  dist[static_cast<std::size_t>(idx(start))] = 0.0;
  open.push({0.0, idx(start)});
  const double res = g.resolution();
  const Vec2 dest = scen().destination;
  double best = kInf;
  std::int32_t best_i = -1;
  std::size_t expanded = 0;
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[static_cast<std::size_t>(i)]) continue;
    ++expanded;
    const Cell c{i % w, i / w};
    bool gap = false;
    for (Cell n : {Cell{c.x + 1, c.y}, Cell{c.x - 1, c.y}, Cell{c.x, c.y + 1}, Cell{c.x, c.y - 1}})
      if (!g.contains(n) || (g[n] == kUnknown && !next_to_wall(n))) gap = true;
    if (gap && i != idx(start)) {
      const double score = d + distance(wg.cell_center(c + off), dest);
      if (score < best) {
        best = score;
        best_i = i;
      }
    }
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell n{c.x + dx, c.y + dy};
        if ((dx == 0 && dy == 0) || !g.contains(n) || pg[n] != 0) continue;
        if (dx != 0 && dy != 0 && (pg[Cell{c.x + dx, c.y}] != 0 || pg[Cell{c.x, c.y + dy}] != 0))
          continue;  // no corner cutting
        const double nd = d + res * ((dx != 0 && dy != 0) ? std::sqrt(2.0) : 1.0);
        if (nd < dist[static_cast<std::size_t>(idx(n))]) {
          dist[static_cast<std::size_t>(idx(n))] = nd;
          parent[static_cast<std::size_t>(idx(n))] = i;
          open.push({nd, idx(n)});
        }
      }
  }
  report_.metrics.work += g.size() * 2 + expanded;
  if (best_i < 0) return false;  // no gap left in its known space
  std::vector<Vec2> way;
  for (std::int32_t i = best_i; i >= 0 && i != idx(start); i = parent[static_cast<std::size_t>(i)])
    way.push_back(wg.cell_center(Cell{i % w, i / w} + off));
  std::reverse(way.begin(), way.end());
  s.waypoints = std::move(way);
  s.wp = 0;
  map_before_walk_ = s.map;
  boxed_in_ = true;
  s.walk = Walk::kSense;
  s.walk_since_check = 0.0;
  s.walk_map_changed = false;
  search_deadline_ = kInf;  // no Search retry while it walks: it searches again at the gap
  ++report_.sensing_walks;
  NS_DEBUG("t=%.1f source boxed in at (%.1f,%.1f): senses the gap at (%.1f,%.1f)\n", now_, s.pos.x,
           s.pos.y, s.waypoints.back().x, s.waypoints.back().y);
  return true;
}

/// The sensing walk, every metre its map changed and at its end: when the source's own map now
/// holds a way to the destination it answers itself; where the walk ends (at the gap, or where
/// no way on is left) it sends a new Search from there.
void RobotAgent::sensing_walk_progress(bool arrived) {
  auto& r = r_;
  if (source_sees_way()) {
    end_sensing_walk();
    trail_ = {r.pos};
    r.walk = Walk::kIdle;
    r.waypoints.clear();
    answer_path();
    return;
  }
  if (!arrived) return;
  const std::size_t opened = end_sensing_walk();
  NS_DEBUG("t=%.1f source sensed the gap at (%.1f,%.1f): %zu cells found free\n", now_, r.pos.x,
           r.pos.y, opened);
  r.walk = Walk::kIdle;
  r.waypoints.clear();
  // The gap showed (almost) only wall: the next gap at once; a Search only where the walk found
  // new free space (kOpenedCells, 1 m^2 at 0.2 m cells), which its open points now reach into.
  if (opened < kOpenedCells && start_sensing_walk()) return;
  start_search();
  // It waits for an answer as long as for a Repair answer, then senses the next gap (timers).
  search_deadline_ = now_ + opt().repair_timeout_s;
}

/// Marks the world cells the walk made known (unknown when it started, known now).
std::size_t RobotAgent::end_sensing_walk() {
  std::size_t opened = 0;
  if (!map_before_walk_) return opened;
  const auto& m = r_.map;
  if (sensed_by_walks_.size() == 0) sensed_by_walks_ = BinaryGrid(scen().world.geometry(), 0);
  for (int y = 0; y < m.grid().height(); ++y)
    for (int x = 0; x < m.grid().width(); ++x) {
      const Cell c = Cell{x, y} + m.offset();
      if (m.grid()[Cell{x, y}] != kUnknown && map_before_walk_->at(c) == kUnknown &&
          sensed_by_walks_.geometry().contains(c)) {
        sensed_by_walks_[c] = 1;
        if (m.grid()[Cell{x, y}] == kFree) ++opened;
      }
    }
  map_before_walk_.reset();
  return opened;
}

/// At arrival: the route the source drove used what its sensing walks sensed when one of its
/// points past the first (the source's own start) lies on a cell a walk made known.
void RobotAgent::note_route_used_sensing() {
  if (sensed_by_walks_.size() == 0) return;
  const auto& g = sensed_by_walks_.geometry();
  for (std::size_t i = 1; i < route_.size(); ++i) {
    const auto c = g.world_to_cell(route_[i].position);
    if (c && sensed_by_walks_[*c]) report_.route_used_sensing = true;
  }
}

// ---- Table 2: a relay -------------------------------------------------------------------------
void RobotAgent::on(const Header& h, const SearchMessage& m) {
  auto& r = r_;
  if (is_source() && m.source == r.id && m.num == search_num_ && opt().search_activity_s > 0.0)
    // A neighbour (re-)forwards the current Search: it is still spreading, wait for it.
    search_deadline_ = std::max(search_deadline_, now_ + opt().search_activity_s);
  if (is_source() || m.source != source_id()) return;
  if (r.s_num != kNone && m.num < r.s_num) return;  // an older search
  // Loop guard: a Search that already went through this robot is not taken again (its Path
  // would come back to it).
  if (contains(m.relays, r.id)) return;
  if (r.s_num != m.num) {
    process_search(h.sender, m, h.hops);
    return;
  }
  // The same search from another robot (or the source's retry).
  if (r.walk == Walk::kDestination || r.path_forwarded || (r.saved && r.saved->num == m.num))
    return;
  if (r.s_done && !copy_is_new(m)) {
    // Table 2 line 4, "IF (Receive New Search Message)": a copy of a Search this relay already
    // forwarded that lowers none of its costs is not new. Ignored: no search, no forward, its
    // points are not kept (docs/reproductions/networked.md, "Table 2: which copy is new").
    ++report_.search_copies_ignored;
    return;
  }
  const Vec2 spos = neighbour_position(h.sender).value_or(r.pos);
  r.s_senders.push_back(
      {h.sender, spos, m.relays, r.s_in.open_points.size(), m.open_points.size()});
  r.s_in.open_points.insert(r.s_in.open_points.end(), m.open_points.begin(), m.open_points.end());
  if (r.s_done) {
    // Already forwarded and the copy is new: re-forward when the costs improve (distributed
    // shortest path), at most 3 times.
    std::vector<std::pair<Vec2, double>> before;
    for (std::size_t i : r.s_sent)
      before.emplace_back(r.s_comb[i].position, r.s_search.cost[i]);
    if (!try_continue() || r.reforwards >= 3) return;
    bool better = r.s_sent.size() > before.size();
    for (std::size_t i : r.s_sent)
      for (const auto& [p, c] : before)
        if (p == r.s_comb[i].position && r.s_search.cost[i] < c - kCopyImproveM) better = true;
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
    return;
  }
  if (r.walk == Walk::kIdle) consider_bridge(m);
}

/// Table 2's "New Search Message" for a copy of the Search this relay already forwarded: new when
/// its points would lower the cost of one of the relay's own points, its trail or the
/// destination (or reach one its search had not reached), checked without running the search
/// (network::search_would_improve). When the robot's map, its trail or the points it holds
/// changed since its last search, that search no longer says what its costs are: the copy is
/// then handled as new (searched again), as before.
bool RobotAgent::copy_is_new(const SearchMessage& m) {
  auto& r = r_;
  if (r.points_dirty || r.s_map_version != r.map.version() ||
      r.s_trail_size != r.walk_trail.size() || r.s_na != r.s_in.open_points.size() ||
      r.s_search.cost.size() != r.s_comb.size())
    return true;
  std::vector<double> start(m.open_points.size());
  for (std::size_t i = 0; i < start.size(); ++i)
    start[i] = m.open_points[i].cost;
  const auto chk = timed([&] {
    if (!r.s_check) r.s_check.emplace(r.s_comb, r.s_search, opt().robot_radius_m, r.s_na);
    return r.s_check->improves(m.open_points, start, kCopyImproveM);
  });
  report_.metrics.work += chk.work;
  return chk.improves;
}

void RobotAgent::process_search(RobotId sender, const SearchMessage& m, std::uint8_t hops) {
  auto& r = r_;
  r.s_num = m.num;
  r.s_done = false;
  r.s_in = m;
  const Vec2 spos = sender == r.id ? r.pos : neighbour_position(sender).value_or(r.pos);
  if (r.walk != Walk::kBridge) r.walk_trail.clear();
  r.s_senders = {{sender, spos, m.relays, 0, m.open_points.size()}};
  r.reforwards = 0;
  // A robot walking to the destination stays committed; one bridging a gap may keep walking
  // (the new Search's points are tried as it senses, walk_progress).
  const bool bridging = r.walk == Walk::kBridge && opt().keep_bridge_on_new_search;
  if (r.walk != Walk::kDestination && !bridging && r.walk != Walk::kBack) r.walk = Walk::kIdle;
  r.bridge_at = -1.0;
  r.got_paths.clear();
  r.path_deadline = -1.0;
  r.path_forwarded = false;
  r.s_hops = hops;
  if (try_continue()) {
    after_continue(hops);
    return;
  }
  if (bridging) return;
  consider_bridge(m);
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
    r.walk_trail = {r.pos};
    NS_DEBUG("t=%.1f robot %u bridges to (%.1f,%.1f)\n", now_, r.id.value, near.x, near.y);
    r.walk = Walk::kBridge;
    r.walk_since_check = 0.0;
  }
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
  // Walk toward the destination and sense it on the source's behalf (figure 18) when the
  // hand-off rule names no radio neighbour (this robot is the frontier); otherwise forward.
  const double ref = reference_distance();
  bool frontier = true;
  for (const auto& n : transport_.nearby(r.id))
    if (n.id != source_id() && hands_off_to(n.position, ref, 0.0)) {
      frontier = false;
      if (is_source() && !contains(handed_to_, n.id)) handed_to_.push_back(n.id);
    }
  // The source also walks toward the destination itself from its second attempt on (as the
  // centralized source does), while it keeps waiting for answers.
  const bool source_walks =
      is_source() && opt().source_walks_on_retry && report_.search_attempts >= 2;
  if (frontier || source_walks || r.walk == Walk::kDestination) {
    bool walking = r.walk == Walk::kDestination;
    if (!walking && plan_walk(scen().destination)) {
      if (!is_source() && r.walk_trail.empty()) r.walk_trail = {r.pos};
      NS_DEBUG("t=%.1f robot %u walks to the destination (frontier %d)\n", now_, r.id.value,
               frontier ? 1 : 0);
      r.walk = Walk::kDestination;
      r.walk_since_check = 0.0;
      walking = true;
    }
    if (walking && !is_source()) return;
  }
  if (!is_source() || r.walk != Walk::kDestination) {
    r.walk = Walk::kIdle;
    r.waypoints.clear();
  }
  r.s_done = true;
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
    p.cost = static_cast<float>(c);
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
  NS_DEBUG("t=%.1f robot %u forwards search %u (%zu points, ref %.1f)\n", now_, r.id.value, out.num,
           out.open_points.size(), reference_distance());
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
  if (r.walk == Walk::kSense) {
    sensing_walk_progress(arrived);
    return;
  }
  if (r.walk == Walk::kRepair) {
    repair_walk_progress(arrived);
    return;
  }
  if (r.walk == Walk::kBack) {
    if (arrived) r.walk = Walk::kIdle;
    return;
  }
  if (r.s_done) {
    if (arrived) r.walk = Walk::kIdle;
    return;
  }
  if (is_source()) {
    // Is the destination reachable from where the source stands now?
    if (source_sees_way()) {
      trail_ = {r.pos};
      r.walk = Walk::kIdle;
      r.waypoints.clear();
      answer_path();
      return;
    }
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
      r.walk = Walk::kIdle;  // may take the Search on again for another sender
    }
  } else if (r.walk == Walk::kDestination) {
    if (cont && dest_reached()) {
      r.walk = Walk::kIdle;
      r.waypoints.clear();
      r.s_done = true;
      answer_path();
    } else if (arrived) {
      NS_DEBUG("t=%.1f robot %u arrived without a way (cont %d, d %.1f, dcl %.2f)\n", now_,
               r.id.value, cont ? 1 : 0, distance(r.pos, scen().destination),
               clearance_at(r.map.grid(), scen().destination));
      r.walk = Walk::kIdle;
      r.s_done = true;
    }
  }
}

/// The chain of s_comb indices ending at `last`: the sender's exit point followed by the robot's
/// own piece (Path messages carry the exit point first, so the receiver finds where the answer
/// joins its points by position).
RobotAgent::Piece RobotAgent::own_piece(std::size_t last) const {
  const auto& r = r_;
  const auto chain = trace_points(r.s_search, last);
  std::size_t exit = chain.front();
  std::vector<VoronoiPoint> piece;
  for (std::size_t i : chain) {
    if (i < r.s_na) {
      exit = i;
      piece.clear();
    }
    VoronoiPoint p = r.s_comb[i];
    p.cost = 0.0f;
    piece.push_back(p);
  }
  const std::size_t k = sender_of(exit);
  return {k, static_cast<std::uint32_t>(exit - r.s_senders[k].offset), piece};
}

void RobotAgent::answer_path() {
  auto& r = r_;
  NS_DEBUG("t=%.1f robot %u answers\n", now_, r.id.value);
  auto pc = own_piece(r.s_comb.size() - 1);
  PathMessage p;
  p.source = r.s_in.source;
  p.num = r.s_in.num;
  p.relays = r.s_senders[pc.sender].relays;
  p.whole_path = pc.points;
  p.exit_index = pc.exit;
  p.owners.assign(p.whole_path.size(), r.id);
  p.owners.front() = r.s_senders[pc.sender].id;  // the exit point is the sender's
  if (is_source()) {
    finish_route(p, true);
    return;
  }
  r.saved = p;
  r.saved_cost = r.s_search.cost.back();
  deliver_path(p, r.s_senders[pc.sender].id, r.s_senders[pc.sender].pos, false);
}

}  // namespace voronav::sim
