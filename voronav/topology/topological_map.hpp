// Topological map from a binary grid (seed 003, sections III.3 and IV): critical points on the
// Voronoi diagram, critical lines, topological regions, the topological graph, and planning on
// that graph.
//
//  - critical point: a diagram cell inside a branch (not a junction or end) whose clearance is a
//    local minimum along the diagram: walking along the diagram from it in both directions, the
//    clearance rises by at least max(min_rise [m], rise_ratio * clearance) before it ever drops
//    below the critical value (a door or a narrowing). A plateau of equal minima gives one point,
//    its middle. Its two basis points are the nearest obstacle cell and the nearest obstacle cell
//    on the other side (the site of a neighbour farthest from the first one).
//    Options beyond the paper (issue #15; measured in docs/reproductions/topology.md): the rise
//    test may continue across junctions (max_rise_walk, off); a passage, a run of at least
//    passage_length whose clearance stays within one cell of its minimum, is cut at the ends
//    where the clearance rises to (1 + passage_rise_ratio) x its own, also when only one end
//    opens (a corridor mouth, an open-fronted room, a dead end), past any bulge that narrows
//    back to the passage's width before it opens (on by default since the second #15 stop,
//    with the room test below);
//    critical points on obstacle pieces under min_wall_area (furniture) are dropped (off); and the
//    room test (validate_sides, on) drops a line when neither region it separates holds a cell
//    whose clearance reaches that rise (two pieces of one passage). Openings in wall lines (issue
//    #15, on by default; wall_openings.hpp): a door-width gap between two collinear wall faces, or
//    between a wall stub's end and the wall ahead of it, is a critical line too
//    (CriticalPoint::wall_gap), unless a narrowing's line is next to it. basis_across (off): a
//    point whose two sites lie on one wall (a notch's jambs at a corridor's mouth) takes the
//    obstacle across it as its second basis point, so that its line crosses the narrowing.
//    passage_junctions (on; stop 24): a passage that rises at one end and runs into a junction
//    of narrower branches at the other (a corridor's foot on a link, beside a door) is cut at
//    that mouth too (CriticalPoint::passage_junction; not dropped by the room test).
//    furniture_line_area (0.25 m^2; stop 24): a narrowing's line ending on a small obstacle piece
//    (a chair beside a door's jamb) no longer hides the door's wall-line opening.
//  - critical line: the Bresenham segment between the two basis points.
//  - regions: the free cells cut by the critical lines, 4-connected components; the cells of the
//    lines join the smallest adjacent region. Merge rule: a region smaller than min_region_area
//    [m^2] is merged into the neighbour it shares the most critical-line cells with (the smallest
//    region first, repeated until none is left); a critical line whose two sides end up in the
//    same region does not separate anything and is marked so.
//    Regions still under min_region_area then merge into the neighbour sharing the longest
//    border (4-neighbour cell pairs); one without any neighbour is dropped (no region).
//  - graph: node = region centre (the region cell nearest its centroid), edge = a separating
//    critical line between two regions, or the common border of two regions that touch without
//    one (crossing at the border cell nearest its middle), cost = centre -> crossing -> centre [m].
//  - planning: A* on the graph (heuristic: straight distance between centres), expanded back to
//    a metric path start -> midpoints of the crossed critical lines -> goal.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"
#include "voronav/topology/wall_openings.hpp"
#include "voronav/voronoi/gvd.hpp"
#include "voronav/voronoi/labeled_voronoi.hpp"

namespace voronav::topology {

enum class DiagramMethod : std::uint8_t {
  kEdt,                ///< the EDT-based generalized Voronoi diagram (default)
  kCellularAutomaton,  ///< the paper's labeled Voronoi diagram by cellular automaton
};

/// The method's name on the command line and in JSON ("edt", "ca").
[[nodiscard]] std::string_view diagram_method_name(DiagramMethod m);
/// The method named `name` ("edt" or "ca"); throws voronav::Error naming `what` otherwise.
[[nodiscard]] DiagramMethod parse_diagram_method(std::string_view name, std::string_view what);

struct TopologyOptions {
  DiagramMethod method = DiagramMethod::kEdt;
  voronoi::GvdOptions gvd{};       ///< for kEdt (also the spur pruning of kCellularAutomaton)
  voronoi::CaVoronoiOptions ca{};  ///< for kCellularAutomaton
  /// A critical point needs the clearance to rise by max(min_rise [m], rise_ratio * its
  /// clearance) on both sides along the diagram. 0.3 since stop 27 (was 0.25): benches against
  /// a corridor's walls narrow it by a fifth (a rise back to 1.25x), a door far more; every
  /// target of issue #15 holds from 0.29 to 0.36 (docs/reproductions/topology.md, "The rise
  /// ratio").
  double min_rise = 0.1;
  double rise_ratio = 0.3;
  /// Critical points wider than this door width [m] (2 x clearance) are ignored; 0 = no limit.
  double max_door_width = 0.0;
  /// The rise test of a critical point walks at most this far [m] along the diagram and
  /// continues across junctions into every other branch (a branch that rises suffices);
  /// 0 = the walk stays on the point's own edge, unbounded (the earlier rule).
  double max_rise_walk = 0.0;
  /// A minimum whose clearance stays within one cell of it along at least this length [m] is a
  /// passage (a corridor): it is cut at its ends where the clearance rises, not in its middle,
  /// also when only one end rises; 0 = off.
  double passage_length = 2.0;
  /// A passage end is cut only where the clearance beyond it reaches (1 + this) x the
  /// passage's clearance (a room opens, not a bump in the corridor).
  double passage_rise_ratio = 0.75;
  /// A passage's end lies past its bulges: where the clearance, before it reaches the opening
  /// rise, comes back within one cell of the passage's, the passage goes on (a bend, a short
  /// widening), and it is cut at that last narrowing instead of at the first bump.
  bool passage_bulges = true;
  /// A passage (as above) that opens at one end and whose other end runs, without opening, into
  /// a junction where every other branch narrows below the passage's band (a door, a narrower
  /// corridor: the passage does not go on) is cut at that end too, at its last cell within the
  /// band before the junction; the room test does not drop such a line. On since stop 24 (the
  /// lab_ipa plans' corridor foot; no floor plan lower, docs/reproductions/topology.md).
  bool passage_junctions = true;
  /// Obstacle components (8-connected) smaller than this [m^2] are free-standing furniture; a
  /// critical point with a basis point on one is not a door and is dropped; 0 = off.
  double min_wall_area = 0.0;
  /// Room test of the critical lines: a line is dropped (its two sides merged) when neither side
  /// holds a cell whose clearance reaches max(clearance + min_rise, clearance x (1 +
  /// max(rise_ratio, passage_rise_ratio))): both are no wider than the line, pieces of one passage.
  bool validate_sides = true;
  /// The room test joins two sides only when one of them is a passage piece: its elongation,
  /// area / (2 x its widest clearance)^2, is at least this (about 1-2 for a room, length / width
  /// for a corridor piece); two room-shaped sides behind a wide opening stay apart. 0 = any.
  double room_test_elongation = 2.5;
  /// Regions smaller than this [m^2] are merged into a neighbour (see the file comment).
  double min_region_area = 1.0;
  /// An obstacle piece (8-connected) of at most this area [m^2], off the map's border, whose
  /// neighbouring free cells all lie in one region joins that region in `region` (the label
  /// image, the polygons, the areas): rooms without holes for tables and pillars. A piece next
  /// to two regions (a wall between rooms) never joins. 0 = off.
  double regions_absorb_obstacles = 2.0;
  /// Openings in wall lines (wall_openings.hpp): a gap of door width between two collinear wall
  /// faces is closed by a critical line too, unless a critical line already crosses it; off
  /// while wall_openings.max_width is 0.
  WallOpeningOptions wall_openings{};
  /// Where a wall-line opening and a narrowing's critical line close the same opening, keep the
  /// wall line (true) or the narrowing's line (false).
  bool wall_openings_first = false;
  /// A narrowing's line with a basis point on an obstacle piece (8-connected) smaller than this
  /// [m^2] (a chair, a bin, a pillar) does not hide a wall-line opening next to it (the rule
  /// above): a line from a door's jamb to a chair standing beside it does not close the door,
  /// so the door's wall-line opening is kept; 0 = off (every narrowing's line hides one). 0.25
  /// since stop 24 (the furnished lab door; no floor plan lower).
  double furniture_line_area = 0.25;
  /// A critical point whose two nearest sites lie on one wall (the neighbourhood's farthest site
  /// closer to the first than 1.5 x the clearance, at a corner or a corridor's mouth) gets as its
  /// second basis point the obstacle across it, on the ray from the first through the point, so
  /// that its line crosses the narrowing; none when no obstacle lies within 1.5 x the clearance
  /// (issue #15, beyond the paper).
  bool basis_across = false;
};

struct CriticalPoint {
  Cell cell;                  ///< on the diagram
  std::array<Cell, 2> basis;  ///< the two nearest obstacle cells (may lie on the border ring)
  double clearance_m = 0.0;   ///< distance from cell to basis[0] [m]
  std::vector<Cell> line;     ///< free cells of the critical line (basis to basis)
  Cell midpoint;              ///< the free line cell nearest the middle of the two basis points
  bool separates = true;      ///< whether its two sides are different regions
  bool wall_gap = false;      ///< from an opening in a wall line, not a narrowing of the diagram
  bool passage_junction = false;  ///< a passage's end at a junction (passage_junctions)
};

struct Region {
  int id = 0;
  std::size_t cells = 0;           ///< free cells + absorbed obstacle cells
  std::size_t absorbed_cells = 0;  ///< obstacle cells joined (regions_absorb_obstacles)
  double area_m2 = 0.0;
  Cell centre;        ///< free region cell nearest the centroid
  Vec2 centre_world;  ///< its world position [m]
};

struct TopoEdge {
  int a = 0, b = 0;        ///< region ids
  int critical_point = 0;  ///< index into critical_points; -1: the regions touch without a line
  Cell midpoint;           ///< where the edge crosses: the line's midpoint or a border cell
  double length_m = 0.0;   ///< centre(a) -> midpoint -> centre(b) [m]
};

struct TopologicalMap {
  GridGeometry geometry;
  BinaryGrid blocked;
  BinaryGrid diagram;        ///< the Voronoi diagram used (thinned, pruned)
  GridMap<float> clearance;  ///< [cells]
  std::vector<CriticalPoint> critical_points;
  /// Region id per free cell, -1 on obstacles (on an absorbed obstacle piece: its region, see
  /// TopologyOptions::regions_absorb_obstacles).
  GridMap<std::int32_t> region;
  std::vector<Region> regions;
  std::vector<TopoEdge> edges;
  std::size_t absorbed_obstacles = 0;  ///< obstacle pieces joined to a region
  std::size_t basis_across = 0;        ///< critical points given a basis point across them
  /// Wall-line openings kept although a narrowing's line ending on furniture lies next to them
  /// (TopologyOptions::furniture_line_area).
  std::size_t openings_past_furniture = 0;

  /// The region of a free cell, -1 for blocked (also absorbed) or outside cells.
  [[nodiscard]] int region_of(Cell c) const {
    return geometry.contains(c) && blocked[c] == 0 ? region[c] : -1;
  }
};

/// Builds the diagram with options.method, then the topological map. Throws voronav::Error for
/// invalid options.
[[nodiscard]] TopologicalMap build_topological_map(const BinaryGrid& blocked,
                                                   const TopologyOptions& options = {});
/// The topological map over a given one-cell-wide diagram (e.g. an incrementally updated one).
[[nodiscard]] TopologicalMap build_topological_map(const BinaryGrid& blocked,
                                                   const BinaryGrid& diagram,
                                                   const TopologyOptions& options = {});

enum class TopoPlanStatus : std::uint8_t {
  kOk,
  kStartBlocked,  ///< start outside the map or on an obstacle
  kGoalBlocked,
  kUnreachable,  ///< no chain of regions joins them
};

struct TopoPlan {
  TopoPlanStatus status = TopoPlanStatus::kUnreachable;
  std::vector<int> regions;        ///< region sequence from the start's to the goal's
  std::vector<int> edges;          ///< the graph edges crossed
  std::vector<Cell> waypoints;     ///< start, crossed critical-line midpoints, goal
  double graph_cost_m = 0.0;       ///< sum of the crossed edge costs [m]
  double waypoint_length_m = 0.0;  ///< length of the waypoint polyline [m]
  std::size_t expanded = 0;        ///< A* expansions on the graph
  [[nodiscard]] bool ok() const { return status == TopoPlanStatus::kOk; }
};

/// A* over the topological graph from the region of `start` to the region of `goal`.
[[nodiscard]] TopoPlan plan_on_graph(const TopologicalMap& map, Cell start, Cell goal);

}  // namespace voronav::topology
