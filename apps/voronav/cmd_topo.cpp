// voronav topo: the topological map of a map file (seed 003): one picture per stage like the
// paper's figure 8 (a) binary map, (b) edges, (c) labeled Voronoi diagram, (d) critical points and
// lines, (e) topological regions, (f) topological graph, plus topology.json; optionally the
// segmentation scores against a ground-truth room image.
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli_common.hpp"
#include "command.hpp"
#include "topo_pictures.hpp"
#include "voronav/bag/command_bags.hpp"
#include "voronav/core/error.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/render/figure.hpp"
#include "voronav/topology/region_export.hpp"
#include "voronav/topology/segmentation.hpp"
#include "voronav/topology/topological_map.hpp"
#include "voronav/voronoi/labeled_voronoi.hpp"

namespace voronav::cli {
namespace {

struct TopoArgs {
  std::filesystem::path map, out, ground_truth, labels;
  std::string method{topology::diagram_method_name(topology::TopologyOptions{}.method)};
  std::string metric = "ipa";
  int free_from = 250;
  double min_region_area = topology::TopologyOptions{}.min_region_area;
  double absorb_obstacles = topology::TopologyOptions{}.regions_absorb_obstacles;
  double max_rise_walk = topology::TopologyOptions{}.max_rise_walk;
  double passage_length = topology::TopologyOptions{}.passage_length;
  double passage_rise_ratio = topology::TopologyOptions{}.passage_rise_ratio;
  double min_rise = topology::TopologyOptions{}.min_rise;
  double rise_ratio = topology::TopologyOptions{}.rise_ratio;
  bool passage_bulges = topology::TopologyOptions{}.passage_bulges;
  bool passage_junctions = topology::TopologyOptions{}.passage_junctions;
  bool validate_sides = topology::TopologyOptions{}.validate_sides;
  double room_test_elongation = topology::TopologyOptions{}.room_test_elongation;
  double min_wall_area = topology::TopologyOptions{}.min_wall_area;
  topology::WallOpeningOptions wall = topology::TopologyOptions{}.wall_openings;
  bool wall_first = topology::TopologyOptions{}.wall_openings_first;
  bool basis_across = topology::TopologyOptions{}.basis_across;
  double furniture_line_area = topology::TopologyOptions{}.furniture_line_area;
  bool json = false;
  std::filesystem::path mcap;
};

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void run(const TopoArgs& a) {
  const topology::DiagramMethod method = topology::parse_diagram_method(a.method, "--method");
  if (a.metric != "ipa" && a.metric != "intersection")
    throw Error("--metric", 0, "expected ipa or intersection, got '" + a.metric + "'");
  io::FloorplanOptions fo;
  fo.occupied_below = a.free_from;
  fo.free_from = a.free_from;
  const io::LoadedMap loaded = io::load_map(a.map, fo);
  const BinaryGrid blocked = binarize(loaded.grid);
  topology::TopologyOptions opt;
  opt.method = method;
  opt.min_region_area = a.min_region_area;
  opt.regions_absorb_obstacles = a.absorb_obstacles;
  opt.max_rise_walk = a.max_rise_walk;
  opt.passage_length = a.passage_length;
  opt.passage_rise_ratio = a.passage_rise_ratio;
  opt.min_rise = a.min_rise;
  opt.rise_ratio = a.rise_ratio;
  opt.passage_bulges = a.passage_bulges;
  opt.passage_junctions = a.passage_junctions;
  opt.validate_sides = a.validate_sides;
  opt.room_test_elongation = a.room_test_elongation;
  opt.min_wall_area = a.min_wall_area;
  opt.wall_openings = a.wall;
  opt.wall_openings_first = a.wall_first;
  opt.basis_across = a.basis_across;
  opt.furniture_line_area = a.furniture_line_area;
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  const topology::TopologicalMap m = topology::build_topological_map(blocked, opt);
  const double build_ms = ms_since(t0);
  const double cpu_ms = 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  const GridGeometry& geo = m.geometry;
  if (!a.mcap.empty()) bag::write_topology_bag(a.mcap, loaded.grid, m);

  nlohmann::json j;
  j["map"] = a.map.string();
  j["method"] = topology::diagram_method_name(method);
  j["width"] = geo.width;
  j["height"] = geo.height;
  j["resolution"] = geo.resolution;
  j["frame_id"] = "map";
  j["cell_frame"] = "grid_y_up";  // "cell" fields: grid cells, row 0 at the bottom
  j["origin"] = pose_json(geo.origin);
  j["resolution_unit"] = "m/cell";
  j["time_ms"] = build_ms;
  j["cpu_ms"] = cpu_ms;
  std::size_t diagram_cells = 0;
  for (const auto v : m.diagram.values())
    diagram_cells += v != 0;
  j["voronoi_cells"] = diagram_cells;
  nlohmann::json cps = nlohmann::json::array();
  for (const auto& cp : m.critical_points) {
    const Vec2 w = geo.cell_center(cp.cell);
    cps.push_back({{"cell", {cp.cell.x, cp.cell.y}},
                   {"world", {w.x, w.y}},
                   {"clearance_m", cp.clearance_m},
                   {"basis", {{cp.basis[0].x, cp.basis[0].y}, {cp.basis[1].x, cp.basis[1].y}}},
                   {"separates", cp.separates},
                   {"source", cp.wall_gap           ? "wall_gap"
                              : cp.passage_junction ? "passage_junction"
                                                    : "narrowing"}});
  }
  j["critical_points"] = cps;
  j["regions"] = m.regions.size();
  j["absorbed_obstacles"] = m.absorbed_obstacles;
  j["basis_across"] = m.basis_across;
  j["openings_past_furniture"] = m.openings_past_furniture;
  std::size_t junction_cuts = 0;
  for (const auto& cp : m.critical_points)
    junction_cuts += cp.passage_junction ? 1 : 0;
  j["passage_junctions"] = junction_cuts;
  nlohmann::json nodes = nlohmann::json::array(), edges = nlohmann::json::array();
  const auto outlines = topology::region_outlines(m.region, static_cast<int>(m.regions.size()));
  for (const auto& r : m.regions) {
    nodes.push_back({{"id", r.id},
                     {"label", r.id + 1},
                     {"cells", r.cells},
                     {"absorbed_cells", r.absorbed_cells},
                     {"cell", {r.centre.x, r.centre.y}},
                     {"world", {r.centre_world.x, r.centre_world.y}},
                     {"area_m2", r.area_m2}});
    // Outline rings in the world frame [m]: outer rings counter-clockwise, holes clockwise.
    nlohmann::json rings = nlohmann::json::array();
    for (const auto& ring : outlines[static_cast<std::size_t>(r.id)]) {
      nlohmann::json pts = nlohmann::json::array();
      for (const Vec2& p : ring)
        pts.push_back({p.x, p.y});
      rings.push_back(pts);
    }
    nodes.back()["polygon"] = rings;
  }
  for (const auto& e : m.edges)
    edges.push_back(
        {{"a", e.a}, {"b", e.b}, {"length_m", e.length_m}, {"critical_point", e.critical_point}});
  j["graph"] = {{"nodes", nodes}, {"edges", edges}};
  if (!a.ground_truth.empty()) {
    BinaryGrid gt = binarize(io::load_map(a.ground_truth, fo).grid);
    if (gt.width() != geo.width || gt.height() != geo.height) {
      std::cerr << "notice: " << a.ground_truth.string() << " is " << gt.width() << "x"
                << gt.height() << ", the map " << geo.width << "x" << geo.height
                << ": the ground truth is scaled to the map (nearest neighbour)\n";
      j["ground_truth_scaled_from"] = {gt.width(), gt.height()};
      gt = topology::resample_nearest(gt, geo.width, geo.height);
    }
    topology::SegmentationScores s;
    if (a.metric == "ipa") {
      s = topology::segmentation_scores_ipa(m.region, gt);
    } else {
      // Ground-truth rooms smaller than the region merge area are specks, not rooms.
      const auto min_cells =
          static_cast<std::size_t>(a.min_region_area / (geo.resolution * geo.resolution));
      s = topology::segmentation_scores(m.region, topology::free_components(gt), min_cells);
    }
    j["segmentation"] = {{"metric", a.metric},
                         {"recall", s.recall},
                         {"precision", s.precision},
                         {"rooms", s.rooms},
                         {"regions", s.regions}};
  }
  if (!a.labels.empty()) {
    topology::write_label_image(a.labels, m.region);
    j["labels"] = a.labels.string();
  }
  if (!a.out.empty()) {
    save_stages(loaded.grid, blocked, m, opt.gvd.border_is_blocked, a.out);
    std::ofstream(a.out / "topology.json") << j.dump(2) << "\n";
  }
  if (a.json) {
    print_json(j);
    return;
  }
  std::cout << "map:             " << a.map.string() << " (" << geo.width << "x" << geo.height
            << ", " << geo.resolution << " m)\n"
            << "method:          " << a.method << "\n"
            << "voronoi cells:   " << diagram_cells << "\n"
            << "critical points: " << m.critical_points.size() << "\n"
            << "regions:         " << m.regions.size() << "\n"
            << "graph edges:     " << m.edges.size() << "\n"
            << "time:            " << build_ms << " ms\n";
  if (j.contains("segmentation"))
    std::cout << "recall:          " << 100.0 * j["segmentation"]["recall"].get<double>() << " %\n"
              << "precision:       " << 100.0 * j["segmentation"]["precision"].get<double>()
              << " %\n";
  if (!a.out.empty()) std::cout << "pictures:        " << a.out.string() << "/{a..f}_*.png\n";
}

void setup(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "topo",
      "Topological map of a floor plan: Voronoi diagram, critical points (doorways), regions "
      "(rooms) and their graph (Choi et al., 'Topological map building', 2002)");
  auto args = std::make_shared<TopoArgs>();
  cmd->add_option("--map", args->map, "Map file: ROS .yaml, Moving AI .map, floor plan .png/.pgm")
      ->required();
  cmd->add_option("--method", args->method,
                  "edt (EDT-based generalized Voronoi) | ca (the paper's cellular automaton)")
      ->capture_default_str();
  cmd->add_option("--out", args->out,
                  "Folder for the stage pictures a_binary .. f_graph.png and topology.json")
      ->check(output_dir());
  cmd->add_option("--ground-truth", args->ground_truth,
                  "Ground-truth room image (white rooms): adds segmentation recall/precision "
                  "(an image of another size is scaled to the map, nearest neighbour, with a "
                  "notice)");
  cmd->add_option("--labels", args->labels,
                  "Write the regions as a 16-bit label image (.png or .pgm): 0 = no region, "
                  "region id + 1 otherwise, same size and orientation as the map image");
  cmd->add_option("--metric", args->metric,
                  "Segmentation score: ipa (ipa_room_segmentation: 8-connected rooms and regions "
                  "over 100 px, full areas) | intersection (4-connected rooms >= "
                  "--min-region-area, areas cut to room and region cells)")
      ->capture_default_str();
  cmd->add_option("--free-from", args->free_from,
                  "Image maps: a pixel is free when its grey is >= this (0..255)")
      ->check(CLI::Range(1, 255))
      ->capture_default_str();
  cmd->add_option("--min-region-area", args->min_region_area,
                  "Regions smaller than this [m^2] are merged into a neighbour")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--regions-absorb-obstacles", args->absorb_obstacles,
                  "An obstacle piece up to this area [m^2] enclosed by one region (furniture, a "
                  "pillar) joins it in the labels, polygons and areas (0 = off)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--max-rise-walk", args->max_rise_walk,
                  "Critical points: the clearance rise is sought up to this far [m] along the "
                  "diagram, across junctions (0 = only on the point's own edge)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--min-rise", args->min_rise,
                  "Critical points: a narrowing counts where the clearance rises by at least "
                  "max(this [m], --rise-ratio x its clearance) on both sides along the diagram")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--rise-ratio", args->rise_ratio, "See --min-rise")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--passage-length", args->passage_length,
                  "Critical points: a narrowing of near-constant clearance at least this long "
                  "[m] (a corridor) is cut at its ends, also when only one end widens (0 = off)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--passage-rise-ratio", args->passage_rise_ratio,
                  "A passage end is cut only where the clearance beyond it reaches (1 + this) x "
                  "the passage's")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--passage-bulges", args->passage_bulges,
                  "A passage goes on through a bend or widening that narrows again before it "
                  "opens, and is cut at that last narrowing (true/false)")
      ->capture_default_str();
  cmd->add_option("--passage-junctions", args->passage_junctions,
                  "A passage open at one end that runs into a junction of narrower branches "
                  "(doors, a narrower corridor) is cut there too (true/false)")
      ->capture_default_str();
  cmd->add_option("--validate-sides", args->validate_sides,
                  "Room test: drop a critical line when a region it separates is no wider than "
                  "the line (true/false)")
      ->capture_default_str();
  cmd->add_option("--room-test-elongation", args->room_test_elongation,
                  "Room test: join two sides only when one is a passage piece, area / (2 x "
                  "widest clearance)^2 at least this (0 = any shape)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--min-wall-area", args->min_wall_area,
                  "Obstacle pieces smaller than this [m^2] are furniture: no critical line "
                  "(door) ends on them (0 = off)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--wall-gap-max-width", args->wall.max_width,
                  "Openings in wall lines: a gap up to this wide [m] between two collinear wall "
                  "faces is closed by a critical line (0 = off)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--wall-gap-min-width", args->wall.min_width,
                  "Openings in wall lines: the narrowest gap [m]")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--wall-min-length", args->wall.min_wall_length,
                  "Openings in wall lines: each wall face at least this long [m]")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--wall-max-offset", args->wall.max_offset,
                  "Openings in wall lines: collinear when each face end is within this [m] of "
                  "the other face's line")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--wall-max-thickness", args->wall.max_wall_thickness,
                  "Openings in wall lines: two opposite gaps this close [m] are one wall's faces")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--wall-gap-first", args->wall_first,
                  "Where a wall-line opening and a narrowing close the same opening, keep the "
                  "wall line (true/false)")
      ->capture_default_str();
  cmd->add_option("--furniture-line-area", args->furniture_line_area,
                  "A narrowing's line ending on an obstacle piece smaller than this [m^2] (a "
                  "chair, a bin) does not hide a wall-line opening next to it (0 = off)")
      ->check(non_negative())
      ->capture_default_str();
  cmd->add_option("--basis-across", args->basis_across,
                  "Critical points whose two nearest sites lie on one wall (a corner, a corridor's "
                  "mouth) take the obstacle across the point as second basis point, so the line "
                  "crosses the narrowing (true/false)")
      ->capture_default_str();
  cmd->add_option("--mcap", args->mcap,
                  "Write a ROS 2 bag (MCAP): /map, /voronoi, /topology (docs/ros.md)");
  cmd->add_flag("--json", args->json,
                "JSON output: critical_points, regions (count), graph {nodes, edges}, time_ms, "
                "segmentation");
  cmd->callback([args] { run(*args); });
}

const Command reg{{"topo", setup, 40}};

}  // namespace
}  // namespace voronav::cli
