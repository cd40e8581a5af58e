// Shared helpers of the Python bindings: numpy views of GridMap<T> (zero-copy, row y = cell y,
// so arr[y, x] is cell (x, y) and row 0 is the bottom row of the map), point conversion (a tuple
// of two ints is a cell, a voronav.Vec2 is a world point [m] in the REP-103 frame), option
// structs filled from keyword arguments, and string-convertible enums.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "voronav/core/error.hpp"
#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::python {

namespace py = pybind11;

/// A numpy view (shape (height, width), C order) of `grid`'s storage kept alive by `owner`.
template <typename T>
py::array_t<T> grid_view(const GridMap<T>& grid, py::handle owner) {
  const auto w = static_cast<py::ssize_t>(grid.width());
  const auto h = static_cast<py::ssize_t>(grid.height());
  const auto s = static_cast<py::ssize_t>(sizeof(T));
  // The view is writable: writing into it changes the C++ grid (the point of zero copy).
  return py::array_t<T>({h, w}, {w * s, s}, const_cast<T*>(grid.data().data()), owner);
}

/// A copy of a 2-D numpy array (rows = cell y) into a GridMap<T> with the given geometry.
template <typename T>
GridMap<T> grid_from_array(const py::array& in, double resolution, const Pose2& origin,
                           const char* what) {
  if (in.ndim() != 2)
    throw Error(
        what, 0,
        "expected a 2-D array (height, width), got " + std::to_string(in.ndim()) + " dimensions");
  auto arr = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(in);
  if (!arr) throw Error(what, 0, "cannot convert the array to the grid's dtype");
  GridGeometry g{static_cast<int>(arr.shape(1)), static_cast<int>(arr.shape(0)), resolution,
                 origin};
  GridMap<T> grid(g);
  std::copy_n(arr.data(), grid.size(), grid.data().data());
  return grid;
}

/// A cell from a Python point: (x, y) ints = cell; voronav.Vec2 = world point [m] through
/// `geometry` (REP-103; cell (0, 0)'s lower-left corner at the origin).
Cell to_cell(const GridGeometry& geometry, py::handle point, const char* what);

/// Fills an option struct bound to Python from keyword arguments; an unknown key raises
/// voronav.Error naming the option and `what`.
template <typename T>
void apply_kwargs(T& options, const py::kwargs& kwargs, const char* what) {
  py::object o = py::cast(&options, py::return_value_policy::reference);
  for (auto item : kwargs) {
    const std::string key = py::str(item.first);
    if (key.starts_with("_") || !py::hasattr(o, key.c_str()))
      throw Error(what, 0, "unknown option '" + key + "'");
    o.attr(key.c_str()) = item.second;
  }
}

/// Binds an enum whose values also convert from strings ("optimal" -> RasDirection::kOptimal),
/// so options accept both voronav.RasDirection.optimal and "optimal".
template <typename E>
py::enum_<E> bind_enum(py::module_& m, const char* name,
                       std::initializer_list<std::pair<const char*, E>> values,
                       const char* doc = "") {
  py::enum_<E> e(m, name, doc);
  std::vector<std::pair<std::string, E>> table;
  for (const auto& [n, v] : values) {
    e.value(n, v);
    table.emplace_back(n, v);
  }
  e.def(py::init([table, n = std::string(name)](const std::string& s) {
    std::string accepted;
    for (const auto& [k, v] : table) {
      if (k == s) return v;
      accepted += (accepted.empty() ? "" : ", ") + k;
    }
    throw Error(n, 0, "'" + s + "': expected one of " + accepted);
  }));
  py::implicitly_convertible<py::str, E>();
  return e;
}

/// World points as a new (N, 2) float64 array [m] (x, y per row).
inline py::array_t<double> points_array(const std::vector<Vec2>& pts) {
  py::array_t<double> a({static_cast<py::ssize_t>(pts.size()), py::ssize_t{2}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    v(static_cast<py::ssize_t>(i), 0) = pts[i].x;
    v(static_cast<py::ssize_t>(i), 1) = pts[i].y;
  }
  return a;
}

void bind_core(py::module_& m);
void bind_io(py::module_& m);
void bind_planning(py::module_& m);
void bind_field(py::module_& m);
void bind_mapping(py::module_& m);
void bind_coordination(py::module_& m);
void bind_sim(py::module_& m);
void bind_render(py::module_& m);

}  // namespace voronav::python
