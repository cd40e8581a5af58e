// voronav._voronav: the extension module; every area binds itself in its own file (bind_*.cpp).
// voronav::Error becomes voronav.Error (a ValueError) with the same message (file:line: ...).
#include "common.hpp"

PYBIND11_MODULE(_voronav, m) {
  namespace vp = voronav::python;
  m.doc() = "voronav C++ library bindings (use the `voronav` package, not this module)";
  pybind11::register_exception<voronav::Error>(m, "Error", PyExc_ValueError);
  vp::bind_core(m);
  vp::bind_io(m);
  vp::bind_planning(m);
  vp::bind_field(m);
  vp::bind_mapping(m);
  vp::bind_coordination(m);
  vp::bind_sim(m);
  vp::bind_render(m);
}
