// Planning: any planner of the factory by name (planner_names(); new planners appear without
// rebinding) plus the topological planner ("topo"), RAS with its numbered regions, and results
// with status, path in cells and metres, length, expanded. Status results are returned, never
// raised; the GIL is released while planning.
#include <mutex>

#include "common.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/planner_factory.hpp"
#include "voronav/planning/ras.hpp"
#include "voronav/topology/topo_planner.hpp"

namespace voronav::python {

namespace {

py::array_t<std::int32_t> cells_array(const std::vector<Cell>& cells) {
  py::array_t<std::int32_t> a({static_cast<py::ssize_t>(cells.size()), py::ssize_t{2}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    v(static_cast<py::ssize_t>(i), 0) = cells[i].x;
    v(static_cast<py::ssize_t>(i), 1) = cells[i].y;
  }
  return a;
}

py::array_t<double> world_array(const GridGeometry& g, const std::vector<Cell>& cells) {
  py::array_t<double> a({static_cast<py::ssize_t>(cells.size()), py::ssize_t{2}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Vec2 p = g.cell_center(cells[i]);
    v(static_cast<py::ssize_t>(i), 0) = p.x;
    v(static_cast<py::ssize_t>(i), 1) = p.y;
  }
  return a;
}

/// A PlanResult with the geometry of the grid it was planned on (for metres).
struct PyPlanResult {
  planning::PlanResult r;
  GridGeometry g;
  std::string planner;
};

/// Any GridPlanner, made by name. A planner is a reusable workspace (its buffers are reused by
/// every query), and plan() runs without the GIL, so two Python threads sharing one Planner are
/// serialized by the mutex instead of racing on those buffers.
struct PyPlanner {
  std::unique_ptr<planning::GridPlanner> p;
  std::unique_ptr<std::mutex> busy = std::make_unique<std::mutex>();
  PyPlanResult plan(const BinaryGrid& grid, Cell start, Cell goal) {
    const std::lock_guard<std::mutex> lock(*busy);
    return {p->plan(grid, start, goal), grid.geometry(), std::string(p->name())};
  }
};

planning::Connectivity to_connectivity(int c) {
  if (c != 4 && c != 8) throw Error("connectivity", 0, "expected 4 or 8, got " + std::to_string(c));
  return c == 4 ? planning::Connectivity::k4 : planning::Connectivity::k8;
}

std::vector<std::string> all_planner_names() {
  std::vector<std::string> names;
  for (auto n : planning::planner_names())
    names.emplace_back(n);
  names.emplace_back("topo");
  return names;
}

PyPlanner make_py_planner(const std::string& name, int connectivity, double robot_radius,
                          bool record_expanded, const planning::RasOptions& ras,
                          const topology::TopologyOptions& topo) {
  planning::PlannerOptions o;
  o.connectivity = to_connectivity(connectivity);
  o.robot_radius = robot_radius;
  o.record_expanded = record_expanded;
  if (name == "topo") return {std::make_unique<topology::TopologicalPlanner>(o, topo)};
  return {planning::make_planner(planning::parse_planner_kind(name), o, ras)};
}

/// RasResult plus what a user inspects: the region ids of the numbering and the region grid.
struct PyRasResult {
  planning::RasResult r;
  GridGeometry g;
  GridMap<std::int32_t> ids;  ///< per region: id >= 0, -1 obstacle, -2 below density, -3 unnumbered
  BinaryGrid region_blocked;
  int region_size = 1;
  int steps = 0;
};

}  // namespace

void bind_planning(py::module_& m) {
  auto pl = m.def_submodule("planning", "Grid planners (A*, Dijkstra, RAS, topological, ...).");
  pl.def("planner_names", &all_planner_names,
         "Names accepted by Planner(): the factory's planners and 'topo'.");

  py::class_<PyPlanResult>(pl, "PlanResult", "What a planner returns; check .ok or .status.")
      .def_property_readonly(
          "status", [](const PyPlanResult& r) { return std::string(to_string(r.r.status)); },
          "'ok', 'start_occupied', 'goal_occupied', 'out_of_map', "
          "'unreachable' or 'cancelled'")
      .def_property_readonly("ok", [](const PyPlanResult& r) { return r.r.ok(); })
      .def_property_readonly("planner", [](const PyPlanResult& r) { return r.planner; })
      .def_property_readonly(
          "path", [](const PyPlanResult& r) { return cells_array(r.r.path); },
          "Cells (x, y) start..goal, int32 array (N, 2); empty unless ok")
      .def_property_readonly(
          "path_m", [](const PyPlanResult& r) { return world_array(r.g, r.r.path); },
          "Cell centres of the path in world metres, float64 (N, 2)")
      .def_property_readonly(
          "length_cells", [](const PyPlanResult& r) { return r.r.length_cells; },
          "Octile length [cells] (1 per straight step, sqrt 2 per diagonal)")
      .def_property_readonly(
          "length_m", [](const PyPlanResult& r) { return r.r.length_cells * r.g.resolution; },
          "Octile length [m]")
      .def_property_readonly(
          "expanded", [](const PyPlanResult& r) { return r.r.expanded; },
          "Expanded nodes (numbered regions for RAS)")
      .def_property_readonly(
          "time_ms", [](const PyPlanResult& r) { return r.r.time_ms; }, "[ms]")
      .def_property_readonly(
          "expanded_cells", [](const PyPlanResult& r) { return cells_array(r.r.expanded_cells); },
          "With record_expanded: the expanded cells, int32 (N, 2)")
      .def("__bool__", [](const PyPlanResult& r) { return r.r.ok(); })
      .def("__repr__", [](const PyPlanResult& r) {
        std::string s = "PlanResult(" + r.planner + ", " + std::string(to_string(r.r.status));
        if (r.r.ok())
          s += ", " + std::to_string(r.r.path.size()) + " cells, length " +
               std::to_string(r.r.length_cells) + " cells";
        return s + ", expanded " + std::to_string(r.r.expanded) + ")";
      });

  bind_enum<planning::RegionRule>(pl, "RegionRule",
                                  {{"any_blocked", planning::RegionRule::kAnyBlocked},
                                   {"majority_blocked", planning::RegionRule::kMajorityBlocked}});
  bind_enum<planning::RasDirection>(
      pl, "RasDirection",
      {{"default", planning::RasDirection::kDefault},
       {"optimal", planning::RasDirection::kOptimal},
       {"optimal_per_region", planning::RasDirection::kOptimalPerRegion}});
  bind_enum<planning::RasExtent>(pl, "RasExtent",
                                 {{"until_goal", planning::RasExtent::kUntilGoal},
                                  {"whole_map", planning::RasExtent::kWholeMap}});
  bind_enum<planning::RasStartDensity>(pl, "RasStartDensity",
                                       {{"exempt", planning::RasStartDensity::kExempt},
                                        {"enforced", planning::RasStartDensity::kEnforced}});
  bind_enum<planning::RasCornerRule>(
      pl, "RasCornerRule",
      {{"no_corner_cutting", planning::RasCornerRule::kNoCornerCutting},
       {"allow_corner_cutting", planning::RasCornerRule::kAllowCornerCutting}});
  py::class_<planning::RasOptions>(pl, "RasOptions",
                                   "Options of RAS (seed 001); keywords = fields.")
      .def(py::init([](const py::kwargs& kw) {
        planning::RasOptions o;
        apply_kwargs(o, kw, "RasOptions");
        planning::validate(o);
        return o;
      }))
      .def_readwrite("region_size", &planning::RasOptions::region_size,
                     "Region side S_p [cells], >= 1")
      .def_readwrite("region_rule", &planning::RasOptions::region_rule)
      .def_readwrite("density", &planning::RasOptions::density, "Density threshold D in [0, 8]")
      .def_readwrite("direction", &planning::RasOptions::direction)
      .def_property(
          "connectivity",
          [](const planning::RasOptions& o) { return static_cast<int>(o.connectivity); },
          [](planning::RasOptions& o, int c) { o.connectivity = to_connectivity(c); }, "4 or 8")
      .def_readwrite("extent", &planning::RasOptions::extent)
      .def_readwrite("start_density", &planning::RasOptions::start_density)
      .def_readwrite("corner_rule", &planning::RasOptions::corner_rule)
      .def("__repr__", [](const planning::RasOptions& o) {
        return "RasOptions(region_size=" + std::to_string(o.region_size) +
               ", density=" + std::to_string(o.density) + ")";
      });

  // Topology options are bound in bind_field (topology lives there); Planner takes them by type.
  py::class_<PyPlanner>(pl, "Planner",
                        "A grid planner by name (planner_names()). plan() works on a BinaryGrid "
                        "already inflated (make_planning_grid) or use voronav.plan().")
      .def(py::init([](const std::string& name, int connectivity, double robot_radius,
                       bool record_expanded, const py::object& ras, const py::object& topology) {
             planning::RasOptions r =
                 ras.is_none() ? planning::RasOptions{} : ras.cast<planning::RasOptions>();
             topology::TopologyOptions t = topology.is_none()
                                               ? topology::TopologyOptions{}
                                               : topology.cast<topology::TopologyOptions>();
             return make_py_planner(name, connectivity, robot_radius, record_expanded, r, t);
           }),
           py::arg("name") = "astar", py::arg("connectivity") = 8, py::arg("robot_radius") = 0.0,
           py::arg("record_expanded") = false, py::arg("ras") = py::none(),
           py::arg("topology") = py::none(),
           "name: a planner_names() entry; connectivity 4 or 8; robot_radius [m] (recorded in the "
           "options; plan() does not inflate again); ras: RasOptions for 'ras'; topology: "
           "TopologyOptions for 'topo'.")
      .def_property_readonly("name", [](const PyPlanner& p) { return std::string(p.p->name()); })
      .def(
          "plan",
          [](PyPlanner& p, const BinaryGrid& grid, py::handle start, py::handle goal) {
            const Cell s = to_cell(grid.geometry(), start, "start");
            const Cell g = to_cell(grid.geometry(), goal, "goal");
            py::gil_scoped_release release;
            return p.plan(grid, s, g);
          },
          py::arg("grid"), py::arg("start"), py::arg("goal"),
          "Plans on `grid` (1 = blocked); start/goal: cells (x, y) or voronav.Vec2 [m]. The GIL "
          "is released while planning.")
      .def("__repr__",
           [](const PyPlanner& p) { return "Planner('" + std::string(p.p->name()) + "')"; });

  pl.def(
      "make_planning_grid",
      [](const BinaryGrid& blocked, double radius) {
        return planning::make_planning_grid(blocked, radius);
      },
      py::arg("blocked"), py::arg("robot_radius"), py::call_guard<py::gil_scoped_release>(),
      "Blocks every cell whose centre is closer than robot_radius [m] to a blocked cell.");
  pl.def(
      "plan",
      [](const py::object& map, py::handle start, py::handle goal, const std::string& planner,
         double robot_radius, int connectivity, const py::object& ras) {
        BinaryGrid blocked;
        if (py::isinstance<OccupancyGrid>(map))
          blocked = binarize(map.cast<const OccupancyGrid&>());
        else
          blocked = map.cast<const BinaryGrid&>();
        const Cell s = to_cell(blocked.geometry(), start, "start");
        const Cell g = to_cell(blocked.geometry(), goal, "goal");
        planning::RasOptions r =
            ras.is_none() ? planning::RasOptions{} : ras.cast<planning::RasOptions>();
        PyPlanner p = make_py_planner(planner, connectivity, robot_radius, false, r, {});
        py::gil_scoped_release release;
        const BinaryGrid inflated = planning::make_planning_grid(blocked, robot_radius);
        return p.plan(inflated, s, g);
      },
      py::arg("map"), py::arg("start"), py::arg("goal"), py::arg("planner") = "astar",
      py::arg("robot_radius") = 0.0, py::arg("connectivity") = 8, py::arg("ras") = py::none(),
      "One query: binarizes an OccupancyGrid (unknown = blocked), inflates by robot_radius [m], "
      "plans. start/goal: cells (x, y) or voronav.Vec2 world points [m].");
  pl.def("octile_distance", [](py::handle a, py::handle b) {
    const GridGeometry g{};
    return planning::octile_distance(to_cell(g, a, "a"), to_cell(g, b, "b"));
  });
  pl.def(
      "is_valid_path",
      [](const BinaryGrid& grid, const std::vector<std::pair<int, int>>& path, int connectivity) {
        std::vector<Cell> cells;
        for (auto [x, y] : path)
          cells.push_back({x, y});
        return planning::is_valid_path(grid, cells, to_connectivity(connectivity));
      },
      py::arg("grid"), py::arg("path"), py::arg("connectivity") = 8);

  py::class_<PyRasResult>(pl, "RasResult", "The full RAS answer (seed 001) and its numbering.")
      .def_property_readonly(
          "status", [](const PyRasResult& r) { return std::string(to_string(r.r.status)); })
      .def_property_readonly("ok", [](const PyRasResult& r) { return r.r.ok(); })
      .def_property_readonly(
          "regions", [](const PyRasResult& r) { return r.r.regions; },
          "Numbered regions ('region num')")
      .def_property_readonly(
          "steps", [](const PyRasResult& r) { return r.steps; }, "Expansion steps")
      .def_property_readonly(
          "region_size", [](const PyRasResult& r) { return r.region_size; }, "[cells]")
      .def_property_readonly("path_ids", [](const PyRasResult& r) { return r.r.path_ids; })
      .def_property_readonly(
          "path_regions", [](const PyRasResult& r) { return cells_array(r.r.path_regions); },
          "Region coordinates of the route, int32 (N, 2)")
      .def_property_readonly(
          "waypoints", [](const PyRasResult& r) { return points_array(r.r.waypoints); },
          "Start, region centres, goal [m, world], float64 (N, 2)")
      .def_property_readonly(
          "path", [](const PyRasResult& r) { return cells_array(r.r.path_cells); },
          "Dense cell path, int32 (N, 2)")
      .def_property_readonly("path_m",
                             [](const PyRasResult& r) { return world_array(r.g, r.r.path_cells); })
      .def_property_readonly(
          "length_cells",
          [](const PyRasResult& r) { return planning::path_length_cells(r.r.path_cells); })
      .def_property_readonly(
          "ids", [](const PyRasResult& r) { return r.ids; },
          "LabelGrid over the regions: id >= 0, -1 obstacle, -2 below density, "
          "-3 not numbered")
      .def_property_readonly(
          "region_blocked", [](const PyRasResult& r) { return r.region_blocked; },
          "BinaryGrid over the regions, 1 = blocked")
      .def_property_readonly("time_ms", [](const PyRasResult& r) { return r.r.time_ms; })
      .def("__repr__", [](const PyRasResult& r) {
        return "RasResult(" + std::string(to_string(r.r.status)) + ", " +
               std::to_string(r.r.regions) + " regions numbered, route of " +
               std::to_string(r.r.path_regions.size()) + " regions)";
      });
  pl.def(
      "plan_ras",
      [](const BinaryGrid& grid, py::handle start, py::handle goal,
         const planning::RasOptions& ras) {
        const Cell s = to_cell(grid.geometry(), start, "start");
        const Cell g = to_cell(grid.geometry(), goal, "goal");
        py::gil_scoped_release release;
        planning::PlannerOptions po;
        po.connectivity = ras.connectivity;
        planning::RasPlanner planner(ras, po);
        PyRasResult out;
        out.r = planner.plan_ras(grid, s, g);
        out.g = grid.geometry();
        const auto& f = planner.field();
        const auto& rg = planner.region_grid();
        out.region_blocked = rg.blocked();
        out.region_size = rg.region_size();
        out.steps = f.steps();
        out.ids = GridMap<std::int32_t>(rg.blocked().geometry(), -1);
        for (int y = 0; y < rg.height(); ++y)
          for (int x = 0; x < rg.width(); ++x)
            out.ids[Cell{x, y}] = f.id_at({x, y});
        return out;
      },
      py::arg("grid"), py::arg("start"), py::arg("goal"), py::arg("ras") = planning::RasOptions{},
      "RAS (seed 001) on a BinaryGrid with its numbered regions. start/goal: cells or Vec2 [m].");
  pl.def(
      "ras_parameters_for_robot",
      [](double size, double res, int density) {
        const auto p = planning::ras_parameters_for_robot(size, res, density);
        return py::dict(py::arg("region_size") = p.region_size, py::arg("density") = p.density);
      },
      py::arg("robot_size"), py::arg("resolution"), py::arg("density") = 8,
      "Region size [cells] and density for a robot of diameter robot_size [m].");
}

}  // namespace voronav::python
