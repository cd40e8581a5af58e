// mapping (log-odds occupancy map, laser/sonar insert, simulated sensors and sweep) and
// coordination (robots on fixed paths from Python lists or files, coordinate() -> schedule,
// continuous-time validation). Invalid schedules and failed searches are returned as status.
#include <cmath>

#include "common.hpp"
#include "voronav/coordination/coordinator.hpp"
#include "voronav/coordination/priority_search.hpp"
#include "voronav/coordination/scenario.hpp"
#include "voronav/coordination/schedule_io.hpp"
#include "voronav/mapping/occupancy_map.hpp"
#include "voronav/mapping/range_simulation.hpp"
#include "voronav/mapping/sweep.hpp"

namespace voronav::python {

namespace {

namespace mp = voronav::mapping;
namespace co = voronav::coordination;

mp::RangeScan make_scan(const Pose2& pose, const std::vector<double>& bearings,
                        const std::vector<double>& ranges) {
  if (bearings.size() != ranges.size())
    throw Error("scan", 0,
                "bearings and ranges differ in length (" + std::to_string(bearings.size()) +
                    " vs " + std::to_string(ranges.size()) + ")");
  return {pose, bearings, ranges};
}

py::tuple scan_tuple(const mp::RangeScan& s) {
  return py::make_tuple(
      py::array_t<double>(static_cast<py::ssize_t>(s.bearings.size()), s.bearings.data()),
      py::array_t<double>(static_cast<py::ssize_t>(s.ranges.size()), s.ranges.data()));
}

py::dict agreement_dict(const mp::CellAgreement& a) {
  return py::dict(py::arg("agreement") = a.agreement, py::arg("observed") = a.observed,
                  py::arg("compared") = a.compared);
}

std::vector<Vec2> points_from(const py::handle& h, const char* what) {
  std::vector<Vec2> out;
  for (auto p : h.cast<py::iterable>()) {
    auto s = p.cast<py::sequence>();
    if (s.size() != 2) throw Error(what, 0, "each point is (x, y) [m]");
    out.push_back({s[0].cast<double>(), s[1].cast<double>()});
  }
  return out;
}

py::list conflicts_list(const std::vector<co::Conflict>& cs) {
  py::list l;
  for (const auto& c : cs)
    l.append(py::dict(py::arg("a") = c.a, py::arg("b") = c.b, py::arg("time") = c.time,
                      py::arg("distance") = c.distance));
  return l;
}

/// coordinate()'s result together with the agents it scheduled (ids, schedule export).
struct PySchedule {
  co::CoordinationResult r;
  std::vector<co::Agent> agents;
  co::CollisionMapOptions map;
  [[nodiscard]] co::Schedule schedule() const {
    return {agents, r.delays, map.at_start, map.at_goal, r.valid, {}, {}};
  }
};

}  // namespace

void bind_mapping(py::module_& m) {
  auto mm =
      m.def_submodule("mapping", "Log-odds occupancy mapping with sonar/laser models (seed 003).");
  py::class_<mp::SonarModelOptions>(mm, "SonarModelOptions",
                                    "Sonar inverse model; keywords = fields.")
      .def(py::init([](const py::kwargs& kw) {
        mp::SonarModelOptions o;
        apply_kwargs(o, kw, "SonarModelOptions");
        return o;
      }))
      .def_readwrite("half_angle", &mp::SonarModelOptions::half_angle, "[rad]")
      .def_readwrite("max_range", &mp::SonarModelOptions::max_range, "[m]")
      .def_readwrite("sigma", &mp::SonarModelOptions::sigma, "[m], 0 = cell size")
      .def_readwrite("p_occupied", &mp::SonarModelOptions::p_occupied)
      .def_readwrite("p_empty", &mp::SonarModelOptions::p_empty);
  py::class_<mp::LaserModelOptions>(mm, "LaserModelOptions", "Laser beam model; keywords = fields.")
      .def(py::init([](const py::kwargs& kw) {
        mp::LaserModelOptions o;
        apply_kwargs(o, kw, "LaserModelOptions");
        return o;
      }))
      .def_readwrite("max_range", &mp::LaserModelOptions::max_range, "[m]")
      .def_readwrite("p_occupied", &mp::LaserModelOptions::p_occupied)
      .def_readwrite("p_empty", &mp::LaserModelOptions::p_empty);
  py::class_<mp::OccupancyMap>(mm, "OccupancyMap", "Log-odds occupancy grid (prior 0.5 = 0).")
      .def(py::init([](const GridGeometry& g, double prior, double clamp_min, double clamp_max) {
             return mp::OccupancyMap(g, {prior, clamp_min, clamp_max});
           }),
           py::arg("geometry"), py::arg("prior") = 0.5, py::arg("clamp_min") = 0.12,
           py::arg("clamp_max") = 0.97)
      .def_property_readonly("geometry", &mp::OccupancyMap::geometry)
      .def_property_readonly("log_odds", &mp::OccupancyMap::log_odds,
                             py::return_value_policy::reference_internal,
                             "FloatGrid of log-odds (0 = prior); .array is a zero-copy view")
      .def("probability",
           [](const mp::OccupancyMap& o, py::handle c) {
             return o.probability(to_cell(o.geometry(), c, "cell"));
           })
      .def("observed", [](const mp::OccupancyMap& o,
                          py::handle c) { return o.observed(to_cell(o.geometry(), c, "cell")); })
      .def(
          "update",
          [](mp::OccupancyMap& o, py::handle c, double p) {
            o.update(to_cell(o.geometry(), c, "cell"), p);
          },
          py::arg("cell"), py::arg("p_occupied"), "One Bayesian update with P(OCC|d).")
      .def(
          "insert_sonar",
          [](mp::OccupancyMap& o, const Pose2& pose, double range,
             const mp::SonarModelOptions& model) { o.insert_sonar(pose, range, model); },
          py::arg("pose"), py::arg("range"), py::arg("model") = mp::SonarModelOptions{},
          "One sonar reading range [m] from sensor pose (beam axis = yaw).")
      .def(
          "insert_sonar_scan",
          [](mp::OccupancyMap& o, const Pose2& pose, const std::vector<double>& b,
             const std::vector<double>& r, const mp::SonarModelOptions& model) {
            const auto scan = make_scan(pose, b, r);
            py::gil_scoped_release release;
            o.insert_scan(scan, model);
          },
          py::arg("pose"), py::arg("bearings"), py::arg("ranges"),
          py::arg("model") = mp::SonarModelOptions{},
          "Readings ranges [m] at bearings [rad, sensor frame] with the sonar model.")
      .def(
          "insert_laser_scan",
          [](mp::OccupancyMap& o, const Pose2& pose, const std::vector<double>& b,
             const std::vector<double>& r, const mp::LaserModelOptions& model) {
            const auto scan = make_scan(pose, b, r);
            py::gil_scoped_release release;
            o.insert_scan(scan, model);
          },
          py::arg("pose"), py::arg("bearings"), py::arg("ranges"),
          py::arg("model") = mp::LaserModelOptions{},
          "Readings ranges [m] at bearings [rad, sensor frame] with the laser beam model.")
      .def("to_occupancy_grid", &mp::OccupancyMap::to_occupancy_grid,
           "-1 never observed, else round(100 P)")
      .def(
          "threshold",
          [](const mp::OccupancyMap& o, double free_below, double occupied_above) {
            return o.threshold({free_below, occupied_above, true});
          },
          py::arg("free_below") = 0.35, py::arg("occupied_above") = 0.65)
      .def(
          "to_binary",
          [](const mp::OccupancyMap& o, double free_below, double occupied_above,
             bool unknown_is_blocked) {
            return o.to_binary({free_below, occupied_above, unknown_is_blocked});
          },
          py::arg("free_below") = 0.35, py::arg("occupied_above") = 0.65,
          py::arg("unknown_is_blocked") = true)
      .def("__repr__", [](const mp::OccupancyMap& o) {
        return "OccupancyMap(" + std::to_string(o.geometry().width) + "x" +
               std::to_string(o.geometry().height) + ")";
      });
  mm.def(
      "simulate_laser_scan",
      [](const BinaryGrid& world, const Pose2& pose, int beams, double fov, double max_range,
         double noise, std::uint64_t seed) {
        mp::RangeScan s;
        {
          py::gil_scoped_release release;
          s = mp::simulate_laser_scan(world, pose, {beams, fov, max_range, noise, seed});
        }
        return scan_tuple(s);
      },
      py::arg("world"), py::arg("pose"), py::arg("beams") = 360,
      py::arg("field_of_view") = 2 * M_PI, py::arg("max_range") = 10.0,
      py::arg("noise_stddev") = 0.0, py::arg("seed") = 1,
      "(bearings [rad], ranges [m]) of a laser scan over a BinaryGrid.");
  mm.def(
      "simulate_sonar_ring",
      [](const BinaryGrid& world, const Pose2& pose, int sonars, double half_angle,
         double max_range, int rays) {
        mp::RangeScan s;
        {
          py::gil_scoped_release release;
          s = mp::simulate_sonar_ring(world, pose, {sonars, half_angle, max_range, rays});
        }
        return scan_tuple(s);
      },
      py::arg("world"), py::arg("pose"), py::arg("sonars") = 16,
      py::arg("half_angle") = 12.5 * M_PI / 180.0, py::arg("max_range") = 5.0,
      py::arg("rays_per_cone") = 9, "(bearings [rad], ranges [m]) of a sonar ring.");
  mm.def(
      "simulate_sweep",
      [](const BinaryGrid& truth, const std::string& sensor, int poses, double range,
         double clearance, double noise, std::uint64_t seed) {
        mp::SweepOptions o;
        if (sensor != "laser" && sensor != "sonar")
          throw Error("sensor", 0, "'" + sensor + "': expected laser or sonar");
        o.sensor = sensor == "laser" ? mp::SweepSensor::kLaser : mp::SweepSensor::kSonar;
        o.poses = poses;
        o.range = range;
        o.clearance = clearance;
        o.noise_stddev = noise;
        o.seed = seed;
        std::optional<mp::SweepResult> r;
        {
          py::gil_scoped_release release;
          r.emplace(mp::simulate_sweep(truth, o));
        }
        py::list ps;
        for (const auto& p : r->poses)
          ps.append(p);
        return py::make_tuple(std::move(r->map), ps, agreement_dict(r->agreement));
      },
      py::arg("truth"), py::arg("sensor") = "laser", py::arg("poses") = 100, py::arg("range") = 0.0,
      py::arg("clearance") = 0.3, py::arg("noise_stddev") = 0.0, py::arg("seed") = 1,
      "(OccupancyMap, poses, agreement dict) of a simulated sensing sweep over a ground truth.");
  mm.def(
      "cell_agreement",
      [](const OccupancyGrid& map, const BinaryGrid& truth) {
        return agreement_dict(mp::cell_agreement(map, truth));
      },
      py::arg("map"), py::arg("truth"));
}

void bind_coordination(py::module_& m) {
  auto cm = m.def_submodule("coordination", "Start delays for robots on fixed paths (seed 002).");
  bind_enum<co::AtStart>(cm, "AtStart",
                         {{"wait", co::AtStart::kWait}, {"appear", co::AtStart::kAppear}});
  bind_enum<co::AtGoal>(cm, "AtGoal", {{"stay", co::AtGoal::kStay}, {"leave", co::AtGoal::kLeave}});

  py::class_<co::Agent>(cm, "Agent", "A disc robot of radius [m] on a timed path [m] (seed 002).")
      .def(py::init([](int id, const py::object& path, double radius, double v_max, double a_max) {
             return co::Agent{id, co::TimedPath(points_from(path, "path"), {v_max, a_max}), radius};
           }),
           py::arg("id"), py::arg("path"), py::arg("radius") = 0.5, py::arg("v_max") = 1.0,
           py::arg("a_max") = co::kInfinity,
           "path: [(x, y), ...] [m]; v_max [m/s]; a_max [m/s^2] (inf = instantaneous).")
      .def_readonly("id", &co::Agent::id)
      .def_readonly("radius", &co::Agent::radius, "[m]")
      .def_property_readonly(
          "path", [](const co::Agent& a) { return points_array(a.path.nodes()); }, "[m], (N, 2)")
      .def_property_readonly("v_max", [](const co::Agent& a) { return a.path.limits().v_max; })
      .def_property_readonly("a_max", [](const co::Agent& a) { return a.path.limits().a_max; })
      .def_property_readonly(
          "length", [](const co::Agent& a) { return a.path.length(); }, "[m]")
      .def_property_readonly(
          "travel_time", [](const co::Agent& a) { return a.path.travel_time(); }, "[s]")
      .def(
          "position", [](const co::Agent& a, double t) { return a.path.position(t); }, py::arg("t"),
          "Position [m] t [s] after departure")
      .def("__repr__", [](const co::Agent& a) {
        return "Agent(" + std::to_string(a.id) + ", " + std::to_string(a.path.nodes().size()) +
               " nodes, length " + std::to_string(a.path.length()) + " m, radius " +
               std::to_string(a.radius) + " m)";
      });

  py::class_<co::Scenario>(cm, "Scenario", "Robots with start/goal or explicit paths on a map.")
      .def(py::init([](const py::list& robots, const py::object& map, bool cell_coordinates,
                       double node_spacing, co::AtStart at_start, co::AtGoal at_goal) {
             co::Scenario s;
             s.source = "<python>";
             if (!map.is_none())
               s.map = io::LoadedMap{map.cast<OccupancyGrid>(), io::MapFormat::kRos, "<python>"};
             s.cell_coordinates = cell_coordinates;
             s.map_options.node_spacing = node_spacing;
             s.map_options.at_start = at_start;
             s.map_options.at_goal = at_goal;
             int k = 0;
             for (auto item : robots) {
               ++k;
               auto d = item.cast<py::dict>();
               co::RobotSpec r;
               r.id = d.contains("id") ? d["id"].cast<int>() : k;
               r.line = k;
               for (auto kv : d) {
                 const std::string key = py::str(kv.first);
                 if (key != "id" && key != "start" && key != "goal" && key != "path" &&
                     key != "radius" && key != "v_max" && key != "a_max")
                   throw Error(
                       "robots[" + std::to_string(k - 1) + "]", 0,
                       "unknown key '" + key + "' (id, start, goal, path, radius, v_max, a_max)");
               }
               auto pt = [&](const char* key) {
                 auto s2 = d[key].cast<py::sequence>();
                 return Vec2{s2[0].cast<double>(), s2[1].cast<double>()};
               };
               if (d.contains("start")) r.start = pt("start");
               if (d.contains("goal")) r.goal = pt("goal");
               if (d.contains("path")) r.path = points_from(d["path"], "path");
               if (d.contains("radius")) r.radius = d["radius"].cast<double>();
               if (d.contains("v_max")) r.limits.v_max = d["v_max"].cast<double>();
               if (d.contains("a_max")) r.limits.a_max = d["a_max"].cast<double>();
               if (r.path.empty() && (!r.start || !r.goal))
                 throw Error("robots[" + std::to_string(k - 1) + "]", 0,
                             "give a path or a start and a goal");
               if (r.path.empty() && !s.map)
                 throw Error("robots[" + std::to_string(k - 1) + "]", 0,
                             "start/goal need a map to plan on");
               s.robots.push_back(std::move(r));
             }
             return s;
           }),
           py::arg("robots"), py::arg("map") = py::none(), py::arg("cell_coordinates") = false,
           py::arg("node_spacing") = 0.0, py::arg("at_start") = co::AtStart::kWait,
           py::arg("at_goal") = co::AtGoal::kStay,
           "robots: [{'id', 'start': (x, y), 'goal': (x, y) | 'path': [(x, y), ...], 'radius' [m], "
           "'v_max' [m/s], 'a_max' [m/s^2]}, ...]; start/goal in metres, or cells with "
           "cell_coordinates=True; node_spacing [m], 0 = automatic.")
      .def_property_readonly("robots", [](const co::Scenario& s) { return s.robots.size(); })
      .def_property_readonly("map",
                             [](const co::Scenario& s) -> py::object {
                               if (!s.map) return py::none();
                               return py::cast(s.map->grid);
                             })
      .def_property_readonly("node_spacing",
                             [](const co::Scenario& s) { return s.map_options.node_spacing; })
      .def_property_readonly("at_start",
                             [](const co::Scenario& s) { return s.map_options.at_start; })
      .def_property_readonly("at_goal", [](const co::Scenario& s) { return s.map_options.at_goal; })
      .def(
          "plan_agents",
          [](const co::Scenario& s) {
            co::PlannedAgents p;
            {
              py::gil_scoped_release release;
              p = co::plan_agents(s);
            }
            return p.agents;
          },
          "Plans every robot's path (A* on the map inflated by its radius); explicit paths kept.")
      .def("__repr__", [](const co::Scenario& s) {
        return "Scenario(" + std::to_string(s.robots.size()) + " robots" +
               (s.map ? ", with map" : "") + ")";
      });
  cm.def(
      "load_scenario", [](const std::string& p) { return co::load_scenario(p); }, py::arg("path"),
      "A coordination scenario YAML (docs/formats.md).");
  cm.def(
      "load_mapf",
      [](const std::string& map, const std::string& scen, int k, double radius) {
        return co::load_mapf(map, scen, k, radius);
      },
      py::arg("map"), py::arg("scen"), py::arg("agents"), py::arg("radius") = 0.5,
      "The first `agents` rows of a MAPF .scen as robots.");

  py::class_<PySchedule>(cm, "CoordinationResult", "coordinate()'s schedule: check .ok and .valid.")
      .def_property_readonly(
          "status", [](const PySchedule& s) { return std::string(co::to_string(s.r.status)); })
      .def_property_readonly(
          "ok", [](const PySchedule& s) { return s.r.status == co::ResolveStatus::kOk; })
      .def_property_readonly("message", [](const PySchedule& s) { return s.r.message; })
      .def_property_readonly(
          "order", [](const PySchedule& s) { return s.r.order; },
          "Robot indices, highest priority first")
      .def_property_readonly("order_ids",
                             [](const PySchedule& s) {
                               std::vector<int> ids;
                               for (int i : s.r.order)
                                 ids.push_back(s.agents[static_cast<std::size_t>(i)].id);
                               return ids;
                             })
      .def_property_readonly("ids",
                             [](const PySchedule& s) {
                               std::vector<int> ids;
                               for (const auto& a : s.agents)
                                 ids.push_back(a.id);
                               return ids;
                             })
      .def_property_readonly(
          "delays", [](const PySchedule& s) { return s.r.delays; }, "Start delay per robot [s]")
      .def_property_readonly(
          "arrivals", [](const PySchedule& s) { return s.r.arrivals; }, "[s]")
      .def_property_readonly(
          "makespan", [](const PySchedule& s) { return s.r.makespan; }, "[s]")
      .def_property_readonly(
          "sum_of_arrivals", [](const PySchedule& s) { return s.r.sum_of_arrivals; }, "[s]")
      .def_property_readonly(
          "valid", [](const PySchedule& s) { return s.r.valid; },
          "The continuous-time check passed")
      .def_property_readonly("verified", [](const PySchedule& s) { return s.r.verified; })
      .def_property_readonly("repairs", [](const PySchedule& s) { return s.r.repairs; })
      .def_property_readonly("missed",
                             [](const PySchedule& s) { return conflicts_list(s.r.missed); })
      .def_property_readonly("remaining",
                             [](const PySchedule& s) { return conflicts_list(s.r.remaining); })
      .def_property_readonly("boxes", [](const PySchedule& s) { return s.r.boxes; })
      .def_property_readonly("evaluations",
                             [](const PySchedule& s) { return s.r.search.evaluations; })
      .def_property_readonly("time_ms", [](const PySchedule& s) { return s.r.time_ms; })
      .def_property_readonly("agents", [](const PySchedule& s) { return s.agents; })
      .def(
          "to_json", [](const PySchedule& s) { return co::schedule_to_json(s.schedule()); },
          "The schedule file format (voronav validate-schedule reads it)")
      .def(
          "save",
          [](const PySchedule& s, const std::string& p) { co::write_schedule(p, s.schedule()); },
          py::arg("path"), ".json or .yaml")
      .def("__repr__", [](const PySchedule& s) {
        return "CoordinationResult(" + std::string(co::to_string(s.r.status)) + ", " +
               std::to_string(s.agents.size()) + " robots, makespan " +
               std::to_string(s.r.makespan) + " s, valid " + (s.r.valid ? "True" : "False") + ")";
      });
  cm.def(
      "coordinate",
      [](const std::vector<co::Agent>& agents, const std::string& search, std::uint64_t seed,
         bool edf_reduction, double node_spacing, co::AtStart at_start, co::AtGoal at_goal,
         bool verify, const std::string& ga_preset) {
        co::CoordinateOptions o;
        o.search.kind = co::parse_search_kind(search);
        o.search.ga = co::ga_preset(ga_preset);
        o.search.ga.seed = seed;
        o.search.edf_reduction = edf_reduction;
        o.map.node_spacing = node_spacing;
        o.map.at_start = at_start;
        o.map.at_goal = at_goal;
        o.verify = verify;
        PySchedule out;
        {
          py::gil_scoped_release release;
          out.r = co::coordinate(agents, o);
        }
        out.agents = agents;
        out.map = o.map;
        return out;
      },
      py::arg("agents"), py::arg("search") = "ga", py::arg("seed") = 1,
      py::arg("edf_reduction") = true, py::arg("node_spacing") = 0.0,
      py::arg("at_start") = co::AtStart::kWait, py::arg("at_goal") = co::AtGoal::kStay,
      py::arg("verify") = true, py::arg("ga_preset") = "paper",
      "Collision boxes, (M,D) network, priority search (none | exhaustive | edf | ga), start "
      "delays, continuous-time check. node_spacing [m] (0 = automatic). ga_preset: the GA's "
      "settings by name, 'paper' (the paper's GA) or 'fast' (issue #16, CLI --ga-preset).");
  cm.def(
      "verify_schedule",
      [](const std::vector<co::Agent>& agents, const std::vector<double>& delays,
         co::AtStart at_start, co::AtGoal at_goal, double tolerance) {
        if (delays.size() != agents.size())
          throw Error("delays", 0,
                      "one delay per agent expected (" + std::to_string(agents.size()) + "), got " +
                          std::to_string(delays.size()));
        co::VerifyOptions o;
        o.at_start = at_start;
        o.at_goal = at_goal;
        o.tolerance = tolerance;
        co::Verification v;
        {
          py::gil_scoped_release release;
          v = co::verify_schedule(agents, delays, o);
        }
        return py::dict(py::arg("valid") = v.valid,
                        py::arg("conflicts") = conflicts_list(v.conflicts),
                        py::arg("undecided_pairs") = v.undecided_pairs,
                        py::arg("min_clearance") = v.min_clearance);
      },
      py::arg("agents"), py::arg("delays"), py::arg("at_start") = co::AtStart::kWait,
      py::arg("at_goal") = co::AtGoal::kStay, py::arg("tolerance") = 1e-6,
      "Checks that no two discs overlap in continuous time; returns {valid, conflicts, ...}.");
  cm.def(
      "read_schedule",
      [](const std::string& p) {
        const auto s = co::read_schedule(p);
        return py::dict(py::arg("agents") = s.agents, py::arg("delays") = s.delays,
                        py::arg("at_start") = s.at_start, py::arg("at_goal") = s.at_goal,
                        py::arg("valid") = s.valid);
      },
      py::arg("path"));
}

}  // namespace voronav::python
