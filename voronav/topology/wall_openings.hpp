// Openings in wall lines (issue #15): door and opening detection from the straight pieces of the
// occupied boundary, for room segmentation. A floor plan's room boundaries often follow a wall
// line across an opening (a door without jambs that narrow the free space, a room open onto a
// corridor over the corridor's width): the clearance along the Voronoi diagram does not narrow
// there, so the critical-point rule of seed 003 cannot see them. Here:
//  1. wall faces: the boundary between blocked and free cells is followed as closed chains of cell
//     edges (free side on the left), each chain split at its corners by split-and-merge (Ramer -
//     Douglas - Peucker, tolerance fit_tolerance) and every piece refitted by least squares
//     (principal axis of its boundary vertices);
//  2. an opening: two faces of at least min_wall_length, nearly collinear (angle <= max_angle_deg,
//     each end within max_offset of the other face's line), facing the same side, whose gap along
//     the line is min_width..max_width and free on both sides of the line (a gap in one wall, not
//     a pillar or a niche face);
//  3. the two faces of one thick wall give two such gaps, a wall's thickness apart and facing
//     opposite sides: they are one opening, closed on their middle line; a gap with only one face
//     is closed half a cell behind that face. The closing line runs from jamb (blocked cell) to
//     jamb, so that it separates the free space 4-connectedly like a critical line.
#pragma once

#include <array>
#include <vector>

#include "voronav/core/cell.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::topology {

struct WallOpeningOptions {
  double min_width = 0.5;           ///< [m] narrowest gap that is an opening
  double max_width = 2.0;           ///< [m] widest gap that is an opening; 0 = off (none found)
  double min_wall_length = 0.5;     ///< [m] each of the two wall faces at least this long
  double max_offset = 0.1;          ///< [m] each face end within this of the other face's line
  double max_angle_deg = 10.0;      ///< [deg] the two faces' directions differ by at most this
  double fit_tolerance = 0.075;     ///< [m] split-and-merge tolerance of the boundary chains
  double max_wall_thickness = 0.5;  ///< [m] two opposite gaps this close are one wall's faces
  /// Also close the gap between a wall's free end (a stub no thicker than max_wall_thickness)
  /// and the obstacle its line meets min_width..max_width ahead.
  bool wall_ends = true;
};

/// A straight piece of the occupied boundary, in cell-corner coordinates [cells] (cell (x, y)
/// covers [x, x+1] x [y, y+1]); free space lies on the left of a -> b.
struct WallSegment {
  double ax = 0.0, ay = 0.0, bx = 0.0, by = 0.0;
  [[nodiscard]] double length() const;
};

struct WallOpening {
  std::array<Cell, 2> jambs;  ///< the blocked cells at the two ends of the closing line
  std::vector<Cell> line;     ///< the free cells closing the opening (8-connected, jamb to jamb)
  double width_cells = 0.0;   ///< the gap along the wall line [cells]
  bool both_faces = false;    ///< both faces of the wall continue across the gap
  bool wall_end = false;      ///< from a wall's free end to the obstacle ahead of it
};

/// The straight pieces of the boundary between blocked and free cells (outside the map counts as
/// blocked), split with tolerance `fit_tolerance_cells`, those at least `min_length_cells` long.
[[nodiscard]] std::vector<WallSegment> wall_segments(const BinaryGrid& blocked,
                                                     double fit_tolerance_cells,
                                                     double min_length_cells);

/// Throws voronav::Error naming the option when one is negative, not finite, max_angle_deg is
/// not in [0, 90), or max_width is neither 0 nor at least min_width.
void check_wall_opening_options(const WallOpeningOptions& options);

/// The openings in wall lines (see the file comment); lengths in options are metres, converted
/// with the grid's resolution. Empty when options.max_width is 0. Throws voronav::Error for
/// invalid options.
[[nodiscard]] std::vector<WallOpening> find_wall_openings(const BinaryGrid& blocked,
                                                          const WallOpeningOptions& options);

}  // namespace voronav::topology
