// voronav coordinate: seed 002 on a scenario YAML or a MAPF map + .scen (first K rows): plans the
// paths, builds the (M,D) network, searches a priority order, resolves the start delays and checks
// the schedule in continuous time. --json prints makespan, sum_of_arrivals, agents [{id, delay,
// arrival}], valid and time_ms; --out DIR writes schedule.json/.yaml and pictures
// (trajectories over the map, the (M,D) network, a collision map).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <set>
#include <string>

#include "cli_common.hpp"
#include "command.hpp"
#include "recordings.hpp"
#include "voronav/bag/command_bags.hpp"
#include "voronav/coordination/coordinator.hpp"
#include "voronav/coordination/prioritized.hpp"
#include "voronav/coordination/scenario.hpp"
#include "voronav/coordination/schedule_io.hpp"
#include "voronav/core/error.hpp"
#include "voronav/render/figure.hpp"
#include "voronav/render/plot.hpp"
#include "voronav/report/replay_html.hpp"

namespace voronav::cli {
namespace {

namespace co = coordination;

struct CoordArgs {
  std::filesystem::path scenario, map, scen, out;
  int agents = 10;
  double radius = 0.5;
  std::string search = "ga";
  std::string method = "delays";
  int max_restarts = -1;
  std::string order = "ga";
  bool cross_goals = false;
  std::string objective = "makespan";
  bool no_pbs_fallback = false;
  double pbs_time_limit = 60.0;
  std::size_t pbs_max_nodes = 20000;
  double sipp_ga_time_limit = 0.0;
  std::string at_start, at_goal;
  std::uint64_t seed = 1;
  int ga_three_opt = 0;
  std::string ga_three_opt_order = "paper";
  int ga_three_opt_depth = 2;
  int ga_three_opt_patience = 0;
  int ga_threads = 0;
  int ga_workers = 1;
  int ga_population = 0;
  int ga_stall = 0;
  int ga_delayed_gate = 0;
  int ga_polish = 0;
  int ga_ils = 0;
  std::string ga_preset = "paper";
  std::set<std::string> given;  ///< the GA options given on the command line (over the preset)
  int ga_ils_kick = 2;
  std::size_t ga_ils_evaluations = 0;
  double node_spacing = -1.0;
  bool no_reduction = false;
  bool json = false;
  std::filesystem::path mcap;
};

void draw_trajectories(const co::Scenario& sc, const std::vector<co::Agent>& agents,
                       const std::filesystem::path& file) {
  if (!sc.map) return;
  render::FigureOptions fo;
  fo.title = "paths (numbers: robot id; disc: start, dot: goal)";
  render::Figure fig(sc.map->grid.geometry(), fo);
  fig.occupancy(sc.map->grid);
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const auto c = render::palette(static_cast<int>(i));
    const auto& nodes = agents[i].path.nodes();
    fig.polyline(nodes, c, 2.0);
    fig.circle(nodes.front(), agents[i].radius, c.with_alpha(0.5), c);
    fig.point(nodes.back(), c, 3.0);
    fig.text(nodes.front(), std::to_string(agents[i].id), render::colors::kBlack, 10.0);
  }
  fig.save(file);
}

void draw_network(const co::MdNetwork& net, const co::CoordinationResult& r,
                  const std::vector<co::Agent>& agents, const std::filesystem::path& file) {
  const int n = net.size();
  GridGeometry g;
  g.width = g.height = 100;
  render::FigureOptions fo;
  fo.pixels_per_cell = 8;
  fo.title = "(M,D) network of the chosen order after resolution (arc: M/D)";
  fo.scale_unit = "";  // a diagram, not a map
  render::Figure fig(g, fo);
  std::vector<Vec2> pos(static_cast<std::size_t>(n));
  std::vector<int> rank(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p)
    rank[static_cast<std::size_t>(r.order[static_cast<std::size_t>(p)])] = p;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * rank[static_cast<std::size_t>(i)] / std::max(1, n);
    pos[static_cast<std::size_t>(i)] = {50.0 + 40.0 * std::sin(a), 50.0 + 40.0 * std::cos(a)};
  }
  const auto arcs = co::network_for_order(net, r.order, r.delays);
  for (const auto& arc : arcs) {
    const Vec2 a = pos[static_cast<std::size_t>(arc.high)],
               b = pos[static_cast<std::size_t>(arc.low)];
    const Vec2 dir = (b - a) / std::max(1e-9, distance(a, b));
    fig.arrow(a + dir * 3.0, b - dir * 3.0, render::colors::kGrey, 1.2);
    if (n <= 20) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.1f/%.1f", arc.m, arc.d);
      fig.text((a + b) * 0.5, buf, render::colors::kBlue, 9.0);
    }
  }
  for (int i = 0; i < n; ++i) {
    fig.circle(pos[static_cast<std::size_t>(i)], 2.5, render::colors::kWhite,
               render::colors::kBlack);
    fig.text(pos[static_cast<std::size_t>(i)] + Vec2{-1.0, -0.8},
             std::to_string(agents[static_cast<std::size_t>(i)].id), render::colors::kBlack, 11.0);
  }
  fig.save(file);
}

/// Collision map of the lower robot of the first box (figures 3, 4, 6): the exact region, the
/// boxes and the TLVSTC of the low robot with its delay, in the high robot's clock.
void draw_collision_map(const std::vector<co::Agent>& agents, const co::CoordinationResult& r,
                        const co::CollisionMapOptions& mo, const std::filesystem::path& file) {
  const double h = co::effective_node_spacing(agents, mo);
  std::vector<int> rank(agents.size());
  for (std::size_t p = 0; p < r.order.size(); ++p)
    rank[static_cast<std::size_t>(r.order[p])] = static_cast<int>(p);
  for (std::size_t p = 0; p < r.order.size(); ++p) {
    for (std::size_t q = p + 1; q < r.order.size(); ++q) {
      const int hi = r.order[p], lo = r.order[q];
      const auto& A = agents[static_cast<std::size_t>(hi)];
      const auto& B = agents[static_cast<std::size_t>(lo)];
      const auto boxes = co::collision_boxes(A, hi, B, lo, h, mo);
      if (boxes.empty()) continue;
      render::PlotOptions po;
      po.title = "collision map of robot " + std::to_string(B.id) + " against robot " +
                 std::to_string(A.id);
      po.x_label = "time [s] (robot " + std::to_string(A.id) + " departs at its delay)";
      po.y_label = "normalized travelled length of robot " + std::to_string(B.id);
      render::Plot plot(po);
      const double dh = r.delays[static_cast<std::size_t>(hi)];
      const double dl = r.delays[static_cast<std::size_t>(lo)];
      std::vector<double> rx, ry;
      for (const auto& s :
           co::collision_region(A, B, std::max(0.02, A.path.travel_time() / 400.0))) {
        for (const auto& [a, b] : s.intervals) {
          for (double l = a; l <= b; l += 0.01) {
            rx.push_back(s.t + dh);
            ry.push_back(l);
          }
        }
      }
      plot.scatter("collision region (eq. 5)", rx, ry, render::colors::kRed);
      const double horizon = std::max(A.path.travel_time() + dh, B.path.travel_time() + dl);
      int k = 0;
      for (const auto& b : boxes) {
        const double t1 = std::isfinite(b.t1) ? b.t1 + dh : 0.0;
        const double t4 = std::isfinite(b.t4) ? b.t4 + dh : horizon;
        plot.line(k++ == 0 ? "collision box" : "", {t1, t4, t4, t1, t1},
                  {b.l_s, b.l_s, b.l_e, b.l_e, b.l_s}, render::colors::kBlack);
      }
      std::vector<double> tx, ty;
      const double len = std::max(1e-9, B.path.length());
      for (int i = 0; i <= 200; ++i) {
        const double t = horizon * i / 200.0;
        tx.push_back(t);
        ty.push_back(B.path.arc_at(t - dl) / len);
      }
      plot.line("TLVSTC (delay " + std::to_string(dl).substr(0, 5) + " s)", tx, ty,
                render::colors::kBlue);
      plot.save(file);
      return;
    }
  }
}

/// Replay of SIPP plans: poses sampled along the trajectories.
report::Recording sipp_recording(const OccupancyGrid& map, const std::vector<co::Agent>& agents,
                                 const co::SippCoordinationResult& r) {
  report::Recording rec;
  rec.title = "Coordinated team: prioritized SIPP (" + r.order_source + " order)";
  rec.description = std::to_string(agents.size()) + " robots; " + r.message + ". Makespan " +
                    std::to_string(r.plan.makespan) + " s; the continuous-time check " +
                    (r.valid ? "passed" : "failed") + ".";
  rec.map = map;
  const double end = r.plan.makespan, dt = 0.1;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    report::RobotTrack track;
    track.id = agents[i].id;
    track.radius = agents[i].radius;
    const co::Trajectory& tr = r.trajectories[i];
    double yaw = 0.0;
    for (double t = 0.0;; t += dt) {
      const double tt = std::min(t, end);
      const Vec2 p = tr.position(tt), ahead = tr.position(tt + dt);
      if ((ahead - p).norm() > 1e-9) yaw = std::atan2(ahead.y - p.y, ahead.x - p.x);
      track.poses.push_back({tt, {p, yaw}});
      if (tt >= end) break;
    }
    std::vector<Vec2> pts;
    for (const auto& w : r.plan.plans[i])
      if (pts.empty() || (pts.back() - w.p).norm() > 0.0) pts.push_back(w.p);
    rec.paths.push_back({agents[i].id, 0.0, "SIPP path", pts});
    rec.robots.push_back(std::move(track));
  }
  return rec;
}

/// Writes the schedule (with the map it was planned on, relative to the output folder).
void write_schedules(const co::Scenario& sc, co::Schedule s, const std::filesystem::path& dir) {
  if (sc.map && !sc.map->source.empty()) {
    std::error_code ec;
    const auto rel = std::filesystem::relative(std::filesystem::absolute(sc.map->source),
                                               std::filesystem::absolute(dir), ec);
    s.map = ec ? std::filesystem::absolute(sc.map->source).string() : rel.string();
  }
  co::write_schedule(dir / "schedule.json", s);
  co::write_schedule(dir / "schedule.yaml", s);
}

/// --method sipp: prioritized SIPP in a priority order (--order; default the GA over orders),
/// checked in continuous time.
void run_sipp(const CoordArgs& a, const co::Scenario& sc, const std::vector<co::Agent>& agents,
              const co::CollisionMapOptions& mo) {
  if (!sc.map) throw Error("--method", 0, "sipp plans on a grid: the scenario needs a map");
  const BinaryGrid blocked = binarize(sc.map->grid);
  co::SippCoordinateOptions opt;
  opt.map = mo;
  opt.order = co::parse_order_rule(a.order);
  if (a.objective == "sum") {
    opt.objective = co::Objective::kSumOfArrivals;
  } else if (a.objective != "makespan") {
    throw Error("--objective", 0, "expected makespan|sum, got '" + a.objective + "'");
  }
  opt.planning.max_restarts = a.max_restarts;
  opt.planning.avoid_goals = !a.cross_goals;
  opt.pbs_fallback = !a.no_pbs_fallback;
  opt.pbs.time_limit_s = a.pbs_time_limit;
  opt.pbs.max_nodes = a.pbs_max_nodes;
  opt.ga.seed = a.seed;
  opt.ga.time_limit_s = a.sipp_ga_time_limit;
  const co::SippCoordinationResult r = co::coordinate_sipp(blocked, agents, opt);
  const co::IndividualBounds lb =
      r.bounds.travel.size() == agents.size() ? r.bounds : co::individual_bounds(blocked, agents);
  const bool ok = r.plan.ok;
  nlohmann::json js_agents = nlohmann::json::array();
  for (std::size_t i = 0; i < agents.size(); ++i) {
    js_agents.push_back(
        {{"id", agents[i].id},
         {"arrival", ok ? nlohmann::json(r.plan.arrivals[i]) : nlohmann::json(nullptr)},
         {"shortest", lb.travel[i]}});
  }
  nlohmann::json failures = nlohmann::json::array();
  for (const int i : r.plan.failures)
    failures.push_back(agents[static_cast<std::size_t>(i)].id);
  nlohmann::json order = nlohmann::json::array();
  for (const int i : r.plan.order)
    order.push_back(agents[static_cast<std::size_t>(i)].id);
  const nlohmann::json out = {
      {"method", "sipp"},
      {"order_source", r.order_source},
      {"status", ok ? "ok" : "sipp_failed"},
      {"message", r.message},
      {"makespan", ok ? nlohmann::json(r.plan.makespan) : nlohmann::json(nullptr)},
      {"sum_of_arrivals", ok ? nlohmann::json(r.plan.sum_of_arrivals) : nlohmann::json(nullptr)},
      {"bound_makespan", lb.makespan},
      {"bound_sum", lb.sum},
      {"valid", r.valid},
      {"min_clearance", std::isfinite(r.verification.min_clearance)
                            ? nlohmann::json(r.verification.min_clearance)
                            : nlohmann::json(nullptr)},
      {"time_ms", r.time_ms},
      {"order_ms", r.order_ms},
      {"plan_ms", r.plan_ms},
      {"verify_ms", r.verify_ms},
      {"restarts", r.plan.restarts},
      {"failures", failures},
      {"soft_fallbacks", r.plan.soft_fallbacks},
      {"pbs_used", r.pbs_used},
      {"pbs_nodes", r.pbs_nodes},
      {"pbs_priority_pairs", r.pbs_pairs},
      {"pbs_replans", r.pbs_replans},
      {"ga_generations", r.ga_generations},
      {"ga_evaluations", r.ga_evaluations},
      {"ga_improved_over_seeds", r.ga_improved},
      {"expansions", r.plan.expansions},
      {"order", order},
      {"at_start", co::to_string(mo.at_start)},
      {"at_goal", co::to_string(mo.at_goal)},
      {"agents", js_agents}};
  if (!a.out.empty() && ok) {
    make_output_dir(a.out, "--out");
    co::Schedule s{agents, {}, mo.at_start, mo.at_goal, r.valid, r.plan.plans, {}};
    for (const auto& w : r.plan.plans)
      s.delays.push_back(w.front().t);
    write_schedules(sc, s, a.out);
    draw_trajectories(sc, agents, a.out / "trajectories.png");
    report::write_replay_html(sipp_recording(sc.map->grid, agents, r),
                              (a.out / "index.html").string());
  }
  if (a.json) {
    print_json(out);
  } else {
    std::cout << agents.size() << " robots, prioritized SIPP (" << r.order_source
              << " order): " << r.message << "\n";
    if (ok) {
      std::cout << "makespan " << r.plan.makespan << " s (bound " << lb.makespan
                << "), sum of arrivals " << r.plan.sum_of_arrivals << " s (bound " << lb.sum
                << "), valid " << (r.valid ? "yes" : "no") << ", " << r.time_ms << " ms\n";
    }
  }
  if (!r.valid) exit_code() = 1;
}

/// Heading [rad] of the first (start) or last (goal) path segment of non-zero length; 0 if none.
double heading(const co::Agent& agent, bool at_start) {
  const auto& n = agent.path.nodes();
  for (std::size_t k = 1; k < n.size(); ++k) {
    const std::size_t i = at_start ? k : n.size() - k;
    const Vec2 d = n[i] - n[i - 1];
    if (d.norm() > 1e-12) return std::atan2(d.y, d.x);
  }
  return 0.0;
}

/// [t, x, y] per path node: t [s] = delay + travel time to the node, x, y [m] in frame "map".
nlohmann::json waypoints(const co::Agent& agent, double delay) {
  nlohmann::json w = nlohmann::json::array();
  const auto& nodes = agent.path.nodes();
  for (std::size_t k = 0; k < nodes.size(); ++k)
    w.push_back(
        {delay + agent.path.time_at_arc(agent.path.cumulative()[k]), nodes[k].x, nodes[k].y});
  return w;
}

void run(const CoordArgs& a) {
  co::Scenario sc;
  if (!a.scenario.empty()) {
    if (!a.map.empty() || !a.scen.empty())
      throw Error("--scenario", 0, "use either --scenario or --map/--scen");
    sc = co::load_scenario(a.scenario);
  } else {
    if (a.map.empty() || a.scen.empty())
      throw Error("--map", 0, "give --scenario FILE or --map M --scen S");
    sc = co::load_mapf(a.map, a.scen, a.agents, a.radius);
    sc.map_options.at_start = co::AtStart::kWait;
    sc.map_options.at_goal = co::AtGoal::kStay;
  }
  if (!a.at_start.empty()) sc.map_options.at_start = co::parse_at_start(a.at_start);
  if (!a.at_goal.empty()) sc.map_options.at_goal = co::parse_at_goal(a.at_goal);
  if (a.node_spacing >= 0.0) sc.map_options.node_spacing = a.node_spacing;
  const auto planned = co::plan_agents(sc);
  const auto& agents = planned.agents;
  if (a.method == "sipp") return run_sipp(a, sc, agents, sc.map_options);
  if (a.method != "delays")
    throw Error("--method", 0, "expected delays|sipp, got '" + a.method + "'");
  co::CoordinateOptions opt;
  opt.map = sc.map_options;
  opt.search.kind = co::parse_search_kind(a.search);
  // --ga-preset first; a GA option given on the command line overrides the preset's value.
  opt.search.ga = co::ga_preset(a.ga_preset);
  auto& g = opt.search.ga;
  const auto given = [&](const char* name) { return a.given.count(name) > 0; };
  g.seed = a.seed;
  if (given("--ga-three-opt")) g.three_opt_iterations = a.ga_three_opt;
  if (given("--ga-three-opt-order"))
    g.three_opt_order = co::parse_three_opt_order(a.ga_three_opt_order);
  if (given("--ga-three-opt-depth")) g.three_opt_depth = a.ga_three_opt_depth;
  if (given("--ga-three-opt-patience")) g.three_opt_patience = a.ga_three_opt_patience;
  if (given("--ga-threads")) g.threads = a.ga_threads;
  if (given("--ga-workers")) g.workers = a.ga_workers;
  if (given("--ga-population")) g.population = a.ga_population;
  if (given("--ga-stall")) g.stall_generations = a.ga_stall;
  if (given("--ga-delayed-gate")) g.delayed_gate = a.ga_delayed_gate;
  if (given("--ga-polish")) g.polish_sweeps = a.ga_polish;
  if (given("--ga-ils")) g.ils_patience = a.ga_ils;
  if (given("--ga-ils-kick")) g.ils_kick = a.ga_ils_kick;
  if (given("--ga-ils-evaluations")) g.ils_evaluations = a.ga_ils_evaluations;
  opt.search.edf_reduction = !a.no_reduction;
  const co::CoordinationResult r = co::coordinate(agents, opt);

  const bool ok = r.status == co::ResolveStatus::kOk;
  nlohmann::json js_agents = nlohmann::json::array();
  for (std::size_t i = 0; i < agents.size(); ++i) {
    js_agents.push_back(
        {{"id", agents[i].id},
         {"delay", r.delays[i]},
         {"arrival", ok ? nlohmann::json(r.arrivals[i]) : nlohmann::json(nullptr)},
         {"travel", agents[i].path.travel_time()},
         // issue 19: poses in frame "map" and timed waypoints [t s, x m, y m]
         {"start", pose_json({agents[i].path.nodes().front(), heading(agents[i], true)})},
         {"goal", pose_json({agents[i].path.nodes().back(), heading(agents[i], false)})},
         {"path_length_m", agents[i].path.length()},
         {"waypoints", waypoints(agents[i], r.delays[i])}});
  }
  nlohmann::json order = nlohmann::json::array();
  for (const int i : r.order)
    order.push_back(agents[static_cast<std::size_t>(i)].id);
  nlohmann::json missed = nlohmann::json::array();
  for (const auto& c : r.missed) {
    missed.push_back({{"a", agents[static_cast<std::size_t>(c.a)].id},
                      {"b", agents[static_cast<std::size_t>(c.b)].id},
                      {"time", c.time}});
  }
  const nlohmann::json out = {
      {"search", co::to_string(opt.search.kind)},
      {"status", co::to_string(r.status)},
      {"message", r.message},
      {"makespan", ok ? nlohmann::json(r.makespan) : nlohmann::json(nullptr)},
      {"sum_of_arrivals", ok ? nlohmann::json(r.sum_of_arrivals) : nlohmann::json(nullptr)},
      {"valid", r.valid},
      {"time_ms", r.time_ms},
      {"order", order},
      {"urgent_group", r.search.urgent_group.size()},
      {"boxes", r.boxes},
      {"repairs", r.repairs},
      {"missed_conflicts", missed},
      {"fallback_paths", planned.fallback_paths},
      {"ga_rounds", r.search.rounds},
      {"ga_generations", r.search.generations},
      {"ga_best_per_round", r.search.best_per_round},
      {"evaluations", r.search.evaluations},
      {"three_opt_order", co::to_string(opt.search.ga.three_opt_order)},
      {"three_opt_improvements", r.search.three_opt_improvements},
      {"three_opt_local_optima", r.search.three_opt_local_optima},
      {"three_opt_exact_cuts", r.search.three_opt_exact_cuts},
      {"three_opt_delayed_improvements", r.search.three_opt_delayed_improvements},
      {"ga_polish_improvements", r.search.polish_improvements},
      {"ga_polish_sweeps", r.search.polish_sweeps},
      {"ga_makespan_before_polish", r.search.makespan_before_polish},
      {"ga_ils_steps", r.search.ils_steps},
      {"ga_ils_improvements", r.search.ils_improvements},
      {"ga_makespan_before_ils", r.search.makespan_before_ils},
      {"at_start", co::to_string(opt.map.at_start)},
      {"at_goal", co::to_string(opt.map.at_goal)},
      {"agents", js_agents},
      {"frame_id", "map"},
      {"units", {{"time", "s"}, {"length", "m"}}}};
  if (!a.out.empty()) {
    make_output_dir(a.out, "--out");
    write_schedules(
        sc, co::Schedule{agents, r.delays, opt.map.at_start, opt.map.at_goal, r.valid, {}, {}},
        a.out);
    draw_trajectories(sc, agents, a.out / "trajectories.png");
    if (ok) {
      draw_network(co::build_network(agents, opt.map), r, agents, a.out / "network.png");
      draw_collision_map(agents, r, opt.map, a.out / "collision_map.png");
      if (sc.map)
        report::write_replay_html(coordination_recording(sc.map->grid, agents, r),
                                  (a.out / "index.html").string());
    }
  }
  if (!a.mcap.empty())
    bag::write_coordination_bag(a.mcap, sc.map ? sc.map->grid : OccupancyGrid{}, agents, r,
                                opt.map);
  if (a.json) {
    print_json(out);
  } else {
    std::cout << agents.size() << " robots, " << r.boxes << " collision boxes, search "
              << co::to_string(opt.search.kind) << ": " << r.message << "\n";
    if (ok) {
      std::cout << "makespan " << r.makespan << " s, sum of arrivals " << r.sum_of_arrivals
                << " s, valid " << (r.valid ? "yes" : "no") << ", " << r.time_ms << " ms\n";
      for (std::size_t i = 0; i < agents.size(); ++i) {
        std::cout << "  robot " << agents[i].id << ": delay " << r.delays[i] << " s, arrival "
                  << r.arrivals[i] << " s\n";
      }
    }
  }
  if (!r.valid) exit_code() = 1;
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "coordinate",
      "Coordinate robots on fixed paths by start delays: collision maps, an (M,D) network and "
      "a search over priorities (Ji, Jung & Lee, 'Priority-based interactive multi-agent motion "
      "planning with collision maps')");
  auto a = std::make_shared<CoordArgs>();
  cmd->add_option("--scenario", a->scenario,
                  "scenario YAML: map, robots with start, goal, radius and speed (docs/formats.md)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--map", a->map, "MAPF map (Moving AI .map; 1 cell = 1 m), with --scen")
      ->check(CLI::ExistingFile);
  cmd->add_option("--scen", a->scen,
                  "MAPF .scen file: its first K rows (--agents) are the robots' starts and goals")
      ->check(CLI::ExistingFile);
  cmd->add_option("--agents", a->agents, "K: number of .scen rows used (robots)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--radius", a->radius,
                  "robot radius for --map/--scen input [m] (a Moving AI cell is 1 m, so also "
                  "[cells])")
      ->check(positive())
      ->capture_default_str();
  cmd->add_option("--method", a->method,
                  "delays (the paper: start delays on fixed paths) | sipp (prioritized SIPP)")
      ->capture_default_str();
  cmd->add_option("--search", a->search,
                  "none | exhaustive | edf | ga (delays only; sipp uses --order)")
      ->capture_default_str();
  cmd->add_option(
         "--order", a->order,
         "sipp: priority order ga | edf | index | shortest-first | longest-first | deps | best | "
         "pbs (ga, the default: the paper's GA over orders seeded with EDF and the other rules, "
         "CPU budget --sipp-ga-time-limit; best: all orders, keep the best by --objective; pbs: "
         "priority-based search, Ma et al. 2019)")
      ->capture_default_str();
  cmd->add_flag("--cross-goals", a->cross_goals,
                "sipp: do not try to keep off the goals of robots planned later first");
  cmd->add_option("--objective", a->objective, "sipp --order best / pbs: makespan | sum")
      ->capture_default_str();
  cmd->add_flag("--no-pbs-fallback", a->no_pbs_fallback,
                "sipp: do not run PBS when prioritized planning fails in every order");
  cmd->add_option("--pbs-time-limit", a->pbs_time_limit, "sipp: PBS wall-clock budget [s]")
      ->check(positive())
      ->capture_default_str();
  cmd->add_option("--sipp-ga-time-limit", a->sipp_ga_time_limit,
                  "sipp --order ga: CPU-time budget of the GA over SIPP orders [s] (0 = auto: "
                  "0.01 s per robot, within [0.2, 2])")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--pbs-max-nodes", a->pbs_max_nodes, "sipp: PBS high-level node budget")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--max-restarts", a->max_restarts,
                  "sipp: failed-robot-first restarts (-1 = number of robots)")
      ->capture_default_str();
  cmd->add_flag("--no-reduction", a->no_reduction,
                "search all robots, not only the EDF urgent group");
  cmd->add_option("--ga-three-opt", a->ga_three_opt,
                  "GA: 3-opt moves tried per child (0 = N(N-1), the paper's; -1 = no 3-opt)")
      ->capture_default_str();
  cmd->add_option("--ga-three-opt-order", a->ga_three_opt_order,
                  "GA: 3-opt moves: paper (uniform random, the paper's) | critical-first (moves "
                  "of the last robot and the robots delaying it; stops at a local optimum) | "
                  "critical-delayed (critical-first, then sweeps over every delayed robot's "
                  "blockers)")
      ->capture_default_str();
  cmd->add_option("--ga-three-opt-depth", a->ga_three_opt_depth,
                  "GA, critical-first: levels of robots delaying the critical robot whose moves "
                  "are tried")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--ga-three-opt-patience", a->ga_three_opt_patience,
                  "GA, critical-first: random moves (minus the exact cut) after a local optimum, "
                  "until this many in a row did not improve (0 = none)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--ga-threads", a->ga_threads,
                  "GA: 0 = one random stream (earlier results); N >= 1 = per-child streams, the "
                  "children of a generation on N threads (same result for every N >= 1)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  cmd->add_option("--ga-workers", a->ga_workers,
                  "GA with --ga-threads 0 and the paper's 3-opt: make the children of a "
                  "generation on W threads with the same result as W = 1 (the one-stream run)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_option("--ga-stall", a->ga_stall,
                  "GA: 0 = the paper's stop rule (two rounds of 20 crossovers with the same best "
                  "makespan); G > 0 = stop after G generations without a better makespan")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--ga-delayed-gate", a->ga_delayed_gate,
                  "GA, critical-delayed: 0 = sweeps on every child; K > 0 = only on children "
                  "that critical-first makes no worse than the K-th best of the population")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--ga-polish", a->ga_polish,
                  "GA: after the GA, at most this many sweeps of the paper's N(N-1) segment moves "
                  "on the best order only, until a sweep improves nothing (0 = none, the paper's)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--ga-preset", a->ga_preset,
                  "GA settings by name, each GA option given overrides its value: paper (the "
                  "paper's GA, default); fast (issue #16: --ga-three-opt-order critical-delayed "
                  "--ga-delayed-gate 10 --ga-stall 2 --ga-ils 15 --ga-ils-kick 2 "
                  "--ga-ils-evaluations 250000 --ga-threads 2)")
      ->check(CLI::IsMember({"paper", "fast"}))
      ->capture_default_str();
  cmd->add_option("--ga-ils", a->ga_ils,
                  "GA: after the GA, iterated local search from the best order: steps of 10 "
                  "kicks (--ga-ils-kick random segment moves, then the child's 3-opt), stopping "
                  "after this many steps in a row without a better order (0 = none, the paper's)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--ga-ils-kick", a->ga_ils_kick, "GA, --ga-ils: random segment moves per kick")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--ga-ils-evaluations", a->ga_ils_evaluations,
                  "GA, --ga-ils: start no ILS step once the whole search has made this many "
                  "evaluations (0 = no cap)")
      ->capture_default_str();
  cmd->add_option("--ga-population", a->ga_population, "GA: population size (0 = N, the paper's)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "seed of the genetic search (--search ga)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--at-start", a->at_start,
                  "before its delay a robot waits at its start (wait, default) or is not there "
                  "yet (appear)");
  cmd->add_option("--at-goal", a->at_goal,
                  "after arriving a robot stays at its goal (stay, default) or leaves the map "
                  "(leave)");
  cmd->add_option("--node-spacing", a->node_spacing,
                  "spacing of the path nodes the collision maps use [m] (0 = automatic)")
      ->check(non_negative());
  add_quiet_flag(cmd);
  cmd->add_flag("--json", a->json,
                "JSON output: per robot start/goal poses, delay, arrival, waypoints [t s, x m, y "
                "m]; makespan, frame_id, units (docs/ros.md)");
  cmd->add_option("--out", a->out, "folder for schedule.json/.yaml and pictures")
      ->check(output_dir());
  cmd->add_option("--mcap", a->mcap,
                  "Write a ROS 2 bag (MCAP): /map, /robot_N/plan, /tf, /robots, /collision_boxes, "
                  "/events (docs/ros.md)");
  cmd->callback([a, cmd] {
    for (const char* name : {"--ga-three-opt", "--ga-three-opt-order", "--ga-three-opt-depth",
                             "--ga-three-opt-patience", "--ga-threads", "--ga-workers",
                             "--ga-population", "--ga-stall", "--ga-delayed-gate", "--ga-polish",
                             "--ga-ils", "--ga-ils-kick", "--ga-ils-evaluations"}) {
      if (cmd->count(name) > 0) a->given.insert(name);
    }
    run(*a);
  });
}

const Command reg{{"coordinate", setup, 40}};

}  // namespace
}  // namespace voronav::cli
