#include "voronav/topology/topo_planner.hpp"

#include <chrono>

namespace voronav::topology {

TopologicalPlanner::TopologicalPlanner(planning::PlannerOptions options, TopologyOptions topology)
    : GridPlanner(options), topology_(std::move(topology)), astar_(options) {}

planning::PlanResult TopologicalPlanner::plan(const BinaryGrid& grid, Cell start, Cell goal) {
  using planning::PlanStatus;
  const auto t0 = std::chrono::steady_clock::now();
  planning::PlanResult out;
  auto finish = [&](PlanStatus s) {
    out.status = s;
    out.time_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  if (!grid.contains(start) || !grid.contains(goal)) return finish(PlanStatus::kOutOfMap);
  if (grid[start]) return finish(PlanStatus::kStartOccupied);
  if (grid[goal]) return finish(PlanStatus::kGoalOccupied);
  if (!map_ || map_->blocked != grid) map_ = build_topological_map(grid, topology_);
  last_ = plan_on_graph(*map_, start, goal);
  if (!last_.ok()) return finish(PlanStatus::kUnreachable);
  out.path.push_back(start);
  for (std::size_t k = 1; k < last_.waypoints.size(); ++k) {
    planning::PlanResult leg = astar_.plan(grid, last_.waypoints[k - 1], last_.waypoints[k]);
    out.expanded += leg.expanded;
    if (!leg.ok())
      return finish(leg.status == PlanStatus::kCancelled ? leg.status : PlanStatus::kUnreachable);
    out.path.insert(out.path.end(), leg.path.begin() + 1, leg.path.end());
    out.length_cells += leg.length_cells;
  }
  return finish(PlanStatus::kOk);
}

}  // namespace voronav::topology
