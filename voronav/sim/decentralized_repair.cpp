// The decentralized method of seed 000, Tables 4–5: a robot that finds the saved path broken
// repairs it locally (own detour) or asks its neighbours with a Repair message.
#include "voronav/sim/robot_agent.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/sim/agent_internal.hpp"

namespace voronav::sim {

using namespace network;
using namespace agent_detail;

namespace {

/// The centres of `cells` in the frame of `g`, sorted by row then column, each once (what a
/// Repair carries in `blocked`).
std::vector<Vec2> sorted_centres(std::vector<Cell> cells, const GridGeometry& g) {
  std::sort(cells.begin(), cells.end(),
            [](Cell a, Cell b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::vector<Vec2> out;
  out.reserve(cells.size());
  for (Cell c : cells)
    out.push_back(g.cell_center(c));
  return out;
}

}  // namespace

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

/// With repair_rejoin_m > 0: the end of the break `br` of `path` moved past every route point
/// closer than repair_rejoin_m to a cell that blocks one of the broken moves (an occupied cell
/// within the robot radius of it, in this robot's map). The robot sees only the front of a new
/// obstacle, so the first route point after the blocked move can lie inside it (its cell still
/// unknown) or right beside it, and a detour that re-joins there runs into the obstacle again
/// (s1r6, docs/reproductions/networked.md, fourth pass). The last point (the destination) stays.
std::uint32_t RobotAgent::rejoin_past_block(const std::vector<VoronoiPoint>& path,
                                            std::pair<std::uint32_t, std::uint32_t> br) {
  std::uint32_t to = br.second;
  const double margin = opt().repair_rejoin_m;
  if (margin <= 0.0) return to;
  const auto& g = r_.map.world();
  const double rad = opt().robot_radius_m / g.resolution - 0.01;
  std::vector<Vec2> block;
  for (std::uint32_t i = br.first; i < br.second && i + 1 < path.size(); ++i) {
    const auto a = g.world_to_cell(path[i].position), b = g.world_to_cell(path[i + 1].position);
    if (!a || !b) continue;
    for_each_line_cell(*a, *b, [&](Cell c) {
      for_each_disc_cell(c, rad, [&](Cell d) {
        if (r_.map.at(d) == kOccupied) block.push_back(g.cell_center(d));
        return true;
      });
      return true;
    });
  }
  report_.metrics.work += block.size();
  auto near_block = [&](Vec2 p) {
    return std::any_of(block.begin(), block.end(), [&](Vec2 q) { return distance(p, q) < margin; });
  };
  while (to + 1 < path.size() && near_block(path[to].position))
    ++to;
  return to;
}

/// The centres of the cells this robot knows occupied within the robot radius of the broken
/// moves `br` of `path` (each once): what a Repair tells the others of the change
/// (repair_share_blocks) and where the source checks answers (repair_check_seen).
std::vector<Vec2> RobotAgent::blocking_cells(const std::vector<VoronoiPoint>& path,
                                             std::pair<std::uint32_t, std::uint32_t> br) {
  const auto& g = r_.map.world();
  const double rad = opt().robot_radius_m / g.resolution - 0.01;
  std::vector<Cell> cells;
  for (std::uint32_t i = br.first; i < br.second && i + 1 < path.size(); ++i) {
    const auto a = g.world_to_cell(path[i].position), b = g.world_to_cell(path[i + 1].position);
    if (!a || !b) continue;
    for_each_line_cell(*a, *b, [&](Cell c) {
      for_each_disc_cell(c, rad, [&](Cell d) {
        if (r_.map.at(d) == kOccupied) cells.push_back(d);
        return true;
      });
      return true;
    });
  }
  report_.metrics.work += cells.size();
  return sorted_centres(std::move(cells), g);
}

/// repair_share_changed: `cells` (blocking_cells of a break) with every cell this robot knows
/// occupied inside the free disc of a point of `path` (the clearance its maker sensed, before
/// shrink_to_map): the part of the change those robots saw free, e.g. the whole closed door and
/// not only its cells beside the broken move. Sorted, each once.
std::vector<Vec2> RobotAgent::changed_cells(const std::vector<VoronoiPoint>& path,
                                            std::vector<Vec2> cells) {
  if (!opt().repair_share_changed) return cells;
  return occupied_in_discs(path, std::move(cells));
}

/// `cells` with every cell this robot knows occupied inside the free disc of a point of `path`
/// (the clearance its maker sensed): where this robot's map contradicts the makers' maps, i.e.
/// the changes they have not seen. Sorted, each once.
std::vector<Vec2> RobotAgent::occupied_in_discs(const std::vector<VoronoiPoint>& path,
                                                std::vector<Vec2> cells) {
  const auto& g = r_.map.world();
  std::vector<Cell> out;
  for (Vec2 q : cells)
    if (const auto c = g.world_to_cell(q)) out.push_back(*c);
  for (const auto& p : path) {
    const auto c = g.world_to_cell(p.position);
    if (!c || !(p.clearance > 0.0f)) continue;
    const double rad = p.clearance / g.resolution;
    for_each_disc_cell(*c, rad, [&](Cell d) {
      if (r_.map.at(d) == kOccupied) out.push_back(d);
      return true;
    });
    report_.metrics.work += static_cast<std::uint64_t>(std::ceil(3.2 * rad * rad)) + 1;
  }
  return sorted_centres(std::move(out), g);
}

/// Marks the cells a Repair says are blocked occupied in this robot's map (repair_share_blocks):
/// what its sender sensed, so this robot's points and detours no longer pass through them.
void RobotAgent::learn_blocks(const std::vector<Vec2>& blocked) {
  const auto& g = r_.map.world();
  bool changed = false;
  for (Vec2 p : blocked) {
    const auto c = g.world_to_cell(p);
    if (!c || !g.contains(*c) || r_.map.at(*c) == kOccupied) continue;
    r_.map.set(*c, kOccupied);
    changed = true;
  }
  report_.metrics.work += blocked.size();
  if (!changed) return;
  r_.points_dirty = true;
  // The break these cells cause in this robot's own saved path is the one the Repair is about:
  // it is already being repaired, so this robot does not ask about it again (check_relay_route).
  if (r_.saved && !is_source()) {
    const auto& path = r_.saved->whole_path;
    if (const auto br = find_break(path, 0))
      relay_break_ = std::pair{path[br->first].position, path[br->second].position};
  }
}

/// repair_share_met_blocks (source): adds `cells` (cell centres) to the cells it knows blocked at
/// the changes it has met; returns how many were new.
std::size_t RobotAgent::add_met_blocks(const std::vector<Vec2>& cells) {
  const auto& g = r_.map.world();
  const auto before = met_blocks_.size();
  for (Vec2 q : cells)
    if (const auto c = g.world_to_cell(q)) met_blocks_.push_back(*c);
  auto by_row = [](Cell a, Cell b) { return a.y != b.y ? a.y < b.y : a.x < b.x; };
  std::sort(met_blocks_.begin(), met_blocks_.end(), by_row);
  met_blocks_.erase(std::unique(met_blocks_.begin(), met_blocks_.end()), met_blocks_.end());
  report_.metrics.work += cells.size() + met_blocks_.size();
  return met_blocks_.size() - before;
}

/// repair_share_met_blocks: `cells` (what a Repair carries of its own break) with the cells the
/// source knows blocked at every change it has met, sorted, each once.
std::vector<Vec2> RobotAgent::with_met_blocks(std::vector<Vec2> cells) const {
  if (!opt().repair_share_met_blocks || met_blocks_.empty()) return cells;
  const auto& g = r_.map.world();
  std::vector<Cell> all = met_blocks_;
  for (Vec2 q : cells)
    if (const auto c = g.world_to_cell(q)) all.push_back(*c);
  return sorted_centres(std::move(all), g);
}

/// repair_share_met_blocks (source): whether `cells` holds a cell the Repair `m` does not carry.
bool RobotAgent::tells_more(const RepairMessage& m, const std::vector<Vec2>& cells) const {
  const auto& g = r_.map.world();
  std::vector<Cell> carried;
  for (Vec2 q : m.blocked)
    if (const auto c = g.world_to_cell(q)) carried.push_back(*c);
  return std::any_of(cells.begin(), cells.end(), [&](Vec2 q) {
    const auto c = g.world_to_cell(q);
    return c && std::find(carried.begin(), carried.end(), *c) == carried.end();
  });
}

/// repair_share_met_blocks (source): an answer it refused (`rest`: its position, then the
/// answer's route ahead) crosses cells its map knows blocked and its answerer did not. It learns
/// those cells (blocking_cells of every broken move) and, when its Repair did not carry them all,
/// asks again (check_source_route: a new Repair, new Num, from its current map), so the
/// answerers mark them and plan round them.
void RobotAgent::learn_from_refusal(const std::vector<VoronoiPoint>& rest) {
  if (!opt().repair_share_met_blocks) return;
  const auto br = find_break(rest, 0);
  if (!br) return;  // refused by seen_near_block alone: no cell to tell
  // The cells beside the refused moves, and every cell it knows occupied inside the free disc of
  // a point of the answer (its maker saw them free): the whole change as the source knows it,
  // not only the cells the refused move touched (the next answer would pass a cell beside them).
  const auto cells = occupied_in_discs(rest, blocking_cells(rest, *br));
  add_met_blocks(cells);
  if (repair_out_ && tells_more(*repair_out_, cells)) check_source_route();
}

/// repair_fix_answer (source): an answer it refused (`rest`: its position, then the answer's
/// route ahead) crosses cells its map knows blocked; its answerer had not seen the change, but
/// the rest of the answer's way is what that robot saw free. The source keeps the answer and
/// replaces only its blocked part, on its own map: first by a detour through its own open points
/// (detour(), as for its own route, Table 5), else by A* on its own map (plan_walk, as the repair
/// timeout's replan_to_route) to the first point of the answer past the block that it can plan
/// to. With repair_fix_seen_only that A* first keeps to space someone sensed free: cells the
/// source knows free and the free discs of the answer's points (shrunk to its map); only when
/// no such walk exists it plans through unknown space as before (s4r11: the optimistic walk led
/// into the unseen rest of the change, 127 replans). Local replanning of the blocked part of a
/// global route; not in the paper. Returns whether the source now drives the repaired answer.
bool RobotAgent::fix_refused_answer(std::vector<VoronoiPoint> rest, RobotId from) {
  if (!opt().repair_fix_answer || route_.empty() || rest.size() < 2) return false;
  const auto br = find_break(rest, 0);
  if (!br) return false;  // refused by seen_near_block alone: nothing to replan
  auto& s = r_;
  const std::uint32_t to = rejoin_past_block(rest, *br);
  const std::size_t done = std::min(next_route_index(), route_.size());
  shrink_to_map(rest);  // as in check_source_route: its own view of the change
  const auto fixed = detour(rest, br->first, to);
  const std::string who = "robot " + std::to_string(from.value) + "'s detour";
  if (!fixed.empty()) {
    route_.erase(route_.begin() + static_cast<std::ptrdiff_t>(done), route_.end());
    route_.insert(route_.end(), fixed.begin() + 1, fixed.end());
    set_source_waypoints(done);
    repair_done();
    ++report_.repairs_executed;
    ++report_.repair_answers_fixed;
    log_repair(true,
               "repairs " + who + " (blocked in its map) by its own points (Repair executed)");
    return true;
  }
  for (const bool seen_only : {true, false}) {
    if (seen_only && !opt().repair_fix_seen_only) continue;
    for (std::size_t i = std::max<std::size_t>(to, 1); i < rest.size(); ++i) {
      if (!plan_walk(rest[i].position, seen_only ? &rest : nullptr)) continue;
      if (opt().repair_walk_keep_ratio > 0.0) {
        // The walk onto the answer is planned again to this point while it is at most
        // repair_walk_keep_ratio times this walk or the answer's piece it replaces.
        double piece = 0.0;
        for (std::size_t k = 1; k <= i; ++k)
          piece += distance(rest[k - 1].position, rest[k].position);
        fix_walk_target_ = rest[i].position;
        fix_walk_first_m_ = std::max(walk_length(), piece);
        fix_walk_bound_m_ = opt().repair_walk_keep_ratio * fix_walk_first_m_;
      }
      route_.assign(1, VoronoiPoint{s.pos, 1.0f, 0.0f});
      route_.insert(route_.end(), rest.begin() + static_cast<std::ptrdiff_t>(i), rest.end());
      drive_walk_then_route();
      repair_done();
      ++report_.repairs_executed;
      ++report_.repair_answers_fixed_walk;
      if (seen_only) ++report_.repair_answers_fixed_seen;
      log_repair(true, "repairs " + who + " (blocked in its map) by A* on its own map" +
                           (seen_only ? " through space seen free" : "") + " (Repair executed)");
      return true;
    }
  }
  return false;
}

/// repair_check_seen: whether the moves of `ahead` (from the source's position) keep clear of
/// where the obstacle the source saw may continue unseen: no cell within the robot radius of a
/// move may be unknown to the source and next to (8-neighbour of) a cell that blocked its route.
/// In s1r7 the accepted detour crossed the doorway through door cells next to the seen ones,
/// beyond the source's sensing; a detour that passes the block through space nobody has to guess
/// about (the hall of the Repair tests) is not affected.
bool RobotAgent::seen_near_block(const std::vector<VoronoiPoint>& ahead) const {
  if (!opt().repair_check_seen || block_seen_.empty()) return true;
  const auto& g = r_.map.world();
  const double rad = opt().robot_radius_m / g.resolution - 0.01;
  std::vector<Cell> block;
  for (Vec2 q : block_seen_)
    if (const auto c = g.world_to_cell(q)) block.push_back(*c);
  Cell lo = block.front(), hi = lo;
  for (Cell c : block) {
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
  }
  auto next_to_block = [&](Cell d) {
    if (d.x < lo.x - 1 || d.x > hi.x + 1 || d.y < lo.y - 1 || d.y > hi.y + 1) return false;
    return std::any_of(block.begin(), block.end(), [&](Cell b) {
      return std::abs(b.x - d.x) <= 1 && std::abs(b.y - d.y) <= 1;
    });
  };
  Vec2 a = r_.pos;
  for (const auto& pt : ahead) {
    const auto ca = g.world_to_cell(a), cb = g.world_to_cell(pt.position);
    a = pt.position;
    if (!ca || !cb) return false;
    bool ok = true;
    for_each_line_cell(*ca, *cb, [&](Cell c) {
      for_each_disc_cell(c, rad, [&](Cell d) {
        if (r_.map.at(d) == kUnknown && next_to_block(d)) ok = false;
        return ok;
      });
      return ok;
    });
    if (!ok) return false;
  }
  return true;
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
  // Asked once per break: the map of a relay changes every step it walks, and the same break
  // would otherwise start a new Repair each time (Table 4 line 1: only a new Repair is handled).
  const std::pair<Vec2, Vec2> ends{path[br->first].position, path[br->second].position};
  if (relay_break_ && distance(relay_break_->first, ends.first) < 1e-3 &&
      distance(relay_break_->second, ends.second) < 1e-3)
    return;
  relay_break_ = ends;
  ++report_.repairs;
  const std::uint32_t to = rejoin_past_block(path, *br);
  shrink_to_map(path);  // so the Repair tells the others which free discs the change cut
  auto fixed = detour(path, br->first, to);
  if (!fixed.empty()) {
    // Its own detour goes to the source like an answer; it counts as a Repair executed when the
    // source takes it (splice_route).
    // `owners` (one per point of the first route) no longer matches the repaired path: a Path
    // with a mismatched list does not decode, so the source never got this detour (s3r12).
    PathMessage p = *r.saved;
    p.num = next_repair_num();
    p.whole_path = fixed;
    p.owners.clear();
    r.saved->whole_path = fixed;
    r.saved->owners.clear();
    relay_break_.reset();
    if (!p.relays.empty()) {
      ++report_.repair_answers;
      send_reliable(p.relays.back(), p);
    }
    return;
  }
  RepairMessage m;
  m.source = source_id();
  m.num = (r.id.value << 16) | (++r.repair_counter & 0xFFFFu);
  m.relays = r.saved->relays;
  m.relays.push_back(r.id);
  m.whole_path = path;
  m.broken_from = br->first;
  m.broken_to = to;
  if (opt().repair_share_blocks)
    m.blocked = changed_cells(r.saved->whole_path, blocking_cells(path, *br));
  r.repairs_seen.insert(m.num);
  ++report_.repair_requests;
  log_repair(false, "finds the route blocked and asks its neighbours (Repair message)");
  broadcast(m, 1);
}

void RobotAgent::on(const Header& h, const RepairMessage& m) {
  auto& r = r_;
  if (!r.repairs_seen.insert(m.num).second) return;
  if (m.broken_to >= m.whole_path.size()) return;
  // The source does not learn them: it meets the block itself, and a relay's Repair of its route
  // is under way (learning would make it ask again about the same break).
  const auto version = r.map.version();
  if (opt().repair_share_blocks && !is_source()) learn_blocks(m.blocked);
  auto fixed = detour(m.whole_path, m.broken_from, m.broken_to);
  // repair_sense_walk: it knows no way round, or the Repair told it of blocked cells its map
  // did not know (it has not seen the change, so its detour may cross it): the robot named by
  // the hand-off rule goes and senses the break first. A detour it has now still goes out.
  if ((fixed.empty() || r.map.version() != version) && walks_for_repair(h)) start_repair_walk(m);
  NS_DEBUG("t=%.1f robot %u repair from %u: detour %zu\n", now_, r.id.value, h.sender.value,
           fixed.size());
  if (!fixed.empty()) {
    // Table 4 line 3: it knows a way and answers (once: a Repair it has seen is not new). The
    // answer counts as a Repair executed where the source takes it (splice_route).
    PathMessage p;
    p.source = m.source;
    p.num = next_repair_num();
    p.relays = m.relays;
    p.whole_path = fixed;
    ++report_.repair_answers;
    if (is_source()) {
      on_repair_path(p, r.id);
    } else {
      send_reliable(h.sender, p);
    }
    return;
  }
  // Relay (Table 4 line 5) within the Repair's hop limit: its own (repair_expand_hops, an
  // expanding ring) or the fixed repair_hops. A robot that relays a ring Repair adds itself to
  // its relays, so the answer comes back hop by hop (on_repair_path) from beyond two hops.
  const int limit = m.hop_limit != 0 ? m.hop_limit : opt().repair_hops;
  if (h.hops >= limit) return;
  if (m.hop_limit == 0) {
    broadcast(m, static_cast<std::uint8_t>(h.hops + 1));
    return;
  }
  RepairMessage out = m;
  out.relays.push_back(r.id);
  broadcast(std::move(out), static_cast<std::uint8_t>(h.hops + 1));
}

void RobotAgent::on_repair_path(PathMessage m, RobotId from) {
  auto& r = r_;
  if (is_source() && (m.exit_index == kSenseWalking || m.exit_index == kSenseGaveUp)) {
    // repair_sense_walk: a relay walks to sense the break of the Repair it waits an answer
    // for (it waits repair_sense_wait_s for it), or gave up (it waits no longer for it).
    if (repair_out_ && (repair_out_->num | kRepairFlag) == m.num)
      sense_wait_until_ = m.exit_index == kSenseWalking ? now_ + opt().repair_sense_wait_s : -1.0;
    return;
  }
  if (is_source()) {
    ++report_.repair_answers_received;
    const bool sensed = m.exit_index == kSensedAnswer;
    if (sensed) ++report_.repair_answers_sensed;
    if (splice_route(m.whole_path, from, sensed) && sensed) ++report_.repair_answers_sensed_taken;
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
    r.saved->owners.clear();  // one per point of the first route: no longer matches
    relay_break_.reset();
  }
  if (!m.relays.empty()) send_reliable(m.relays.back(), m);
}

/// Source: sends its Repair `m` to its neighbours (Table 5) and keeps it as the one it waits an
/// answer for; notes who hears it now (repair_resend_new_only) and when to send it again.
void RobotAgent::send_repair(const RepairMessage& m) {
  repair_out_ = m;
  repair_heard_.clear();
  for (const auto& n : transport_.nearby(r_.id))
    repair_heard_.push_back(n.id);
  repair_resend_gap_ = opt().repair_resend_s;
  repair_resend_at_ = repair_resend_gap_ > 0.0 ? now_ + repair_resend_gap_ : -1.0;
  broadcast(m, 1);
}

/// repair_expand_hops (source), at its repair timeout: when no answer at all reached it since it
/// sent its Repair, it sends a new Repair (new Num, so every robot handles it again, Table 4
/// line 1) with twice the hop limit, up to repair_expand_hops and hop_limit, and waits
/// repair_timeout_s again. An expanding-ring search; not in the paper (its Repair goes to the
/// neighbours only). Returns whether it sent one.
bool RobotAgent::expand_repair_ring() {
  if (opt().repair_expand_hops <= 0 || !repair_out_) return false;
  if (report_.repair_answers_received != answers_at_repair_) return false;  // answered (refused)
  const int now_limit = repair_out_->hop_limit != 0 ? repair_out_->hop_limit : opt().repair_hops;
  const int next = std::min({2 * now_limit, opt().repair_expand_hops, opt().hop_limit});
  if (next <= now_limit) return false;
  auto& s = r_;
  RepairMessage m = *repair_out_;
  m.num = (s.id.value << 16) | (++s.repair_counter & 0xFFFFu);
  m.relays = {s.id};
  m.hop_limit = static_cast<std::uint8_t>(next);
  s.repairs_seen.insert(m.num);
  ++report_.repair_rings_expanded;
  log_repair(false, "got no answer and asks again up to " + std::to_string(next) +
                        " hops (Repair message, expanding ring)");
  blocked_since_ = now_;
  send_repair(m);
  return true;
}

/// The source stops waiting for a Repair answer (repaired, re-planned or given up).
void RobotAgent::repair_done() {
  blocked_since_ = -1.0;
  sense_wait_until_ = -1.0;
  repair_out_.reset();
  repair_resend_at_ = -1.0;
}

/// Source: re-sends its unanswered Repair (same Num: only robots that have not had it handle it)
/// after repair_resend_s, doubling the wait each time (option, not in the paper).
void RobotAgent::repair_timers() {
  if (!repair_out_ || blocked_since_ < 0.0 || repair_resend_at_ < 0.0) return;
  if (now_ + 1e-9 < repair_resend_at_) return;
  if (opt().repair_resend_new_only) {
    // Only when a robot that has not had it is in range now (checked again every step).
    bool fresh = false;
    for (const auto& n : transport_.nearby(r_.id))
      if (std::find(repair_heard_.begin(), repair_heard_.end(), n.id) == repair_heard_.end()) {
        repair_heard_.push_back(n.id);
        fresh = true;
      }
    if (!fresh) return;
  }
  repair_resend_gap_ *= 2.0;
  repair_resend_at_ = now_ + repair_resend_gap_;
  broadcast(*repair_out_, 1);
}

/// Source: takes a repaired route (the answer to a Repair, or a relay's own detour). With
/// repair_check_answer the route ahead must be free in the source's own map (it has seen the
/// change; the answerer may not have): an answer that still runs into the change is ignored and
/// the source keeps waiting. The first answer taken ends the wait, so later answers to the same
/// Repair no longer match the source's position and are ignored. Returns whether it was taken.
/// `sensed`: the answer comes from a relay that sensed the break (repair_sense_walk).
bool RobotAgent::splice_route(const std::vector<VoronoiPoint>& whole, RobotId from, bool sensed) {
  auto dropped = [&] {
    ++report_.repair_answers_dropped;
    return false;
  };
  if (whole.empty() || route_.empty()) return dropped();
  auto& s = r_;
  const std::size_t done = next_route_index();
  auto free_ahead = [&](const std::vector<VoronoiPoint>& ahead) {
    if (!opt().repair_check_answer) return true;
    // An answer from a relay that sensed the break (repair_sense_walk) starts where that relay
    // stood beside the source (within two robot radii, where its walk to the source stopped).
    // The source may stand within the robot radius of the change it met, so every move from
    // its position is blocked in its map (s1r4); it moves onto the answer as its own A* walk
    // leaves its start cell, and the check starts at the answer's first point.
    if (sensed && !ahead.empty() &&
        distance(s.pos, ahead.front().position) <= 2.0 * opt().robot_radius_m)
      return !find_break(ahead, 0) && seen_near_block(ahead);
    std::vector<VoronoiPoint> rest{VoronoiPoint{s.pos, 1.0f, 0.0f}};
    rest.insert(rest.end(), ahead.begin(), ahead.end());
    return !find_break(rest, 0) && seen_near_block(ahead);
  };
  auto taken = [&] {
    ++report_.repair_answers_taken;
    ++report_.repairs_executed;
    if (from == s.id) ++report_.repairs_own;
    log_repair(true, from == s.id ? "repairs its route with its own detour (Repair executed)"
                                  : "takes robot " + std::to_string(from.value) +
                                        "'s detour (Repair executed)");
  };
  if (distance(whole.front().position, s.pos) < 1e-3) {
    // The answer to the source's own Repair: it starts where the source stands (it waits there
    // while blocked) and replaces the rest of the route.
    if (!repair_out_) return dropped();  // already answered: the first answer won
    const std::vector<VoronoiPoint> ahead(whole.begin() + 1, whole.end());
    if (!free_ahead(ahead)) {
      ++report_.repair_answers_refused;
      if (opt().repair_fix_answer || opt().repair_share_met_blocks) {
        std::vector<VoronoiPoint> rest{VoronoiPoint{s.pos, 1.0f, 0.0f}};
        rest.insert(rest.end(), ahead.begin(), ahead.end());
        if (fix_refused_answer(rest, from)) return true;
        learn_from_refusal(rest);
      }
#ifdef VORONAV_NS_TRACE
      std::vector<VoronoiPoint> rest{VoronoiPoint{s.pos, 1.0f, 0.0f}};
      rest.insert(rest.end(), ahead.begin(), ahead.end());
      if (const auto b = find_break(rest, 0))
        NS_DEBUG("t=%.1f   refused move (%.2f,%.2f)-(%.2f,%.2f), %zu shared cells\n", now_,
                 rest[b->first].position.x, rest[b->first].position.y,
                 rest[b->first + 1].position.x, rest[b->first + 1].position.y,
                 repair_out_->blocked.size());
#endif
      NS_DEBUG("t=%.1f source ignores robot %u's detour (blocked in its map)\n", now_, from.value);
      return false;
    }
    route_.erase(route_.begin() + static_cast<std::ptrdiff_t>(std::min(done, route_.size())),
                 route_.end());
    route_.insert(route_.end(), ahead.begin(), ahead.end());
    set_source_waypoints(std::min(done, route_.size()));
    repair_done();
    taken();
    NS_DEBUG("t=%.1f source splices a repaired route (%zu points)\n", now_, whole.size());
    return true;
  }
  for (std::size_t i = route_.size(); i-- > 0;) {
    if (distance(route_[i].position, whole.front().position) < 1e-3) {
      if (i + 1 < done) break;  // already passed: the splice point is behind the source
      std::vector<VoronoiPoint> n(route_.begin(), route_.begin() + static_cast<std::ptrdiff_t>(i));
      n.insert(n.end(), whole.begin(), whole.end());
      const std::size_t next = std::max<std::size_t>(done, 1) - 1;
      const std::vector<VoronoiPoint> ahead(
          n.begin() + static_cast<std::ptrdiff_t>(std::min(next, n.size())), n.end());
      if (!free_ahead(ahead)) {
        ++report_.repair_answers_refused;
        if (opt().repair_fix_answer || opt().repair_share_met_blocks) {
          std::vector<VoronoiPoint> rest{VoronoiPoint{s.pos, 1.0f, 0.0f}};
          rest.insert(rest.end(), ahead.begin(), ahead.end());
          if (fix_refused_answer(rest, from)) return true;
          learn_from_refusal(rest);
        }
        NS_DEBUG("t=%.1f source ignores robot %u's relay detour (blocked in its map)\n", now_,
                 from.value);
        return false;
      }
      route_ = std::move(n);
      set_source_waypoints(next);
      s.waypoints.insert(s.waypoints.begin(), s.pos);
      back_steps_ = 1;
      repair_done();
      taken();
      return true;
    }
  }
  return dropped();  // the splice point is behind the source or not on its route
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
  const std::uint32_t to = rejoin_past_block(rest, *br);
  if (opt().repair_share_blocks || opt().repair_check_seen || opt().repair_share_met_blocks)
    block_seen_ = blocking_cells(rest, *br);
  const std::vector<VoronoiPoint> sensed = rest;  // the clearances its makers sensed
  shrink_to_map(rest);                            // as in check_relay_route
  auto fixed = detour(rest, br->first, to);
  NS_DEBUG("t=%.1f source own detour %zu\n", now_, fixed.size());
  if (!fixed.empty()) {
    ++report_.repairs_executed;
    ++report_.repairs_own;
    log_repair(true, "detours around the block on its own map (Repair executed)");
    route_.erase(route_.begin() + static_cast<std::ptrdiff_t>(std::min(next, route_.size())),
                 route_.end());
    route_.insert(route_.end(), fixed.begin() + 1, fixed.end());
    set_source_waypoints(std::min(next, route_.size()));
    repair_done();
    return;
  }
  // Its Repair is out: wait for an answer (re-sent by repair_timers). With
  // repair_share_met_blocks it asks again when it now knows blocked cells that Repair did not
  // carry (it met more of the change while it waited, or an answer it refused crossed them): the
  // old Repair's break and cells are out of date.
  const bool reask = repair_out_.has_value();
  if (reask &&
      !(opt().repair_share_met_blocks && tells_more(*repair_out_, with_met_blocks(block_seen_))))
    return;
  RepairMessage m;
  m.source = s.id;
  m.num = (s.id.value << 16) | (++s.repair_counter & 0xFFFFu);
  m.relays = {s.id};
  m.whole_path = rest;
  m.broken_from = br->first;
  m.broken_to = to;
  if (opt().repair_share_blocks) m.blocked = changed_cells(sensed, block_seen_);
  if (opt().repair_share_met_blocks) {
    // Every change it has met, not only this break (the answerers may not have seen them).
    add_met_blocks(block_seen_);
    m.blocked = with_met_blocks(std::move(m.blocked));
    report_.repair_cells_max =
        std::max(report_.repair_cells_max, static_cast<int>(m.blocked.size()));
  }
  s.repairs_seen.insert(m.num);
  ++report_.repair_requests;
  if (reask) {
    ++report_.repair_reasks;
    log_repair(false, "asks again with the blocked cells it learned (Repair message)");
  } else {
    log_repair(false, "is blocked and asks its neighbours (Repair message)");
  }
  answers_at_repair_ = report_.repair_answers_received;
  send_repair(m);
}

/// Length of the source's planned waypoints from where it stands [m].
double RobotAgent::walk_length() const {
  double m = 0.0;
  Vec2 a = r_.pos;
  for (Vec2 w : r_.waypoints) {
    m += distance(a, w);
    a = w;
  }
  return m;
}

/// Source, when no Repair answered in time: A* on its own map to the first route point past the
/// break that it can plan to, then the rest of the route. On a planned walk back onto the route
/// (it drives waypoints before route_[1]) the walk is what is blocked, not the route. When that
/// walk goes to a refused answer the source repaired by A* (fix_refused_answer), with
/// repair_walk_keep_ratio it first plans again to route_[1], the walk's own target, and keeps
/// that walk while it is at most that many times the first walk or the answer's piece.
bool RobotAgent::replan_to_route() {
  auto& s = r_;
  const std::size_t next = next_route_index();
  const bool keep = fix_walk_bound_m_ >= 0.0 && s.wp < back_steps_ && route_.size() > 1 &&
                    distance(fix_walk_target_, route_[1].position) < 1e-3;
  const double bound = fix_walk_bound_m_;
  fix_walk_bound_m_ = -1.0;  // unless kept below
  for (std::size_t i = std::max<std::size_t>(next, 1) + (keep ? 0 : 1); i < route_.size(); ++i) {
    if (!plan_walk(route_[i].position)) continue;
    if (keep && i == 1 && walk_length() > bound)
      continue;  // too long a way round to the answer: drop the point, as without the option
    ++report_.replans;
    if (keep && i == 1) {
      ++report_.repair_walk_targets_kept;
      fix_walk_bound_m_ = opt().repair_walk_keep_ratio * fix_walk_first_m_;
    }
    route_.erase(route_.begin() + 1, route_.begin() + static_cast<std::ptrdiff_t>(i));
    route_[0] = VoronoiPoint{s.pos, 1.0f, 0.0f};
    drive_walk_then_route();
    return true;
  }
  return false;
}

/// After plan_walk to route_[1] (route_[0] is where the source stands): the source drives the
/// planned walk, then the route from route_[1] on; the walk's waypoints are its way back onto
/// the route (back_steps_), and the route proper starts at route_[1] (route_base_).
void RobotAgent::drive_walk_then_route() {
  auto& s = r_;
  for (std::size_t k = 2; k < route_.size(); ++k)
    s.waypoints.push_back(route_[k].position);
  s.wp = 0;
  back_steps_ = s.waypoints.size() - (route_.size() - 1);
  route_base_ = 1;
}

}  // namespace voronav::sim
