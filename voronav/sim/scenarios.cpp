#include "voronav/sim/scenarios.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <tuple>

#include "voronav/core/error.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/grid_planner.hpp"

namespace voronav::sim {

PaperScenario paper_scenario(int id) {
  switch (id) {
    case 1:
      return {1, 6, 40.0};
    case 2:
      return {2, 6, 80.0};
    case 3:
      return {3, 12, 40.0};
    case 4:
      return {4, 12, 80.0};
    default:
      throw Error("scenario", 0, "expected 1, 2, 3 or 4, got " + std::to_string(id));
  }
}

namespace {

planning::PlanResult truth_plan(const BinaryGrid& pg, Cell a, Cell b) {
  planning::AStarPlanner planner;
  return planner.plan(pg, a, b);
}

}  // namespace

namespace {

/// A placement and what the obstacle changes of the office worlds need to be built on it.
struct Placement {
  NetSimScenario scenario;
  BinaryGrid blocked;  ///< ground truth, 1 = blocked
  BinaryGrid pg;       ///< planning grid (blocked inflated by the robot radius + 0.1 m)
  Cell source;
  Cell destination;
};

Placement place(const OccupancyGrid& world, const PlacementOptions& o,
                std::optional<Vec2> destination) {
  if (o.robots < 1 || o.robots > 100000)
    throw Error("placement.robots", 0, "expected 1..100000 robots");
  if (o.changes < 0 || o.changes > 16)
    throw Error("placement.changes", 0, "expected 0..16 changes");
  Placement out;
  NetSimScenario& sc = out.scenario;
  sc.world = world;
  const auto& g = world.geometry();
  out.blocked = binarize(world);
  const BinaryGrid& blocked = out.blocked;
  out.pg = planning::make_planning_grid(blocked, o.robot_radius_m + 0.1);
  const BinaryGrid& pg = out.pg;
  std::mt19937_64 rng(o.seed);
  std::vector<Cell> free_cells;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      if (!pg[Cell{x, y}]) free_cells.push_back({x, y});
  if (free_cells.empty()) throw Error("placement", 0, "the world has no free space");
  std::vector<Cell> vor = voronoi_cells(blocked, o.robot_radius_m + 0.3);
  std::erase_if(vor, [&](Cell c) { return pg[c] != 0; });
  if (vor.empty()) vor = free_cells;
  auto pick = [&](const std::vector<Cell>& v) {
    std::uniform_int_distribution<std::size_t> d(0, v.size() - 1);
    return v[d(rng)];
  };
  Cell s = pick(free_cells);
  Cell dest = s;
  if (destination) {
    // Given destination: draw the source until it can reach it.
    const auto c = g.world_to_cell(*destination);
    if (!c || !g.contains(*c) || pg[*c])
      throw Error("placement", 0,
                  "the destination has less than robot_radius_m + 0.1 m of clearance");
    dest = *c;
    bool ok = truth_plan(pg, s, dest).ok();
    for (int k = 0; k < 200 && !ok; ++k) {
      s = pick(free_cells);
      ok = truth_plan(pg, s, dest).ok();
    }
    if (!ok) throw Error("placement", 0, "no free place found that reaches the destination");
  } else {
    // Source at random; destination: the farthest reachable of 48 random candidates.
    double best = -1.0;
    const double min_d = 0.3 * std::min(g.width, g.height);
    for (int k = 0; k < 400 && (k < 48 || best < min_d); ++k) {
      if (k % 48 == 47 && best < min_d) s = pick(free_cells);  // enclosed source: pick another
      const Cell c = pick(free_cells);
      const double d = std::hypot(c.x - s.x, c.y - s.y);
      if (d > best && truth_plan(pg, s, c).ok()) {
        best = d;
        dest = c;
      }
    }
  }
  sc.robots.push_back(g.cell_center(s));
  for (int i = 1; i < o.robots; ++i)
    sc.robots.push_back(g.cell_center(pick(i % 2 == 1 ? vor : free_cells)));
  sc.source = 0;
  sc.destination = destination ? *destination : g.cell_center(dest);
  out.source = s;
  out.destination = dest;
  return out;
}

}  // namespace

NetSimScenario place_robots(const OccupancyGrid& world, const PlacementOptions& o,
                            std::optional<Vec2> destination) {
  if (o.changes != 0)
    throw Error("placement.changes", 0, "obstacle changes need an office world (doors)");
  OccupancyGrid truth = world;
  for (auto& v : truth.data())
    v = v == kFree ? kFree : kOccupied;
  return place(truth, o, destination).scenario;
}

NetSimScenario place_robots(const OfficeWorld& world, const PlacementOptions& o) {
  Placement p = place(world.grid, o, std::nullopt);
  NetSimScenario& sc = p.scenario;
  const auto& g = world.grid.geometry();
  const Cell s = p.source, dest = p.destination;
  // Obstacle changes: close doors on the true shortest route, ahead of the source.
  if (o.changes > 0) {
    auto plan = truth_plan(p.pg, s, dest);
    BinaryGrid changed = p.blocked;
    int made = 0;
    for (std::size_t i = 0; i < plan.path.size() && made < o.changes; ++i) {
      const Vec2 w = g.cell_center(plan.path[i]);
      if (distance(w, g.cell_center(s)) < 6.0) continue;
      for (const auto& d : world.doors) {
        if (distance(d.centre, w) > 0.6) continue;
        bool used = false;
        for (const auto& ch : sc.changes)
          used |= ch.cells == d.cells;
        if (used) continue;
        BinaryGrid trial = changed;
        for (Cell c : d.cells)
          trial[c] = 1;
        if (!truth_plan(planning::make_planning_grid(trial, o.robot_radius_m + 0.1), s, dest).ok())
          continue;
        changed = std::move(trial);
        ++made;
        ObstacleChange ch;
        ch.after_route_s = o.change_every_s * made;
        ch.cells = d.cells;
        sc.changes.push_back(std::move(ch));
        break;
      }
    }
  }
  return std::move(p.scenario);
}

namespace {

/// The source's trajectory in a change-free run of one method (the probe of time_changes).
struct Probe {
  double route_s = -1.0, end_s = 0.0;
  int changes_applied = 0, changes_on_route = 0;
  std::vector<double> t;
  std::vector<Vec2> pos;
  std::vector<double> along;  ///< distance driven up to pos[i]
};

/// The options of the probe runs that place Table 7's changes: the defaults, with the source's
/// Repair options that are off by default (beyond the paper: repair_share_met_blocks,
/// repair_fix_answer, repair_fix_seen_only, repair_expand_hops, repair_walk_keep_ratio) pinned
/// off and repair_sense_walk (on by default since stop 28) pinned on, so the same scenario (the same change times and places) comes out whatever their
/// defaults are, and variants of them are compared on the same changes. Without the pin, a
/// source that repairs differently drives another way after a change, and the later changes are
/// placed on that way or not at all (stop 25: with repair_fix_answer and repair_walk_keep_ratio
/// 1000 as defaults, s1 runs 9-16 got 12 changes instead of 18; docs/reproductions/networked.md).
NetSimOptions probe_options(Method m) {
  NetSimOptions o;
  o.method = m;
  o.record = true;
  o.repair_share_met_blocks = false;
  o.repair_fix_answer = false;
  o.repair_fix_seen_only = false;
  o.repair_expand_hops = 0;
  o.repair_walk_keep_ratio = 0.0;
  o.repair_sense_walk = true;
  return o;
}

Probe probe(const NetSimScenario& base, Method m) {
  const NetSimOptions o = probe_options(m);
  const auto res = run_netsim(base, o);
  Probe p;
  p.route_s = res.metrics.route_time_s;
  p.changes_applied = res.metrics.changes_applied;
  p.changes_on_route = res.metrics.changes_on_route;
  p.end_s = res.metrics.success ? res.metrics.arrival_time_s : res.metrics.simulated_s;
  double along = 0.0;
  for (const auto& st : res.recording.steps) {
    const Vec2 q = st.positions[base.source];
    if (!p.pos.empty()) along += distance(p.pos.back(), q);
    p.t.push_back(st.t_s);
    p.pos.push_back(q);
    p.along.push_back(along);
  }
  return p;
}

/// The last time the source of the probe, driving its route (after route_s), is `ahead_m` or
/// farther from the door before it first drives through it (within the robot radius + one cell of
/// the door's cells, as the source counts a change on its route); -1 when it never passes the
/// door that far into its route. Also the source position then.
struct Ahead {
  double t = -1.0;
  Vec2 pos;
};
Ahead time_before(const Probe& p, const GridGeometry& g, const std::vector<Cell>& door,
                  double margin, double ahead_m, double from_t) {
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (Cell c : door) {
    const Vec2 w = g.cell_center(c);
    lo = {std::min(lo.x, w.x), std::min(lo.y, w.y)};
    hi = {std::max(hi.x, w.x), std::max(hi.y, w.y)};
  }
  auto through = [&](Vec2 q) {
    return q.x >= lo.x - margin && q.x <= hi.x + margin && q.y >= lo.y - margin &&
           q.y <= hi.y + margin;
  };
  std::size_t k = 0;  // first step with the route in use, not before from_t
  while (k < p.t.size() && (p.t[k] + 1e-9 < p.route_s + 0.5 || p.t[k] + 1e-9 < from_t))
    ++k;
  auto box_distance = [&](Vec2 q) {
    const Vec2 c{std::clamp(q.x, lo.x, hi.x), std::clamp(q.y, lo.y, hi.y)};
    return distance(q, c);
  };
  for (std::size_t i = k; i < p.pos.size(); ++i) {
    if (!through(p.pos[i])) continue;
    // The last step before it comes within `ahead_m` of the door (so it has not sensed it).
    std::size_t j = i;
    while (j > k && box_distance(p.pos[j]) < ahead_m)
      --j;
    if (box_distance(p.pos[j]) < ahead_m) return {};  // too close to where the route starts
    return {p.t[j], p.pos[j]};
  }
  return {};
}

}  // namespace

namespace {

/// The free cells of a square box of side `side_m` centred at q: a partial block (an object put
/// down on the way), for where no door can close.
std::vector<Cell> box_cells(const GridGeometry& g, const BinaryGrid& blocked, Vec2 q,
                            double side_m) {
  std::vector<Cell> out;
  const auto c = g.world_to_cell(q);
  if (!c) return out;
  const int k = static_cast<int>(std::ceil(0.5 * side_m / g.resolution));
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx) {
      const Cell d{c->x + dx, c->y + dy};
      if (!g.contains(d) || blocked[d]) continue;
      const Vec2 w = g.cell_center(d);
      if (std::abs(w.x - q.x) <= 0.5 * side_m && std::abs(w.y - q.y) <= 0.5 * side_m)
        out.push_back(d);
    }
  return out;
}

}  // namespace

namespace {

/// Appends changes to sc.changes (a prefix this function made) until there are `changes`, or no
/// candidate passes. Each change is timed on the trajectories of runs *with* the changes before
/// it (a change moves both sources, so a later change timed on the change-free runs misses the
/// route: the third pass got fewer changes than Table 7 asks for in runs 9-16), and kept only when
/// a run of each method with it meets every change on the route ahead (changes_on_route). The
/// choice of change k depends only on the changes before it, so runs 5, 9 and 13 of a placement
/// share their first change and runs 9 and 13 their second.
/// The probe runs of a scenario with its changes so far (kept between calls: the runs that end
/// extend_changes are the start of the next extension of the same placement).
struct Probes {
  bool valid = false;
  Probe c, d;
  /// Entries of sc.changes per Table 7 change, in order: 1 for a change on both routes, 2 for
  /// a pair (one on each method's route, see extend_changes).
  std::vector<int> event_sizes;
};

/// The simulated time at which method m's run applies `ch` (changes_due).
double change_time(const ObstacleChange& ch, Method m) {
  return m == Method::kCentralized && ch.centralized_at_s >= 0.0 ? ch.centralized_at_s : ch.at_s;
}

/// The source position of a probe at time t (its last recorded one before or at t; the first
/// one before the recording starts).
Vec2 position_at(const Probe& p, double t) {
  if (p.pos.empty()) return {};
  const auto it = std::upper_bound(p.t.begin(), p.t.end(), t + 1e-9);
  return it == p.t.begin() ? p.pos.front() : p.pos[static_cast<std::size_t>(it - p.t.begin()) - 1];
}

// How far before a change its source is when it happens [m], in order of preference; the side of
// the box put down where no door can close [m]; the verified candidates per change, at most.
constexpr double kAhead[] = {2.0, 2.5, 3.0, 1.5};
constexpr double kBoxM = 0.8;
constexpr int kMaxTrials = 8;

/// A place on one method's route and when its source is before it (place_pair).
struct OnRoute {
  std::vector<Cell> cells;
  Ahead a;
  int rank = 0;  ///< position in the list of its method (doors first, then boxes)
};

/// The places on the route in use of probe `p` from `from` s on: the doors its source drives
/// through, in the order it meets them, then a box every 2 m along what it drives (not in the
/// last 1.5 m before the destination), each at every kAhead distance.
std::vector<OnRoute> places_on_route(const OfficeWorld& world, const NetSimScenario& sc,
                                     const BinaryGrid& changed, const Probe& p, double margin,
                                     double from) {
  const auto& g = world.grid.geometry();
  std::vector<OnRoute> out;
  auto add = [&](const std::vector<Cell>& cells) {
    for (double ahead : kAhead) {
      const auto a = time_before(p, g, cells, margin, ahead, from);
      if (a.t >= 0.0) out.push_back({cells, a, 0});
    }
  };
  for (const auto& door : world.doors)
    add(door.cells);
  std::stable_sort(out.begin(), out.end(),
                   [](const OnRoute& a, const OnRoute& b) { return a.a.t < b.a.t; });
  double last = -1e9;
  for (std::size_t i = 0; i < p.pos.size(); ++i) {
    if (p.t[i] < p.route_s + 0.5 || p.t[i] < from || p.along[i] < last + 2.0) continue;
    if (distance(p.pos[i], sc.destination) < 1.5) break;
    last = p.along[i];
    const auto cells = box_cells(g, changed, p.pos[i], kBoxM);
    if (!cells.empty()) add(cells);
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i].rank = static_cast<int>(i);
  return out;
}

/// Where no change can be put on both routes in use (the routes share no door and no place
/// ahead of both sources: s3 placement 3, docs/reproductions/networked.md "Table 7 changes where
/// the routes share no place"), the change of Table 7 is a pair: the same kind of change (a door
/// that closes, else a 0.8 m box) put on each method's route, each when that method's source is
/// 1.5-3 m before it. Both entries happen at the same simulated times and places in both
/// methods' runs (at_s only, no centralized_at_s), so each method meets the one on its route
/// while the other closes off it. Pairs are tried in the order of their two places in their
/// lists (doors before boxes, earlier before later); a pair is kept when both runs with it apply
/// every change and meet at least one entry of it on the route ahead. Appends the pair to
/// sc.changes and returns true, or leaves sc unchanged and returns false.
template <typename Met>
bool place_pair(const OfficeWorld& world, NetSimScenario& sc, double robot_radius_m,
                BinaryGrid& changed, Probes& probes, double from, const Met& met) {
  const auto& g = world.grid.geometry();
  const auto dest = g.world_to_cell(sc.destination);
  if (!dest) return false;
  const double margin = robot_radius_m;
  const auto on_c = places_on_route(world, sc, changed, probes.c, margin, from);
  const auto on_d = places_on_route(world, sc, changed, probes.d, margin, from);
  struct Pair {
    const OnRoute *c, *d;
  };
  std::vector<Pair> pairs;
  for (const auto& c : on_c)
    for (const auto& d : on_d)
      pairs.push_back({&c, &d});
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.c->rank + a.d->rank < b.c->rank + b.d->rank;
  });
  auto overlaps = [](const std::vector<Cell>& a, const std::vector<Cell>& b) {
    return std::any_of(a.begin(), a.end(),
                       [&](Cell c) { return std::find(b.begin(), b.end(), c) != b.end(); });
  };
  int trials = 0;
  for (const auto& pr : pairs) {
    if (trials >= kMaxTrials) break;
    if (overlaps(pr.c->cells, pr.d->cells)) continue;
    bool used = false;
    for (const auto& ch : sc.changes)
      used |= overlaps(ch.cells, pr.c->cells) || overlaps(ch.cells, pr.d->cells);
    if (used) continue;
    // The two entries in time order; at each, both sources (where the probes put them then)
    // must still reach the destination with every change so far.
    std::array<const OnRoute*, 2> e{pr.c, pr.d};
    if (e[1]->a.t < e[0]->a.t) std::swap(e[0], e[1]);
    BinaryGrid trial = changed;
    bool ok = true;
    for (const OnRoute* x : e) {
      for (Cell c : x->cells)
        trial[c] = 1;
      const auto pg = planning::make_planning_grid(trial, robot_radius_m + 0.1);
      for (const Probe* p : {&probes.c, &probes.d}) {
        const auto at = g.world_to_cell(position_at(*p, x->a.t));
        ok = ok && at && !pg[*at] && truth_plan(pg, *at, *dest).ok();
      }
    }
    if (!ok) continue;
    ++trials;
    for (const OnRoute* x : e) {
      ObstacleChange ch;
      ch.at_s = x->a.t;  // the same time for both methods
      ch.cells = x->cells;
      sc.changes.push_back(std::move(ch));
    }
    Probe nc = probe(sc, Method::kCentralized);
    bool kept = met(probes.c, nc, true);
    Probe nd;
    if (kept) {
      nd = probe(sc, Method::kDecentralized);
      kept = met(probes.d, nd, true);
    }
    if (!kept) {
      sc.changes.resize(sc.changes.size() - 2);
      continue;
    }
    probes.c = std::move(nc);
    probes.d = std::move(nd);
    changed = std::move(trial);
    probes.event_sizes.push_back(2);
    return true;
  }
  return false;
}

void extend_changes(const OfficeWorld& world, NetSimScenario& sc, int changes, double every_s,
                    double robot_radius_m, Probes& probes) {
  auto events = [&] { return static_cast<int>(probes.event_sizes.size()); };
  if (events() >= changes) return;
  if (!probes.valid) {
    probes.c = probe(sc, Method::kCentralized);
    probes.d = probe(sc, Method::kDecentralized);
    probes.valid = true;
  }
  Probe& pc = probes.c;
  Probe& pd = probes.d;
  const auto& g = world.grid.geometry();
  BinaryGrid changed = binarize(world.grid);
  for (const auto& ch : sc.changes)
    for (Cell c : ch.cells)
      changed[c] = 1;
  const auto dest = g.world_to_cell(sc.destination);
  // The same place for both methods, closing in front of each source: the last moment it is
  // `ahead` m or more from it before it drives through it. Closer than its 3 m sensing range,
  // so its plan already goes through it (the centralized plan through unknown space cuts
  // corners beside a door it has not seen yet, and a change there would not be on its route),
  // and far enough to stop (Repair, replan). Places: the doors both sources drive through; then,
  // where no door can close without cutting off the destination (scenario 3), a 0.8 m box put
  // down where both trajectories pass (a partial block: the way narrows or a detour is needed).
  // Each candidate is checked by a run of each method with it and the changes before it: it is
  // kept only when every change is on each method's route in use when it happens (the probe
  // trajectory says where the source drives, not where the centralized plan goes then).
  struct Cand {
    std::vector<Cell> cells;
    Ahead c, d;
  };
  const double margin = robot_radius_m;  // a source driving through passes this close
  double from_c = -1e9, from_d = -1e9;
  if (!sc.changes.empty()) {
    from_c = change_time(sc.changes.back(), Method::kCentralized) + every_s;
    from_d = change_time(sc.changes.back(), Method::kDecentralized) + every_s;
  }
  // A run with a new change meets it when every change is applied and the new one (at least one
  // entry of a pair) is on the route ahead in addition to those before.
  auto met = [&](const Probe& before, const Probe& after, bool pair) {
    const int n = static_cast<int>(sc.changes.size());
    const int on = after.changes_on_route - before.changes_on_route;
    return after.changes_applied == n && (pair ? on >= 1 : on == 1);
  };
  while (events() < changes) {
    if (pc.route_s < 0.0 || pd.route_s < 0.0) return;  // no route to change: no changes
    std::vector<Cand> cands;
    auto add = [&](const std::vector<Cell>& cells) {
      for (double ahead : kAhead) {
        const auto c = time_before(pc, g, cells, margin, ahead, from_c);
        const auto d = time_before(pd, g, cells, margin, ahead, from_d);
        if (c.t >= 0.0 && d.t >= 0.0) cands.push_back({cells, c, d});
      }
    };
    for (const auto& door : world.doors)  // doors, in the order the decentralized source meets them
      add(door.cells);
    std::stable_sort(cands.begin(), cands.end(),
                     [](const Cand& a, const Cand& b) { return a.d.t < b.d.t; });
    // Then boxes every 2 m along the decentralized route in use where the centralized source
    // also passes within the robot radius.
    double last = -1e9;
    for (std::size_t i = 0; i < pd.pos.size(); ++i) {
      if (pd.t[i] < pd.route_s + 0.5 || pd.t[i] < from_d || pd.along[i] < last + 2.0) continue;
      const Vec2 q = pd.pos[i];
      if (distance(q, sc.destination) < 1.5) break;
      double near = 1e300;
      for (std::size_t j = 0; j < pc.pos.size(); ++j)
        if (pc.t[j] >= pc.route_s && pc.t[j] >= from_c)
          near = std::min(near, distance(pc.pos[j], q));
      if (near > robot_radius_m) continue;
      last = pd.along[i];
      const auto cells = box_cells(g, changed, q, kBoxM);
      if (!cells.empty()) add(cells);
    }
    int trials = 0;
    bool placed = false;
    for (const auto& cd : cands) {
      if (trials >= kMaxTrials) break;
      bool used = false;
      for (const auto& ch : sc.changes)
        for (Cell c : cd.cells)
          used |= std::find(ch.cells.begin(), ch.cells.end(), c) != ch.cells.end();
      if (used) continue;
      BinaryGrid trial = changed;
      for (Cell c : cd.cells)
        trial[c] = 1;
      const auto pg = planning::make_planning_grid(trial, robot_radius_m + 0.1);
      const auto ca = g.world_to_cell(cd.c.pos), cb = g.world_to_cell(cd.d.pos);
      if (!ca || !cb || !dest || pg[*ca] || pg[*cb] || !truth_plan(pg, *ca, *dest).ok() ||
          !truth_plan(pg, *cb, *dest).ok())
        continue;
      ++trials;
      ObstacleChange ch;
      ch.at_s = cd.d.t;
      ch.centralized_at_s = cd.c.t;
      ch.cells = cd.cells;
      sc.changes.push_back(std::move(ch));
      Probe nc = probe(sc, Method::kCentralized);
      if (!met(pc, nc, false)) {
        sc.changes.pop_back();
        continue;
      }
      Probe nd = probe(sc, Method::kDecentralized);
      if (!met(pd, nd, false)) {
        sc.changes.pop_back();
        continue;
      }
      pc = std::move(nc);
      pd = std::move(nd);
      changed = std::move(trial);
      from_c = cd.c.t + every_s;
      from_d = cd.d.t + every_s;
      probes.event_sizes.push_back(1);
      placed = true;
      break;
    }
    if (!placed)
      placed =
          place_pair(world, sc, robot_radius_m, changed, probes, std::max(from_c, from_d), met);
    if (!placed) return;
    from_c = std::max(from_c, change_time(sc.changes.back(), Method::kCentralized) + every_s);
    from_d = std::max(from_d, change_time(sc.changes.back(), Method::kDecentralized) + every_s);
  }
}

}  // namespace

void time_changes_on_routes(const OfficeWorld& world, NetSimScenario& sc, int changes,
                            double every_s, double robot_radius_m) {
  sc.changes.clear();
  if (changes <= 0) return;
  Probes probes;
  extend_changes(world, sc, changes, every_s, robot_radius_m, probes);
}

NetSimScenario make_paper_run(int id, int run, std::uint64_t seed) {
  const auto ps = paper_scenario(id);
  if (run < 1 || run > kTable7Runs)
    throw Error("run", 0,
                "expected 1.." + std::to_string(kTable7Runs) + ", got " + std::to_string(run));
  OfficeWorldOptions wo;
  wo.width_m = wo.height_m = ps.size_m;
  wo.seed = seed * 1000 + static_cast<std::uint64_t>(id);
  const auto world = make_office_world(wo);
  PlacementOptions po;
  po.robots = ps.robots;
  po.seed = seed * 7919 + static_cast<std::uint64_t>(id * 16 + (run - 1) % 4);
  auto sc = place_robots(world, po);
  const int changes = (run - 1) / 4;
  if (changes == 0) return sc;
  // Runs 5, 9 and 13 of a placement share their first changes (extend_changes): what one run
  // placed is kept for the next in this process (the choice is deterministic, so this only saves
  // the probe runs).
  struct Known {
    std::vector<ObstacleChange> changes;
    int asked = 0;  // the most changes asked for so far (fewer placed: no more candidates)
    Probes probes;  // the probe runs with `changes` and its Table 7 changes (event_sizes)
  };
  static std::mutex mutex;
  static std::map<std::tuple<int, int, std::uint64_t>, Known> known;
  const std::tuple<int, int, std::uint64_t> key{id, (run - 1) % 4, seed};
  Probes probes;
  {
    std::lock_guard lock(mutex);
    const auto it = known.find(key);
    if (it != known.end()) {
      const auto& sizes = it->second.probes.event_sizes;
      const bool exhausted = static_cast<int>(sizes.size()) < it->second.asked;
      if (it->second.asked >= changes || exhausted) {
        // The entries of its first `changes` Table 7 changes (a pair has two).
        std::size_t n = 0;
        for (std::size_t k = 0; k < sizes.size() && static_cast<int>(k) < changes; ++k)
          n += static_cast<std::size_t>(sizes[k]);
        sc.changes.assign(it->second.changes.begin(),
                          it->second.changes.begin() + static_cast<std::ptrdiff_t>(n));
        return sc;
      }
      sc.changes = it->second.changes;
      probes = it->second.probes;
    }
  }
  extend_changes(world, sc, changes, po.change_every_s, po.robot_radius_m, probes);
  std::lock_guard lock(mutex);
  auto& k = known[key];
  if (changes > k.asked) k = {sc.changes, changes, std::move(probes)};
  return sc;
}

NetSimScenario make_scale_run(int robots, double size_m, std::uint64_t seed) {
  OfficeWorldOptions wo;
  wo.width_m = wo.height_m = size_m;
  wo.seed = seed;
  const auto world = make_office_world(wo);
  PlacementOptions po;
  po.robots = robots;
  po.seed = seed * 31 + static_cast<std::uint64_t>(robots);
  return place_robots(world, po);
}

Summary summarize(const std::vector<NetSimMetrics>& runs) {
  Summary s;
  s.runs = static_cast<int>(runs.size());
  if (runs.empty()) return s;
  int ok = 0;
  for (const auto& m : runs) {
    ok += m.success ? 1 : 0;
    s.traffic_bytes += static_cast<double>(m.traffic_bytes);
    s.messages += static_cast<double>(m.messages);
    s.computation += static_cast<double>(m.computation);
    s.max_robot_computation += static_cast<double>(m.max_robot_computation);
    s.cpu_s += m.cpu_s;
    s.max_robot_cpu_s += m.max_robot_cpu_s;
    s.alpha_bytes += m.alpha_bytes;
    s.beta_bytes += m.beta_bytes;
    s.gamma_bytes += m.gamma_bytes;
    if (m.success) {
      s.route_time_s += m.route_time_s;
      s.travel_m += m.travel_m;
    }
  }
  const double n = static_cast<double>(runs.size());
  s.success_rate = ok / n;
  for (double* v : {&s.traffic_bytes, &s.messages, &s.computation, &s.max_robot_computation,
                    &s.cpu_s, &s.max_robot_cpu_s, &s.alpha_bytes, &s.beta_bytes, &s.gamma_bytes})
    *v /= n;
  if (ok > 0) {
    s.route_time_s /= ok;
    s.travel_m /= ok;
  }
  return s;
}

}  // namespace voronav::sim
