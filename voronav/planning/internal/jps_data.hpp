// Per-map data of the JPS planners (jps.hpp): the bit-packed map and its transpose, and for JPS+
// the jump-point tables; and the per-planner search state reused between queries. Internal; built
// by JpsPlanner::prepare().
#pragma once

#include <cstdint>
#include <vector>

#include "voronav/planning/internal/bit_grid.hpp"

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
  /// JPS+ only: entry 8 * (y * width + x) + d in -127..127: > 0: a jump point that many steps
  /// away in direction d; <= 0: no jump point, -entry free steps before the wall (or the map
  /// edge). kFarJump: no jump point within 127 steps, all free: continue from the cell 127 steps
  /// on. One byte per entry (8 bytes per cell, one cache line holds 8 cells): the tables of a
  /// 512x512 map take 2 MB, and a query touches fewer cache lines.
  std::vector<std::int8_t> table;

  [[nodiscard]] bool free(int x, int y) const { return rows.free(y, x); }
};

inline constexpr int kFarJump = -128;
inline constexpr int kFarSteps = 127;

/// Builds the JPS+ tables of `m` (m.rows must be built).
void build_jump_tables(JpsMapData& m);

/// Search state of one node (one cell), 16 bytes so one cache line holds four: reset lazily by a
/// search stamp instead of clearing arrays per query.
struct JpsNode {
  std::uint32_t stamp;  ///< == search id: generated (open); == search id + 1: closed
  std::int32_t parent;  ///< cell index of the parent jump point, -1 for the start
  std::int32_t gs, gd;  ///< g as exact (straight, diagonal) step counts
};

/// Open list entry: a 128-bit key ordered like (f, larger g first, node): bits 64-127 = the bits
/// of f (exact, double; f >= 0 so its bits order like its value), bits 32-63 = inverted bits of g
/// as a float (g only breaks f ties), bits 0-31 = the node index.
__extension__ using JpsOpenItem = unsigned __int128;

/// A successor found while expanding one node: cell, and the steps from that node.
struct JpsSuccessor {
  std::int32_t node, x, y, ds, dd;
};

struct JpsSearchState {
  std::vector<JpsNode> nodes;
  std::vector<JpsSuccessor> successors;
  std::vector<std::int32_t> chain;  ///< jump points from the goal back to the start
  std::vector<JpsOpenItem> open;
  std::uint32_t search_id = 0;  ///< even; advanced by 2 per query
};

}  // namespace voronav::planning::internal
