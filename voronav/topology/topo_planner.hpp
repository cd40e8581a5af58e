// TopologicalPlanner: the GridPlanner that plans through the topological graph (seed 003,
// section IV.2): A* over the regions, then A* on the grid between consecutive waypoints (start,
// the midpoints of the crossed critical lines, goal). The topological map is built on the first
// query on a grid and reused while the grid stays the same. `voronav plan --planner topo`.
#pragma once

#include <memory>
#include <optional>

#include "voronav/planning/astar.hpp"
#include "voronav/planning/grid_planner.hpp"
#include "voronav/topology/topological_map.hpp"

namespace voronav::topology {

class TopologicalPlanner : public planning::GridPlanner {
 public:
  explicit TopologicalPlanner(planning::PlannerOptions options = {}, TopologyOptions topology = {});
  [[nodiscard]] std::string_view name() const override { return "topo"; }
  planning::PlanResult plan(const BinaryGrid& grid, Cell start, Cell goal) override;

  /// The topological map of the last grid planned on (empty before the first query).
  [[nodiscard]] const std::optional<TopologicalMap>& map() const { return map_; }
  /// The graph plan of the last query.
  [[nodiscard]] const TopoPlan& last_graph_plan() const { return last_; }

 private:
  TopologyOptions topology_;
  std::optional<TopologicalMap> map_;
  planning::AStarPlanner astar_;
  TopoPlan last_;
};

}  // namespace voronav::topology
