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

#include "cli_common.hpp"
#include "command.hpp"
#include "recordings.hpp"
#include "voronav/coordination/coordinator.hpp"
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
  std::string at_start, at_goal;
  std::uint64_t seed = 1;
  double node_spacing = -1.0;
  bool no_reduction = false;
  bool json = false;
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
  co::CoordinateOptions opt;
  opt.map = sc.map_options;
  opt.search.kind = co::parse_search_kind(a.search);
  opt.search.ga.seed = a.seed;
  opt.search.edf_reduction = !a.no_reduction;
  const co::CoordinationResult r = co::coordinate(agents, opt);

  const bool ok = r.status == co::ResolveStatus::kOk;
  nlohmann::json js_agents = nlohmann::json::array();
  for (std::size_t i = 0; i < agents.size(); ++i) {
    js_agents.push_back({{"id", agents[i].id},
                         {"delay", r.delays[i]},
                         {"arrival", ok ? nlohmann::json(r.arrivals[i]) : nlohmann::json(nullptr)},
                         {"travel", agents[i].path.travel_time()}});
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
      {"evaluations", r.search.evaluations},
      {"at_start", co::to_string(opt.map.at_start)},
      {"at_goal", co::to_string(opt.map.at_goal)},
      {"agents", js_agents}};
  if (!a.out.empty()) {
    std::filesystem::create_directories(a.out);
    co::Schedule s{agents, r.delays, opt.map.at_start, opt.map.at_goal, r.valid};
    co::write_schedule(a.out / "schedule.json", s);
    co::write_schedule(a.out / "schedule.yaml", s);
    draw_trajectories(sc, agents, a.out / "trajectories.png");
    if (ok) {
      draw_network(co::build_network(agents, opt.map), r, agents, a.out / "network.png");
      draw_collision_map(agents, r, opt.map, a.out / "collision_map.png");
      if (sc.map)
        report::write_replay_html(coordination_recording(sc.map->grid, agents, r),
                                  (a.out / "index.html").string());
    }
  }
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
      "Coordinate robots on fixed paths by start delays: collision maps, (M,D) network and "
      "priority search (seed 002)");
  auto a = std::make_shared<CoordArgs>();
  cmd->add_option("--scenario", a->scenario, "scenario YAML (map, robots)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--map", a->map, "MAPF map (Moving AI .map)")->check(CLI::ExistingFile);
  cmd->add_option("--scen", a->scen, "MAPF .scen (first K rows = K robots)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--agents", a->agents, "K: number of .scen rows used")->capture_default_str();
  cmd->add_option("--radius", a->radius, "robot radius for MAPF input [cells]")
      ->capture_default_str();
  cmd->add_option("--search", a->search, "none | exhaustive | edf | ga")->capture_default_str();
  cmd->add_flag("--no-reduction", a->no_reduction,
                "search all robots, not only the EDF urgent group");
  cmd->add_option("--seed", a->seed, "GA seed")->capture_default_str();
  cmd->add_option("--at-start", a->at_start, "wait (default) | appear");
  cmd->add_option("--at-goal", a->at_goal, "stay (default) | leave");
  cmd->add_option("--node-spacing", a->node_spacing, "path node spacing [m] (0 = automatic)");
  cmd->add_flag("--json", a->json, "JSON output");
  cmd->add_option("--out", a->out, "folder for schedule.json/.yaml and pictures");
  cmd->callback([a] { run(*a); });
}

const Command reg{{"coordinate", setup, 40}};

}  // namespace
}  // namespace voronav::cli
