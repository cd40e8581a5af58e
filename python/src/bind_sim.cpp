// netsim (seed 000) and explore (seed 004): scenarios from Python lists or files, runs with
// options given as keywords, metrics as dicts with per-robot records; render: Figure with
// save() and to_rgb()/to_rgba() numpy images. Long runs release the GIL.
#include "common.hpp"
#include "voronav/exploration/explorer.hpp"
#include "voronav/render/figure.hpp"
#include "voronav/sim/netsim.hpp"
#include "voronav/sim/scenario_file.hpp"
#include "voronav/sim/scenarios.hpp"

namespace voronav::python {

namespace {

namespace sm = voronav::sim;
namespace ex = voronav::exploration;
namespace rd = voronav::render;

py::dict traffic_dict(const network::TrafficCounter& c) {
  return py::dict(py::arg("messages") = c.messages, py::arg("bytes") = c.bytes);
}

/// The options an exploration used, as the library echoes them (the CLI's `input`).
py::object options_dict(const ex::ExplorationOptions& o) {
  return py::module_::import("json").attr("loads")(ex::to_json(o));
}

py::dict metrics_dict(const sm::NetSimMetrics& m) {
  py::dict by_type;
  for (const auto& [k, v] : m.by_type)
    by_type[py::str(k)] = traffic_dict(v);
  py::list robots;
  for (const auto& r : m.robots) {
    py::dict sent;
    for (int t = 1; t < network::kMessageTypeCount; ++t)
      sent[py::str(std::string(network::to_string(static_cast<network::MessageType>(t))))] =
          traffic_dict(r.sent_by_type[static_cast<std::size_t>(t)]);
    robots.append(py::dict(py::arg("work") = r.work, py::arg("cpu_s") = r.cpu_s,
                           py::arg("travel_m") = r.travel_m, py::arg("sent_bytes") = r.sent_bytes,
                           py::arg("sent_messages") = r.sent_messages,
                           py::arg("sent_by_type") = sent));
  }
  py::dict d;
  d["success"] = m.success;
  d["route_time_s"] = m.route_time_s;
  d["arrival_time_s"] = m.arrival_time_s;
  d["travel_m"] = m.travel_m;
  d["source_travel_m"] = m.source_travel_m;
  d["route_length_m"] = m.route_length_m;
  d["traffic_bytes"] = m.traffic_bytes;
  d["messages"] = m.messages;
  d["computation"] = m.computation;
  d["max_robot_computation"] = m.max_robot_computation;
  d["cpu_s"] = m.cpu_s;
  d["max_robot_cpu_s"] = m.max_robot_cpu_s;
  d["by_type"] = by_type;
  d["alpha_bytes"] = m.alpha_bytes;
  d["beta_bytes"] = m.beta_bytes;
  d["gamma_bytes"] = m.gamma_bytes;
  d["search_attempts"] = m.search_attempts;
  d["repairs"] = m.repairs;
  d["replans"] = m.replans;
  d["corrupt_packets"] = m.corrupt_packets;
  // Which mechanism produced the result (docs/reproductions/networked.md): who built the route,
  // the Repairs executed and where they came from, the obstacle changes met.
  d["route_found_by"] = std::string(sm::to_string(m.route_found_by));
  d["route_robots"] = m.route_robots;
  d["paths_lost"] = m.paths_lost;
  d["repairs_executed"] = m.repairs_executed;
  d["repair_requests"] = m.repair_requests;
  d["source_repair_requests"] = m.source_repair_requests;
  d["repair_answers"] = m.repair_answers;
  d["repair_sense_walks"] = m.repair_sense_walks;
  d["repair_sense_walk_m"] = m.repair_sense_walk_m;
  d["repair_sense_answers"] = m.repair_sense_answers;
  sm::SourceRepairTrace::fields([&](const char* name, auto member) { d[name] = m.*member; });
  d["changes_applied"] = m.changes_applied;
  d["changes_on_route"] = m.changes_on_route;
  d["simulated_s"] = m.simulated_s;
  d["wall_s"] = m.wall_s;
  d["robots"] = robots;
  return d;
}

rd::Color to_color(py::handle h) {
  if (py::isinstance<py::str>(h)) {
    const std::string s = h.cast<std::string>();
    static const std::pair<const char*, rd::Color> named[] = {
        {"black", rd::colors::kBlack},
        {"white", rd::colors::kWhite},
        {"grey", rd::colors::kGrey},
        {"gray", rd::colors::kGrey},
        {"red", rd::colors::kRed},
        {"green", rd::colors::kGreen},
        {"blue", rd::colors::kBlue},
        {"orange", rd::colors::kOrange},
        {"purple", rd::colors::kPurple},
        {"cyan", rd::colors::kCyan},
        {"transparent", rd::colors::kTransparent}};
    for (const auto& [n, c] : named)
      if (s == n) return c;
    if (s.size() == 7 && s[0] == '#') {
      try {
        return rd::Color::hex(static_cast<std::uint32_t>(std::stoul(s.substr(1), nullptr, 16)));
      } catch (const std::exception&) {
      }
    }
    throw Error(
        "color", 0,
        "'" + s + "': expected a name (red, blue, ...), '#rrggbb' or (r, g, b[, a]) in 0..1");
  }
  auto t = h.cast<py::sequence>();
  if (t.size() != 3 && t.size() != 4)
    throw Error("color", 0, "expected (r, g, b) or (r, g, b, a) in 0..1");
  return {t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(),
          t.size() == 4 ? t[3].cast<double>() : 1.0};
}

std::vector<Cell> cells_from(const GridGeometry& g, const py::handle& h) {
  std::vector<Cell> out;
  if (py::isinstance<py::array>(h)) {
    auto a = py::array_t<int, py::array::c_style | py::array::forcecast>::ensure(h);
    if (!a || a.ndim() != 2 || a.shape(1) != 2)
      throw Error("cells", 0, "expected an (N, 2) array of cells");
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      out.push_back({a.at(i, 0), a.at(i, 1)});
    return out;
  }
  for (auto c : h.cast<py::iterable>())
    out.push_back(to_cell(g, c, "cells"));
  return out;
}

std::vector<Vec2> points_from(const py::handle& h) {
  std::vector<Vec2> out;
  if (py::isinstance<py::array>(h)) {
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
    if (!a || a.ndim() != 2 || a.shape(1) != 2)
      throw Error("points", 0, "expected an (N, 2) array [m]");
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      out.push_back({a.at(i, 0), a.at(i, 1)});
    return out;
  }
  for (auto p : h.cast<py::iterable>()) {
    auto s = p.cast<py::sequence>();
    out.push_back({s[0].cast<double>(), s[1].cast<double>()});
  }
  return out;
}

Vec2 point_from(py::handle h) {
  auto s = h.cast<py::sequence>();
  if (s.size() != 2) throw Error("point", 0, "expected (x, y) [m]");
  return {s[0].cast<double>(), s[1].cast<double>()};
}

/// A Figure with the grid geometry it draws on (for cell arguments given as Vec2).
struct PyFigure {
  GridGeometry g;
  rd::Figure f;
};

}  // namespace

void bind_sim(py::module_& m) {
  auto ns = m.def_submodule("netsim", "Networked robots finding a route (seed 000).");
  bind_enum<sm::Method>(
      ns, "Method",
      {{"centralized", sm::Method::kCentralized}, {"decentralized", sm::Method::kDecentralized}});
  py::class_<sm::NetSimScenario>(ns, "Scenario",
                                 "World, robots [m], source index, destination [m].")
      .def(py::init([](const OccupancyGrid& world, const py::object& robots,
                       const py::object& destination, std::size_t source) {
             sm::NetSimScenario s;
             s.world = world;
             s.robots = points_from(robots);
             s.destination = point_from(destination);
             s.source = source;
             s.validate();
             return s;
           }),
           py::arg("world"), py::arg("robots"), py::arg("destination"), py::arg("source") = 0,
           "world: OccupancyGrid of kFree/kOccupied; robots: [(x, y), ...] [m]; destination (x, y) "
           "[m].")
      .def_readonly("world", &sm::NetSimScenario::world)
      .def_property_readonly("robots", [](const sm::NetSimScenario& s) { return s.robots; })
      .def_readonly("source", &sm::NetSimScenario::source)
      .def_readonly("destination", &sm::NetSimScenario::destination)
      .def_property_readonly("changes",
                             [](const sm::NetSimScenario& s) { return s.changes.size(); })
      .def("__repr__", [](const sm::NetSimScenario& s) {
        return "netsim.Scenario(" + std::to_string(s.robots.size()) + " robots, " +
               std::to_string(s.changes.size()) + " obstacle changes)";
      });
  py::class_<sm::NetSimOptions>(ns, "Options", "Run options (sim/netsim.hpp); keywords = fields.")
      .def(py::init([](const py::kwargs& kw) {
        sm::NetSimOptions o;
        apply_kwargs(o, kw, "netsim.Options");
        return o;
      }))
      .def_readwrite("method", &sm::NetSimOptions::method)
      .def_readwrite("sensing_range_m", &sm::NetSimOptions::sensing_range_m)
      .def_readwrite("speed_mps", &sm::NetSimOptions::speed_mps)
      .def_readwrite("robot_radius_m", &sm::NetSimOptions::robot_radius_m)
      .def_readwrite("dt_s", &sm::NetSimOptions::dt_s)
      .def_readwrite("time_limit_s", &sm::NetSimOptions::time_limit_s)
      .def_property(
          "radio_range_m", [](const sm::NetSimOptions& o) { return o.radio.range_m; },
          [](sm::NetSimOptions& o, double v) { o.radio.range_m = v; })
      .def_property(
          "radio_loss", [](const sm::NetSimOptions& o) { return o.radio.loss; },
          [](sm::NetSimOptions& o, double v) { o.radio.loss = v; })
      .def_readwrite("path_wait_s", &sm::NetSimOptions::path_wait_s)
      .def_readwrite("bridge_wait_s", &sm::NetSimOptions::bridge_wait_s)
      .def_readwrite("search_timeout_s", &sm::NetSimOptions::search_timeout_s)
      .def_readwrite("max_search_attempts", &sm::NetSimOptions::max_search_attempts)
      .def_readwrite("hop_limit", &sm::NetSimOptions::hop_limit)
      .def_readwrite("repair_hops", &sm::NetSimOptions::repair_hops)
      .def_readwrite("repair_expand_hops", &sm::NetSimOptions::repair_expand_hops)
      .def_readwrite("repair_fix_seen_only", &sm::NetSimOptions::repair_fix_seen_only)
      .def_readwrite("repair_walk_keep_ratio", &sm::NetSimOptions::repair_walk_keep_ratio)
      .def_readwrite("repair_sense_walk", &sm::NetSimOptions::repair_sense_walk)
      .def_readwrite("repair_sense_wait_s", &sm::NetSimOptions::repair_sense_wait_s)
      .def_readwrite("collect_s", &sm::NetSimOptions::collect_s)
      .def_readwrite("repair_timeout_s", &sm::NetSimOptions::repair_timeout_s)
      .def_readwrite("seed", &sm::NetSimOptions::seed)
      .def_readwrite("record", &sm::NetSimOptions::record,
                     "Return 'route' (source's final route [m]) and 'steps' (positions per step)")
      .def("scale_options", &sm::NetSimOptions::scale_options)
      .def("__repr__", [](const sm::NetSimOptions& o) {
        return "netsim.Options(method=" + std::string(sm::to_string(o.method)) + ")";
      });
  ns.def(
      "paper_run",
      [](int id, int run, std::uint64_t seed) { return sm::make_paper_run(id, run, seed); },
      py::arg("scenario"), py::arg("run"), py::arg("seed") = 1,
      py::call_guard<py::gil_scoped_release>(),
      "Run `run` (1..16) of Table 7 for paper scenario 1..4.");
  ns.def(
      "load_scenario",
      [](const std::string& p) {
        auto f = sm::load_netsim_scenario(p);
        return py::make_tuple(std::move(f.scenario), f.options);
      },
      py::arg("path"), "(Scenario, Options) of a netsim scenario YAML file.");
  ns.def(
      "run",
      [](const sm::NetSimScenario& s, const py::object& options, const py::kwargs& kw) {
        sm::NetSimOptions o =
            options.is_none() ? sm::NetSimOptions{} : options.cast<sm::NetSimOptions>();
        apply_kwargs(o, kw, "netsim.run");
        o.validate();
        sm::NetSimResult r;
        {
          py::gil_scoped_release release;
          r = sm::run_netsim(s, o);
        }
        py::dict d = metrics_dict(r.metrics);
        if (o.record) {  // the source's final route [m] and the robots' positions per step
          py::list route, steps;
          for (const Vec2& v : r.recording.route)
            route.append(py::make_tuple(v.x, v.y));
          for (const auto& st : r.recording.steps) {
            py::list pos;
            for (const Vec2& v : st.positions)
              pos.append(py::make_tuple(v.x, v.y));
            steps.append(py::dict(py::arg("t_s") = st.t_s, py::arg("positions") = pos));
          }
          d["route"] = route;
          d["steps"] = steps;
        }
        return d;
      },
      py::arg("scenario"), py::arg("options") = py::none(),
      "Runs one scenario; keywords override Options fields (method='centralized', ...). "
      "Returns the metrics dict with 'robots': one record per robot (and 'route', 'steps' "
      "with record=True).");

  auto xp =
      m.def_submodule("explore", "Swarm exploration (seed 004): tree, frontier, coordinated.");
  bind_enum<ex::ExplorationMethod>(xp, "Method",
                                   {{"tree", ex::ExplorationMethod::kTree},
                                    {"frontier", ex::ExplorationMethod::kFrontier},
                                    {"coordinated", ex::ExplorationMethod::kCoordinated},
                                    {"tree_frontier", ex::ExplorationMethod::kTreeFrontier}});
  bind_enum<ex::TreeReplan>(
      xp, "TreeReplan", {{"none", ex::TreeReplan::kNone}, {"robots", ex::TreeReplan::kFromRobots}},
      "tree: after its leaves a robot searches reactively (none, the paper) "
      "or gets a new tree rooted where it is (robots; CLI --tree-replan).");
  bind_enum<ex::TreeLegReplan>(
      xp, "TreeLegReplan",
      {{"none", ex::TreeLegReplan::kNone}, {"robots", ex::TreeLegReplan::kAroundRobots}},
      "tree: a robot blocked on a tree leg skips a waypoint (none) or re-plans the leg around the "
      "robots near it (robots; CLI --tree-leg-replan).");
  bind_enum<ex::FrontGuard>(
      xp, "FrontGuard", {{"cone", ex::FrontGuard::kCone}, {"corridor", ex::FrontGuard::kCorridor}},
      "The front guard of a robot on its route: stop for anything in a +-0.7 rad fan (cone) or "
      "for a robot there and a wall on the route's swept corridor (corridor; CLI --guard).");
  bind_enum<robot::AvoidEscape>(
      xp, "AvoidEscape",
      {{"spin", robot::AvoidEscape::kSpin}, {"corridor", robot::AvoidEscape::kCorridor}},
      "Reactive rule 2 when no heading clears the front (CLI --avoid-escape).");
  bind_enum<robot::Table1Variant>(
      xp, "Table1Variant",
      {{"paper", robot::Table1Variant::kPaper}, {"corrected", robot::Table1Variant::kCorrected}},
      "Table 1 as printed (paper) or with its two trapping rows corrected.");
  py::class_<robot::ReactiveControllerOptions>(
      xp, "ControllerOptions",
      "The reactive controller of seed 004 (sections 3.2, Tables 1-2); keywords = fields.")
      .def(py::init([](const py::kwargs& kw) {
        robot::ReactiveControllerOptions o;
        apply_kwargs(o, kw, "explore.ControllerOptions");
        return o;
      }))
      .def_readwrite("table", &robot::ReactiveControllerOptions::table)
      .def_readwrite("drive_velocity", &robot::ReactiveControllerOptions::drive_velocity, "[m/s]")
      .def_readwrite("obs_approach", &robot::ReactiveControllerOptions::obs_approach, "[m/s]")
      .def_readwrite("obs_avoid", &robot::ReactiveControllerOptions::obs_avoid, "[rad/s]")
      .def_readwrite("approach_dist", &robot::ReactiveControllerOptions::approach_dist, "[m]")
      .def_readwrite("obs_dist", &robot::ReactiveControllerOptions::obs_dist, "[m]")
      .def_readwrite("desired_wf_dist", &robot::ReactiveControllerOptions::desired_wf_dist, "[m]")
      .def_readwrite("wall_detect_dist", &robot::ReactiveControllerOptions::wall_detect_dist, "[m]")
      .def_readwrite("wall_lost_time", &robot::ReactiveControllerOptions::wall_lost_time, "[s]")
      .def_readwrite("wall_follow_timeout", &robot::ReactiveControllerOptions::wall_follow_timeout,
                     "[s] (0 = never)")
      .def_readwrite("wf_gain", &robot::ReactiveControllerOptions::wf_gain, "[rad/s per m]")
      .def_readwrite("random_turn_rate", &robot::ReactiveControllerOptions::random_turn_rate,
                     "[rad/s] (CLI --random-turn-rate)")
      .def_readwrite("random_period", &robot::ReactiveControllerOptions::random_period, "[s]")
      .def_readwrite("seed", &robot::ReactiveControllerOptions::seed,
                     "(the runner sets it per robot)")
      .def_readwrite("avoid_escape", &robot::ReactiveControllerOptions::avoid_escape)
      .def_readwrite("escape_after_turn", &robot::ReactiveControllerOptions::escape_after_turn,
                     "[rad]")
      .def_readwrite("escape_half_width", &robot::ReactiveControllerOptions::escape_half_width,
                     "[m]")
      .def_readwrite("escape_min_length", &robot::ReactiveControllerOptions::escape_min_length,
                     "[m]")
      .def_readwrite("escape_max_length", &robot::ReactiveControllerOptions::escape_max_length,
                     "[m]")
      .def_readwrite("stuck_time", &robot::ReactiveControllerOptions::stuck_time, "[s] (0 = never)")
      .def_readwrite("stuck_radius", &robot::ReactiveControllerOptions::stuck_radius, "[m]")
      .def("__repr__", [](const robot::ReactiveControllerOptions& o) {
        return "explore.ControllerOptions(random_turn_rate=" + std::to_string(o.random_turn_rate) +
               ", avoid_escape=" + std::string(robot::to_string(o.avoid_escape)) + ")";
      });
  xp.def("tree_search_controller", &ex::tree_search_controller,
         "The tree method's reactive search: straight ahead while clear, corridor escape.");
  xp.def("frontier_window_controller", &ex::frontier_window_controller,
         "The frontier methods' reactive windows: random turns up to 0.4 rad/s, rule 2 spins.");
  py::class_<ex::ExplorationOptions>(xp, "Options", "Exploration options; keywords = fields.")
      .def(py::init([](const py::kwargs& kw) {
        ex::ExplorationOptions o;
        apply_kwargs(o, kw, "explore.Options");
        return o;
      }))
      .def_readwrite("method", &ex::ExplorationOptions::method)
      .def_readwrite("robots", &ex::ExplorationOptions::robots)
      .def_readwrite("time_limit", &ex::ExplorationOptions::time_limit, "[s]")
      .def_readwrite("dt", &ex::ExplorationOptions::dt, "[s]")
      .def_readwrite("seed", &ex::ExplorationOptions::seed)
      .def_readwrite("start", &ex::ExplorationOptions::start, "[m] or None")
      .def_readwrite("start_spacing", &ex::ExplorationOptions::start_spacing, "[m]")
      .def_readwrite("stop_at_coverage", &ex::ExplorationOptions::stop_at_coverage)
      .def_readwrite("map_period", &ex::ExplorationOptions::map_period, "[s]")
      .def_readwrite("record_period", &ex::ExplorationOptions::record_period, "[s]")
      .def_readwrite("tree_start_time", &ex::ExplorationOptions::tree_start_time, "[s]")
      .def_readwrite("replan_period", &ex::ExplorationOptions::replan_period, "[s]")
      .def_readwrite("goal_tolerance", &ex::ExplorationOptions::goal_tolerance, "[m]")
      .def_readwrite("clearance", &ex::ExplorationOptions::clearance, "[m]")
      .def_readwrite("min_cell_size", &ex::ExplorationOptions::min_cell_size, "[m]")
      .def_readwrite("map_beam_stride", &ex::ExplorationOptions::map_beam_stride)
      .def_readwrite("tree_replan", &ex::ExplorationOptions::tree_replan)
      .def_readwrite("tree_leg_replan", &ex::ExplorationOptions::tree_leg_replan)
      .def_readwrite("hybrid_tree_start_time", &ex::ExplorationOptions::hybrid_tree_start_time,
                     "[s]")
      .def_readwrite("hybrid_tree_period", &ex::ExplorationOptions::hybrid_tree_period, "[s]")
      .def_readwrite("min_leaf_gain", &ex::ExplorationOptions::min_leaf_gain)
      .def_readwrite("gain_radius", &ex::ExplorationOptions::gain_radius, "[m]")
      .def_readwrite("stall_time", &ex::ExplorationOptions::stall_time, "[s]")
      .def_readwrite("stall_distance", &ex::ExplorationOptions::stall_distance, "[m]")
      .def_readwrite("stall_reach_radius", &ex::ExplorationOptions::stall_reach_radius,
                     "[m] 0 = the planning radius (CLI --stall-reach-radius)")
      .def_readwrite("unstick", &ex::ExplorationOptions::unstick, "tree (CLI --unstick on|off)")
      .def_readwrite("frontier_unstick", &ex::ExplorationOptions::frontier_unstick,
                     "frontier methods (CLI --frontier-unstick on|off)")
      .def_readwrite("idle_unstick", &ex::ExplorationOptions::idle_unstick,
                     "frontier methods, goalless robots (CLI --idle-unstick on|off)")
      .def_readwrite("disperse_neighbours", &ex::ExplorationOptions::disperse_neighbours,
                     "tree (CLI --disperse-neighbours on|off)")
      .def_readwrite("disperse_range", &ex::ExplorationOptions::disperse_range, "[m]")
      .def_readwrite("clear_way_out", &ex::ExplorationOptions::clear_way_out,
                     "tree (CLI --clear-way-out on|off)")
      .def_readwrite("unstick_retry", &ex::ExplorationOptions::unstick_retry,
                     "tree (CLI --unstick-retry on|off)")
      .def_readwrite("unstick_retry_period", &ex::ExplorationOptions::unstick_retry_period, "[s]")
      .def_readwrite("unstick_right_of_way", &ex::ExplorationOptions::unstick_right_of_way,
                     "tree (CLI --unstick-right-of-way on|off)")
      .def_readwrite("yield_to_held", &ex::ExplorationOptions::yield_to_held,
                     "every method (CLI --yield-to-held on|off)")
      .def_readwrite("retry_banned", &ex::ExplorationOptions::retry_banned,
                     "frontier methods (CLI --retry-banned on|off)")
      .def_readwrite("share_bans", &ex::ExplorationOptions::share_bans,
                     "frontier methods (CLI --share-bans on|off)")
      .def_readwrite("crowd_limit", &ex::ExplorationOptions::crowd_limit,
                     "frontier: 0 = off (CLI --crowd-limit N)")
      .def_readwrite("drop_goalless_routes", &ex::ExplorationOptions::drop_goalless_routes,
                     "frontier methods (CLI --drop-goalless-routes on|off)")
      .def_readwrite("margin_escape", &ex::ExplorationOptions::margin_escape,
                     "every method (CLI --margin-escape on|off)")
      .def_readwrite("skip_known_leaves", &ex::ExplorationOptions::skip_known_leaves,
                     "tree (CLI --skip-known-leaves on|off)")
      .def_readwrite("unknown_leaves_first", &ex::ExplorationOptions::unknown_leaves_first,
                     "tree (CLI --unknown-leaves-first on|off)")
      .def_readwrite("nearest_leaf_next", &ex::ExplorationOptions::nearest_leaf_next,
                     "tree (CLI --nearest-leaf-next on|off)")
      .def_readwrite("frontiers_after_leaves", &ex::ExplorationOptions::frontiers_after_leaves,
                     "tree (CLI --frontiers-after-leaves on|off)")
      .def_readwrite("gain_through_free", &ex::ExplorationOptions::gain_through_free,
                     "targets' information gain (CLI --gain-through-free on|off)")
      .def_readwrite("guard", &ex::ExplorationOptions::guard,
                     "every method: FrontGuard cone|corridor (CLI --guard)")
      .def_readwrite("controller", &ex::ExplorationOptions::controller,
                     "tree: the reactive search's ControllerOptions")
      .def_readwrite("frontier_controller", &ex::ExplorationOptions::frontier_controller,
                     "frontier methods: their reactive windows' ControllerOptions")
      .def("to_dict", &options_dict,
           "Every top-level option by name, as the CLI's `input` echoes it (on/off as strings).")
      .def("__repr__", [](const ex::ExplorationOptions& o) {
        return "explore.Options(method=" + std::string(ex::to_string(o.method)) +
               ", robots=" + std::to_string(o.robots) + ")";
      });
  xp.def(
      "run",
      [](const OccupancyGrid& world, const py::object& options, bool include_recording,
         const py::kwargs& kw) {
        ex::ExplorationOptions o =
            options.is_none() ? ex::ExplorationOptions{} : options.cast<ex::ExplorationOptions>();
        apply_kwargs(o, kw, "explore.run");
        std::string js;
        OccupancyGrid team;
        {
          py::gil_scoped_release release;
          auto r = ex::run_exploration(world, o);
          js = ex::to_json(r, include_recording);
          team = std::move(r.recording.team_map);
        }
        py::dict d = py::module_::import("json").attr("loads")(js);
        d["input"] = options_dict(o);
        d["team_map"] = std::move(team);
        return d;
      },
      py::arg("world"), py::arg("options") = py::none(), py::arg("include_recording") = false,
      "Runs one exploration; keywords override Options fields. Returns the result dict (coverage, "
      "t90_s, t99_s, distance_m, ...; frames with include_recording), 'input' (the options used, "
      "as the CLI echoes them) and 'team_map'.");
  xp.def("paper_world", &ex::paper_world, py::arg("resolution") = 0.05,
         "The 20 x 20 m world of seed 004; robots start near (2, 2).");

  auto rm =
      m.def_submodule("render", "Pictures of grids and what lies on them (PNG/SVG, numpy RGB).");
  py::class_<PyFigure>(rm, "Figure", "Draws rasters and shapes on a grid; save() or to_rgb().")
      .def(py::init([](const GridGeometry& g, double ppc, const std::string& title) {
             rd::FigureOptions o;
             o.pixels_per_cell = ppc;
             o.title = title;
             return PyFigure{g, rd::Figure(g, o)};
           }),
           py::arg("geometry"), py::arg("pixels_per_cell") = 0.0, py::arg("title") = "",
           "geometry: a GridGeometry (grid.geometry); pixels_per_cell 0 = larger side 900 px.")
      .def(
          "occupancy",
          [](PyFigure& f, const OccupancyGrid& g) {
            f.f.occupancy(g);
            return &f;
          },
          py::return_value_policy::reference_internal)
      .def(
          "binary",
          [](PyFigure& f, const BinaryGrid& g, py::handle on, py::handle off) {
            f.f.binary(g, to_color(on), off.is_none() ? rd::colors::kTransparent : to_color(off));
            return &f;
          },
          py::arg("grid"), py::arg("on") = "black", py::arg("off") = py::none(),
          py::return_value_policy::reference_internal)
      .def(
          "scalar",
          [](PyFigure& f, const GridMap<float>& g, double lo, double hi, double alpha) {
            f.f.scalar(g, lo, hi, alpha);
            return &f;
          },
          py::arg("field"), py::arg("lo"), py::arg("hi"), py::arg("alpha") = 1.0,
          py::return_value_policy::reference_internal)
      .def(
          "labels",
          [](PyFigure& f, const GridMap<std::int32_t>& g, double alpha) {
            f.f.labels(g, alpha);
            return &f;
          },
          py::arg("labels"), py::arg("alpha") = 0.55, py::return_value_policy::reference_internal)
      .def(
          "cells",
          [](PyFigure& f, const py::object& cells, py::handle color) {
            f.f.cells(cells_from(f.g, cells), to_color(color));
            return &f;
          },
          py::arg("cells"), py::arg("color"), py::return_value_policy::reference_internal)
      .def(
          "path",
          [](PyFigure& f, const py::object& cells, py::handle color, double w) {
            f.f.path(cells_from(f.g, cells), to_color(color), w);
            return &f;
          },
          py::arg("cells"), py::arg("color") = "red", py::arg("width_px") = 2.5,
          py::return_value_policy::reference_internal)
      .def(
          "marker",
          [](PyFigure& f, py::handle c, py::handle color, double r, const std::string& label) {
            f.f.marker(to_cell(f.g, c, "cell"), to_color(color), r, label);
            return &f;
          },
          py::arg("cell"), py::arg("color") = "red", py::arg("radius_px") = 6.0,
          py::arg("label") = "", py::return_value_policy::reference_internal)
      .def(
          "polyline",
          [](PyFigure& f, const py::object& pts, py::handle color, double w, bool closed) {
            f.f.polyline(points_from(pts), to_color(color), w, closed);
            return &f;
          },
          py::arg("points"), py::arg("color") = "blue", py::arg("width_px") = 2.0,
          py::arg("closed") = false, py::return_value_policy::reference_internal,
          "points: [(x, y), ...] [m]")
      .def(
          "segment",
          [](PyFigure& f, py::handle a, py::handle b, py::handle color, double w) {
            f.f.segment(point_from(a), point_from(b), to_color(color), w);
            return &f;
          },
          py::arg("a"), py::arg("b"), py::arg("color") = "blue", py::arg("width_px") = 1.5,
          py::return_value_policy::reference_internal)
      .def(
          "point",
          [](PyFigure& f, py::handle p, py::handle color, double r) {
            f.f.point(point_from(p), to_color(color), r);
            return &f;
          },
          py::arg("p"), py::arg("color") = "red", py::arg("radius_px") = 3.0,
          py::return_value_policy::reference_internal)
      .def(
          "circle",
          [](PyFigure& f, py::handle c, double r, py::handle fill, py::handle stroke) {
            f.f.circle(point_from(c), r, to_color(fill),
                       stroke.is_none() ? rd::colors::kTransparent : to_color(stroke));
            return &f;
          },
          py::arg("centre"), py::arg("radius_m"), py::arg("fill") = "orange",
          py::arg("stroke") = py::none(), py::return_value_policy::reference_internal)
      .def(
          "text",
          [](PyFigure& f, py::handle p, const std::string& t, py::handle color, double size) {
            f.f.text(point_from(p), t, to_color(color), size);
            return &f;
          },
          py::arg("p"), py::arg("text"), py::arg("color") = "black", py::arg("size_px") = 12.0,
          py::return_value_policy::reference_internal)
      .def(
          "legend",
          [](PyFigure& f, const py::list& entries) {
            std::vector<std::pair<std::string, rd::Color>> e;
            for (auto it : entries) {
              auto t = it.cast<py::sequence>();
              e.emplace_back(t[0].cast<std::string>(), to_color(t[1]));
            }
            f.f.legend(std::move(e));
            return &f;
          },
          py::arg("entries"), py::return_value_policy::reference_internal, "[(name, color), ...]")
      .def(
          "save",
          [](const PyFigure& f, const std::string& p) {
            py::gil_scoped_release release;
            f.f.save(p);
          },
          py::arg("path"), ".png or .svg")
      .def(
          "to_rgba",
          [](const PyFigure& f) {
            std::vector<std::uint8_t> px;
            {
              py::gil_scoped_release release;
              px = f.f.to_rgba();
            }
            py::array_t<std::uint8_t> a({static_cast<py::ssize_t>(f.f.height_px()),
                                         static_cast<py::ssize_t>(f.f.width_px()), py::ssize_t{4}});
            std::copy(px.begin(), px.end(), a.mutable_data());
            return a;
          },
          "uint8 (height_px, width_px, 4) RGBA image, top row first (plt.imshow shows it as saved)")
      .def(
          "to_rgb",
          [](const PyFigure& f) {
            std::vector<std::uint8_t> px;
            {
              py::gil_scoped_release release;
              px = f.f.to_rgba();
            }
            py::array_t<std::uint8_t> a({static_cast<py::ssize_t>(f.f.height_px()),
                                         static_cast<py::ssize_t>(f.f.width_px()), py::ssize_t{3}});
            std::uint8_t* out = a.mutable_data();
            for (std::size_t i = 0, k = 0; i < px.size(); i += 4) {
              const unsigned alpha = px[i + 3];
              for (std::size_t c = 0; c < 3;
                   ++c)  // composed over white, as image viewers show a PNG
                out[k++] = static_cast<std::uint8_t>(
                    (px[i + c] * alpha + 255U * (255U - alpha) + 127U) / 255U);
            }
            return a;
          },
          "uint8 (height_px, width_px, 3) RGB image on white, top row first (for plt.imshow)")
      .def_property_readonly("width_px", [](const PyFigure& f) { return f.f.width_px(); })
      .def_property_readonly("height_px", [](const PyFigure& f) { return f.f.height_px(); })
      .def("__repr__", [](const PyFigure& f) {
        return "Figure(" + std::to_string(f.f.width_px()) + "x" + std::to_string(f.f.height_px()) +
               " px)";
      });
}

void bind_render(py::module_&) {}  // bound with bind_sim (one translation unit fewer to compile)

}  // namespace voronav::python
