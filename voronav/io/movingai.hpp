// Moving AI grid benchmark formats (Sturtevant, "Benchmarks for Grid-Based Pathfinding", 2012):
// `.map` ("type octile", height, width, "map", then one text row per grid row, top row first) and
// `.map.scen` ("version 1" or "version 1.0", then per query 9 columns: bucket, map, width, height,
// start x, start y, goal x, goal y, optimal length). File coordinates have y down (row 0 at the
// top); voronav cells have row 0 at the bottom, so movingai_to_cell/cell_to_movingai flip y.
//
// As the files are in the wild (movingai.com/benchmarks/formats.html and the published sets):
// - columns are tab-separated in most sets and space-separated in others (bgmaps, wc3maps): a
//   line with a tab is split at tabs (a map name may hold spaces), any other at whitespace;
// - terrain: '.' and 'G' passable, '@' 'O' out of bounds, 'T' trees (blocked), 'S' swamp
//   (passable from regular terrain), 'W' water (traversable, but not passable from regular
//   terrain): MovingAiTerrain keeps the characters, and a query is searched on the land grid
//   (. G S) or, when it starts on water, on the water grid (W only: water to water);
// - the map-size columns may differ from the map: the format says the map is then scaled to that
//   size (scale_movingai_terrain, nearest cell);
// - optimal lengths are printed with 3 or 8 decimals or, by %g, with 6 significant digits and
//   trailing zeros dropped ("1001" for 1000.997): MovingAiQuery::optimal_rounding is one unit in
//   the last significant digit the value carries (at least 6 digits).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "voronav/core/occupancy.hpp"

namespace voronav::io {

/// The characters of a .map file (voronav frame: row 0 at the bottom).
struct MovingAiTerrain {
  GridMap<char> cells;

  /// Water ('W') cells are only traversable from water.
  [[nodiscard]] bool is_water(Cell c) const { return cells[c] == 'W'; }
  /// 0 = free: the land grid ('.', 'G', 'S') or, for water == true, the water grid ('W').
  [[nodiscard]] BinaryGrid traversable(bool water) const;
};

/// Loads a .map file keeping its terrain characters.
[[nodiscard]] MovingAiTerrain load_movingai_terrain(const std::filesystem::path& path);
/// Nearest-cell scaling to width x height (file cell (X, Y) of the result is cell
/// (X * w / width, Y * h / height) of the original, in the file frame).
[[nodiscard]] MovingAiTerrain scale_movingai_terrain(const MovingAiTerrain& terrain, int width,
                                                     int height);

/// Loads a .map file: land cells ('.', 'G', 'S') kFree, the rest (water included) kOccupied;
/// resolution 1, origin 0.
[[nodiscard]] OccupancyGrid load_movingai_map(const std::filesystem::path& path);
/// Writes a .map file: occupied and unknown cells as '@', free cells as '.'.
void save_movingai_map(const OccupancyGrid& grid, const std::filesystem::path& path);

struct MovingAiQuery {
  int bucket = 0;
  std::string map;  ///< the map column as written
  int map_width = 0, map_height = 0;
  int start_x = 0, start_y = 0, goal_x = 0, goal_y = 0;  ///< file frame (y down)
  double optimal_length = 0.0;
  /// One unit in the last significant digit of the optimal-length column, counting at least 6
  /// significant digits (%g drops trailing zeros: "1001" for 1000.997, so "1001" carries 6): some
  /// files print 3 decimals, others 8 or %g, and the 3-decimal ones are truncated rather than
  /// rounded (32room_000 line 645: 262.764 for 262.76450...), so comparisons allow one unit.
  double optimal_rounding = 0.0;
  int line = 0;  ///< line in the .scen file (1-based)
};

/// Loads a .scen file ("version 1" or "version 1.0"). Blank lines are skipped.
[[nodiscard]] std::vector<MovingAiQuery> load_movingai_scen(const std::filesystem::path& path);
void save_movingai_scen(const std::vector<MovingAiQuery>& queries,
                        const std::filesystem::path& path);

/// Throws voronav::Error naming the scen file and line of the first query whose map size or
/// coordinates do not fit `grid`. With allow_scaling, a query whose map-size columns differ from
/// the grid is accepted when its coordinates fit those columns (the map is scaled to them).
void check_scen_fits(const std::vector<MovingAiQuery>& queries, const OccupancyGrid& grid,
                     const std::filesystem::path& scen_path, bool allow_scaling = false);

/// Whether a found length equals the query's optimal length at the precision the file printed:
/// |found - optimal| <= max(tolerance, optimal_rounding) ("1001" accepts 1000.997, rejects 1000.9).
[[nodiscard]] bool matches_optimal(const MovingAiQuery& query, double found,
                                   double tolerance = 1e-4);

/// One unit in the last significant digit of `text` (a printed number), counting at least
/// `min_digits` significant digits: "1001" -> 0.01, "262.764" -> 0.001, "1.41421356" -> 1e-8.
[[nodiscard]] double last_digit_unit(const std::string& text, int min_digits = 6);

[[nodiscard]] inline Cell movingai_to_cell(int x, int y, int height) {
  return {x, height - 1 - y};
}
[[nodiscard]] inline std::pair<int, int> cell_to_movingai(Cell c, int height) {
  return {c.x, height - 1 - c.y};
}

}  // namespace voronav::io
