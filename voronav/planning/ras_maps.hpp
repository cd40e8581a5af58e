// Stand-ins for the maps of seed 001's Tables 3 and 4, whose originals are not published: built
// deterministically from rectangles and dot lattices so the tables can be re-run anywhere. Both
// use the paper's image frame for the layout (x right, y down, 1 pixel = 1 cell); the grids use
// voronav cells (row 0 at the bottom), so image (x, y) is cell (x, H - 1 - y).
//
// Table 3 (figure 12): 512x512, two walls forcing an S-shaped route from the lower left to the
// upper right, a pillar, a stub and a block; everything is 16-cell aligned so region sizes 8 and 16
// see the same obstacles. Wall lengths were chosen so that the minimum region counts (56 at
// r = 16, 107 at r = 8) are close to the paper's 57 and 106.
// Table 4 (figure 13): 1000x1000, start (100,250), goal (700,250); two long walls force the route
// down under the first wall, through a field of 4x4 dots whose spacing grows with depth (gaps
// 4, 8 and 32 cells), and back up over the second wall. The gaps decide which rows a robot of
// size 8 may use: density 0 takes the narrow gaps, density 8 goes deeper (figure 14).
// Layouts are described in full in docs/reproductions/ras.md.
#pragma once

#include <string>

#include "voronav/core/cell.hpp"
#include "voronav/core/occupancy.hpp"

namespace voronav::planning {

struct RasStandInMap {
  std::string name;
  BinaryGrid grid;  ///< 1 = blocked, resolution 1 (one cell per paper pixel)
  Cell start;       ///< voronav cell
  Cell goal;
};

/// 512x512 stand-in for Table 3 / figure 12.
[[nodiscard]] RasStandInMap ras_table3_map();
/// 1000x1000 stand-in for Table 4 / figure 13, start (100,250) and goal (700,250) in the image
/// frame.
[[nodiscard]] RasStandInMap ras_table4_map();

}  // namespace voronav::planning
