#include "voronav/coordination/prioritized.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "voronav/coordination/pbs.hpp"
#include "voronav/coordination/sipp_ga.hpp"
#include "voronav/core/error.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/planning/planner_factory.hpp"

namespace voronav::coordination {

namespace {
double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

OrderRule parse_order_rule(const std::string& s) {
  if (s == "edf") return OrderRule::kEdf;
  if (s == "index" || s == "none") return OrderRule::kIndex;
  if (s == "shortest-first") return OrderRule::kShortestFirst;
  if (s == "longest-first") return OrderRule::kLongestFirst;
  if (s == "deps") return OrderRule::kDependencies;
  if (s == "best") return OrderRule::kBest;
  if (s == "pbs") return OrderRule::kPbs;
  if (s == "ga") return OrderRule::kGa;
  throw Error("--order", 0,
              "expected edf|index|shortest-first|longest-first|deps|best|ga|pbs, got '" + s + "'");
}

const char* to_string(OrderRule r) {
  switch (r) {
    case OrderRule::kEdf:
      return "edf";
    case OrderRule::kIndex:
      return "index";
    case OrderRule::kShortestFirst:
      return "shortest-first";
    case OrderRule::kLongestFirst:
      return "longest-first";
    case OrderRule::kDependencies:
      return "deps";
    case OrderRule::kBest:
      return "best";
    case OrderRule::kPbs:
      return "pbs";
    case OrderRule::kGa:
      return "ga";
  }
  return "?";
}

PrioritizedResult plan_prioritized(const BinaryGrid& blocked, const std::vector<SippRobot>& robots,
                                   std::vector<int> order, const PrioritizedOptions& options) {
  const std::size_t n = robots.size();
  if (order.size() != n) throw Error("order", 0, "expected one entry per robot");
  double rmax = 0.0;
  std::map<double, BinaryGrid> inflated;
  for (const auto& r : robots) {
    rmax = std::max(rmax, r.radius);
    if (!inflated.count(r.radius))
      inflated.emplace(r.radius, planning::make_planning_grid(blocked, r.radius));
  }
  PrioritizedResult out;
  const int max_restarts = options.max_restarts < 0 ? static_cast<int>(n) : options.max_restarts;
  const GridGeometry& g = blocked.geometry();
  const bool soft = options.avoid_unplanned && (options.sipp.at_start == AtStart::kWait ||
                                                options.sipp.at_goal == AtGoal::kStay);
  // Earliest arrival of each robot (its shortest travel time, A* on its inflated map).
  std::vector<double> earliest(n, 0.0);
  if (options.goals_from_arrival && options.sipp.at_goal == AtGoal::kStay) {
    auto planner =
        planning::make_planner(planning::PlannerKind::kAStar, planning::PlannerOptions{});
    for (std::size_t j = 0; j < n; ++j) {
      const auto res =
          planner->plan(inflated.at(robots[j].radius), robots[j].start, robots[j].goal);
      if (res.ok()) earliest[j] = res.length_cells * g.resolution / robots[j].v_max;
    }
  }
  for (;;) {
    Reservations res(g, rmax);
    // Owners 0..n-1: the unplanned robots' starts (wait) and goals (stay) for all time;
    // owners n..2n-1: their starts only while they need to get away (2 cells of travel).
    std::vector<char> tier0(2 * n, 1), tier1(2 * n, 1), none(2 * n, 1);
    if (soft) {
      for (std::size_t j = 0; j < n; ++j) {
        const auto& r = robots[j];
        const int full = static_cast<int>(j), brief = static_cast<int>(n + j);
        if (options.sipp.at_start == AtStart::kWait) {
          if (options.full_starts)
            res.add_soft(g.cell_center(r.start), r.radius, 0.0, kInfinity, full);
          res.add_soft(g.cell_center(r.start), r.radius, 0.0, 2.0 * g.resolution / r.v_max, brief);
          tier1[n + j] = 0;
          if (!options.full_starts) tier0[n + j] = 0;
        }
        // A robot cannot park before its shortest travel time: before that its goal is free.
        if (options.sipp.at_goal == AtGoal::kStay && options.avoid_goals)
          res.add_soft(g.cell_center(r.goal), r.radius,
                       options.goals_from_arrival ? earliest[j] : 0.0, kInfinity, full);
        tier0[j] = 0;
      }
    }
    out.plans.assign(n, {});
    out.failed = -1;
    out.soft_fallbacks = 0;
    for (const int i : order) {
      const SippRobot& r = robots[static_cast<std::size_t>(i)];
      SippStats st;
      tier0[static_cast<std::size_t>(i)] = 1;
      tier1[n + static_cast<std::size_t>(i)] = 1;
      tier0[n + static_cast<std::size_t>(i)] = 1;
      SippOptions so = options.sipp;
      std::optional<std::vector<TimedWaypoint>> plan;
      int tier = 0;
      for (const std::vector<char>* inactive : {&tier0, &tier1, &none}) {
        if (!soft && inactive != &none) continue;
        so.inactive_owners = inactive;
        plan = sipp_plan(inflated.at(r.radius), r.start, r.goal, r.radius, r.v_max, res, so, &st);
        if (plan) break;
        ++tier;
      }
      if (plan && soft && tier > 0) ++out.soft_fallbacks;
      out.expansions += st.expansions;
      if (!plan) {
        out.failed = i;
        break;
      }
      res.add(trajectory_of(*plan, options.sipp.at_start, options.sipp.at_goal), r.radius);
      out.plans[static_cast<std::size_t>(i)] = std::move(*plan);
    }
    out.order = order;
    if (out.failed < 0) break;
    out.failures.push_back(out.failed);
    if (out.restarts >= max_restarts || order.front() == out.failed) return out;
    ++out.restarts;
    order.erase(std::find(order.begin(), order.end(), out.failed));
    order.insert(order.begin(), out.failed);
  }
  out.ok = true;
  out.arrivals.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.arrivals[i] = out.plans[i].back().t;
    out.makespan = std::max(out.makespan, out.arrivals[i]);
    out.sum_of_arrivals += out.arrivals[i];
  }
  return out;
}

SippCoordinationResult coordinate_sipp(const BinaryGrid& blocked, const std::vector<Agent>& agents,
                                       const SippCoordinateOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  SippCoordinationResult out;
  const GridGeometry& g = blocked.geometry();
  std::vector<SippRobot> robots;
  for (const Agent& a : agents) {
    if (std::isfinite(a.path.limits().a_max)) {
      throw Error(
          "robot " + std::to_string(a.id), 0,
          "--method sipp plans with instantaneous acceleration; a_max must be null/infinity");
    }
    const auto s = g.world_to_cell(a.path.nodes().front());
    const auto e = g.world_to_cell(a.path.nodes().back());
    if (!s || !e || !g.contains(*s) || !g.contains(*e))
      throw Error("robot " + std::to_string(a.id), 0, "start or goal outside the map");
    robots.push_back({a.id, *s, *e, a.radius, a.path.limits().v_max});
  }
  const std::size_t n = agents.size();
  auto index_order = [&] {
    std::vector<int> o(n);
    for (std::size_t i = 0; i < n; ++i)
      o[i] = static_cast<int>(i);
    return o;
  };
  std::vector<std::pair<OrderRule, std::vector<int>>> candidates;
  bool have_bounds = false;  // individual_bounds() once, for every rule that needs it
  auto bounds = [&]() -> const IndividualBounds& {
    if (!have_bounds) out.bounds = individual_bounds(blocked, agents);
    have_bounds = true;
    return out.bounds;
  };
  const bool best = options.order == OrderRule::kBest || options.order == OrderRule::kGa;
  if (best || options.order == OrderRule::kEdf) {
    if (n > 1) {
      const MdNetwork net = build_network(agents, options.map);
      candidates.push_back({OrderRule::kEdf, bottom_level_edf(net).order});
    } else {
      candidates.push_back({OrderRule::kEdf, index_order()});
    }
  }
  if (best || options.order == OrderRule::kIndex)
    candidates.push_back({OrderRule::kIndex, index_order()});
  if (best || options.order == OrderRule::kShortestFirst ||
      options.order == OrderRule::kLongestFirst) {
    const IndividualBounds& lb = bounds();
    std::vector<int> o = index_order();
    std::stable_sort(o.begin(), o.end(), [&](int a, int b) {
      return lb.travel[static_cast<std::size_t>(a)] < lb.travel[static_cast<std::size_t>(b)];
    });
    if (best || options.order == OrderRule::kShortestFirst)
      candidates.push_back({OrderRule::kShortestFirst, o});
    std::reverse(o.begin(), o.end());
    if (best || options.order == OrderRule::kLongestFirst)
      candidates.push_back({OrderRule::kLongestFirst, o});
  }
  if (best || options.order == OrderRule::kDependencies) {
    const IndividualBounds& lb = bounds();
    candidates.push_back({OrderRule::kDependencies,
                          dependency_order(g, robots, lb, options.map.at_start == AtStart::kWait,
                                           options.map.at_goal == AtGoal::kStay)});
  }
  out.order_ms = ms_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  PrioritizedOptions po = options.planning;
  po.sipp.at_start = options.map.at_start;
  po.sipp.at_goal = options.map.at_goal;
  auto key = [&](const PrioritizedResult& r) {
    return options.objective == Objective::kMakespan ? std::pair{r.makespan, r.sum_of_arrivals}
                                                     : std::pair{r.sum_of_arrivals, r.makespan};
  };
  bool have = false;
  bool ga_fallback = false;
  if (options.order == OrderRule::kGa) {
    // The paper's GA over SIPP orders, seeded with every order rule (sipp_ga.hpp).
    std::vector<std::vector<int>> seeds;
    for (const auto& c : candidates)
      seeds.push_back(c.second);
    SippGaResult ga =
        sipp_genetic_search(blocked, robots, seeds, options.objective, po, options.ga);
    out.ga_generations = ga.generations;
    out.ga_evaluations = ga.evaluations;
    out.ga_improved = ga.improved_over_seeds != 0;
    if (ga.best.ok) {
      out.plan = std::move(ga.best);
      out.order_source = "ga";
      have = true;
      candidates.clear();
    }
    // Else no order the GA planned works without restarts (K = 200 wait/stay): the rules with
    // their restarts, the dependency order first (the cheapest that succeeds there: restarts
    // are seconds each at that size), stopping at the first that succeeds; then PBS.
    ga_fallback = !have;
    std::stable_partition(candidates.begin(), candidates.end(),
                          [](const auto& c) { return c.first == OrderRule::kDependencies; });
  }
  for (const auto& [rule, order] : candidates) {
    PrioritizedResult r = plan_prioritized(blocked, robots, order, po);
    if (!have || (r.ok && (!out.plan.ok || key(r) < key(out.plan)))) {
      out.plan = std::move(r);
      out.order_source = to_string(rule);
      have = true;
    }
    if (ga_fallback && out.plan.ok) break;
  }
  const bool pbs_first = options.order == OrderRule::kPbs;
  if (pbs_first || (!out.plan.ok && options.pbs_fallback)) {
    PbsOptions pb;
    pb.sipp = po.sipp;
    pb.objective = options.objective;
    pb.max_nodes = options.pbs.max_nodes;
    pb.time_limit_s = options.pbs.time_limit_s;
    const PbsResult r = plan_pbs(blocked, robots, pb);
    out.pbs_used = true;
    out.pbs_nodes = r.nodes_expanded;
    out.pbs_pairs = r.priority_pairs;
    out.pbs_replans = r.replans;
    std::vector<int> failures = out.plan.failures;
    const int restarts = out.plan.restarts;
    out.plan = PrioritizedResult{};
    out.plan.ok = r.ok;
    out.plan.expansions = r.expansions;
    out.plan.restarts = restarts;
    out.plan.failures = std::move(failures);
    out.order_source = "pbs";
    if (r.ok) {
      out.plan.plans = r.plans;
      out.plan.order = r.order;
      out.plan.arrivals = r.arrivals;
      out.plan.makespan = r.makespan;
      out.plan.sum_of_arrivals = r.sum_of_arrivals;
    } else {
      out.plan_ms = ms_since(t1);
      out.message = "PBS failed: " + r.message;
      out.time_ms = ms_since(t0);
      return out;
    }
  }
  out.plan_ms = ms_since(t1);
  if (!out.plan.ok) {
    out.message = "prioritized SIPP failed: robot " +
                  std::to_string(agents[static_cast<std::size_t>(out.plan.failed)].id) +
                  " has no plan after " + std::to_string(out.plan.restarts) + " restarts";
    out.time_ms = ms_since(t0);
    return out;
  }
  const auto t2 = std::chrono::steady_clock::now();
  std::vector<double> radii;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    out.trajectories.push_back(
        trajectory_of(out.plan.plans[i], options.map.at_start, options.map.at_goal));
    radii.push_back(agents[i].radius);
  }
  out.verification = verify_trajectories(out.trajectories, radii, options.tolerance);
  out.verify_ms = ms_since(t2);
  out.valid = out.verification.valid;
  if (out.pbs_used) {
    out.message = out.valid ? "ok (PBS, " + std::to_string(out.pbs_nodes) + " nodes, " +
                                  std::to_string(out.pbs_pairs) + " priority pairs)"
                            : "the continuous-time check found overlaps in the PBS plans";
    out.time_ms = ms_since(t0);
    return out;
  }
  out.message = out.valid ? (out.plan.restarts == 0
                                 ? "ok"
                                 : "ok after " + std::to_string(out.plan.restarts) + " restarts")
                          : "the continuous-time check found overlaps in the SIPP plans";
  out.time_ms = ms_since(t0);
  return out;
}

IndividualBounds individual_bounds(const BinaryGrid& blocked, const std::vector<Agent>& agents) {
  IndividualBounds out;
  const GridGeometry& g = blocked.geometry();
  std::map<double, BinaryGrid> inflated;
  auto planner = planning::make_planner(planning::PlannerKind::kAStar, planning::PlannerOptions{});
  for (const Agent& a : agents) {
    if (!inflated.count(a.radius))
      inflated.emplace(a.radius, planning::make_planning_grid(blocked, a.radius));
    const auto s = g.world_to_cell(a.path.nodes().front());
    const auto e = g.world_to_cell(a.path.nodes().back());
    double t = kInfinity;
    std::vector<Cell> path;
    if (s && e) {
      auto res = planner->plan(inflated.at(a.radius), *s, *e);
      if (res.ok()) {
        t = res.length_cells * g.resolution / a.path.limits().v_max;
        path = std::move(res.path);
      }
    }
    out.travel.push_back(t);
    out.paths.push_back(std::move(path));
    out.makespan = std::max(out.makespan, t);
    out.sum += t;
  }
  return out;
}

std::vector<int> dependency_order(const GridGeometry& g, const std::vector<SippRobot>& robots,
                                  const IndividualBounds& bounds, bool use_starts, bool use_goals) {
  const std::size_t n = robots.size();
  if (bounds.paths.size() != n || bounds.travel.size() != n)
    throw Error("bounds", 0, "expected one path per robot");
  // Robots whose path comes near each cell.
  std::vector<std::vector<int>> touch(g.size());
  auto mark = [&](Cell c, int j) {
    if (!g.contains(c)) return;
    auto& v = touch[g.index(c)];
    if (v.empty() || v.back() != j) v.push_back(j);
  };
  for (std::size_t j = 0; j < n; ++j) {
    const auto& p = bounds.paths[j];
    for (std::size_t k = 0; k < p.size(); ++k) {
      mark(p[k], static_cast<int>(j));
      if (k > 0 && p[k].x != p[k - 1].x && p[k].y != p[k - 1].y) {
        mark({p[k].x, p[k - 1].y}, static_cast<int>(j));
        mark({p[k - 1].x, p[k].y}, static_cast<int>(j));
      }
    }
  }
  std::vector<std::vector<int>> succ(n);  // i -> j: i before j
  std::vector<int> indeg(n, 0);
  auto arc = [&](int a, int b) {
    if (a == b) return;
    succ[static_cast<std::size_t>(a)].push_back(b);
    ++indeg[static_cast<std::size_t>(b)];
  };
  for (std::size_t i = 0; i < n; ++i) {
    const int ii = static_cast<int>(i);
    if (use_starts) {
      for (const int j : touch[g.index(robots[i].start)])
        arc(ii, j);
    }
    if (use_goals) {
      for (const int j : touch[g.index(robots[i].goal)])
        arc(j, ii);
    }
  }
  std::vector<int> order;
  std::vector<char> placed(n, 0);
  for (std::size_t step = 0; step < n; ++step) {
    int pick = -1;
    for (std::size_t i = 0; i < n; ++i) {
      if (placed[i]) continue;
      if (pick < 0 || indeg[i] < indeg[static_cast<std::size_t>(pick)] ||
          (indeg[i] == indeg[static_cast<std::size_t>(pick)] &&
           bounds.travel[i] > bounds.travel[static_cast<std::size_t>(pick)]))
        pick = static_cast<int>(i);
    }
    placed[static_cast<std::size_t>(pick)] = 1;
    order.push_back(pick);
    for (const int j : succ[static_cast<std::size_t>(pick)])
      --indeg[static_cast<std::size_t>(j)];
  }
  return order;
}

}  // namespace voronav::coordination
