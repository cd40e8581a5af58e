// Moving AI grid benchmark formats (Sturtevant, "Benchmarks for Grid-Based Pathfinding", 2012):
// `.map` ("type octile", height, width, "map", then one text row per grid row, top row first;
// '.', 'G', 'S' passable; '@', 'O', 'T', 'W' blocked) and `.map.scen` ("version 1", then per
// query 9 tab-separated columns: bucket, map, width, height, start x, start y, goal x, goal y,
// optimal length). File coordinates have y down (row 0 at the top); voronav cells have row 0 at
// the bottom, so movingai_to_cell/cell_to_movingai flip y.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "voronav/core/occupancy.hpp"

namespace voronav::io {

/// Loads a .map file: passable cells kFree, blocked kOccupied; resolution 1, origin 0.
[[nodiscard]] OccupancyGrid load_movingai_map(const std::filesystem::path& path);
/// Writes a .map file: occupied and unknown cells as '@', free cells as '.'.
void save_movingai_map(const OccupancyGrid& grid, const std::filesystem::path& path);

struct MovingAiQuery {
  int bucket = 0;
  std::string map;  ///< the map column as written
  int map_width = 0, map_height = 0;
  int start_x = 0, start_y = 0, goal_x = 0, goal_y = 0;  ///< file frame (y down)
  double optimal_length = 0.0;
  /// One unit in the last decimal printed in the optimal-length column (0 for an integer): some
  /// benchmark files print 3 decimals, others 8, and the 3-decimal ones are truncated rather than
  /// rounded (32room_000 line 645: 262.764 for 262.76450...), so comparisons allow that much.
  double optimal_rounding = 0.0;
  int line = 0;  ///< line in the .scen file (1-based)
};

/// Loads a .scen file ("version 1" or "version 1.0"). Blank lines are skipped.
[[nodiscard]] std::vector<MovingAiQuery> load_movingai_scen(const std::filesystem::path& path);
void save_movingai_scen(const std::vector<MovingAiQuery>& queries,
                        const std::filesystem::path& path);

/// Throws voronav::Error naming the scen file and line of the first query whose map size or
/// coordinates do not fit `grid`.
void check_scen_fits(const std::vector<MovingAiQuery>& queries, const OccupancyGrid& grid,
                     const std::filesystem::path& scen_path);

[[nodiscard]] inline Cell movingai_to_cell(int x, int y, int height) {
  return {x, height - 1 - y};
}
[[nodiscard]] inline std::pair<int, int> cell_to_movingai(Cell c, int height) {
  return {c.x, height - 1 - c.y};
}

}  // namespace voronav::io
