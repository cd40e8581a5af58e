// The labeled Voronoi diagram by cellular automaton (seed 003, section III.2, after Tzionas et
// al. 1997): obstacle boundary cells are coded from their 4-neighbours (von Neumann), flagged as
// sources, and expand one 4-neighbour ring per time step; where fronts of different labels meet,
// the cell is a Voronoi cell and vor(i, j) = t, the step at which the fronts met (the clearance in
// the 4-connected metric).
//
// Edge codes (the paper's figure 5 is missing from the text; this is the project's definition,
// from which of the 4 neighbours E, N, W, S of an obstacle cell are free):
//   1  free cell (not an obstacle)              - not an edge
//   2  obstacle, no free 4-neighbour (interior) - not an edge
//   3  obstacle, free on two opposite sides (a one-cell-thick wall)   - noise
//   4  obstacle, free on three or four sides (a tip or a lone cell)   - noise
//   5..8   straight edges, the free side is E, N, W, S respectively
//   9..12  corners, the free sides are NE, NW, SW, SE respectively
// (the 8 edge shapes of the paper are codes 5..12).
//
// CA rule per step t for each free, unflagged, non-Voronoi cell (seed 003, steps 1-2):
//   - its flagged 4-neighbours all carry the same obstacle -> it takes that label and its source,
//     is flagged, and time(i, j) = t (the paper also stamps vor here; we keep the time stamp in
//     `time` for every reached cell and reserve `vor` for the diagram, since stamping every cell
//     would make the whole free space "Voronoi");
//   - they carry different obstacles -> vor(i, j) = t, not flagged (the expansion stops there);
// and, what the paper leaves implicit, two 4-adjacent cells flagged in the same step by different
// obstacles meet between cells: the one farther from its source (ties: lower index) becomes a
// Voronoi cell. The run ends when a step flags nothing.
//
// "Different obstacles": different labels, and by default (as for the EDT diagram) also sources of
// the same label farther apart than max(site_separation, site_separation_ratio * t), which a wave
// carrying its source cell can check. The default label is the obstacle component; the paper's
// edge-code labels are available (`labels = kEdgeCode`).
#pragma once

#include <cstdint>

#include "voronav/core/grid_map.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::voronoi {

enum class CaLabels : std::uint8_t {
  kObstacleComponent,  ///< 8-connected obstacle component of the source cell (default)
  kEdgeCode,           ///< the paper: the source cell's edge code
};

struct CaVoronoiOptions {
  bool border_is_blocked = true;  ///< the outside of the grid is an obstacle
  CaLabels labels = CaLabels::kObstacleComponent;
  /// Noise cells (codes 3, 4: thin walls, tips) are sources too; the paper ignores them, which
  /// loses one-cell-thick walls of drawn floor plans.
  bool noise_cells_are_sources = true;
  /// Same-label sources farther apart than max(site_separation [cells],
  /// site_separation_ratio * t) count as different obstacles; a huge value disables it.
  double site_separation = 2.5;
  double site_separation_ratio = 0.0;
  /// Thin the diagram to one cell wide (the same thinning as the EDT diagram).
  bool thin = true;
};

struct LabeledVoronoi {
  GridMap<std::uint8_t> edge_code;  ///< 1..12 as above
  GridMap<std::int32_t> label;  ///< c(i, j): label of the source that reached the cell (-1 none)
  GridMap<std::int32_t> time;   ///< step at which the cell was reached (0 on sources, -1 never)
  BinaryGrid vor;               ///< the raw diagram: 1 where fronts of different obstacles met
  BinaryGrid diagram;           ///< vor thinned to one cell wide (== vor when thin is false)
  int steps = 0;                ///< the last time step that flagged or stamped a cell
};

/// The edge code (1..12) of every cell, border outside the grid counted as blocked or not.
[[nodiscard]] GridMap<std::uint8_t> edge_codes(const BinaryGrid& blocked, bool border_is_blocked);

/// Runs the cellular automaton. Throws voronav::Error for invalid options.
[[nodiscard]] LabeledVoronoi build_labeled_voronoi(const BinaryGrid& blocked,
                                                   const CaVoronoiOptions& options = {});

/// How well two diagrams agree: the fraction of the cells of `a` within `tolerance` [cells] of a
/// cell of `b`, and the other way round.
struct DiagramAgreement {
  double a_in_b = 0.0;
  double b_in_a = 0.0;
  std::size_t a_cells = 0, b_cells = 0;
};
[[nodiscard]] DiagramAgreement compare_diagrams(const BinaryGrid& a, const BinaryGrid& b,
                                                double tolerance);

}  // namespace voronav::voronoi
