// Per-map data of the JPS planners (jps.hpp): the bit-packed map and its transpose, and for JPS+
// the jump-point tables. Internal; built by JpsPlanner::prepare().
#pragma once

#include <cstdint>
#include <vector>

#include "voronav/planning/internal/bit_grid.hpp"
#include "voronav/planning/internal/indexed_heap.hpp"

namespace voronav::planning::internal {

/// Direction d in 0..7: E, W, N, S, NE, NW, SE, SW.
inline constexpr int kDirX[8] = {1, -1, 0, 0, 1, -1, 1, -1};
inline constexpr int kDirY[8] = {0, 0, 1, -1, 1, 1, -1, -1};
[[nodiscard]] inline int dir_index(int dx, int dy) {
  if (dy == 0) return dx > 0 ? 0 : 1;
  if (dx == 0) return dy > 0 ? 2 : 3;
  return dy > 0 ? (dx > 0 ? 4 : 5) : (dx > 0 ? 6 : 7);
}

struct JpsMapData {
  const void* key = nullptr;  ///< the grid's cell array
  int width = 0, height = 0;
  BitGrid rows;  ///< row-major bits (free(row = y, col = x))
  BitGrid cols;  ///< transposed (free(row = x, col = y))
  /// JPS+ only: table[8 * (y * width + x) + d] > 0: a jump point that many steps away in
  /// direction d; <= 0: no jump point, -table free steps before the wall (or the map edge).
  std::vector<std::int32_t> table;

  [[nodiscard]] bool free(int x, int y) const { return rows.free(y, x); }
};

/// Builds the JPS+ tables of `m` (m.rows must be built).
void build_jump_tables(JpsMapData& m);

struct JpsSearchState {
  std::vector<std::int32_t> gs, gd, parent, heap_pos;
  std::vector<std::uint32_t> stamp;
  std::vector<std::uint8_t> closed;
  std::uint32_t search_id = 0;
  IndexedMinHeap open;
};

}  // namespace voronav::planning::internal
