// A* and Dijkstra on a 4- or 8-connected grid with octile costs (1 per straight step, sqrt 2 per
// diagonal step). Diagonal moves need both adjacent straight cells free (the Moving AI rule, so
// paths never cut corners). A* uses the octile distance, which is admissible and consistent
// under that rule; Dijkstra is the same search with a zero heuristic.
//
// Costs are kept exact: g is stored as (straight steps, diagonal steps) and every f or g compared
// is computed as a + b * sqrt 2 from integers, so two nodes on optimal paths have bit-identical f
// (sqrt 2 is irrational, so equal costs mean equal counts). Ties are then real ties and the open
// list breaks them toward larger g (IndexedMinHeap), which keeps open space at about the path
// length in expansions (an empty 970x170 map, corner to corner: 970, not 118,974 with summed
// doubles whose last-bit noise ordered the ties at random).
#pragma once

#include <cstdint>
#include <vector>

#include "voronav/planning/grid_planner.hpp"
#include "voronav/planning/internal/indexed_heap.hpp"

namespace voronav::planning {

class AStarPlanner : public GridPlanner {
 public:
  /// use_heuristic = false gives Dijkstra's algorithm.
  explicit AStarPlanner(PlannerOptions options = {}, bool use_heuristic = true);
  [[nodiscard]] std::string_view name() const override {
    return use_heuristic_ ? "astar" : "dijkstra";
  }
  PlanResult plan(const BinaryGrid& grid, Cell start, Cell goal) override;

 private:
  bool use_heuristic_;
  // Search state reused between queries; a node's g is valid when stamp_[node] == search_id_.
  std::vector<std::int32_t> gs_, gd_;  // g as (straight, diagonal) step counts
  std::vector<std::int32_t> parent_;
  std::vector<std::int32_t> heap_pos_;
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint8_t> closed_;
  std::uint32_t search_id_ = 0;
  internal::IndexedMinHeap open_;
};

class DijkstraPlanner : public AStarPlanner {
 public:
  explicit DijkstraPlanner(PlannerOptions options = {}) : AStarPlanner(std::move(options), false) {}
};

/// Octile distance between two cells [cells].
[[nodiscard]] double octile_distance(Cell a, Cell b);

/// Octile cost of a path given as consecutive 8-neighbour cells [cells].
[[nodiscard]] double path_length_cells(const std::vector<Cell>& path);

/// Checks a path: consecutive cells are neighbours under `connectivity`, no cell is blocked or
/// outside the grid, and no diagonal step cuts a blocked corner. Empty paths are invalid.
[[nodiscard]] bool is_valid_path(const BinaryGrid& grid, const std::vector<Cell>& path,
                                 Connectivity connectivity);

}  // namespace voronav::planning
