// Breadth-first flood of the free cells reachable from a start cell: the memory-bound floor that
// any search touching the whole map pays. Used as the baseline in the planner benchmarks and as
// an independent oracle for reachability in tests.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "voronav/planning/grid_planner.hpp"

namespace voronav::planning {

class BfsFlood {
 public:
  /// Floods from start over free cells (same neighbour rule as A*: no corner cutting) and returns
  /// the number of cells reached (0 when start is blocked or outside the grid).
  std::size_t flood(const BinaryGrid& grid, Cell start, Connectivity connectivity);
  /// Steps from start to each cell after flood(); -1 for unreached cells.
  [[nodiscard]] std::int32_t steps(const BinaryGrid& grid, Cell c) const;
  /// After flood(): the indices (grid.index) of the reached cells in the order they were
  /// reached, so their step counts never decrease; the start first. Valid until the next flood.
  [[nodiscard]] std::span<const std::int32_t> reached() const {
    return std::span<const std::int32_t>(queue_).first(reached_);
  }

 private:
  std::vector<std::int32_t> dist_;
  std::vector<std::int32_t> queue_;
  std::size_t reached_ = 0;
};

}  // namespace voronav::planning
