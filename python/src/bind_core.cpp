// Core types: Vec2, Pose2, GridGeometry and the four grid types with zero-copy numpy views
// (OccupancyGrid int8, BinaryGrid uint8, FloatGrid float32, LabelGrid int32), plus io (ROS map
// YAML, Moving AI map/scen, floor plans).
#include <cstdio>
#include <sstream>

#include "common.hpp"
#include "voronav/io/floorplan.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/io/movingai.hpp"
#include "voronav/io/ros_map.hpp"

namespace voronav::python {

namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string geometry_repr(const GridGeometry& g) {
  return std::to_string(g.width) + "x" + std::to_string(g.height) + " cells, " + fmt(g.resolution) +
         " m/cell, origin (" + fmt(g.origin.position.x) + ", " + fmt(g.origin.position.y) + ", " +
         fmt(g.origin.yaw) + ")";
}

Pose2 pose_from_sequence(const py::sequence& s) {
  if (s.size() != 2 && s.size() != 3)
    throw Error("pose", 0,
                "expected (x, y) or (x, y, yaw), got " + std::to_string(s.size()) + " values");
  return {{s[0].cast<double>(), s[1].cast<double>()}, s.size() == 3 ? s[2].cast<double>() : 0.0};
}

template <typename T>
void bind_grid(py::module_& m, const char* name, const char* doc) {
  using G = GridMap<T>;
  py::class_<G>(m, name, py::buffer_protocol(), doc)
      .def(py::init([name](const py::array& a, double resolution, const Pose2& origin) {
             return grid_from_array<T>(a, resolution, origin, name);
           }),
           py::arg("array"), py::arg("resolution") = 1.0, py::arg("origin") = Pose2{},
           "Copies a 2-D array (rows = cell y, row 0 = bottom of the map); resolution [m/cell], "
           "origin = world pose (x [m], y [m], yaw [rad]) of cell (0, 0)'s lower-left corner.")
      .def(py::init([](int w, int h, T fill, double resolution, const Pose2& origin) {
             return G(GridGeometry{w, h, resolution, origin}, fill);
           }),
           py::arg("width"), py::arg("height"), py::arg("fill") = T{}, py::arg("resolution") = 1.0,
           py::arg("origin") = Pose2{})
      .def_buffer([](G& g) {
        const auto s = static_cast<py::ssize_t>(sizeof(T));
        return py::buffer_info(
            g.data().data(), s, py::format_descriptor<T>::format(), 2,
            {static_cast<py::ssize_t>(g.height()), static_cast<py::ssize_t>(g.width())},
            {static_cast<py::ssize_t>(g.width()) * s, s});
      })
      .def_property_readonly(
          "array", [](py::object self) { return grid_view(self.cast<const G&>(), self); },
          "Zero-copy numpy view, shape (height, width): arr[y, x] is cell (x, y); row 0 is the "
          "bottom row of the map (plot with origin='lower'). Writing to it changes the grid.")
      .def_property_readonly("width", &G::width, "[cells]")
      .def_property_readonly("height", &G::height, "[cells]")
      .def_property_readonly("shape",
                             [](const G& g) { return py::make_tuple(g.height(), g.width()); })
      .def_property_readonly("resolution", &G::resolution, "[m/cell]")
      .def_property_readonly(
          "origin", [](const G& g) { return g.geometry().origin; },
          "World pose of cell (0, 0)'s lower-left corner [m, m, rad]")
      .def_property_readonly("geometry", &G::geometry)
      .def(
          "contains",
          [](const G& g, py::handle p) { return g.contains(to_cell(g.geometry(), p, "cell")); },
          py::arg("point"))
      .def(
          "__getitem__",
          [](const G& g, py::handle p) { return g.at(to_cell(g.geometry(), p, "cell")); },
          "Value at a cell (x, y) or a voronav.Vec2 world point; raises outside the grid.")
      .def("__setitem__",
           [](G& g, py::handle p, T v) { g.at(to_cell(g.geometry(), p, "cell")) = v; })
      .def(
          "cell_center",
          [](const G& g, py::handle p) {
            return g.geometry().cell_center(to_cell(g.geometry(), p, "cell"));
          },
          py::arg("cell"), "World position [m] of a cell's centre.")
      .def(
          "world_to_cell",
          [](const G& g, const Vec2& w) {
            const auto c = g.geometry().world_to_cell(w);
            if (!c) throw Error("point", 0, "not a finite world point");
            return py::make_tuple(c->x, c->y);
          },
          py::arg("point"), "The cell (x, y) holding a world point [m] (may lie outside).")
      .def("copy", [](const G& g) { return G(g); })
      .def("__eq__", [](const G& a, const G& b) { return a == b; })
      .def("__repr__", [name](const G& g) {
        return std::string(name) + "(" + geometry_repr(g.geometry()) + ")";
      });
}

}  // namespace

Cell to_cell(const GridGeometry& geometry, py::handle point, const char* what) {
  if (py::isinstance<Vec2>(point)) {
    const auto c = geometry.world_to_cell(point.cast<Vec2>());
    if (!c) throw Error(what, 0, "not a finite world point");
    return *c;
  }
  if (py::isinstance<py::sequence>(point) && !py::isinstance<py::str>(point)) {
    auto s = point.cast<py::sequence>();
    if (s.size() == 2) {
      auto is_int = [](py::handle h) {
        return py::isinstance<py::int_>(h) ||
               (py::hasattr(h, "dtype") &&
                py::str(h.attr("dtype").attr("kind")).cast<std::string>() == "i");
      };
      if (is_int(s[0]) && is_int(s[1])) return {s[0].cast<int>(), s[1].cast<int>()};
      throw Error(what, 0,
                  "a cell is two ints (x, y); for a world point in metres use voronav.Vec2(x, y)");
    }
  }
  throw Error(what, 0,
              "expected a cell (x, y) of ints or a voronav.Vec2 world point [m], got " +
                  std::string(py::str(py::repr(point))));
}

void bind_core(py::module_& m) {
  py::class_<Vec2>(m, "Vec2", "A world point or vector [m], x forward / y left (REP-103).")
      .def(py::init<>())
      .def(py::init([](double x, double y) {
             return Vec2{x, y};
           }),
           py::arg("x"), py::arg("y"))
      .def_readwrite("x", &Vec2::x, "[m]")
      .def_readwrite("y", &Vec2::y, "[m]")
      .def("__iter__", [](const Vec2& v) { return py::iter(py::make_tuple(v.x, v.y)); })
      .def("__eq__", [](const Vec2& a, const Vec2& b) { return a == b; })
      .def("__repr__", [](const Vec2& v) { return "Vec2(" + fmt(v.x) + ", " + fmt(v.y) + ")"; });
  py::class_<Pose2>(m, "Pose2", "Position [m] and heading yaw [rad, counter-clockwise from +x].")
      .def(py::init<>())
      .def(py::init([](double x, double y, double yaw) {
             return Pose2{{x, y}, yaw};
           }),
           py::arg("x"), py::arg("y"), py::arg("yaw") = 0.0)
      .def(py::init([](const py::tuple& t) { return pose_from_sequence(t); }))
      .def(py::init([](const py::list& t) { return pose_from_sequence(t); }))
      .def_property(
          "x", [](const Pose2& p) { return p.position.x; },
          [](Pose2& p, double v) { p.position.x = v; }, "[m]")
      .def_property(
          "y", [](const Pose2& p) { return p.position.y; },
          [](Pose2& p, double v) { p.position.y = v; }, "[m]")
      .def_readwrite("yaw", &Pose2::yaw, "[rad]")
      .def("__iter__",
           [](const Pose2& p) {
             return py::iter(py::make_tuple(p.position.x, p.position.y, p.yaw));
           })
      .def("__eq__", [](const Pose2& a, const Pose2& b) { return a == b; })
      .def("__repr__", [](const Pose2& p) {
        return "Pose2(" + fmt(p.position.x) + ", " + fmt(p.position.y) + ", " + fmt(p.yaw) + ")";
      });
  py::implicitly_convertible<py::tuple, Pose2>();
  py::implicitly_convertible<py::list, Pose2>();
  py::class_<GridGeometry>(m, "GridGeometry",
                           "Size [cells], resolution [m/cell] and origin of a grid.")
      .def(py::init([](int w, int h, double res, const Pose2& o) {
             return GridGeometry{w, h, res, o};
           }),
           py::arg("width"), py::arg("height"), py::arg("resolution") = 1.0,
           py::arg("origin") = Pose2{})
      .def_readonly("width", &GridGeometry::width)
      .def_readonly("height", &GridGeometry::height)
      .def_readonly("resolution", &GridGeometry::resolution, "[m/cell]")
      .def_readonly("origin", &GridGeometry::origin)
      .def("cell_center",
           [](const GridGeometry& g, py::handle c) { return g.cell_center(to_cell(g, c, "cell")); })
      .def("__eq__", [](const GridGeometry& a, const GridGeometry& b) { return a == b; })
      .def("__repr__",
           [](const GridGeometry& g) { return "GridGeometry(" + geometry_repr(g) + ")"; });

  bind_grid<std::int8_t>(m, "OccupancyGrid",
                         "Occupancy as ROS nav_msgs/OccupancyGrid: 0 free, 100 occupied, 1..99 "
                         "probability [%], -1 unknown (int8).");
  bind_grid<std::uint8_t>(m, "BinaryGrid", "Traversability: 1 blocked, 0 free (uint8).");
  bind_grid<float>(m, "FloatGrid", "A scalar field per cell (float32), e.g. distances.");
  bind_grid<std::int32_t>(m, "LabelGrid", "An integer label per cell (int32), -1 = none.");

  m.def(
      "binarize",
      [](const OccupancyGrid& g, int occupied_threshold, bool unknown_is_blocked) {
        return binarize(g, {occupied_threshold, unknown_is_blocked});
      },
      py::arg("grid"), py::arg("occupied_threshold") = 50, py::arg("unknown_is_blocked") = true,
      "Blocked (1) where value >= occupied_threshold [0..100] (and unknown when asked).");
}

void bind_io(py::module_& m) {
  auto io = m.def_submodule("io", "Map files: ROS map YAML, Moving AI, floor-plan images.");
  bind_enum<io::RosMapMode>(io, "RosMapMode",
                            {{"trinary", io::RosMapMode::kTrinary},
                             {"scale", io::RosMapMode::kScale},
                             {"raw", io::RosMapMode::kRaw}});
  py::class_<io::RosMapMetadata>(io, "RosMapMetadata", "The YAML fields of a ROS map.")
      .def_property_readonly("image", [](const io::RosMapMetadata& d) { return d.image.string(); })
      .def_readonly("resolution", &io::RosMapMetadata::resolution, "[m/cell]")
      .def_readonly("origin", &io::RosMapMetadata::origin)
      .def_readonly("negate", &io::RosMapMetadata::negate)
      .def_readonly("occupied_thresh", &io::RosMapMetadata::occupied_thresh)
      .def_readonly("free_thresh", &io::RosMapMetadata::free_thresh)
      .def_readonly("mode", &io::RosMapMetadata::mode)
      .def("__repr__", [](const io::RosMapMetadata& d) {
        return "RosMapMetadata(image='" + d.image.string() + "', resolution=" + fmt(d.resolution) +
               ", mode=" + io::to_string(d.mode) + ")";
      });
  io.def(
      "load_map",
      [](const std::string& path, double resolution, int occupied_below, int free_from) {
        io::FloorplanOptions fo;
        fo.resolution = resolution;
        fo.occupied_below = occupied_below;
        fo.free_from = free_from;
        return io::load_map(path, fo).grid;
      },
      py::arg("path"), py::arg("image_resolution") = 0.05, py::arg("occupied_below") = 128,
      py::arg("free_from") = 128, py::call_guard<py::gil_scoped_release>(),
      "Any map by extension: ROS YAML (.yaml/.yml), Moving AI (.map), image (.png/.pgm, at "
      "image_resolution [m/pixel]; grey < occupied_below occupied, >= free_from free).");
  io.def(
      "map_format",
      [](const std::string& path) { return std::string(io::to_string(io::load_map(path).format)); },
      py::arg("path"), "The format load_map reads the file as ('ros', 'movingai', 'image').");
  io.def(
      "read_ros_map",
      [](const std::string& path) {
        auto r = io::read_ros_map(path);
        return py::make_tuple(std::move(r.grid), r.metadata);
      },
      py::arg("yaml_path"), "(OccupancyGrid, RosMapMetadata) of a ROS map_server YAML file.");
  io.def(
      "load_ros_map", [](const std::string& path) { return io::load_ros_map(path); },
      py::arg("yaml_path"), py::call_guard<py::gil_scoped_release>());
  io.def(
      "save_ros_map",
      [](const OccupancyGrid& g, const std::string& yaml, io::RosMapMode mode,
         const std::string& image_name) {
        io::SaveRosMapOptions o;
        o.mode = mode;
        o.image_name = image_name;
        return io::save_ros_map(g, yaml, o).string();
      },
      py::arg("grid"), py::arg("yaml_path"), py::arg("mode") = io::RosMapMode::kTrinary,
      py::arg("image_name") = "", "Writes YAML + image as map_saver does; returns the image path.");
  io.def(
      "load_movingai_map", [](const std::string& p) { return io::load_movingai_map(p); },
      py::arg("path"), "A .map file: passable cells 0, blocked 100; resolution 1.");
  io.def(
      "save_movingai_map",
      [](const OccupancyGrid& g, const std::string& p) { io::save_movingai_map(g, p); },
      py::arg("grid"), py::arg("path"));
  py::class_<io::MovingAiQuery>(io, "MovingAiQuery",
                                "One .scen row; start/goal in the file frame (y down).")
      .def(py::init<>())
      .def_readwrite("bucket", &io::MovingAiQuery::bucket)
      .def_readwrite("map", &io::MovingAiQuery::map)
      .def_readwrite("map_width", &io::MovingAiQuery::map_width)
      .def_readwrite("map_height", &io::MovingAiQuery::map_height)
      .def_readwrite("start_x", &io::MovingAiQuery::start_x)
      .def_readwrite("start_y", &io::MovingAiQuery::start_y)
      .def_readwrite("goal_x", &io::MovingAiQuery::goal_x)
      .def_readwrite("goal_y", &io::MovingAiQuery::goal_y)
      .def_readwrite("optimal_length", &io::MovingAiQuery::optimal_length, "[cells]")
      .def_readwrite("optimal_rounding", &io::MovingAiQuery::optimal_rounding,
                     "One unit in the last printed decimal of optimal_length")
      .def_readonly("line", &io::MovingAiQuery::line)
      .def_property_readonly(
          "start_cell",
          [](const io::MovingAiQuery& q) {
            const Cell c = io::movingai_to_cell(q.start_x, q.start_y, q.map_height);
            return py::make_tuple(c.x, c.y);
          },
          "Start as a voronav cell (row 0 at the bottom)")
      .def_property_readonly(
          "goal_cell",
          [](const io::MovingAiQuery& q) {
            const Cell c = io::movingai_to_cell(q.goal_x, q.goal_y, q.map_height);
            return py::make_tuple(c.x, c.y);
          },
          "Goal as a voronav cell (row 0 at the bottom)")
      .def("__repr__", [](const io::MovingAiQuery& q) {
        return "MovingAiQuery(line " + std::to_string(q.line) + ", (" + std::to_string(q.start_x) +
               ", " + std::to_string(q.start_y) + ") -> (" + std::to_string(q.goal_x) + ", " +
               std::to_string(q.goal_y) + "), optimal " + fmt(q.optimal_length) + ")";
      });
  io.def(
      "load_movingai_scen", [](const std::string& p) { return io::load_movingai_scen(p); },
      py::arg("path"));
  io.def(
      "save_movingai_scen",
      [](const std::vector<io::MovingAiQuery>& q, const std::string& p) {
        io::save_movingai_scen(q, p);
      },
      py::arg("queries"), py::arg("path"));
  io.def(
      "check_scen_fits",
      [](const std::vector<io::MovingAiQuery>& q, const OccupancyGrid& g, const std::string& p) {
        io::check_scen_fits(q, g, p);
      },
      py::arg("queries"), py::arg("grid"), py::arg("scen_path"));
  io.def(
      "load_floorplan",
      [](const std::string& p, double resolution, const Pose2& origin, int occupied_below,
         int free_from) {
        return io::load_floorplan(p, {resolution, origin, occupied_below, free_from});
      },
      py::arg("path"), py::arg("resolution") = 0.05, py::arg("origin") = Pose2{},
      py::arg("occupied_below") = 128, py::arg("free_from") = 128,
      "A PNG/PGM floor plan: grey < occupied_below occupied, >= free_from free; resolution "
      "[m/pixel].");
}

}  // namespace voronav::python
