// JPS+ jump-point tables (see jps.hpp): one sweep per direction, each cell's entry from its
// neighbour's in that direction, so the build is O(8 cells); stored as one byte per entry.
#include <algorithm>

#include "voronav/planning/internal/jps_data.hpp"

namespace voronav::planning::internal {

void build_jump_tables(JpsMapData& m) {
  const int w = m.width, h = m.height;
  std::vector<std::int32_t> table(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 8, 0);
  auto at = [&](int x, int y, int d) -> std::int32_t& {
    return table[8 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                      static_cast<std::size_t>(x)) +
                 static_cast<std::size_t>(d)];
  };
  auto extend = [](std::int32_t next) { return next > 0 ? next + 1 : next - 1; };
  // Straight directions first (the diagonal entries read them), then the diagonals.
  for (int d = 0; d < 8; ++d) {
    const int dx = kDirX[d], dy = kDirY[d];
    // Visit each cell after its neighbour (x + dx, y + dy).
    for (int j = 0; j < h; ++j) {
      const int y = dy > 0 ? h - 1 - j : j;
      for (int i = 0; i < w; ++i) {
        const int x = dx > 0 ? w - 1 - i : i;
        if (!m.free(x, y)) continue;
        const int nx = x + dx, ny = y + dy;
        std::int32_t v = 0;
        if (dx != 0 && dy != 0) {
          if (m.free(nx, y) && m.free(x, ny) && m.free(nx, ny)) {
            const bool jump = at(nx, ny, dir_index(dx, 0)) > 0 || at(nx, ny, dir_index(0, dy)) > 0;
            v = jump ? 1 : extend(at(nx, ny, d));
          }
        } else if (m.free(nx, ny)) {
          // A forced neighbour at n = (nx, ny): a side cell free at n but blocked one step back.
          bool forced;
          if (dy == 0)
            forced = (m.free(nx, ny + 1) && !m.free(x, ny + 1)) ||
                     (m.free(nx, ny - 1) && !m.free(x, ny - 1));
          else
            forced = (m.free(nx + 1, ny) && !m.free(nx + 1, y)) ||
                     (m.free(nx - 1, ny) && !m.free(nx - 1, y));
          v = forced ? 1 : extend(at(nx, ny, d));
        }
        at(x, y, d) = v;
      }
    }
  }
  // Entries past +-127 become kFarJump: along a direction the entries change by one per step
  // (the jump point, or the wall, comes one step nearer), so the entry 127 steps on carries on.
  m.table.resize(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::int32_t v = table[i];
    m.table[i] = static_cast<std::int8_t>(v > kFarSteps || v < -kFarSteps ? kFarJump : v);
  }
}

}  // namespace voronav::planning::internal
