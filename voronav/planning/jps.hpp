// Jump point search on 8-connected octile grids without corner cutting (the rule of every voronav
// grid planner): optimal paths, the same lengths as A*, with far fewer expansions.
//
// JpsPlanner is online JPS (Harabor & Grastien, "Online Graph Pruning for Pathfinding on Grid
// Maps", AAAI 2011): A* over jump points only, with the successor pruning of the no-corner-cutting
// variant (straight moves have forced neighbours where a side row turns from blocked to free,
// diagonal moves have none) and the block-based scanning of "Improving Jump Point Search" (ICAPS
// 2014, section 3): straight jumps read 63 cells per step from a bit-packed map and its transpose.
//
// JpsPlusPlanner is JPS with offline jump-point tables (the 2014 paper's "JPS+", Rabin & Silva's
// formulation): for every cell and each of the 8 directions, the distance to the next jump point or
// to the wall, built once per map in O(cells); a query then jumps by table look-ups, with a goal
// test per jump (the goal on a straight line, or a "target" cell where a diagonal jump crosses the
// goal's row or column).
//
// Both keep g as exact (straight, diagonal) step counts and break f ties toward larger g, like
// AStarPlanner. Both cache per-map data (the bit-packed map; for JPS+ also the tables) keyed by the
// grid's address and size, built on the first plan() on that grid or by prepare(); after editing a
// grid in place call invalidate(). PlanResult::preprocess_ms reports the build time of the call
// that built them (not included in time_ms).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "voronav/planning/grid_planner.hpp"

namespace voronav::planning {

namespace internal {
struct JpsMapData;
struct JpsSearchState;
}  // namespace internal

class JpsPlanner : public GridPlanner {
 public:
  /// Throws voronav::Error when options.connectivity is not 8 (JPS prunes 8-connected grids).
  explicit JpsPlanner(PlannerOptions options = {}, bool with_tables = false);
  ~JpsPlanner() override;
  JpsPlanner(const JpsPlanner&) = delete;
  JpsPlanner& operator=(const JpsPlanner&) = delete;

  [[nodiscard]] std::string_view name() const override { return tables_ ? "jps+" : "jps"; }
  PlanResult plan(const BinaryGrid& grid, Cell start, Cell goal) override;

  /// Builds (or finds cached) the per-map data for `grid`; returns the build time [ms] (0 when
  /// cached).
  double prepare(const BinaryGrid& grid);
  /// Drops every cached map (needed after a grid was edited in place).
  void invalidate();
  /// Total time spent building per-map data so far [ms].
  [[nodiscard]] double total_build_ms() const { return total_build_ms_; }

 private:
  const internal::JpsMapData& map_data(const BinaryGrid& grid, double* build_ms);

  bool tables_;
  std::vector<std::unique_ptr<internal::JpsMapData>> cache_;  // most recent first, at most 4
  std::unique_ptr<internal::JpsSearchState> state_;
  double total_build_ms_ = 0.0;
};

/// JPS+ : JpsPlanner with the offline jump-point tables.
class JpsPlusPlanner : public JpsPlanner {
 public:
  explicit JpsPlusPlanner(PlannerOptions options = {}) : JpsPlanner(std::move(options), true) {}
};

}  // namespace voronav::planning
