// field / voronoi / topology: distance transform, GVD (full and DynamicGvd.update), labeled
// Voronoi by cellular automaton, Voronoi graph, topological map (critical points, region label
// array, graph as a networkx-compatible edge list) and planning on the graph. Grids of results
// are returned as grid objects whose .array is a zero-copy view into the result.
#include "common.hpp"
#include "voronav/field/distance_transform.hpp"
#include "voronav/field/obstacle_labels.hpp"
#include "voronav/topology/segmentation.hpp"
#include "voronav/topology/topological_map.hpp"
#include "voronav/voronoi/gvd.hpp"
#include "voronav/voronoi/labeled_voronoi.hpp"
#include "voronav/voronoi/voronoi_graph.hpp"

namespace voronav::python {

namespace {

py::tuple cell_tuple(Cell c) {
  return py::make_tuple(c.x, c.y);
}

py::list cell_list(const std::vector<Cell>& cells) {
  py::list l;
  for (Cell c : cells)
    l.append(cell_tuple(c));
  return l;
}

/// A factory for py::init: the option struct with the given keyword fields.
template <typename Options>
auto options_factory(const char* what) {
  return [what](const py::kwargs& kw) {
    Options o;
    apply_kwargs(o, kw, what);
    return o;
  };
}

}  // namespace

void bind_field(py::module_& m) {
  auto fd =
      m.def_submodule("field", "Exact Euclidean distance transform, inflation, obstacle labels.");
  py::class_<field::DistanceField>(fd, "DistanceField")
      .def_readonly("squared_distance", &field::DistanceField::squared_distance,
                    "FloatGrid: squared distance [cells^2] to the nearest blocked cell centre")
      .def_readonly("nearest", &field::DistanceField::nearest,
                    "LabelGrid: row-major index of the nearest blocked cell (-1 none)")
      .def_property_readonly(
          "distance_m",
          [](const field::DistanceField& f) {
            GridMap<float> d(f.squared_distance.geometry());
            const float res = static_cast<float>(f.squared_distance.resolution());
            auto src = f.squared_distance.data();
            auto dst = d.data();
            for (std::size_t i = 0; i < src.size(); ++i)
              dst[i] = std::sqrt(src[i]) * res;
            return d;
          },
          "FloatGrid: distance [m] to the nearest blocked cell centre (a new grid)")
      .def("__repr__", [](const field::DistanceField& f) {
        return "DistanceField(" + std::to_string(f.squared_distance.width()) + "x" +
               std::to_string(f.squared_distance.height()) + ")";
      });
  fd.def(
      "distance_transform",
      [](const BinaryGrid& b, bool border) { return field::distance_transform(b, {border}); },
      py::arg("blocked"), py::arg("border_is_blocked") = false,
      py::call_guard<py::gil_scoped_release>(),
      "Exact EDT (Felzenszwalb-Huttenlocher) of a BinaryGrid (1 = blocked).");
  fd.def(
      "inflate", [](const BinaryGrid& b, double r) { return field::inflate(b, r); },
      py::arg("blocked"), py::arg("radius_m"), py::call_guard<py::gil_scoped_release>(),
      "Blocks cells whose centre is closer than radius_m [m] to a blocked cell centre.");
  fd.def(
      "label_obstacles",
      [](const BinaryGrid& b) {
        auto l = field::label_obstacles(b);
        return py::make_tuple(std::move(l.label), l.count);
      },
      py::arg("blocked"), "(LabelGrid of 8-connected obstacle components, count).");

  auto vo = m.def_submodule("voronoi", "Generalized Voronoi diagram (seed 003), incremental too.");
  py::class_<voronoi::GvdOptions>(vo, "GvdOptions", "GVD options; keywords = fields.")
      .def(py::init(options_factory<voronoi::GvdOptions>("GvdOptions")))
      .def_readwrite("border_is_blocked", &voronoi::GvdOptions::border_is_blocked)
      .def_readwrite("site_separation", &voronoi::GvdOptions::site_separation, "[cells]")
      .def_readwrite("site_separation_ratio", &voronoi::GvdOptions::site_separation_ratio)
      .def_readwrite("thin", &voronoi::GvdOptions::thin)
      .def_readwrite("spur_min_length", &voronoi::GvdOptions::spur_min_length, "[m]")
      .def_readwrite("spur_clearance_ratio", &voronoi::GvdOptions::spur_clearance_ratio)
      .def_readwrite("prune_rounds", &voronoi::GvdOptions::prune_rounds);
  py::class_<voronoi::GeneralizedVoronoi>(vo, "GeneralizedVoronoi")
      .def_readonly("geometry", &voronoi::GeneralizedVoronoi::geometry)
      .def_readonly("blocked", &voronoi::GeneralizedVoronoi::blocked)
      .def_readonly("clearance", &voronoi::GeneralizedVoronoi::clearance,
                    "FloatGrid: distance [cells] to the nearest obstacle cell centre")
      .def_readonly("obstacle_label", &voronoi::GeneralizedVoronoi::obstacle_label)
      .def_readonly("raw", &voronoi::GeneralizedVoronoi::raw, "BinaryGrid: diagram before thinning")
      .def_readonly("diagram", &voronoi::GeneralizedVoronoi::diagram,
                    "BinaryGrid: thinned, pruned diagram (1 = Voronoi cell)")
      .def("cells", [](const voronoi::GeneralizedVoronoi& g) { return cell_list(g.cells()); })
      .def("__repr__", [](const voronoi::GeneralizedVoronoi& g) {
        return "GeneralizedVoronoi(" + std::to_string(g.geometry.width) + "x" +
               std::to_string(g.geometry.height) + ", " + std::to_string(g.cells().size()) +
               " diagram cells)";
      });
  vo.def(
      "build_gvd",
      [](const BinaryGrid& b, const voronoi::GvdOptions& o) { return voronoi::build_gvd(b, o); },
      py::arg("blocked"), py::arg("options") = voronoi::GvdOptions{},
      py::call_guard<py::gil_scoped_release>(), "Full build of the GVD of a BinaryGrid.");
  py::class_<voronoi::DynamicGvd>(vo, "DynamicGvd",
                                  "A GVD kept up to date under cell changes (result identical to "
                                  "a full rebuild).")
      .def(py::init<const BinaryGrid&, const voronoi::GvdOptions&>(), py::arg("blocked"),
           py::arg("options") = voronoi::GvdOptions{}, py::call_guard<py::gil_scoped_release>())
      .def(
          "update",
          [](voronoi::DynamicGvd& d, const py::iterable& changes) {
            std::vector<voronoi::CellChange> cc;
            for (auto ch : changes) {
              auto t = ch.cast<py::sequence>();
              if (t.size() != 2) throw Error("changes", 0, "each change is ((x, y), blocked)");
              cc.push_back({to_cell(d.geometry(), t[0], "changes"), t[1].cast<bool>()});
            }
            voronoi::GvdUpdateStats s;
            {
              py::gil_scoped_release release;
              s = d.update(cc);
            }
            return py::dict(py::arg("changed_cells") = s.changed_cells,
                            py::arg("recomputed_rows") = s.recomputed_rows,
                            py::arg("changed_distances") = s.changed_distances,
                            py::arg("labels_repartitioned") = s.labels_repartitioned);
          },
          py::arg("changes"),
          "Applies [((x, y), blocked: bool), ...]; returns what was touched (dict).")
      .def("is_voronoi",
           [](const voronoi::DynamicGvd& d, py::handle c) {
             return d.is_voronoi(to_cell(d.geometry(), c, "cell"));
           })
      .def("is_blocked",
           [](const voronoi::DynamicGvd& d, py::handle c) {
             return d.is_blocked(to_cell(d.geometry(), c, "cell"));
           })
      .def(
          "squared_clearance",
          [](const voronoi::DynamicGvd& d, py::handle c) {
            return d.squared_clearance(to_cell(d.geometry(), c, "cell"));
          },
          "[cells^2], -1 when there is no obstacle")
      .def("snapshot", &voronoi::DynamicGvd::snapshot, py::call_guard<py::gil_scoped_release>(),
           "A full copy of the current state as a GeneralizedVoronoi")
      .def_property_readonly("geometry", &voronoi::DynamicGvd::geometry)
      .def("__repr__", [](const voronoi::DynamicGvd& d) {
        return "DynamicGvd(" + std::to_string(d.geometry().width) + "x" +
               std::to_string(d.geometry().height) + ")";
      });

  bind_enum<voronoi::CaLabels>(vo, "CaLabels",
                               {{"obstacle_component", voronoi::CaLabels::kObstacleComponent},
                                {"edge_code", voronoi::CaLabels::kEdgeCode}});
  py::class_<voronoi::CaVoronoiOptions>(vo, "CaVoronoiOptions", "Labeled Voronoi (CA) options.")
      .def(py::init(options_factory<voronoi::CaVoronoiOptions>("CaVoronoiOptions")))
      .def_readwrite("border_is_blocked", &voronoi::CaVoronoiOptions::border_is_blocked)
      .def_readwrite("labels", &voronoi::CaVoronoiOptions::labels)
      .def_readwrite("noise_cells_are_sources", &voronoi::CaVoronoiOptions::noise_cells_are_sources)
      .def_readwrite("site_separation", &voronoi::CaVoronoiOptions::site_separation, "[cells]")
      .def_readwrite("site_separation_ratio", &voronoi::CaVoronoiOptions::site_separation_ratio)
      .def_readwrite("thin", &voronoi::CaVoronoiOptions::thin);
  py::class_<voronoi::LabeledVoronoi>(vo, "LabeledVoronoi")
      .def_readonly("edge_code", &voronoi::LabeledVoronoi::edge_code,
                    "BinaryGrid-typed (uint8) codes 1..12")
      .def_readonly("label", &voronoi::LabeledVoronoi::label)
      .def_readonly("time", &voronoi::LabeledVoronoi::time, "Step at which a cell was reached")
      .def_readonly("vor", &voronoi::LabeledVoronoi::vor)
      .def_readonly("diagram", &voronoi::LabeledVoronoi::diagram)
      .def_readonly("steps", &voronoi::LabeledVoronoi::steps)
      .def("__repr__", [](const voronoi::LabeledVoronoi& l) {
        return "LabeledVoronoi(" + std::to_string(l.label.width()) + "x" +
               std::to_string(l.label.height()) + ", " + std::to_string(l.steps) + " steps)";
      });
  vo.def(
      "build_labeled_voronoi",
      [](const BinaryGrid& b, const voronoi::CaVoronoiOptions& o) {
        return voronoi::build_labeled_voronoi(b, o);
      },
      py::arg("blocked"), py::arg("options") = voronoi::CaVoronoiOptions{},
      py::call_guard<py::gil_scoped_release>(),
      "The labeled Voronoi diagram by cellular automaton (seed 003, section III.2).");

  py::class_<voronoi::VoronoiGraph>(vo, "VoronoiGraph")
      .def_property_readonly(
          "nodes",
          [](const voronoi::VoronoiGraph& g) {
            py::list l;
            static const char* kinds[] = {"end", "junction", "loop", "isolated"};
            for (const auto& n : g.nodes)
              l.append(py::dict(py::arg("cell") = cell_tuple(n.cell),
                                py::arg("kind") = kinds[static_cast<int>(n.kind)],
                                py::arg("clearance_m") = n.clearance_m,
                                py::arg("degree") = n.degree));
            return l;
          })
      .def(
          "edge_list",
          [](const voronoi::VoronoiGraph& g) {
            py::list l;
            for (const auto& e : g.edges)
              l.append(py::make_tuple(e.a, e.b,
                                      py::dict(py::arg("length_m") = e.length_m,
                                               py::arg("min_clearance_m") = e.min_clearance_m,
                                               py::arg("cells") = cell_list(e.cells))));
            return l;
          },
          "[(a, b, {length_m, min_clearance_m, cells}), ...] for networkx.Graph(add_edges_from)")
      .def_readonly("node_of", &voronoi::VoronoiGraph::node_of)
      .def("__repr__", [](const voronoi::VoronoiGraph& g) {
        return "VoronoiGraph(" + std::to_string(g.nodes.size()) + " nodes, " +
               std::to_string(g.edges.size()) + " edges)";
      });
  vo.def(
      "build_voronoi_graph",
      [](const voronoi::GeneralizedVoronoi& g) { return voronoi::build_voronoi_graph(g); },
      py::arg("gvd"), py::call_guard<py::gil_scoped_release>());

  auto tp =
      m.def_submodule("topology", "Topological map (seed 003): critical points, regions, graph.");
  bind_enum<topology::DiagramMethod>(tp, "DiagramMethod",
                                     {{"edt", topology::DiagramMethod::kEdt},
                                      {"ca", topology::DiagramMethod::kCellularAutomaton}});
  py::class_<topology::WallOpeningOptions>(tp, "WallOpeningOptions",
                                           "Openings in wall lines; keywords = fields.")
      .def(py::init(options_factory<topology::WallOpeningOptions>("WallOpeningOptions")))
      .def_readwrite("min_width", &topology::WallOpeningOptions::min_width, "[m]")
      .def_readwrite("max_width", &topology::WallOpeningOptions::max_width, "[m], 0 = off")
      .def_readwrite("min_wall_length", &topology::WallOpeningOptions::min_wall_length, "[m]")
      .def_readwrite("max_offset", &topology::WallOpeningOptions::max_offset, "[m]")
      .def_readwrite("max_angle_deg", &topology::WallOpeningOptions::max_angle_deg, "[deg]")
      .def_readwrite("fit_tolerance", &topology::WallOpeningOptions::fit_tolerance, "[m]")
      .def_readwrite("max_wall_thickness", &topology::WallOpeningOptions::max_wall_thickness, "[m]")
      .def_readwrite("wall_ends", &topology::WallOpeningOptions::wall_ends);
  py::class_<topology::TopologyOptions>(tp, "TopologyOptions",
                                        "Topological map options; keywords = fields.")
      .def(py::init(options_factory<topology::TopologyOptions>("TopologyOptions")))
      .def_readwrite("method", &topology::TopologyOptions::method)
      .def_readwrite("gvd", &topology::TopologyOptions::gvd)
      .def_readwrite("ca", &topology::TopologyOptions::ca)
      .def_readwrite("min_rise", &topology::TopologyOptions::min_rise, "[m]")
      .def_readwrite("rise_ratio", &topology::TopologyOptions::rise_ratio)
      .def_readwrite("max_door_width", &topology::TopologyOptions::max_door_width,
                     "[m], 0 = no limit")
      .def_readwrite("max_rise_walk", &topology::TopologyOptions::max_rise_walk,
                     "[m], 0 = the rise test stays on the point's own diagram edge")
      .def_readwrite("passage_length", &topology::TopologyOptions::passage_length,
                     "[m], 0 = off; a passage is cut at its ends where the clearance rises")
      .def_readwrite("passage_rise_ratio", &topology::TopologyOptions::passage_rise_ratio)
      .def_readwrite("passage_bulges", &topology::TopologyOptions::passage_bulges)
      .def_readwrite("min_wall_area", &topology::TopologyOptions::min_wall_area,
                     "[m^2], 0 = off; no critical point on smaller obstacle pieces")
      .def_readwrite("validate_sides", &topology::TopologyOptions::validate_sides,
                     "room test of the critical lines")
      .def_readwrite("room_test_elongation", &topology::TopologyOptions::room_test_elongation,
                     "the room test joins only when one side is at least this elongated")
      .def_readwrite("min_region_area", &topology::TopologyOptions::min_region_area, "[m^2]")
      .def_readwrite("regions_absorb_obstacles",
                     &topology::TopologyOptions::regions_absorb_obstacles,
                     "[m^2], 0 = off; enclosed obstacle pieces up to this join their region")
      .def_readwrite("wall_openings", &topology::TopologyOptions::wall_openings,
                     "openings in wall lines closed by critical lines")
      .def_readwrite("wall_openings_first", &topology::TopologyOptions::wall_openings_first)
      .def_readwrite("basis_across", &topology::TopologyOptions::basis_across)
      .def_readwrite("passage_junctions", &topology::TopologyOptions::passage_junctions,
                     "a passage running into a junction of narrower branches is cut there")
      .def_readwrite("furniture_line_area", &topology::TopologyOptions::furniture_line_area,
                     "[m^2], 0 = off; a line to a smaller obstacle piece hides no wall opening");
  py::class_<topology::CriticalPoint>(tp, "CriticalPoint")
      .def_property_readonly("cell",
                             [](const topology::CriticalPoint& c) { return cell_tuple(c.cell); })
      .def_property_readonly("basis",
                             [](const topology::CriticalPoint& c) {
                               return py::make_tuple(cell_tuple(c.basis[0]),
                                                     cell_tuple(c.basis[1]));
                             })
      .def_readonly("clearance_m", &topology::CriticalPoint::clearance_m, "[m]")
      .def_property_readonly("line",
                             [](const topology::CriticalPoint& c) { return cell_list(c.line); })
      .def_property_readonly(
          "midpoint", [](const topology::CriticalPoint& c) { return cell_tuple(c.midpoint); })
      .def_readonly("separates", &topology::CriticalPoint::separates)
      .def_readonly("wall_gap", &topology::CriticalPoint::wall_gap,
                    "from an opening in a wall line, not a narrowing")
      .def("__repr__", [](const topology::CriticalPoint& c) {
        return "CriticalPoint((" + std::to_string(c.cell.x) + ", " + std::to_string(c.cell.y) +
               "), clearance " + std::to_string(c.clearance_m) + " m)";
      });
  py::class_<topology::Region>(tp, "Region")
      .def_readonly("id", &topology::Region::id)
      .def_readonly("cells", &topology::Region::cells)
      .def_readonly("absorbed_cells", &topology::Region::absorbed_cells)
      .def_readonly("area_m2", &topology::Region::area_m2, "[m^2]")
      .def_property_readonly("centre",
                             [](const topology::Region& r) { return cell_tuple(r.centre); })
      .def_readonly("centre_world", &topology::Region::centre_world, "[m]")
      .def("__repr__", [](const topology::Region& r) {
        return "Region(" + std::to_string(r.id) + ", " + std::to_string(r.area_m2) + " m^2)";
      });
  py::class_<topology::TopoPlan>(tp, "TopoPlan")
      .def_property_readonly(
          "status",
          [](const topology::TopoPlan& p) {
            static const char* s[] = {"ok", "start_blocked", "goal_blocked", "unreachable"};
            return std::string(s[static_cast<int>(p.status)]);
          })
      .def_property_readonly("ok", &topology::TopoPlan::ok)
      .def_readonly("regions", &topology::TopoPlan::regions)
      .def_readonly("edges", &topology::TopoPlan::edges)
      .def_property_readonly("waypoints",
                             [](const topology::TopoPlan& p) { return cell_list(p.waypoints); })
      .def_readonly("graph_cost_m", &topology::TopoPlan::graph_cost_m, "[m]")
      .def_readonly("waypoint_length_m", &topology::TopoPlan::waypoint_length_m, "[m]")
      .def_readonly("expanded", &topology::TopoPlan::expanded)
      .def("__repr__", [](const topology::TopoPlan& p) {
        return "TopoPlan(" + std::to_string(p.regions.size()) + " regions, " +
               std::to_string(p.graph_cost_m) + " m)";
      });
  py::class_<topology::TopologicalMap>(tp, "TopologicalMap")
      .def_readonly("geometry", &topology::TopologicalMap::geometry)
      .def_readonly("blocked", &topology::TopologicalMap::blocked)
      .def_readonly("diagram", &topology::TopologicalMap::diagram)
      .def_readonly("clearance", &topology::TopologicalMap::clearance, "[cells]")
      .def_readonly("critical_points", &topology::TopologicalMap::critical_points)
      .def_readonly("region", &topology::TopologicalMap::region,
                    "LabelGrid: region id per free cell, -1 on obstacles")
      .def_readonly("regions", &topology::TopologicalMap::regions)
      .def(
          "edge_list",
          [](const topology::TopologicalMap& t) {
            py::list l;
            for (const auto& e : t.edges)
              l.append(py::make_tuple(
                  e.a, e.b,
                  py::dict(py::arg("length_m") = e.length_m, py::arg("weight") = e.length_m,
                           py::arg("critical_point") = e.critical_point)));
            return l;
          },
          "Graph edges [(a, b, {length_m, weight, critical_point}), ...]: "
          "networkx.Graph().add_edges_from(...) takes it as is")
      .def("region_of", [](const topology::TopologicalMap& t,
                           py::handle c) { return t.region_of(to_cell(t.geometry, c, "cell")); })
      .def(
          "plan",
          [](const topology::TopologicalMap& t, py::handle s, py::handle g) {
            const Cell a = to_cell(t.geometry, s, "start"), b = to_cell(t.geometry, g, "goal");
            py::gil_scoped_release release;
            return topology::plan_on_graph(t, a, b);
          },
          py::arg("start"), py::arg("goal"), "A* over the regions (status returned, not raised).")
      .def("__repr__", [](const topology::TopologicalMap& t) {
        return "TopologicalMap(" + std::to_string(t.regions.size()) + " regions, " +
               std::to_string(t.critical_points.size()) + " critical points, " +
               std::to_string(t.edges.size()) + " edges)";
      });
  tp.def(
      "build_topological_map",
      [](const BinaryGrid& b, const topology::TopologyOptions& o) {
        return topology::build_topological_map(b, o);
      },
      py::arg("blocked"), py::arg("options") = topology::TopologyOptions{},
      py::call_guard<py::gil_scoped_release>(),
      "Diagram, critical points and lines, regions and graph of a BinaryGrid.");
  tp.def(
      "build_topological_map_from_diagram",
      [](const BinaryGrid& b, const BinaryGrid& d, const topology::TopologyOptions& o) {
        return topology::build_topological_map(b, d, o);
      },
      py::arg("blocked"), py::arg("diagram"), py::arg("options") = topology::TopologyOptions{},
      py::call_guard<py::gil_scoped_release>(),
      "The same over a given diagram (e.g. DynamicGvd.snapshot().diagram).");
  tp.def(
      "segmentation_scores",
      [](const GridMap<std::int32_t>& regions, const GridMap<std::int32_t>& rooms,
         std::size_t min_cells) {
        const auto s = topology::segmentation_scores(regions, rooms, min_cells);
        return py::dict(py::arg("recall") = s.recall, py::arg("precision") = s.precision,
                        py::arg("rooms") = s.rooms, py::arg("regions") = s.regions);
      },
      py::arg("regions"), py::arg("rooms"), py::arg("min_room_cells") = 0);
  tp.def("free_components", &topology::free_components, py::arg("blocked"),
         py::arg("eight") = false,
         "Connected free areas (4- or 8-connected), labels 0.. (-1 blocked).");
}

}  // namespace voronav::python
